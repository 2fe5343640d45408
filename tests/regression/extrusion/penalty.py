"""Insensitivity of the ram force to the penalty factors (docs/extrusion_verification.md §4)."""
import numpy as np

from .common import lit, mesh_list


def penalty_sweep(runner, args, checks, key, values, default, tolerance, h_default):
    h = mesh_list(args.meshes, h_default)[0]
    if args.values:
        values = [float(v) for v in args.values.split(",")]
    if default not in values:
        values = sorted(values + [default])
    specs = []
    for v in values:
        sets = [f"Boundary Conditions/{w}/{key}={lit(v)}" for w in runner.walls] if v != default else []
        specs.append((f"h = {h}, nu = 0.1, {key} = {v:g}", dict(name=f"{key.split()[0].lower()}_{v:g}", h=h, nu=0.1,
                                                               sets=sets)))
    runs = runner.run_all(specs, checks)
    if not all(checks.check(r.converged, f"{r.label}: converged") for r in runs):
        return None
    F = dict(zip(values, [r.force for r in runs]))
    ref = F[default]
    rows = []
    for v, r in zip(values, runs):
        rel = (F[v] - ref) / ref
        rows.append({"value": v, "ram_force": F[v], "relative_change": rel,
                     "newton": r.summary["newton_iterations"], "contact_changes": r.summary["contact_changes"],
                     "seconds": r.seconds})
        print(f"    {key} = {v:8g}: F = {F[v]:.8f}  change {rel:+.2e}  Newton {r.summary['newton_iterations']}")
    checks.record("table", rows)
    worst = max(abs(r["relative_change"]) for r in rows)
    checks.check(worst < tolerance, f"{key} over [{min(values):g}, {max(values):g}]: largest ram-force change "
                                    f"{worst:.2e} < {tolerance:g} (default {default:g})")
    return [F[v] for v in values]


def cmd_penalty_normal(runner, args, checks):
    values = [float(v) for v in args.values.split(",")] if args.values else [1e2, 1e3, 1e4, 1e5]
    F = penalty_sweep(runner, args, checks, "Normal Penalty Factor", values, 1e3, 1e-3, "0.1")
    if F is None:
        return
    d = np.diff(F)
    checks.check(all(x > 0 for x in d), "the ram force grows with the normal penalty (the constraint stiffens)")
    values = sorted(set(values) | {1e3})
    if len(d) < 2 or any(abs(b / a - 10.0) > 1e-9 for a, b in zip(values, values[1:])):
        return
    ratios = [d[i] / d[i + 1] for i in range(len(d) - 1)]
    checks.check(all(5 <= q <= 20 for q in ratios),
                 "the penalty error is first order in 1/κ_n: successive differences shrink by "
                 + ", ".join(f"{q:.2f}" for q in ratios) + " per decade (in [5, 20]; 10 for a linear compliance)")


def cmd_penalty_tangential(runner, args, checks):
    F = penalty_sweep(runner, args, checks, "Tangential Penalty Factor", [1.0, 10.0, 100.0, 1000.0], 10.0, 1e-3, "0.2")
    if F is None:
        return
    checks.check(all(b >= a - 1e-9 * abs(a) for a, b in zip(F, F[1:])),
                 "the ram force does not decrease as the sticking penalty stiffens")


def cmd_sticking_penalty(runner, args, checks):
    """F and dF/dν converge as the sticking penalty κ_t grows (ν = 0.2; docs/contact.md).

    The stick branch is the penalty g = α_t u_t: it lets a sticking node slide by
    u_t = g/α_t, so F(κ_t) and dF/dν(κ_t) approach their exact-sticking limits at first order
    in 1/κ_t. Checks: every run converges (up to κ_t = 1e8); the differences from the stiffest
    run shrink by at least 5 per decade of κ_t (10 for a first-order error) while they are
    above 1e-8 relative (below that, the solver tolerance and the penalty's round-off
    dominate); at κ_t >= 1e4 both are within 1e-6 of the stiffest run.
    """
    h = mesh_list(args.meshes, "0.1")[0]
    values = [float(v) for v in args.values.split(",")] if args.values else [1.0, 10.0, 1e2, 1e3, 1e4, 1e6, 1e8]
    nu = float(args.nu) if args.nu else 0.2
    specs = []
    for v in values:
        sets = [f"Boundary Conditions/{w}/Tangential Penalty Factor={lit(v)}" for w in runner.walls]
        sets.append("Sensitivity/Parameters={Friction Coefficient}")
        specs.append((f"h = {h}, nu = {nu}, kappa_t = {v:g}", dict(name=f"sticking_{v:g}", h=h, nu=nu, sets=sets)))
    runs = runner.run_all(specs, checks)
    if not all(checks.check(r.converged, f"{r.label}: converged") for r in runs):
        return
    F = [r.force for r in runs]
    dF = [r.summary["sensitivities"][runner.force_name]["Friction Coefficient"] for r in runs]
    rows = []
    for v, f, d, r in zip(values, F, dF, runs):
        rows.append({"kappa_t": v, "ram_force": f, "dF_dnu": d, "newton": r.summary["newton_iterations"],
                     "contact_changes": r.summary["contact_changes"]})
        print(f"    kappa_t = {v:8g}: F = {f:.10f}  dF/dnu = {d:.10f}  Newton {r.summary['newton_iterations']}")
    checks.record("table", rows)
    for name, series in (("F", F), ("dF/dnu", dF)):
        limit = series[-1]
        diffs = [abs(x - limit) / abs(limit) for x in series[:-1]]
        for i in range(len(diffs) - 1):
            if diffs[i + 1] < 1e-8 or values[i] < 10.0:
                continue
            decades = np.log10(values[i + 1] / values[i])
            rate = (diffs[i] / diffs[i + 1]) ** (1.0 / decades)
            checks.check(rate >= 5.0, f"{name}: the gap to kappa_t = {values[-1]:g} shrinks {rate:.1f}x per decade "
                                      f"from kappa_t = {values[i]:g} to {values[i + 1]:g} (>= 5; 10 at first order)")
        for v, d in zip(values[:-1], diffs):
            if v >= 1e4:
                checks.check(d < 1e-6, f"{name}: kappa_t = {v:g} within {d:.1e} < 1e-6 of kappa_t = {values[-1]:g}")


COMMANDS = {"penalty-normal": cmd_penalty_normal, "penalty-tangential": cmd_penalty_tangential,
            "sticking-penalty": cmd_sticking_penalty}
