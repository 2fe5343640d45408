"""Decisions on ROL against a derivative-free search, and the gradients by parameter type (issue
#29's benchmark; docs/BENCHMARKS.md "Optimization").

1. solves: each shipped decision (xml/drawing_optimal_angle.xml, xml/drawing_identify_friction.xml,
   xml/drawing_identify_two.xml) by ROL — solves, wall seconds, the design — against a
   derivative-free search of the same objective on the same box (each evaluation one run of
   xml/drawing.xml at the design, no sensitivities): golden section for one parameter, stopped
   when its bracket is as narrow as the accuracy the ROL design is good for (± 0.3° for the angle,
   the gradient tolerance's, docs/optimization.md §2; ± σ_ν/10 for the friction, σ_ν the
   Gauss-Newton standard error); Nelder-Mead for two, from the same start, stopped when the
   simplex is within σ/10 of each parameter's standard error;
2. gradients: xml/drawing.xml with the finite-difference check on for one parameter of each type
   (friction, shape, material, boundary value): the DDM (total, through the free surface) against
   the check's re-converged central difference, and the seconds the DDM took.
3. constrained: the constrained decisions (xml/hot_extrusion_max_speed.xml,
   xml/hot_extrusion_window.xml) by the trust-region SQP, by ROL's own general-constraint
   algorithms (Constraint Algorithm = Augmented Lagrangian, Stabilized LCL) and by a
   derivative-free constrained search (scipy's COBYLA on the same scaled design and constraints,
   each evaluation one run of xml/hot_extrusion.xml without sensitivities, stopped at a trust
   radius of 1e-4 of the bounds' range: the SQP design's accuracy); solves, seconds, the design,
   the largest violation of a limit and the flux.

usage: scripts/python bench/optimization_bench.py [FLOWFORM] [--parts solves,gradients,constrained] [--workdir DIR]
The machine's load before and after each part is printed.
"""
import argparse
import math
import os
import time

from drawing_checks import friction
from flowform_tools import default_flowform, launcher, machine, repo_path, tables

TRESCA = friction("Tresca", 0.1)  # xml/drawing_optimal_angle.xml's walls on xml/drawing.xml
GOLDEN = (math.sqrt(5.0) - 1.0) / 2.0


def golden(f, lo, hi, width):
    """Golden-section search of f on [lo, hi] until the bracket is narrower than width; the
    bracket's best point and the number of evaluations."""
    a, b = lo, hi
    c, d = b - GOLDEN * (b - a), a + GOLDEN * (b - a)
    fc, fd = f(c), f(d)
    n = 2
    while b - a > width:
        if fc < fd:
            b, d, fd = d, c, fc
            c = b - GOLDEN * (b - a)
            fc = f(c)
        else:
            a, c, fc = c, d, fd
            d = a + GOLDEN * (b - a)
            fd = f(d)
        n += 1
    return (c if fc < fd else d), n


def nelder_mead(f, start, steps, tolerances, lo, hi):
    """Nelder-Mead on a box (points clamped into it) until every coordinate's spread over the
    simplex is below its tolerance; the best point and the number of evaluations."""
    clamp = lambda x: [min(max(v, a), b) for v, a, b in zip(x, lo, hi)]
    n = len(start)
    simplex = [clamp(start)] + [clamp([start[j] + (steps[j] if j == i else 0.0) for j in range(n)]) for i in range(n)]
    values = [f(x) for x in simplex]
    count = n + 1
    while any(max(x[j] for x in simplex) - min(x[j] for x in simplex) > tolerances[j] for j in range(n)):
        order = sorted(range(n + 1), key=lambda k: values[k])
        simplex, values = [simplex[k] for k in order], [values[k] for k in order]
        centre = [sum(x[j] for x in simplex[:-1]) / n for j in range(n)]
        worst = simplex[-1]
        reflected = clamp([centre[j] + (centre[j] - worst[j]) for j in range(n)])
        fr = f(reflected); count += 1
        if fr < values[0]:
            expanded = clamp([centre[j] + 2.0 * (centre[j] - worst[j]) for j in range(n)])
            fe = f(expanded); count += 1
            simplex[-1], values[-1] = (expanded, fe) if fe < fr else (reflected, fr)
        elif fr < values[-2]:
            simplex[-1], values[-1] = reflected, fr
        else:
            contracted = clamp([centre[j] + 0.5 * (worst[j] - centre[j]) for j in range(n)])
            fc = f(contracted); count += 1
            if fc < values[-1]:
                simplex[-1], values[-1] = contracted, fc
            else:  # shrink towards the best
                for k in range(1, n + 1):
                    simplex[k] = [simplex[0][j] + 0.5 * (simplex[k][j] - simplex[0][j]) for j in range(n)]
                    values[k] = f(simplex[k]); count += 1
    best = min(range(n + 1), key=lambda k: values[k])
    return simplex[best], count


def plain_run(flowform, workdir, sets):
    r = launcher.run(flowform, repo_path("xml", "drawing.xml"), os.path.join(workdir, "eval"),
                     sets + ["Sensitivity/Parameters={}", "Output/Write Solution=false", "Output/Boundary CSV=false"],
                     quiet=True, clean=True)
    if r.status != 0:
        raise SystemExit(f"flowform exited {r.status} on xml/drawing.xml {sets}")
    return r.summary["functionals"]


def solves(flowform, workdir):
    rows = []
    for case, label in (("drawing_optimal_angle.xml", "die angle of least drawing force"),
                        ("drawing_identify_friction.xml", "friction from force and die pressure"),
                        ("drawing_identify_two.xml", "friction and yield stress from force and die pressure")):
        start = time.time()
        r = launcher.run(flowform, repo_path("xml", case), os.path.join(workdir, case), [], quiet=True, clean=True)
        seconds = time.time() - start
        o = r.summary["optimization"]
        name, value = next(iter(o["design"].items()))
        shown = ", ".join(f"{v:.5g}" for v in o["design"].values())
        rows.append([label, "ROL " + o["algorithm"], str(o["solves"]), f"{seconds:.1f}", shown, o["status"]])
        start = time.time()
        names = list(o["design"])
        lo, hi = [o["bounds"][k][0] for k in names], [o["bounds"][k][1] for k in names]

        def sets_at(x):
            """xml/drawing.xml at design x (the friction coefficient on both walls, the yield stress)."""
            sets = []
            for k, v in zip(names, x):
                if k == "Friction Coefficient":
                    sets += [f"Boundary Conditions/{w}/Friction Coefficient={v!r}" for w in ("die_cone", "die_land")]
                elif k == "Yield Stress":
                    sets.append(f"Material/Yield Stress={v!r}")
                else:
                    raise SystemExit(f"the bench does not know the design parameter {k}")
            return sets

        def misfit(x):  # the case's own measurements, echoed in its summary
            f = plain_run(flowform, workdir, sets_at(x))
            return sum(0.5 * ((f[k] - m["measured"]) / m["error"]) ** 2 for k, m in o["measured"].items())
        if "alpha" in name:
            found, n = golden(lambda a: plain_run(flowform, workdir, TRESCA + [f"Mesh/Geo Parameters/alpha={a!r}"])
                              ["drawing_force"], lo[0], hi[0], 0.6)
        elif len(names) == 2:
            sigma = [o["standard_error"][k] for k in names]
            found, n = nelder_mead(misfit, [o["initial_design"][k] for k in names],
                                   [0.1 * (b - a) for a, b in zip(lo, hi)], [0.1 * s_ for s_ in sigma], lo, hi)
            rows.append([label, "Nelder-Mead", str(n), f"{time.time() - start:.1f}",
                         ", ".join(f"{v:.5g}" for v in found), "simplex met"])
            continue
        else:
            found, n = golden(lambda v: misfit([v]), lo[0], hi[0], 0.2 * o["standard_error"][name])
        rows.append([label, "golden section", str(n), f"{time.time() - start:.1f}", f"{found:.5g}", "bracket met"])
    print(tables.markdown(["decision", "method", "solves", "wall s", "design", "stop"], rows))


def gradients(flowform, workdir):
    parameters = ["Friction Coefficient", "Geo Parameter:alpha", "Rate Exponent", "Boundary Value:outlet/Velocity Y"]
    r = launcher.run(flowform, repo_path("xml", "drawing.xml"), os.path.join(workdir, "gradients"),
                     ["Sensitivity/Parameters={" + ", ".join(parameters) + "}",
                      "Sensitivity/Finite Difference Check=true"], quiet=True, clean=True)
    s = r.summary
    # The adjoint gives no dq/dh, which the total derivative through the free surface needs: it is
    # compared on the frozen surface, with the DDM's frozen derivative and the check's frozen FD.
    adjoint = launcher.run(flowform, repo_path("xml", "drawing.xml"), os.path.join(workdir, "gradients_adjoint"),
                           ["Sensitivity/Parameters={" + ", ".join(parameters) + "}", "Sensitivity/Method=Adjoint",
                            "Sensitivity/Shape Derivative=Frozen"], quiet=True, clean=True).summary
    rows = []
    for p in parameters:
        for response in ("drawing_force", "die_pressure", "redundant_work"):
            e = s["fd_check"][response][p]
            a = adjoint["sensitivities"][response][p]
            rows.append([p, response, f"{e['ddm_total_shape']:.7g}", f"{e['fd_moving_shape']:.7g}",
                         f"{e['rel_diff_total_shape']:.1e}", f"{e['ddm']:.7g}", f"{a:.7g}", f"{e['fd']:.7g}",
                         f"{abs(a - e['ddm']) / max(abs(e['ddm']), 1e-300):.1e}"])
    print(tables.markdown(["parameter", "response", "DDM (total)", "FD (re-converged)", "relative",
                           "DDM (frozen)", "adjoint (frozen)", "FD (frozen)", "adjoint/DDM"], rows))
    t = s["timings"]
    print(f"DDM {t.get('sensitivity_ddm', 0):.2f} s for {len(parameters)} parameters, the run {t.get('total', 0):.2f} s")


def constrained(flowform, workdir):
    from scipy.optimize import minimize
    limits = {"exit_temperature": 740.0, "ram_force": 4500.0}
    rows = []
    for case, label in (("hot_extrusion_max_speed.xml", "largest ram speed (T <= 740 K, F <= 4500 N/mm)"),
                        ("hot_extrusion_window.xml", "best point of the window (speed, billet temperature)")):
        reference = None
        for algorithm in ("Trust Region SQP", "Augmented Lagrangian", "Stabilized LCL"):
            start = time.time()
            r = launcher.run(flowform, repo_path("xml", case), os.path.join(workdir, case),
                             [f"Optimization/Constraint Algorithm={algorithm}", "Output/Write Solution=false"],
                             quiet=True, clean=True, timeout=1800)
            seconds = time.time() - start
            o = r.summary["optimization"] if r.summary else {}
            f = r.summary.get("functionals", {}) if r.summary else {}
            if reference is None:
                reference = o
            worst = max((f[k] - v) / v for k, v in limits.items()) if f else float("nan")
            rows.append([label, algorithm, str(o.get("solves", "–")), f"{seconds:.1f}",
                         ", ".join(f"{v:.5g}" for v in o.get("design", {}).values()),
                         f"{max(worst, 0.0):.1e}", f"{f.get('product_flux', float('nan')):.2f}",
                         f"{o.get('status', 'failed')} (exit {r.status})"])
        names = list(reference["design"])
        lo, hi = [reference["bounds"][k][0] for k in names], [reference["bounds"][k][1] for k in names]
        cache, count = {}, [0]

        def evaluate(z):
            key = tuple(round(v, 12) for v in z)
            if key not in cache:
                x = [a + min(max(v, 0.0), 1.0) * (b - a) for v, a, b in zip(z, lo, hi)]
                entries = {"Boundary Value:ram/Velocity X": "Boundary Conditions/ram/Velocity X",
                           "Boundary Value:ram/Temperature": "Boundary Conditions/ram/Temperature"}
                sets = [f"{entries[k]}={v!r}" for k, v in zip(names, x)]
                run = launcher.run(flowform, repo_path("xml", "hot_extrusion.xml"), os.path.join(workdir, "eval"),
                                   sets + ["Output/Write Solution=false", "Output/Boundary CSV=false"],
                                   quiet=True, clean=True)
                count[0] += 1
                cache[key] = run.summary["functionals"] if run.status == 0 else None
            return cache[key]
        flux0 = evaluate([(reference["initial_design"][k] - a) / (b - a) for k, a, b in zip(names, lo, hi)])["product_flux"]
        cons = [{"type": "ineq", "fun": (lambda z, k=k, v=v: (v - evaluate(z)[k]) / v)} for k, v in limits.items()]
        cons += [{"type": "ineq", "fun": (lambda z, j=j: z[j])} for j in range(len(names))]
        cons += [{"type": "ineq", "fun": (lambda z, j=j: 1.0 - z[j])} for j in range(len(names))]
        start = time.time()
        z0 = [(reference["initial_design"][k] - a) / (b - a) for k, a, b in zip(names, lo, hi)]
        result = minimize(lambda z: -evaluate(z)["product_flux"] / flux0, z0, method="COBYLA", constraints=cons,
                          options={"rhobeg": 0.25, "tol": 1e-4, "maxiter": 500})
        f = evaluate(result.x)
        worst = max((f[k] - v) / v for k, v in limits.items())
        design = [a + v * (b - a) for v, a, b in zip(result.x, lo, hi)]
        rows.append([label, "COBYLA (derivative-free)", str(count[0]), f"{time.time() - start:.1f}",
                     ", ".join(f"{v:.5g}" for v in design), f"{max(worst, 0.0):.1e}", f"{f['product_flux']:.2f}",
                     result.message])
    print(tables.markdown(["decision", "method", "solves", "wall s", "design", "violation", "flux", "stop"], rows))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("flowform", nargs="?", default=default_flowform())
    ap.add_argument("--parts", default="solves,gradients")
    ap.add_argument("--workdir", default="out/bench_optimization")
    args = ap.parse_args()
    info = machine.machine_info()
    print(f"# {info.get('date')}, commit {info.get('commit')}, {info.get('Model name')} x {info.get('CPU(s)')}")
    for part in args.parts.split(","):
        before = machine.load()
        {"solves": solves, "gradients": gradients, "constrained": constrained}[part](args.flowform, args.workdir)
        print(f"# {part}: load {before:.2f} -> {machine.load():.2f}\n", flush=True)


if __name__ == "__main__":
    main()
