#!/usr/bin/python3
"""Reference values of the extrusion's ram force F and dF/dnu for the error-estimate
effectivities (docs/theory.md §7, docs/BENCHMARKS.md §10): Richardson extrapolation on
strongly corner-graded meshes, independent of the estimator.

usage: bench/extrusion_references.py [FLOWFORM] [--levels 0.2:0.008,0.1:0.004,0.05:0.002]
                                     [--nu 0,0.1,0.3] [--json FILE] [--workdir DIR]

Each scene (plane xml/extrusion.xml, axisymmetric xml/extrusion_axisym.xml) and friction
coefficient nu (all three walls) runs on meshes (h, hc) halved together (hc = h/25: the die
corners much finer than the bulk, so the first-order die-lip error and the bulk error fall
together). From the three values: the observed order q = log2(d1/d2) and the Richardson value
F_inf = F3 + d2 / (2^q - 1), the same for dF/dnu (DDM). The spread between that and the
Richardson value with q = 1 (the die lip's order) is printed as the reference's uncertainty.
"""
import argparse
import json
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "python"))
from flowform_tools import launcher, summary  # noqa: E402
from flowform_tools.numerics import observed_order, richardson  # noqa: E402

WALLS = ("container", "die_face", "die_land")


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap = argparse.ArgumentParser()
    ap.add_argument("flowform", nargs="?", default=os.path.join(root, "build/flowform"))
    ap.add_argument("--levels", default="0.2:0.008,0.1:0.004,0.05:0.002")
    ap.add_argument("--nu", default="0,0.1,0.3")
    ap.add_argument("--scenes", default="plane,axisym")
    ap.add_argument("--json")
    ap.add_argument("--workdir", default="/tmp/flowform_references")
    a = ap.parse_args()
    cases = {"plane": "xml/extrusion.xml", "axisym": "xml/extrusion_axisym.xml"}
    levels = [tuple(p.split(":")) for p in a.levels.split(",")]
    results = {}
    for scene in a.scenes.split(","):
        for nu in a.nu.split(","):
            values, derivs, dofs = [], [], []
            for h, hc in levels:
                out = os.path.join(a.workdir, f"{scene}_nu{nu}_h{h}_hc{hc}")
                sets = [f"Mesh/Geo Parameters/h={h}", f"Mesh/Geo Parameters/hc={hc}",
                        "Sensitivity/Parameters={Friction Coefficient}"]
                sets += [f"Boundary Conditions/{w}/Friction Coefficient={nu}" for w in WALLS]
                run = launcher.run(a.flowform, os.path.join(root, cases[scene]), out, sets, quiet=True, clean=True)
                s = summary.load(out) or {}
                if run.status != 0:
                    print(f"{scene} nu={nu} h={h} hc={hc}: exit {run.status}", file=sys.stderr)
                values.append(s["functionals"]["ram_force"])
                derivs.append(s["sensitivities"]["ram_force"]["Friction Coefficient"])
                dofs.append(s["dofs"])
            entry = {"dofs": dofs, "F": values, "dFdnu": derivs}
            for key, seq in (("F", values), ("dFdnu", derivs)):
                q = observed_order(seq)[-1]
                entry[key + "_order"] = q
                entry[key + "_ref"] = richardson(seq, q) if math.isfinite(q) and q > 0.2 else richardson(seq, 1.0)
                entry[key + "_spread"] = abs(richardson(seq, 1.0) - entry[key + "_ref"])
            results[f"{scene} nu={nu}"] = entry
            print(f"{scene:6} nu={nu:4} dofs {dofs}  F {['%.6f' % v for v in values]} q={entry['F_order']:.2f} "
                  f"F_ref={entry['F_ref']:.5f} (+-{entry['F_spread']:.1e})  dF/dnu {['%.5f' % v for v in derivs]} "
                  f"q={entry['dFdnu_order']:.2f} ref={entry['dFdnu_ref']:.4f} (+-{entry['dFdnu_spread']:.1e})",
                  flush=True)
    if a.json:
        with open(a.json, "w") as f:
            json.dump(results, f, indent=1)


if __name__ == "__main__":
    main()
