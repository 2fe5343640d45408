"""Reference values of the extrusion's ram force F and dF/dnu for the error-estimate
effectivities (docs/theory.md §7, docs/BENCHMARKS.md §10), independent of the estimator.

usage: scripts/python bench/extrusion_references.py [FLOWFORM] [--families "H:HC,...;H:HC,..."] [--nu 0,0.1,0.3]
                                     [--refinements R0-R1] [--scenes plane,axisym] [--json FILE] [--workdir DIR] [--reuse]
                                     [--from-json FILE] [--effectivity H:HC]

The error of the ram force has two parts with different orders (docs/extrusion_verification.md
§3): the die-lip leak, first order in the corner size hc, and the bulk error, second order in
the bulk size h. One family of meshes with hc/h fixed mixes them (the graded family hc = h/25
even converges non-monotonically: the two parts have opposite signs), so one-parameter
Richardson extrapolation is unreliable. Instead each scene and friction coefficient nu runs on
two families (default: hc = h/4 and hc = h/25, h = 0.2, 0.1, 0.05) and the six values are fitted
by least squares to
        F(h, hc) = F_inf + a hc + b h²,
the reference is F_inf and its uncertainty the largest fit residual (the mesh-to-mesh noise of
the contact pattern, which no extrapolation removes). The same for dF/dnu (DDM).

--refinements R0-R1 makes the families nested instead: every mesh of --families is also run
refined uniformly r = R0..R1 times (Mesh/Uniform Refinements; h and hc halve with each), e.g.
--families "0.1:0.01;0.2:0.008" --refinements 1-3. Refining one mesh keeps its pattern (the
same cells split), so the mesh-to-mesh noise of unrelated meshes leaves the fit: its residual
is then the model's error, several times smaller.

--effectivity H:HC then runs each scene on that mesh with the two-level estimate and prints
eta / (ref - value) for F and dF/dnu, with the reference's uncertainty in units of the true
error ('noise': near 1 or above, the effectivity says nothing). --from-json reuses references.
"""
import argparse
import json
import os
import sys

import numpy as np

from flowform_tools import launcher, summary

WALLS = ("container", "die_face", "die_land")
CASES = {"plane": "xml/extrusion.xml", "axisym": "xml/extrusion_axisym.xml"}


def run_case(a, root, scene, nu, h, hc, extra, name):
    out = os.path.join(a.workdir, name)
    s = summary.load(out) if a.reuse else None
    if not s or s.get("exit_status") != 0:
        sets = ["Adaptivity/Enabled=false", f"Mesh/Geo Parameters/h={h}", f"Mesh/Geo Parameters/hc={hc}",
                "Sensitivity/Parameters={Friction Coefficient}"] + extra
        sets += [f"Boundary Conditions/{w}/Friction Coefficient={nu}" for w in WALLS]
        run = launcher.run(a.flowform, os.path.join(root, CASES[scene]), out, sets, quiet=True, clean=True)
        if run.status != 0:
            print(f"{name}: exit {run.status}", file=sys.stderr)
        s = summary.load(out) or {}
    return s


def fit(points):
    """Least squares F = F_inf + a hc + b h² over (h, hc, F); returns F_inf, a, b, max |residual|."""
    A = np.array([[1.0, hc, h * h] for h, hc, _ in points])
    b = np.array([v for _, _, v in points])
    x, *_ = np.linalg.lstsq(A, b, rcond=None)
    return float(x[0]), float(x[1]), float(x[2]), float(np.max(np.abs(b - A @ x)))


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap = argparse.ArgumentParser()
    ap.add_argument("flowform", nargs="?", default=os.path.join(root, "build/flowform"))
    ap.add_argument("--families", default="0.2:0.05,0.1:0.025,0.05:0.0125;0.2:0.008,0.1:0.004,0.05:0.002")
    ap.add_argument("--nu", default="0,0.1,0.3")
    ap.add_argument("--refinements", default="0-0", help="R0-R1: every mesh also refined R0..R1 times")
    ap.add_argument("--scenes", default="plane,axisym")
    ap.add_argument("--json")
    ap.add_argument("--workdir", default="/tmp/flowform_references")
    ap.add_argument("--reuse", action="store_true", help="keep runs whose summary.json says exit 0")
    ap.add_argument("--from-json")
    ap.add_argument("--effectivity")
    a = ap.parse_args()
    r0, r1 = (int(v) for v in a.refinements.split("-"))
    bases = [tuple(float(v) for v in p.split(":")) for fam in a.families.split(";") for p in fam.split(",")]
    # (h, hc, refinements): the sizes the fit sees are h / 2^r, hc / 2^r
    runs = [(h, hc, r) for h, hc in bases for r in range(r0, r1 + 1)]
    meshes = [(h / 2 ** r, hc / 2 ** r) for h, hc, r in runs]
    results = {}
    if a.from_json:
        with open(a.from_json) as f:
            results = json.load(f)
    for scene in ([] if a.from_json else a.scenes.split(",")):
        for nu in a.nu.split(","):
            F, D, dofs = [], [], []
            for (h, hc, r), (hr, hcr) in zip(runs, meshes):
                s = run_case(a, root, scene, nu, h, hc, [f"Mesh/Uniform Refinements={r}"],
                             f"{scene}_nu{nu}_h{h}_hc{hc}" + (f"_r{r}" if r else ""))
                F.append((hr, hcr, s["functionals"]["ram_force"]))
                D.append((hr, hcr, s["sensitivities"]["ram_force"]["Friction Coefficient"]))
                dofs.append(s["dofs"])
            entry = {"meshes": meshes, "dofs": dofs, "F": [v for *_, v in F], "dFdnu": [v for *_, v in D]}
            for key, pts in (("F", F), ("dFdnu", D)):
                ref, ca, cb, noise = fit(pts)
                entry.update({key + "_ref": ref, key + "_a": ca, key + "_b": cb, key + "_noise": noise})
            results[f"{scene} nu={nu}"] = entry
            print(f"{scene:6} nu={nu:4} F_ref {entry['F_ref']:.5f} +- {entry['F_noise']:.1e} "
                  f"(a {entry['F_a']:+.3g}, b {entry['F_b']:+.3g})  dF/dnu_ref {entry['dFdnu_ref']:.4f} "
                  f"+- {entry['dFdnu_noise']:.1e} (a {entry['dFdnu_a']:+.3g}, b {entry['dFdnu_b']:+.3g})", flush=True)
            print(f"       F {['%.6f' % v for v in entry['F']]}  dF/dnu {['%.5f' % v for v in entry['dFdnu']]}")
    if a.effectivity:
        h, hc = (float(v) for v in a.effectivity.split(":"))
        print(f"\neffectivity eta / (ref - value) on (h, hc) = ({h}, {hc}); noise = reference uncertainty / |true|")
        for key, entry in results.items():
            scene, nu = key.split(" nu=")
            s = run_case(a, root, scene, nu, h, hc, ["Error Estimation/Method=Two-Level"],
                         f"estimate_{scene}_nu{nu}_h{h}_hc{hc}")
            line = f"{scene:6} nu={nu:4}"
            for label, value, eta, ref_key in (
                    ("F", s["functionals"]["ram_force"], s["functionals_error_estimate"]["ram_force"], "F"),
                    ("dF/dnu", s["sensitivities"]["ram_force"]["Friction Coefficient"],
                     s["sensitivities_error_estimate"]["ram_force"]["Friction Coefficient"], "dFdnu")):
                true = entry[ref_key + "_ref"] - value
                entry.setdefault("estimate", {})[ref_key] = {"value": value, "eta": eta, "true": true}
                line += (f"  {label} {value:.5g} eta {eta:+.3e} true {true:+.3e} eff {eta / true:5.2f} "
                         f"noise {entry[ref_key + '_noise'] / abs(true):.2f}")
            print(line, flush=True)
    if a.json:
        with open(a.json, "w") as f:
            json.dump(results, f, indent=1)


if __name__ == "__main__":
    main()
