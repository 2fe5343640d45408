"""Work against error of the extrusion's ram force (docs/theory.md §7): meshes of the .geo's
own grading (hc = h/4, the default's; and the strongly corner-graded hc = h/25) against the
adaptive loop at several targets, every run with its error estimate.

usage: scripts/python bench/adaptivity_bench.py [FLOWFORM] [--case xml/extrusion.xml] [--reference 3.7347]
                                 [--uniform H:HC,...] [--targets 0.02,0.005,...] [--nu NU]
                                 [--dfdnu-reference D] [--workdir /tmp/flowform_adapt_bench]

For each run: dofs of the final mesh, total seconds (wall clock of the whole run, the estimate
included), F, the estimate eta, the true error F_ref - F against --reference (a Richardson value:
bench/extrusion_references.py, docs/BENCHMARKS.md §10), and the effectivity eta / (F_ref - F). Every run estimates
(Error Estimation/Method = Two-Level), so the uniform rows cost what a user who wants the
estimate pays.
"""
import argparse
import os
import time

from flowform_tools import launcher, summary


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap = argparse.ArgumentParser()
    ap.add_argument("flowform", nargs="?", default=os.path.join(root, "build/flowform"))
    ap.add_argument("--case", default=os.path.join(root, "xml/extrusion.xml"))
    ap.add_argument("--reference", type=float, default=3.7347)
    ap.add_argument("--uniform", default="0.1:0.025,0.05:0.0125,0.025:0.00625,0.2:0.008,0.1:0.004,0.05:0.002")
    ap.add_argument("--targets", default="0.02,0.005,0.002,0.001")
    ap.add_argument("--workdir", default="/tmp/flowform_adapt_bench")
    ap.add_argument("--nu", help="friction coefficient of all three walls (default: the case's)")
    ap.add_argument("--dfdnu-reference", type=float,
                    help="also ask for dF/dnu and report its estimate and true error against this value")
    a = ap.parse_args()
    rows = []
    runs = [(f"uniform h={h} hc={hc}", ["Adaptivity/Enabled=false", f"Mesh/Geo Parameters/h={h}",
                                          f"Mesh/Geo Parameters/hc={hc}",
                                          "Error Estimation/Method=Two-Level"]) for h, hc in
            (p.split(":") for p in a.uniform.split(","))]
    runs += [(f"adaptive target {t}", ["Adaptivity/Responses={ram_force}", f"Adaptivity/Target Relative Error={t}"])
             for t in a.targets.split(",")]
    common = []
    if a.nu is not None:
        common += [f"Boundary Conditions/{w}/Friction Coefficient={a.nu}" for w in ("container", "die_face", "die_land")]
    if a.dfdnu_reference is not None:
        common.append("Sensitivity/Parameters={Friction Coefficient}")
    for label, sets in runs:
        sets = sets + common
        out = os.path.join(a.workdir, label.replace(" ", "_").replace("=", ""))
        start = time.monotonic()
        run = launcher.run(a.flowform, a.case, out, sets, quiet=True, clean=True)
        seconds = time.monotonic() - start
        s = summary.load(out) or {}
        f = (s.get("functionals") or {}).get("ram_force")
        eta = (s.get("functionals_error_estimate") or {}).get("ram_force")
        true = a.reference - f if f is not None else None
        d = ((s.get("sensitivities") or {}).get("ram_force") or {}).get("Friction Coefficient")
        deta = ((s.get("sensitivities_error_estimate") or {}).get("ram_force") or {}).get("Friction Coefficient")
        rows.append((label, run.status, s.get("dofs"), seconds, f, eta, true,
                     eta / true if eta is not None and true else None, d, deta))
    print(f"reference F = {a.reference}")
    extra = f" {'dF/dnu':>9} {'eta':>10} {'true':>10} {'eff':>6}" if a.dfdnu_reference is not None else ""
    print(f"{'run':34} {'exit':>4} {'dofs':>7} {'s':>7} {'F':>9} {'eta':>10} {'true':>10} {'rel.true':>9} {'eff':>6}"
          + extra)
    fmt = lambda v, spec: format(v, spec) if v is not None else "-"  # noqa: E731
    for label, status, dofs, seconds, f, eta, true, eff, d, deta in rows:
        line = (f"{label:34} {status:>4} {fmt(dofs, '>7')} {seconds:7.2f} {fmt(f, '9.5f')} {fmt(eta, '10.2e')} "
                f"{fmt(true, '10.2e')} {fmt(abs(true) / a.reference if true is not None else None, '9.1e')} "
                f"{fmt(eff, '6.2f')}")
        if a.dfdnu_reference is not None:
            dtrue = a.dfdnu_reference - d if d is not None else None
            line += (f" {fmt(d, '9.5f')} {fmt(deta, '10.2e')} {fmt(dtrue, '10.2e')} "
                     f"{fmt(deta / dtrue if deta is not None and dtrue else None, '6.2f')}")
        print(line)


if __name__ == "__main__":
    main()
