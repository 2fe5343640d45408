"""The rolling scene against the slab method (docs/rolling.md §7, docs/rolling_theory.md): runs
xml/rolling_flat.xml (the strip's surfaces flat; --case xml/rolling.xml runs the shipped case, both
strip surfaces free) over sets of passes, compares each run with the slab method (Coulomb, on the
exact arc, rolling_theory.py) at the same R, h0, h1, ν and the model's material, prints a table of
the relative differences and the trends, and draws the classical pictures.

Parts (--parts, default all but mesh):
  nu         ν ∈ --nu (0.2, 0.25, 0.3, 0.4, 0.5) at R = 10, h0 = 1, h1 = 0.75 (25 %)
  R          R/h0 ∈ --R (5, 10, 20, 40) at ν = --nu-fixed (0.3), 25 %
  reduction  reductions --reductions (0.10, 0.25, 0.40) at R = 10, ν = 0.3
  sticking   ν = 2 (Coulomb), compared with the slab's Coulomb ν = 2 and with sticking
             (Orowan's cap τ = min(ν p, k), = Tresca m = 1 where ν p > k everywhere); and the FE
             with Tresca m = 1 against the slab's Tresca m = 1
  mesh       the passes (ν = 0.2), (ν = 0.3), (ν = 0.3, R = 20) on h ∈ --h-family (0.1, 0.05,
             0.035; hc = h/2.5): the spread that the tests' tolerances come from
Each pass runs once per Coulomb normal force of --normal-force (docs/contact.md "What Coulomb
multiplies"):
  "Contact Force"  τ = ν σ_n, the normal traction: the slab method's Coulomb law (default here)
  "Pressure"       τ = ν p, the mean pressure (the paper's law), a friction
                   about 0.6 ν in the slab's sense (docs/rolling.md §7)
  both             the two.

Out: OUT/<variant>/<pass>/ (flowform's outputs), OUT/study.csv (one row per run), and the PNGs
  hill_<variant>.png    the roll pressure p_n = p − s_nn along the arc (against the angle from
                        the exit plane) for the ν of the nu part, the slab method's hill dashed,
                        the neutral points marked (FE: the Neutral Angle response)
  slip_<variant>.png    the relative slip v/(ωR) − 1 of the strip surface along the arc, FE and slab
  speed_<variant>.png   |u| on the mesh with the strip surfaces and the arc (default pass, ν = 0.3),
                        whole and near the bite

usage:
  scripts/python scripts/rolling_study.py [FLOWFORM] [--out out/rolling_study] [--parts nu,R,...]
        [--normal-force "Contact Force"|Pressure|both] [--nu 0.2,0.25,...] [--R 5,10,20,40]
        [--reductions 0.1,0.25,0.4] [--nu-fixed 0.3] [--h H] [--h-family 0.1,0.05,0.035]
        [--reuse] [--plots-only] [--timeout S] [--set P=V ...]

  --h       the bulk mesh size of every run but the mesh part (default the scene's 0.05)
  --reuse   keep a run whose converged summary.json is already in OUT (same pass)
  --plots-only  no runs: table and plots from what OUT holds

Every run: no error estimate, no sensitivities (Error Estimation/Method = None,
Sensitivity/Parameters = {}); the inlet's start speed follows R and h1 (rolling_compare.pass_sets;
the roll's centre follows the mesh by itself). Exit 0 when every run converged, 3 when some did not (they
are listed; a pass the roll cannot draw in is an answer too), 2 on bad arguments.
Needs numpy, h5py, matplotlib (/usr/bin/python3).
"""
import argparse
import math
import os
import sys

import numpy as np

from flowform_tools import launcher, plotting, rolling_compare, summary as summary_module, sweep
from flowform_tools import default_flowform, repo_path

VARIANTS = {"Contact Force": "cf", "Pressure": "pressure"}
BASE = ["Error Estimation/Method=None", "Sensitivity/Parameters={}"]
R0, H0, H10 = 10.0, 1.0, 0.75


class Pass:
    """One FE run: pass, friction, mesh, variant."""

    def __init__(self, part, variant, R=R0, h1=H10, nu=0.3, law="Coulomb", h=None):
        self.part, self.variant, self.R, self.h1, self.nu, self.law, self.h = part, variant, R, h1, nu, law, h

    @property
    def key(self):
        return (self.variant, self.R, self.h1, self.nu, self.law, self.h)

    @property
    def name(self):
        law = "m" if self.law == "Tresca" else "nu"
        mesh = f"_h{self.h:g}" if self.h else ""
        return f"{law}{self.nu:g}_R{self.R:g}_h1_{self.h1:g}{mesh}"

    def directory(self, out):
        return os.path.join(out, VARIANTS[self.variant], self.name)

    def sets(self):
        hc = self.h / 2.5 if self.h else None
        return (rolling_compare.pass_sets(R=self.R, h1=self.h1, nu=self.nu, law=self.law, h=self.h, hc=hc)
                + [f"Boundary Conditions/roll/Coulomb Normal Force={self.variant}"])


def passes(a):
    out = []
    for variant in a.variants:
        if "nu" in a.parts:
            out += [Pass("nu", variant, nu=nu, h=a.h) for nu in a.nu]
        if "R" in a.parts:
            out += [Pass("R", variant, R=r * H0, nu=a.nu_fixed, h=a.h) for r in a.R]
        if "reduction" in a.parts:
            out += [Pass("reduction", variant, h1=round(H0 * (1 - r), 12), nu=a.nu_fixed, h=a.h) for r in a.reductions]
        if "sticking" in a.parts:
            out += [Pass("sticking", variant, nu=2.0, h=a.h)]
            if variant == a.variants[0]:
                out += [Pass("sticking", variant, nu=1.0, law="Tresca", h=a.h)]
        if "mesh" in a.parts:
            for R, nu in ((R0, 0.2), (R0, 0.3), (20.0, 0.3)):
                out += [Pass("mesh", variant, R=R, nu=nu, h=h) for h in a.h_family]
    seen, unique = {}, []
    for p in out:                       # a pass in two parts runs once, listed in both
        if p.key in seen:
            unique.append(Pass(p.part, p.variant, p.R, p.h1, p.nu, p.law, p.h))
            unique[-1].shared = seen[p.key]
        else:
            seen[p.key] = p
            unique.append(p)
    return unique


def run_all(a, plist):
    failed = []
    for p in plist:
        d = p.directory(a.out)
        if hasattr(p, "shared") or (a.reuse and rolling_compare.run_dir_ok(d)) or a.plots_only:
            continue
        r, bilateral = rolling_compare.run_pass(a.flowform, repo_path(*a.case.split("/")), d,
                                                BASE + p.sets() + a.sets, timeout=a.timeout)
        print(f"  {VARIANTS[p.variant]}/{p.name}: exit {r.status}, {r.wall:.1f} s"
              + (" (statuses cycled: bilateral roll)" if bilateral else ""), flush=True)
        if r.status != 0:
            failed.append((p, r.status, (r.stderr or "").strip().splitlines()[-1:] or [""]))
    return failed


# --------------------------------------------------------------------------------------- the table


COLUMNS = ["variant", "part", "nu", "law", "R_h0", "reduction", "h", "exit",
           "fe_force", "slab_force", "rel_force", "fe_torque", "slab_torque", "rel_torque",
           "fe_neutral_deg", "slab_neutral_deg", "fe_forward_slip", "slab_forward_slip",
           "fe_contact_length", "slab_contact_length", "rel_contact_length", "rate_factor",
           "flux_mismatch", "entry_surface_flux_rel", "slab_min_nu", "sticking_force", "sticking_torque",
           "bilateral", "newton", "inflow_solves", "seconds", "dir"]


def row_of(a, p):
    d = p.directory(a.out)
    s = summary_module.load(d)
    R, h1 = p.R, p.h1
    row = {"variant": p.variant, "part": p.part, "nu": p.nu, "law": p.law, "R_h0": R / H0, "reduction": (H0 - h1) / H0,
           "h": p.h if p.h else 0.05, "dir": os.path.relpath(d, a.out), "exit": None if s is None else s.get("exit_status")}
    row["slab_min_nu"] = rolling_compare.slab_min_nu(R, H0, h1)
    if s is None or not s.converged:
        return row
    c = rolling_compare.compare(d, s)
    row["bilateral"] = int(rolling_compare.is_bilateral(s))
    row.update(fe_force=c.fe["roll_force"], slab_force=c.slab.force, rel_force=c.rel["roll_force"],
               fe_torque=c.fe["roll_torque"], slab_torque=c.slab.torque, rel_torque=c.rel["roll_torque"],
               fe_neutral_deg=c.fe["neutral_angle"], slab_neutral_deg=c.slab.neutral_angle,
               fe_forward_slip=c.fe["forward_slip"], slab_forward_slip=c.slab.forward_slip,
               fe_contact_length=c.fe["contact_length"], slab_contact_length=c.slab.contact_length,
               rel_contact_length=c.rel["contact_length"], rate_factor=c.rate_factor,
               flux_mismatch=c.flux_mismatch, entry_surface_flux_rel=-c.flux_entry_surface / c.flux_out,
               newton=s.get("newton_iterations"), inflow_solves=(s.get("rigid_inflow") or {}).get("solves"),
               seconds=(s.get("timings") or {}).get("total"))
    if p.law == "Coulomb" and p.nu >= 1.0:      # the sticking limit: Orowan's cap m = 1
        stick = c.ps.slab(friction="orowan", m=1.0)
        row.update(sticking_force=stick.force, sticking_torque=stick.torque)
    return row


def pct(v):
    return "-" if v is None or (isinstance(v, float) and math.isnan(v)) else f"{100 * v:+.1f} %"


def num(v, form="{:.4g}"):
    return "-" if v is None else form.format(v)


def print_table(rows):
    print("| variant | part | ν (m) | R/h0 | r | h | force FE | slab | Δ | torque FE | slab | Δ | φ_n FE ° | slab ° "
          "| slip FE | slab | L_c Δ | σ̄_D/σ̄(e_m) | (Q_in−Q_out)/Q | ν_min slab |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for r in rows:
        nu = f"{r['nu']:g}" + (" (Tresca m)" if r["law"] == "Tresca" else "") + (" ‡" if r.get("bilateral") else "")
        if r.get("fe_force") is None:
            print(f"| {VARIANTS[r['variant']]} | {r['part']} | {nu} | {r['R_h0']:g} | {r['reduction']:.2f} | {r['h']:g} "
                  f"| exit {r['exit']} | | | | | | | | | | | | | {r['slab_min_nu']:.4f} |")
            continue
        print(f"| {VARIANTS[r['variant']]} | {r['part']} | {nu} | {r['R_h0']:g} | {r['reduction']:.2f} | {r['h']:g} "
              f"| {r['fe_force']:.4f} | {r['slab_force']:.4f} | {pct(r['rel_force'])} "
              f"| {r['fe_torque']:.4f} | {r['slab_torque']:.4f} | {pct(r['rel_torque'])} "
              f"| {r['fe_neutral_deg']:.3f} | {r['slab_neutral_deg']:.3f} "
              f"| {r['fe_forward_slip']:.4f} | {r['slab_forward_slip']:.4f} | {pct(r['rel_contact_length'])} "
              f"| {num(r['rate_factor'], '{:.3f}')} | {pct(r['flux_mismatch'])} | {r['slab_min_nu']:.4f} |")
    if any(r.get("bilateral") for r in rows):
        print("‡: the statuses cycled (exit 3); solved with Released Nodes = Never (a bilateral roll)")
    for r in rows:
        if r.get("sticking_force") is not None and r.get("fe_force") is not None:
            print(f"sticking ({VARIANTS[r['variant']]}, ν = {r['nu']:g}): slab with Orowan's cap m = 1: force "
                  f"{r['sticking_force']:.4f} (FE {pct(r['fe_force'] / r['sticking_force'] - 1)}), torque "
                  f"{r['sticking_torque']:.4f} (FE {pct(r['fe_torque'] / r['sticking_torque'] - 1)})")


TRENDS = (("force", "fe_force", "slab_force"), ("torque", "fe_torque", "slab_torque"),
          ("φ_n", "fe_neutral_deg", "slab_neutral_deg"), ("forward slip", "fe_forward_slip", "slab_forward_slip"))
SWEPT = {"nu": "nu", "R": "R_h0", "reduction": "reduction"}


def trends(rows):
    """Per part and variant, the signs of the consecutive differences of FE and slab."""
    out = []
    for part, x in SWEPT.items():
        for variant in VARIANTS:
            rs = sorted([r for r in rows if r["part"] == part and r["variant"] == variant and r.get("fe_force") is not None
                         and r["law"] == "Coulomb"], key=lambda r: r[x])
            if len(rs) < 2:
                continue
            for label, fe, slab in TRENDS:
                sf = [int(np.sign(b[fe] - a[fe])) for a, b in zip(rs, rs[1:])]
                ss = [int(np.sign(b[slab] - a[slab])) for a, b in zip(rs, rs[1:])]
                out.append({"part": part, "variant": variant, "response": label, "fe": sf, "slab": ss,
                            "agree": sf == ss, "x": [r[x] for r in rs]})
    return out


def print_trends(tr):
    print("\n| sweep | variant | response | values of the sweep | sign of Δ, FE | sign of Δ, slab | agree |")
    print("|---|---|---|---|---|---|---|")
    sign = lambda v: "".join("+" if s > 0 else "−" if s < 0 else "0" for s in v)  # noqa: E731
    for t in tr:
        print(f"| {t['part']} | {VARIANTS[t['variant']]} | {t['response']} | {', '.join(f'{v:g}' for v in t['x'])} "
              f"| {sign(t['fe'])} | {sign(t['slab'])} | {'yes' if t['agree'] else 'NO'} |")


# --------------------------------------------------------------------------------------- plots


def plots(a, plist):
    plt = plotting.pyplot()
    for variant in a.variants:
        nus = [p for p in plist if p.part == "nu" and p.variant == variant]
        nus = [p for p in nus if rolling_compare.run_dir_ok(p.directory(a.out))]
        if not nus:
            continue
        tag = VARIANTS[variant]
        fig_h, ax_h = plt.subplots(figsize=(9, 5))
        fig_s, ax_s = plt.subplots(figsize=(9, 5))
        for i, p in enumerate(sorted(nus, key=lambda p: p.nu)):
            d, color = p.directory(a.out), f"C{i}"
            arc = rolling_compare.arc_profile(d)
            ps = rolling_compare.Pass(summary_module.load(d))
            slab = ps.slab()
            inside = arc["status"] > 0.5
            deg = np.degrees(arc["phi"])
            ax_h.plot(deg[inside], arc["p_n"][inside], "-", color=color, label=f"FE ν = {p.nu:g}")
            ax_h.plot(np.degrees(slab.phi), slab.pressure, "--", color=color, lw=1, label=f"slab ν = {p.nu:g}")
            fe_phin = summary_module.load(d).functional("neutral_angle")
            ax_h.axvline(fe_phin, color=color, lw=0.6, ls=":")
            ax_s.plot(deg, arc["slip"], "-", color=color, label=f"FE ν = {p.nu:g}")
            ax_s.plot(np.degrees(slab.phi), -slab.slip / (ps.omega * ps.R), "--", color=color, lw=1)
        ax_h.set_xlabel("angle from the exit plane φ (°)")
        ax_h.set_ylabel("roll pressure p_n = p − s_nn (σ0)")
        ax_h.set_title(f"friction hill, R = {R0:g}, h0 = 1, h1 = 0.75; Coulomb on the {variant.lower()} "
                       "(dotted: FE neutral angle)", fontsize=9)
        ax_h.legend(fontsize=7, ncol=2)
        ax_s.axhline(0.0, color="k", lw=0.6)
        ax_s.set_xlabel("angle from the exit plane φ (°)")
        ax_s.set_ylabel("relative slip v/(ωR) − 1 of the strip surface")
        ax_s.set_title(f"slip along the arc (dashed: slab, homogeneous flow); Coulomb on the {variant.lower()}", fontsize=9)
        ax_s.legend(fontsize=7)
        plotting.grid(ax_h, ax_s)
        plotting.save(fig_h, os.path.join(a.out, f"hill_{tag}.png"))
        plotting.save(fig_s, os.path.join(a.out, f"slip_{tag}.png"))
        speed_map(a, [p for p in nus if abs(p.nu - 0.3) < 1e-12] or nus[:1], tag)


def speed_map(a, plist, tag):
    plt = plotting.pyplot()
    d = plist[0].directory(a.out)
    xy, topo, fields = plotting.read_solution(d)
    tri, _ = plotting.triangulate(xy, topo)
    speed = np.hypot(fields["velocity"][:, 0], fields["velocity"][:, 1])
    fig, axes = plt.subplots(2, 1, figsize=(11, 5.5), gridspec_kw={"height_ratios": [1, 1.3]})
    for ax, zoom in zip(axes, (None, (-1.9, 0.3, 0.0, 0.52))):
        im = ax.tripcolor(tri, speed, shading="gouraud", cmap="viridis")
        ax.triplot(tri, lw=0.15, color="w", alpha=0.4)
        for group, style in (("entry_surface", "r-"), ("exit_surface", "m-"), ("roll", "k-")):
            w = plotting.read_wall(d, group)
            if w is not None:
                ax.plot(w["x"], w["y"], style, lw=1.6, label=group)
        ax.set_aspect("equal")
        if zoom:
            ax.set_xlim(*zoom[:2])
            ax.set_ylim(*zoom[2:])
        fig.colorbar(im, ax=ax, label="|u|", shrink=0.8)
    axes[0].legend(fontsize=7, loc="lower left")
    surfaces = "free (streamlines)" if "flat" not in os.path.basename(a.case) else "flat and fixed"
    axes[0].set_title(f"|u|, {plist[0].name}, Coulomb on the {plist[0].variant.lower()}: the strip surfaces {surfaces}",
                      fontsize=9)
    axes[1].set_title("near the bite", fontsize=9)
    plotting.save(fig, os.path.join(a.out, f"speed_{tag}.png"))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("flowform", nargs="?", default=default_flowform())
    ap.add_argument("--out", default="out/rolling_study")
    ap.add_argument("--case", default="xml/rolling_flat.xml", help="the case, relative to the repository")
    ap.add_argument("--parts", default="nu,R,reduction,sticking")
    ap.add_argument("--normal-force", default="Contact Force", choices=["Contact Force", "Pressure", "both"])
    ap.add_argument("--nu", type=sweep.parse_values, default=[0.2, 0.25, 0.3, 0.4, 0.5])
    ap.add_argument("--R", type=sweep.parse_values, default=[5, 10, 20, 40])
    ap.add_argument("--reductions", type=sweep.parse_values, default=[0.1, 0.25, 0.4])
    ap.add_argument("--nu-fixed", type=float, default=0.3)
    ap.add_argument("--h", type=float, default=None)
    ap.add_argument("--h-family", type=sweep.parse_values, default=[0.1, 0.05, 0.035])
    ap.add_argument("--reuse", action="store_true")
    ap.add_argument("--plots-only", action="store_true")
    ap.add_argument("--timeout", type=float, default=None)
    ap.add_argument("--set", dest="sets", action="append", default=[])
    a = ap.parse_args()
    a.parts = [p.strip() for p in a.parts.split(",") if p.strip()]
    bad = [p for p in a.parts if p not in ("nu", "R", "reduction", "sticking", "mesh")]
    if bad:
        print(f"rolling_study.py: --parts {','.join(bad)}: allowed nu, R, reduction, sticking, mesh", file=sys.stderr)
        return 2
    if not any(0 < r < 1 for r in a.reductions) or any(not 0 < r < 1 for r in a.reductions):
        print("rolling_study.py: --reductions must lie in (0, 1)", file=sys.stderr)
        return 2
    a.variants = list(VARIANTS) if a.normal_force == "both" else [a.normal_force]
    if not a.plots_only:
        launcher.require_executable(a.flowform, "rolling_study.py")
    os.makedirs(a.out, exist_ok=True)
    plist = passes(a)
    failed = run_all(a, plist)
    rows = []
    for p in plist:
        q = getattr(p, "shared", p)
        row = row_of(a, Pass(p.part, q.variant, q.R, q.h1, q.nu, q.law, q.h))
        rows.append(row)
    sweep.write(os.path.join(a.out, "study.csv"), COLUMNS, rows)
    print_table(rows)
    print_trends(trends(rows))
    plots(a, plist)
    for p, status, tail in failed:
        print(f"not converged: {VARIANTS[p.variant]}/{p.name} exit {status}: {tail[0]}")
    print(f"table {os.path.join(a.out, 'study.csv')}, plots in {a.out}")
    return 3 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
