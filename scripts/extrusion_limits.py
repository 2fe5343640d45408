"""The ram speed a hot extrusion may run at (docs/theory.md §10.3): the largest speed V for which
the product's exit temperature stays at a limit, and the largest the press force allows, each
found by Newton on V with the derivative by direct differentiation (Sensitivity/Parameters =
{Boundary Value:<ram>/Velocity X}: one solve and one back-substitution per step), over a range of
billet temperatures: the extrusion limit diagram.

For a billet temperature T_b (the ram's Temperature and the law's start temperature) and a limit
φ_max of a response φ (the exit temperature, or the ram force), Newton on g = φ − φ_max in
s = ln V (the force and the exit temperature of a viscoplastic flow grow about as ln V, on which
Newton in V creeps from below):

    s_{k+1} = s_k − g(V_k) / (V_k φ'(V_k)),   φ' = dφ/dV by DDM,

the step clamped to |Δs| <= ln 2 (V stays positive; a far start does not jump to a speed the
solver cannot reach), until |g| <= tol × |φ_max|. The last run asks for its error
estimate (the two-level estimate): with η the estimated error of φ, the speed's error is
η / φ' (a first-order propagation) — reported as V's error bar.

Writes OUT/limits.csv (billet temperature, limit, V, its error, iterations, solves, φ at V),
OUT/limits.json and OUT/extrusion_limits.png: both speeds against the billet temperature, the
admissible region under both (the extrusion limit diagram). A Newton that does not converge in
--max-iterations, or a run that fails, is reported as such (exit status 3).

usage: scripts/python scripts/extrusion_limits.py [--flowform build/flowform]
           [--case xml/hot_extrusion.xml] [--ram ram] [--billet 698,723,748]
           [--exit-temperature 740] [--ram-force 4500] [--start 5] [--tol 1e-4]
           [--max-iterations 12] [--out out/extrusion_limits] [--set P=V ...] [--no-estimate]
"""
import argparse
import csv
import json
import math
import os
import sys

from flowform_tools import default_flowform, launcher, repo_path
from flowform_tools.plotting import grid, pyplot, save


def solve_at(args, speed, billet, outdir, estimate=False):
    ram = args.ram
    parameter = f"Boundary Value:{ram}/Velocity X"
    sets = [f"Boundary Conditions/{ram}/Velocity X={launcher.lit(speed)}",
            f"Boundary Conditions/{ram}/Temperature={launcher.lit(billet)}",
            f"Material/Temperature={launcher.lit(billet)}",
            "Sensitivity/Parameters={" + parameter + "}",
            "Output/Write Solution=false", "Output/Boundary CSV=false"]
    if estimate:
        sets.append("Error Estimation/Method=Two-Level")
    run = launcher.run(args.flowform, args.case, outdir, sets + list(args.set), quiet=True, clean=True)
    if run.status != 0:
        return None
    s = run.summary
    return {"values": s["functionals"], "slopes": {r: v[parameter] for r, v in s["sensitivities"].items()},
            "eta": s.get("functionals_error_estimate") or {}}


def find_speed(args, billet, response, limit, tag):
    speed, iterations = args.start, 0
    history = []
    while iterations < args.max_iterations:
        iterations += 1
        r = solve_at(args, speed, billet, os.path.join(args.out, f"{tag}_Tb{billet:g}_{iterations}"))
        if r is None:
            return {"converged": False, "message": f"the run at V = {speed:g} failed", "history": history}
        value, slope = r["values"][response], r["slopes"][response]
        if history:
            # The tangent of the last step predicted this value; far off (and back the other way),
            # the solve landed on another solution (a die-corner node's contact state: docs/theory.md §10.3).
            last = history[-1]
            predicted = last["value"] + last["slope"] * (speed - last["speed"])
            if abs(value - predicted) > 0.5 * abs(predicted - last["value"]) + 1e-3 * abs(limit):
                print(f"  {tag}, T_b = {billet:g} K: at V = {speed:.6g} {response} = {value:.6g}, its tangent "
                      f"predicted {predicted:.6g}: another solution branch?")
        history.append({"speed": speed, "value": value, "slope": slope})
        g = value - limit
        if abs(g) <= args.tol * abs(limit):
            out = {"converged": True, "speed": speed, "value": value, "slope": slope, "iterations": iterations,
                   "history": history}
            if args.estimate:
                e = solve_at(args, speed, billet, os.path.join(args.out, f"{tag}_Tb{billet:g}_estimate"), True)
                eta = (e or {}).get("eta", {}).get(response) if e else None
                out["value_error"] = eta
                out["speed_error"] = abs(eta / slope) if eta is not None and slope else None
            return out
        if slope <= 0.0:
            return {"converged": False, "message": f"d{response}/dV = {slope:g} <= 0 at V = {speed:g}: no limit "
                                                   "above it", "history": history}
        step = min(max(-g / (speed * slope), -math.log(2.0)), math.log(2.0))
        speed *= math.exp(step)
    return {"converged": False, "message": f"not converged in {args.max_iterations} Newton steps", "history": history}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--flowform", default=default_flowform())
    ap.add_argument("--case", default=repo_path("xml", "hot_extrusion.xml"))
    ap.add_argument("--ram", default="ram")
    ap.add_argument("--billet", default="698,723,748")
    ap.add_argument("--exit-temperature", type=float, default=740.0)
    ap.add_argument("--ram-force", type=float, default=4500.0)
    ap.add_argument("--start", type=float, default=5.0)
    ap.add_argument("--tol", type=float, default=1e-4)
    ap.add_argument("--max-iterations", type=int, default=12)
    ap.add_argument("--out", default="out/extrusion_limits")
    ap.add_argument("--set", action="append", default=[])
    ap.add_argument("--no-estimate", dest="estimate", action="store_false")
    args = ap.parse_args()
    args.flowform = launcher.require_executable(args.flowform, "extrusion_limits.py")
    os.makedirs(args.out, exist_ok=True)
    billets = [float(b) for b in args.billet.split(",")]
    rows, ok = [], True
    for billet in billets:
        for response, limit, tag in (("exit_temperature", args.exit_temperature, "temperature"),
                                     ("ram_force", args.ram_force, "force")):
            r = find_speed(args, billet, response, limit, tag)
            ok = ok and r["converged"]
            rows.append({"billet_temperature": billet, "limit": tag, "response": response, "limit_value": limit, **r})
            if r["converged"]:
                err = r.get("speed_error")
                print(f"T_b = {billet:g} K, {response} = {limit:g}: V = {r['speed']:.4f}"
                      + (f" ± {err:.2g}" if err is not None else "") + f" mm/s in {r['iterations']} Newton step(s)")
            else:
                print(f"T_b = {billet:g} K, {response} = {limit:g}: NOT CONVERGED: {r['message']}")
    with open(os.path.join(args.out, "limits.json"), "w") as f:
        json.dump(rows, f, indent=1)
    with open(os.path.join(args.out, "limits.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["billet_temperature", "limit", "limit_value", "converged", "speed", "speed_error", "iterations",
                    "value", "value_error"])
        for r in rows:
            w.writerow([r["billet_temperature"], r["limit"], r["limit_value"], int(r["converged"]), r.get("speed"),
                        r.get("speed_error"), r.get("iterations"), r.get("value"), r.get("value_error")])
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    for tag, color, label in (("temperature", "C3", f"exit temperature {args.exit_temperature:g} K"),
                              ("force", "C0", f"ram force {args.ram_force:g}")):
        pts = [r for r in rows if r["limit"] == tag and r["converged"]]
        ax.errorbar([r["billet_temperature"] for r in pts], [r["speed"] for r in pts],
                    yerr=[r.get("speed_error") or 0.0 for r in pts], color=color, marker="o", capsize=3,
                    label=f"largest speed: {label}")
    both = [min(a["speed"], b["speed"]) for a, b in zip(rows[0::2], rows[1::2]) if a["converged"] and b["converged"]]
    if len(both) == len(billets):
        ax.fill_between(billets, 0, both, color="C2", alpha=0.15, label="admissible")
    ax.set_xlabel("billet temperature [K]")
    ax.set_ylabel("ram speed [mm/s]")
    ax.set_ylim(bottom=0)
    ax.legend()
    grid(ax)
    save(fig, os.path.join(args.out, "extrusion_limits.png"))
    return 0 if ok else 3


if __name__ == "__main__":
    sys.exit(main())
