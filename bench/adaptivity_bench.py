#!/usr/bin/python3
"""Work against error of the extrusion's ram force (docs/theory.md §7): uniform corner grading
(the case's own .geo sizes, hc = h/4 halved) against the adaptive loop at several targets.

usage: bench/adaptivity_bench.py [FLOWFORM] [--case xml/extrusion.xml] [--reference 3.735]
                                 [--targets 0.005,0.001] [--workdir /tmp/flowform_adapt_bench]

For each run: dofs of the final mesh, total seconds (wall clock of the whole run, the estimate
included), F, the estimate eta, the true error F_ref - F against --reference (a Richardson value:
docs/extrusion_verification.md §3), and the effectivity eta / (F_ref - F). Every run estimates
(Error Estimation/Method = Two-Level), so the uniform rows cost what a user who wants the
estimate pays.
"""
import argparse
import os
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "python"))
from flowform_tools import launcher, summary  # noqa: E402


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap = argparse.ArgumentParser()
    ap.add_argument("flowform", nargs="?", default=os.path.join(root, "build/flowform"))
    ap.add_argument("--case", default=os.path.join(root, "xml/extrusion.xml"))
    ap.add_argument("--reference", type=float, default=3.735)
    ap.add_argument("--uniform", default="0.1:0.025,0.1:0.0125,0.05:0.0125,0.05:0.00625")
    ap.add_argument("--targets", default="0.005,0.001")
    ap.add_argument("--workdir", default="/tmp/flowform_adapt_bench")
    a = ap.parse_args()
    rows = []
    runs = [(f"uniform h={h} hc={hc}", [f"Mesh/Geo Parameters/h={h}", f"Mesh/Geo Parameters/hc={hc}",
                                          "Error Estimation/Method=Two-Level"]) for h, hc in
            (p.split(":") for p in a.uniform.split(","))]
    runs += [(f"adaptive target {t}", ["Adaptivity/Responses={ram_force}", f"Adaptivity/Target Relative Error={t}"])
             for t in a.targets.split(",")]
    for label, sets in runs:
        out = os.path.join(a.workdir, label.replace(" ", "_").replace("=", ""))
        start = time.monotonic()
        run = launcher.run(a.flowform, a.case, out, sets, quiet=True, clean=True)
        seconds = time.monotonic() - start
        s = summary.load(out) or {}
        f = (s.get("functionals") or {}).get("ram_force")
        eta = (s.get("functionals_error_estimate") or {}).get("ram_force")
        true = a.reference - f if f is not None else None
        rows.append((label, run.status, s.get("dofs"), seconds, f, eta, true,
                     eta / true if eta is not None and true else None))
    print(f"reference F = {a.reference}")
    print(f"{'run':34} {'exit':>4} {'dofs':>7} {'s':>7} {'F':>9} {'eta':>10} {'true':>10} {'rel.true':>9} {'eff':>6}")
    for label, status, dofs, seconds, f, eta, true, eff in rows:
        fmt = lambda v, spec: format(v, spec) if v is not None else "-"  # noqa: E731
        print(f"{label:34} {status:>4} {fmt(dofs, '>7')} {seconds:7.2f} {fmt(f, '9.5f')} {fmt(eta, '10.2e')} "
              f"{fmt(true, '10.2e')} {fmt(abs(true) / a.reference if true is not None else None, '9.1e')} "
              f"{fmt(eff, '6.2f')}")


if __name__ == "__main__":
    main()
