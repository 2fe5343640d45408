"""Limits in ν: ν = 0 against no friction law and Symmetry walls, large ν against no-slip walls,
and the ram force monotone in ν (docs/extrusion_verification.md §5)."""
import os
import subprocess

from flowform_tools import msh
from flowform_tools.case import param, set_group, sublist

from .common import contact_state, lit, mesh_list, observed_order, ram_corner_friction, richardson, symmetry_walls


def cmd_frictionless(runner, args, checks):
    meshes = mesh_list(args.meshes, "0.2,0.1")
    none = [f"Boundary Conditions/{w}/Friction Law=None" for w in runner.walls]
    symmetry_case = runner.variant("frictionless_symmetry_case", symmetry_walls(runner.walls))
    specs = []
    for h in meshes:
        specs += [(f"h = {h}, Coulomb nu = 0", dict(name=f"fl_coulomb_h{h}", h=h, nu=0.0)),
                  (f"h = {h}, Friction Law None", dict(name=f"fl_none_h{h}", h=h, nu=0.0, sets=none)),
                  (f"h = {h}, nu = 0, no release (Pressure Tol 1e9)",
                   dict(name=f"fl_norelease_h{h}", h=h, nu=0.0, sets=["Contact/Pressure Tolerance=1e9",
                                                                                "Contact/Status Update=Certain Iterate"])),
                  (f"h = {h}, Symmetry walls", dict(name=f"fl_symmetry_h{h}", h=h, case=symmetry_case))]
    runs = runner.run_all(specs, checks)
    gaps, table = [], []
    for i, h in enumerate(meshes):
        coulomb, none_run, norelease, sym = runs[4 * i:4 * i + 4]
        if not all(checks.check(r.converged, f"{r.label}: converged") for r in (coulomb, none_run, norelease, sym)):
            continue
        Fc, Fn, Fr, Fs = coulomb.force, none_run.force, norelease.force, sym.force
        checks.check(abs(Fc - Fn) <= 1e-10 * Fn and coulomb.summary["contact_changes"] == none_run.summary["contact_changes"],
                     f"h = {h}: Coulomb ν = 0 {Fc:.12f} = None {Fn:.12f} (|Δ|/F = {abs(Fc - Fn) / Fn:.1e} <= 1e-10), "
                     f"same status changes")
        released = sum(c["free"] for c in contact_state(coulomb, 1e300, 1e300, runner.walls)[2].values())
        penalty_gap = (Fs - Fr) / Fs
        checks.check(0 <= penalty_gap < 5e-4,
                     f"h = {h}: no release {Fr:.8f} vs Symmetry {Fs:.8f}: (Sym - contact)/Sym = {penalty_gap:.2e} "
                     f"in [0, 5e-4] (the normal-penalty compliance)")
        gap = (Fs - Fc) / Fs
        gaps.append((h, gap))
        checks.check(gap > 0 and released > 0,
                     f"h = {h}: with {released} node(s) released (tension) the contact force {Fc:.6f} is below "
                     f"Symmetry's by {gap:.3%}")
        table.append(dict(h=h, coulomb=Fc, none=Fn, no_release=Fr, symmetry=Fs, released=released,
                          gap_symmetry_release=gap, gap_symmetry_norelease=penalty_gap))
    for (h1, g1), (h2, g2) in zip(gaps, gaps[1:]):
        checks.check(g2 < g1, f"the release effect shrinks with h: {g1:.3%} (h = {h1}) -> {g2:.3%} (h = {h2})")
    checks.record("table", table)


def cmd_sticking(runner, args, checks):
    """Large ν against no-slip walls upstream of the die land.

    The walls in flow order: the first (container) meets the ram at the ram corner, the last
    (die land) carries the exit plug; "upstream" is every wall but the last.
    """
    meshes = mesh_list(args.meshes, "0.2,0.1,0.05")
    first, upstream, land_wall = runner.walls[0], runner.walls[:-1], runner.walls[-1]
    nu = float(args.nu or 1.0)
    noslip = [("Type", "string", "Velocity"), ("Velocity X", "double", "0.0"), ("Velocity Y", "double", "0.0")]
    specs = []
    for h in meshes:
        base = os.path.join(runner.out, f"sticking_h{h}.msh")
        geo = runner.scene.mesh_file()  # meshes/extrusion.geo
        subprocess.run(["gmsh", "-2", geo, "-setnumber", "h", lit(h), "-setnumber", "hc", lit(h / 4), "-format", "msh4",
                        "-o", base], check=True, stdout=subprocess.DEVNULL)
        cut = os.path.join(runner.out, f"sticking_h{h}_noslip.msh")
        with open(base) as f:
            text = f.read()
        with open(cut, "w") as g:
            g.write(msh.without_corner_segment(text, first, msh.shared_point(text, runner.tool, first)))

        def on_mesh(path, groups):
            def edit(root):
                mesh = sublist(root, "Mesh")
                mesh.remove(sublist(mesh, "Geo Parameters"))
                param(mesh, "File").set("value", path)
                for w in groups:
                    set_group(root, w, noslip)
            return edit

        contact = runner.variant(f"sticking_contact_h{h}", on_mesh(base, ()))
        two = runner.variant(f"sticking_noslip2_h{h}", on_mesh(cut, upstream))
        three = runner.variant(f"sticking_noslip3_h{h}", on_mesh(cut, runner.walls))
        land = [f"Boundary Conditions/{land_wall}/Friction Coefficient={lit(nu)}"]
        specs += [(f"h = {h}, contact nu = {nu:g}", dict(name=f"st_contact_h{h}", nu=nu, case=contact)),
                  (f"h = {h}, no-slip {'+'.join(upstream)}", dict(name=f"st_noslip2_h{h}", case=two, sets=land)),
                  (f"h = {h}, no-slip on every wall", dict(name=f"st_noslip3_h{h}", case=three))]
    runs = runner.run_all(specs, checks)
    table = []
    for i, h in enumerate(meshes):
        contact, two, three = runs[3 * i:3 * i + 3]
        if not all(checks.check(r.converged, f"{r.label}: converged") for r in (contact, two, three)):
            continue
        corner = ram_corner_friction(contact)
        Fc, F2, F3 = contact.force, two.force, three.force
        dF = (Fc - corner - F2) / F2
        dP = (contact.f("plastic_power") - two.f("plastic_power")) / two.f("plastic_power")
        print(f"    h = {h}: contact F = {Fc:.6f} (ram-corner friction {corner:.6f}), no-slip {'+'.join(upstream)} "
              f"F = {F2:.6f}, no-slip everywhere F = {F3:.6f}")
        print(f"    h = {h}: gaps (contact - no-slip)/no-slip: force less the ram-corner friction {dF:+.3%}, "
              f"plastic power {dP:+.3%}")
        checks.check(F3 > 1.5 * Fc, f"h = {h}: a no-slip die land is another problem: F = {F3:.4f} vs {Fc:.4f} "
                                    f"(Coulomb friction vanishes on the nearly stress-free exit plug)")
        table.append(dict(h=h, nu=nu, contact=Fc, ram_corner_friction=corner, noslip_container_dieface=F2,
                          noslip_all=F3, force_gap=dF, plastic_gap=dP,
                          plastic_contact=contact.f("plastic_power"), plastic_noslip=two.f("plastic_power")))
    # Both gaps are corner effects of one element: the ram-corner node slides at the ram speed
    # (contact: Coulomb friction ν p L/2 there, subtracted; no-slip: a one-element shear band) and
    # the sticking penalty lets the nodes next to it slip by ~ their share of 1/κ_t. So they are
    # O(h): they must shrink, and their Richardson extrapolation to h = 0 must vanish.
    for a, b in zip(table, table[1:]):
        for key in ("force_gap", "plastic_gap"):
            checks.check(abs(b[key]) * 1.4 <= abs(a[key]), f"{key}: {a[key]:+.2%} -> {b[key]:+.2%} "
                         f"(h = {a['h']} -> {b['h']}): shrinks by a factor >= 1.4")
    if len(table) >= 3 and all(abs(a["h"] / b["h"] - 2.0) < 1e-9 for a, b in zip(table, table[1:])):
        for key in ("force_gap", "plastic_gap"):
            gaps = [t[key] for t in table]
            q = observed_order(gaps)[-1]
            limit = richardson(gaps, q)
            checks.record(f"{key}_extrapolated", dict(order=q, value=limit))
            checks.check(abs(limit) < 0.01, f"{key}: observed order {q:.2f}, extrapolated to h = 0: {limit:+.3%} "
                                            f"(|.| < 1%: large ν reaches the no-slip wall)")
    checks.record("table", table)


def cmd_monotone(runner, args, checks):
    h = mesh_list(args.meshes, "0.1")[0]
    nus = [0.0, 0.05, 0.1, 0.2, 0.3, 0.5]
    runs = runner.run_all([(f"h = {h}, nu = {nu}", dict(name=f"mono_nu{nu}", h=h, nu=nu)) for nu in nus], checks)
    if not all(checks.check(r.converged, f"{r.label}: converged") for r in runs):
        return
    F = [r.force for r in runs]
    dz = [r.f(runner.dead_zone_name) for r in runs]
    for nu, f, z in zip(nus, F, dz):
        print(f"    nu = {nu:4}: F = {f:.6f}  dead zone {z:.5f}")
    checks.record("table", [dict(nu=nu, ram_force=f, dead_zone=z) for nu, f, z in zip(nus, F, dz)])
    checks.check(all(b > a for a, b in zip(F, F[1:])), "the ram force increases strictly with ν: increments " +
                 ", ".join(f"{b - a:+.4f}" for a, b in zip(F, F[1:])))
    checks.check(all(b >= a - 1e-12 for a, b in zip(dz, dz[1:])), "the dead zone does not shrink as ν grows")


COMMANDS = {"frictionless": cmd_frictionless, "sticking": cmd_sticking, "monotone": cmd_monotone}
