"""Free surfaces that become streamlines (docs/theory.md §3).

usage: free_surface_checks.py FLOWFORM SOURCE_DIR WORKDIR

1. Newtonian die swell against Tanner's values (xml/die_swell.xml, _axisym; sigma0 = 0, n = 1):
   the swell ratio at h = 0.1 within 0.01 of 1.19 (planar) and 1.13 (axisymmetric). The
   literature's converged values spread over 1.186-1.19 and 1.127-1.13; the mesh study of
   docs/BENCHMARKS.md §12 gives 1.1984, 1.1910, 1.1891, 1.1878 (h = 0.2 ... 0.025, planar) and
   1.1369, 1.1305, 1.1289, 1.1277: 0.01 covers the discretization error at h = 0.1 (<= 0.004)
   and the spread. At most 15 surface updates (measured 5 with Anderson's acceleration, the
   default; 4 with Aitken's relaxation, 9 without). Aitken's relaxation converges to the same swell
   within 3e-4 (the move tolerance's bound, as for Newton below; measured 1.7e-5).
   The swell converges under refinement: |s(0.1) - s(0.05)| < |s(0.2) - s(0.1)| (0.0019 < 0.0074).
   The arc-length update (segments keep their length and turn with the flow; the outlet then
   tilts with the surface's end) gives the same swell within 5e-4 (measured 1.0e-4: the nodes sit
   elsewhere, a difference of the discretization's order, 4 times below the h = 0.1 error).
   Newton on the positions (Relaxation = Newton, the linearized update of docs/theory.md §3.5)
   converges in at most 3 updates (measured 2) to the same swell within 3e-4 (measured 1.6e-4: both
   stop at the move tolerance, 8e-5, amplified by (1 - 0.39)^-1 in position).
   On quadrilaterals (Q1/Q1, gmsh's recombination) the planar swell is within 0.01 of 1.19 too
   (measured 1.1937 in 5 updates: the mesh motion splits each quadrilateral along both diagonals).
2. Conservation on the moved mesh. The pressure equation tested with q = 1 makes the boundary
   fluxes sum to zero exactly (the stabilization term vanishes for constant q): inflow + outflow +
   surface_flux = 0 to 1e-10 of the throughput (Newton's residual). What the surface lets through
   is bounded by the flow-angle tolerance: |surface_flux| <= tol * max|u| * L (1e-4 * 1.5 * 8 =
   1.2e-3; measured 2e-6). Power: the inlet traction's power -t * inflow (t = 4, uniform normal
   traction) equals Plastic + Stabilization Power (no walls, traction-free surface and outlet) to
   1e-8 (solver tolerance).
3. Shear thinning (n = 2, 5; planar, h = 0.1): the swell falls toward 1: s(n=1) > s(2) > s(5) and
   |s(5) - 1| <= 0.02 (measured 1.043 and 0.987; 0.990 at h = 0.05).
4. The loop cannot cycle silently: Free Surface/Maximum Iterations = 2 ends with exit 3, the
   reason in the summary's message, free_surface_iterations = 2.
5. Extrusion with a separating die land (xml/extrusion_separation.xml on the paper's mesh): exit 0,
   a gap is reported (> 0), at most 15 updates; what leaves through the outlet is what the ram
   pushes in up to the normal penalty's penetration of the walls in contact, which falls with it,
   and what the land lets through, which the flow-angle tolerance bounds (tol * |u| * L, |u| = 2,
   L = 1.5): |outflow + inflow| <= 1e-3 at kappa_n = 1e3 (measured 4.6e-4) and <= 1e-5 at 1e5 with
   the surface tolerances at 1e-7, 1e-8 (4.5e-6: die face 1.0e-6 and container 3.5e-6 by
   penetration, land 2e-9). The paper's open corner
   (xml/extrusion.xml) loses more than 1 % there (measured 2.4 %: the die-lip leak).
   Adaptive (the scene as shipped, 0.5 % target) against the bilateral land (Released Nodes =
   Never): both meet the target and agree within the sum of their error estimates (measured
   3.7463 +- 0.0176 and 3.7494 +- 0.0166).
6. Sensitivities on a moving shape: dF/dnu by DDM (frozen shape) = the FD on the frozen shape to
   1e-5 (measured 9e-7); the FD with re-converged surfaces is reported (fd_moving_shape) and
   differs (shape_gap > 0; measured 0.49 %); d(gap)/dnu is 0 on the frozen shape and not with the
   surfaces re-converged. The total derivatives through the surface (sensitivity/ShapeDerivative)
   equal the FD with re-converged surfaces: dF/dnu to 1e-4 (measured 1.4e-6), d(gap)/dnu to 1e-3
   (7e-5); on the die swell d(swell)/dn and d(outflow)/dn to 1e-3 (6e-7, 4e-5; the frozen
   d(outflow)/dn is 2.6 times the total). The bounds leave the FD's own error room: central
   differences with a 2e-4 relative step and surfaces re-converged to 1e-8. The linearized update's
   spectral radius is in (0, 1) (measured 0.39: the plain update's ratio of successive moves).
7. Bad input exits 2 and writes nothing: a Start Group that shares no end of the surface, one the
   mesh does not have, Released Nodes = Free Surface without a Start Group, a Wall Gap on a group
   that is not a contact wall.
8. scripts/plot_free_surface.py draws the planar swell (|u| and history, the surfaces): exit 0,
   both PNGs written (> 10 kB: not empty figures).
"""
import os
import sys

from flowform_tools import checks, launcher, summary

NO_FILES = ["Output/Write Solution=false", "Output/Boundary CSV=false"]


def solve(flowform, case, out, sets):
    run = launcher.run(flowform, case, out, sets, quiet=True, clean=True)
    return run.status, summary.load(out) or {}


def main():
    flowform, source, work = sys.argv[1:4]
    failed = 0
    swell = {}
    for scene, tanner, key in (("xml/die_swell.xml", 1.19, "plane"), ("xml/die_swell_axisym.xml", 1.13, "axisym")):
        for h in ("0.2", "0.1", "0.05") if key == "plane" else ("0.1",):
            files = [] if (key, h) == ("plane", "0.1") else NO_FILES  # this one is plotted (8.)
            status, s = solve(flowform, os.path.join(source, scene), os.path.join(work, f"swell_{key}_{h}"),
                              files + [f"Mesh/Geo Parameters/h={h}", "Responses/plastic/Type=Plastic Power",
                                       "Responses/stab/Type=Stabilization Power"])
            f = s.get("functionals") or {}
            swell[(key, h)] = f.get("swell")
            if h != "0.1":
                continue
            iterations = s.get("free_surface_iterations")
            failed += checks.check(status == 0 and f.get("swell") is not None and abs(f["swell"] - tanner) <= 0.01
                            and iterations is not None and 1 <= iterations <= 15,
                            f"{key} Newtonian swell {f.get('swell')} (Tanner {tanner}), exit {status}, "
                            f"{iterations} updates")
            if status != 0:
                continue
            total = f["inflow"] + f["outflow"] + f["surface_flux"]
            failed += checks.check(abs(total) <= 1e-10 * abs(f["inflow"]) and abs(f["surface_flux"]) <= 1.2e-3,
                            f"{key} mass: inflow + outflow + surface = {total:.2e}, surface flux {f['surface_flux']:.2e}")
            traction = 4.0 if key == "plane" else 10.7
            power_in = -traction * f["inflow"]
            balance = power_in - f["plastic"] - f["stab"]
            failed += checks.check(abs(balance) <= 1e-8 * power_in,
                            f"{key} power: inlet {power_in:.6f} - plastic - stabilization = {balance:.2e}")
    s02, s01, s005 = swell[("plane", "0.2")], swell[("plane", "0.1")], swell[("plane", "0.05")]
    failed += checks.check(None not in (s02, s01, s005) and abs(s01 - s005) < abs(s02 - s01),
                    f"planar swell converges under refinement: {s02}, {s01}, {s005}")

    # The same swell by another update or relaxation: (what, the run's name, its setting, the
    # tolerance on the swell against the default's, at most this many updates).
    for what, name, setting, tolerance, most in (
            ("arc-length update", "swell_arc_length", "Boundary Conditions/free_surface/Update=Arc Length", 5e-4, 15),
            ("Newton on the positions", "swell_newton", "Free Surface/Relaxation=Newton", 3e-4, 3),
            ("Aitken's relaxation", "swell_aitken", "Free Surface/Relaxation=Aitken", 3e-4, 15)):
        status, s = solve(flowform, os.path.join(source, "xml/die_swell.xml"), os.path.join(work, name),
                          NO_FILES + [setting])
        value = (s.get("functionals") or {}).get("swell")
        failed += checks.check(status == 0 and value is not None and s01 is not None and abs(value - s01) <= tolerance
                               and s.get("free_surface_iterations", 99) <= most,
                               f"{what}: swell {value} against the default's {s01}, "
                               f"{s.get('free_surface_iterations')} updates")
    status, s = solve(flowform, os.path.join(source, "xml/die_swell.xml"), os.path.join(work, "swell_quads"),
                      NO_FILES + ["Mesh/Element Type=Quadrilateral"])
    quads = (s.get("functionals") or {}).get("swell")
    failed += checks.check(status == 0 and quads is not None and abs(quads - 1.19) <= 0.01,
                    f"quadrilaterals (Q1/Q1): swell {quads} (Tanner 1.19), {s.get('free_surface_iterations')} updates")

    thinning = {}
    for n in ("2.0", "5.0"):
        status, s = solve(flowform, os.path.join(source, "xml/die_swell.xml"), os.path.join(work, f"swell_n{n}"),
                          NO_FILES + [f"Material/Rate Exponent={n}"])
        thinning[n] = (s.get("functionals") or {}).get("swell") if status == 0 else None
    failed += checks.check(None not in thinning.values() and s01 is not None and s01 > thinning["2.0"] > thinning["5.0"]
                    and abs(thinning["5.0"] - 1.0) <= 0.02,
                    f"shear thinning: swell n = 1, 2, 5: {s01}, {thinning['2.0']}, {thinning['5.0']}")

    status, s = solve(flowform, os.path.join(source, "xml/die_swell.xml"), os.path.join(work, "swell_cap"),
                      NO_FILES + ["Free Surface/Maximum Iterations=2"])
    failed += checks.check(status == 3 and s.get("free_surface_iterations") == 2 and "did not converge" in s.get("message", ""),
                    f"cap: exit {status}, {s.get('free_surface_iterations')} updates, message '{s.get('message')}'")

    separation = os.path.join(source, "xml/extrusion_separation.xml")
    for kappa, bound, tolerances in (("1e3", 1e-3, []), ("1e5", 1e-5, ["Free Surface/Flow Angle Tolerance=1e-7",
                                                                          "Free Surface/Move Tolerance=1e-8"])):
        sets = NO_FILES + tolerances + ["Adaptivity/Enabled=false", "Responses/land/Type=Flow Rate",
                                        "Responses/land/Boundary=die_land"] + [
            f"Boundary Conditions/{w}/Normal Penalty Factor={kappa}" for w in ("container", "die_face", "die_land")]
        status, s = solve(flowform, separation, os.path.join(work, f"separation_{kappa}"), sets)
        f = s.get("functionals") or {}
        leak = f["outflow"] + f["inflow"] if status == 0 else None
        # Through the land: at most the flow-angle tolerance times |u| (2) times its length (1.5).
        land_bound = 3.0 * (1e-7 if tolerances else 1e-4)
        failed += checks.check(status == 0 and abs(leak) <= bound and abs(f["land"]) <= land_bound and f.get("gap", 0.0) > 0.0
                        and 1 <= s.get("free_surface_iterations", 0) <= 15,
                        f"separating land, kappa_n = {kappa}: outflow + inflow = {leak}, through the land "
                        f"{f.get('land')}, gap {f.get('gap')}, {s.get('free_surface_iterations')} updates, exit {status}")
    status, s = solve(flowform, os.path.join(source, "xml/extrusion.xml"), os.path.join(work, "open_corner"),
                      NO_FILES + ["Adaptivity/Enabled=false", "Responses/inflow/Type=Flow Rate",
                                  "Responses/inflow/Boundary=ram", "Responses/outflow/Type=Flow Rate",
                                  "Responses/outflow/Boundary=outlet"])
    f = s.get("functionals") or {}
    failed += checks.check(status == 0 and f["outflow"] + f["inflow"] < -0.01,
                    f"open die lip (the paper's): outflow + inflow = {f.get('outflow', 0) + f.get('inflow', 0):.4f}")

    adaptive = {}
    for land in ("Free Surface", "Never"):
        status, s = solve(flowform, separation, os.path.join(work, f"adaptive_{land}"),
                          NO_FILES + [f"Boundary Conditions/die_land/Released Nodes={land}"])
        adaptive[land] = (status, (s.get("functionals") or {}).get("ram_force"),
                          (s.get("functionals_error_estimate") or {}).get("ram_force"))
    (sa, fa, ea), (sb, fb, eb) = adaptive["Free Surface"], adaptive["Never"]
    failed += checks.check(sa == 0 and sb == 0 and abs(fa - fb) <= abs(ea) + abs(eb),
                    f"adaptive ram force, separating land {fa} +- {ea}, bilateral {fb} +- {eb}")

    status, s = solve(flowform, separation, os.path.join(work, "sensitivity"),
                      NO_FILES + ["Adaptivity/Enabled=false", "Sensitivity/Parameters={Friction Coefficient}",
                                  "Sensitivity/Finite Difference Check=true"])
    force = ((s.get("fd_check") or {}).get("ram_force") or {}).get("Friction Coefficient") or {}
    gap = ((s.get("fd_check") or {}).get("gap") or {}).get("Friction Coefficient") or {}
    failed += checks.check(status == 0 and force.get("rel_diff", 1.0) <= 1e-5 and force.get("shape_gap", 0.0) > 0.0
                    and gap.get("ddm") == 0.0 and abs(gap.get("fd_moving_shape", 0.0)) > 0.0,
                    f"dF/dnu: DDM {force.get('ddm')}, FD frozen {force.get('fd')} (rel {force.get('rel_diff')}), "
                    f"FD moving {force.get('fd_moving_shape')} (gap {force.get('shape_gap')}); d(gap)/dnu moving "
                    f"{gap.get('fd_moving_shape')}")
    failed += checks.check(force.get("rel_diff_total_shape", 1.0) <= 1e-4 and gap.get("rel_diff_total_shape", 1.0) <= 1e-3,
                    f"total derivatives through the surface = FD moving: dF/dnu {force.get('ddm_total_shape')} "
                    f"(rel {force.get('rel_diff_total_shape')}), d(gap)/dnu {gap.get('ddm_total_shape')} "
                    f"(rel {gap.get('rel_diff_total_shape')})")
    status, s = solve(flowform, os.path.join(source, "xml/die_swell.xml"), os.path.join(work, "swell_sensitivity"),
                      NO_FILES + ["Sensitivity/Parameters={Rate Exponent}", "Sensitivity/Finite Difference Check=true"])
    entries = {r: ((s.get("fd_check") or {}).get(r) or {}).get("Rate Exponent") or {} for r in ("swell", "outflow")}
    shape = s.get("shape_derivative") or {}
    failed += checks.check(status == 0 and all(e.get("rel_diff_total_shape", 1.0) <= 1e-3 for e in entries.values())
                    and 0.0 < shape.get("contraction", 1.0) < 1.0,
                    f"d(swell)/dn total {entries['swell'].get('ddm_total_shape')} vs FD moving "
                    f"{entries['swell'].get('fd_moving_shape')} (rel {entries['swell'].get('rel_diff_total_shape')}); "
                    f"d(outflow)/dn rel {entries['outflow'].get('rel_diff_total_shape')}, frozen "
                    f"{entries['outflow'].get('ddm')}; update contraction {shape.get('contraction')}")

    swell_case = os.path.join(source, "xml/die_swell.xml")
    for name, sets in (("start_not_at_end", ["Boundary Conditions/free_surface/Start Group=inlet"]),
                       ("start_unknown", ["Boundary Conditions/free_surface/Start Group=nowhere"])):
        out = os.path.join(work, f"bad_{name}")
        run = launcher.run(flowform, swell_case, out, sets, quiet=True, clean=True)
        failed += checks.check(run.status == 2 and not os.path.exists(out), f"bad input {name}: exit {run.status}")
    out = os.path.join(work, "bad_gap_not_a_wall")
    run = launcher.run(flowform, os.path.join(source, "xml/extrusion.xml"), out,
                       ["Adaptivity/Enabled=false", "Responses/gap/Type=Wall Gap", "Responses/gap/Boundary=outlet"],
                       quiet=True, clean=True)
    failed += checks.check(run.status == 2 and not os.path.exists(out), f"bad input Wall Gap on a non-wall: exit {run.status}")
    out = os.path.join(work, "bad_wall_without_start")
    run = launcher.run(flowform, separation, out, ["Boundary Conditions/die_land/Start Group="], quiet=True, clean=True)
    failed += checks.check(run.status == 2 and not os.path.exists(out), f"bad input wall without Start Group: exit {run.status}")

    plots = os.path.join(work, "plots")
    run = launcher.run_command([sys.executable, os.path.join(source, "scripts/plot_free_surface.py"),
                                os.path.join(work, "swell_plane_0.1"), "--out", plots], capture=True)
    made = [os.path.join(plots, f) for f in ("free_surface_swell_plane_0.1.png", "surfaces.png")]
    failed += checks.check(run.status == 0 and checks.pictures_drawn(made),
                    f"plot_free_surface.py: exit {run.status}, {made}")

    return checks.verdict(failed)


if __name__ == "__main__":
    sys.exit(main())
