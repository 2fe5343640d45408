"""Error estimates side by side (docs/theory.md §7): the effectivity of each Error
Estimation/Method and its share of the run's time, on the scenes of issue 26 part 3.

usage: scripts/python bench/estimate_bench.py [FLOWFORM] [--methods "Newton Step,Two-Level"]
                                 [--scenes plane,axisym,channel,swell] [--fine] [--steps N]
                                 [--adaptive 0.005,0.002] [--workdir /tmp/flowform_estimate_bench]

Every run solves the scene once (Adaptivity/Enabled=false) and estimates with each method; the
row gives the response, its estimate eta, the true error against the reference, the effectivity
eta / (ref - value), the estimate's seconds and its share of the run's total (summary.json
timings: total = setup + solve + sensitivities + estimate + output), and where the estimate's
time went (error_estimation.timings). --fine adds the next finer mesh of each scene.
--adaptive adds the plane and axisymmetric extrusion scenes as shipped (adaptive loop, nu = 0.1)
at these targets: the last cycle's value and estimate, and the estimates' seconds summed over the
cycles (adaptivity.cycles[].error_estimation_seconds) against the loop's (adaptivity.seconds).

References (true errors):
- extrusion, plane and axisymmetric, nu = 0, 0.1, 0.3 on all three walls: the F_inf of the
  open-lip model (docs/BENCHMARKS.md §10, Richardson over two mesh families; at nu = 0.1 within
  +-0.0022, about 2 % of the true error on the shipped mesh); dF/dnu at nu = 0 (4.4505 plane,
  52.4114 axisymmetric; the runs at nu = 0 ask for it);
- channel (xml/channel.xml, triangles, N = 8 and 16): the exact flow rate of the power-law
  channel Q = 2 gamma (sqrt3 G)^(n+1) H^(n+2) / (G (n+2)) for sigma0 = 0, n = 3: Q = 3.6
  (docs/verification.md), Order = 2;
- die swell (xml/die_swell.xml, planar, h = 0.1 and 0.05): the swell's mesh-converged value
  1.1865 (docs/verification.md §11: 1.1878 at h = 0.025 less the first-order tail of the last
  difference, 0.0013; uncertain by about that much, a third of the true error at h = 0.1).
"""
import argparse
import os

from flowform_tools import launcher, summary

WALLS = ("container", "die_face", "die_land")
F_REF = {("plane", "0.0"): 3.30663, ("plane", "0.1"): 3.73325, ("plane", "0.3"): 4.3595,
         ("axisym", "0.0"): 18.2239, ("axisym", "0.1"): 23.10283, ("axisym", "0.3"): 26.646}
DFDNU_REF = {"plane": 4.4505, "axisym": 52.4114}
SWELL_REF = 1.1865


def friction(nu):
    return [f"Boundary Conditions/{w}/Friction Coefficient={nu}" for w in WALLS]


def scenes(selected, fine):
    """(label, case file, sets, response, reference, derivative reference or None)."""
    out = []
    extrusion_meshes = [("0.1", "0.025")] + ([("0.05", "0.0125")] if fine else [])
    for name, case in (("plane", "xml/extrusion.xml"), ("axisym", "xml/extrusion_axisym.xml")):
        if name not in selected:
            continue
        for h, hc in extrusion_meshes:
            for nu in ("0.0", "0.1", "0.3"):
                sets = ["Adaptivity/Enabled=false", f"Mesh/Geo Parameters/h={h}", f"Mesh/Geo Parameters/hc={hc}"]
                sets += friction(nu)
                dref = DFDNU_REF[name] if nu == "0.0" else None
                if dref is not None:
                    sets.append("Sensitivity/Parameters={Friction Coefficient}")
                out.append((f"{name} nu={nu} h={h}", case, sets, "ram_force", F_REF[(name, nu)], dref))
    if "channel" in selected:
        for n in ("8", "16") if fine else ("8",):
            sets = ["Mesh/Element Type=Triangle", f"Mesh/Geo Parameters/N={n}", "Material/Rate Exponent=3.0",
                    "Material/Yield Stress=0.0", "Material/Strain Rate Cutoff=1e-8", "Responses/Q/Type=Flow Rate",
                    "Responses/Q/Boundary=outlet", "Error Estimation/Order=2"]
            out.append((f"channel n=3 N={n}", "xml/channel.xml", sets, "Q", 3.6, None))
    if "swell" in selected:
        for h in ("0.1", "0.05") if fine else ("0.1",):
            out.append((f"die swell h={h}", "xml/die_swell.xml", [f"Mesh/Geo Parameters/h={h}"], "swell",
                        SWELL_REF, None))
    return out


def fmt(v, spec):
    return "–" if v is None else format(v, spec)


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap = argparse.ArgumentParser()
    ap.add_argument("flowform", nargs="?", default=os.path.join(root, "build/flowform"))
    ap.add_argument("--methods", default="Newton Step,Two-Level")
    ap.add_argument("--scenes", default="plane,axisym,channel,swell")
    ap.add_argument("--fine", action="store_true", help="also the next finer mesh of each scene")
    ap.add_argument("--steps", type=int, help="Error Estimation/Newton Steps (default: the case's)")
    ap.add_argument("--sets", nargs="*", default=[], help="more --set entries for every run")
    ap.add_argument("--adaptive", help="targets of the adaptive rows, e.g. 0.005,0.002 (none: no adaptive rows)")
    ap.add_argument("--workdir", default="/tmp/flowform_estimate_bench")
    a = ap.parse_args()
    print("| scene | method | dofs | value | eta | true error | effectivity | dphi/dh eff. | estimate s | "
          "run s | share | refined assembly / factorization / solves / setup s |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|")
    for label, case, sets, response, ref, dref in scenes(a.scenes.split(","), a.fine):
        for method in a.methods.split(","):
            extra = [f"Error Estimation/Method={method}"] + a.sets
            if a.steps is not None:
                extra.append(f"Error Estimation/Newton Steps={a.steps}")
            out = os.path.join(a.workdir, (label + "_" + method).replace(" ", "_").replace("=", ""))
            run = launcher.run(a.flowform, os.path.join(root, case), out, sets + extra, quiet=True, clean=True)
            s = summary.load(out) or {}
            value = (s.get("functionals") or {}).get(response)
            eta = (s.get("functionals_error_estimate") or {}).get(response)
            true = ref - value if value is not None else None
            eff = eta / true if eta is not None and true else None
            deff = None
            if dref is not None:
                d = ((s.get("sensitivities") or {}).get(response) or {}).get("Friction Coefficient")
                deta = ((s.get("sensitivities_error_estimate") or {}).get(response) or {}).get("Friction Coefficient")
                deff = deta / (dref - d) if d is not None and deta is not None and dref != d else None
            est = s.get("error_estimation") or {}
            t = est.get("timings") or {}
            total = (s.get("timings") or {}).get("total")
            seconds = est.get("seconds")
            share = seconds / total if seconds is not None and total else None
            parts = " / ".join(fmt(t.get(k), ".2f") for k in ("assembly", "factorization", "solves", "refined_setup"))
            if method == "Two-Level":
                parts = f"(refined run {fmt(t.get('refined_run'), '.2f')}, setup {fmt(t.get('refined_setup'), '.2f')})"
            status = "" if run.status == 0 else f" (exit {run.status})"
            print(f"| {label} | {method}{status} | {s.get('dofs', '–')} | {fmt(value, '.5f')} | {fmt(eta, '.4g')} | "
                  f"{fmt(true, '.4g')} | {fmt(eff, '.2f')} | {fmt(deff, '.2f')} | {fmt(seconds, '.2f')} | "
                  f"{fmt(total, '.2f')} | {fmt(share, '.0%')} | {parts} |", flush=True)
    for target in (a.adaptive.split(",") if a.adaptive else []):
        for name, case in (("plane", "xml/extrusion.xml"), ("axisym", "xml/extrusion_axisym.xml")):
            for method in a.methods.split(","):
                label = f"{name} nu=0.1 adaptive {float(target):.1%}"
                out = os.path.join(a.workdir, (label + "_" + method).replace(" ", "_").replace("=", "").replace("%", ""))
                sets = [f"Adaptivity/Target Relative Error={target}", f"Error Estimation/Method={method}"] + a.sets
                run = launcher.run(a.flowform, os.path.join(root, case), out, sets, quiet=True, clean=True)
                s = summary.load(out) or {}
                value = (s.get("functionals") or {}).get("ram_force")
                eta = (s.get("functionals_error_estimate") or {}).get("ram_force")
                true = F_REF[(name, "0.1")] - value if value is not None else None
                eff = eta / true if eta is not None and true else None
                cycles = (s.get("adaptivity") or {}).get("cycles") or []
                seconds = sum(c.get("error_estimation_seconds", 0.0) for c in cycles)
                total = (s.get("adaptivity") or {}).get("seconds")
                share = seconds / total if total else None
                status = "" if run.status == 0 else f" (exit {run.status})"
                print(f"| {label} | {method}{status} | {s.get('dofs', '–')} ({len(cycles)} cycles) | {fmt(value, '.5f')} | "
                      f"{fmt(eta, '.4g')} | {fmt(true, '.4g')} | {fmt(eff, '.2f')} | – | {fmt(seconds, '.2f')} | "
                      f"{fmt(total, '.2f')} | {fmt(share, '.0%')} | |", flush=True)


if __name__ == "__main__":
    main()
