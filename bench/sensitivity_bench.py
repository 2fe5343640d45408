"""Cost of the sensitivity analysis on the channel scene (issue #4).

For each mesh size of the channel (xml/channel.xml, σ0 = 0.5, n = 5: nonlinear, Newtonian
predictor + continuation), and for the material parameters {Yield Stress, Rate Exponent,
Rate Constant}, measures against the primal (flow) solve:

  - the DDM with `Jacobian = Converged` (one extra assembly + factorization of K_t at the
    converged state, then one back-substitution and the response derivatives per parameter)
    and with `Jacobian = Last Newton Iterate` (the factors Newton left: no factorization);
  - the built-in finite-difference check (two Newton solves per parameter at h ± δ, started
    from the converged state);
  - the classical finite-difference alternative: two full runs from scratch at h ± δ per
    parameter (same δ as the check), up to --full-fd-max-dofs; beyond, it is estimated as
    2 × the primal.

Runs per size (each under /usr/bin/time -v, written to OUT/<elem>_N<N>/<run>/):
  conv   Sensitivity with Jacobian = Converged and the finite-difference check;
  last   Sensitivity with Jacobian = Last Newton Iterate, no check;
  fd_<symbol>_plus / _minus   no Sensitivity list, the parameter at h ± δ.
Times are summary.json "timings" (seconds): `solve` (the flow solve: Newton, continuation,
responses; the primal), `sensitivity_ddm` (the DDM), `finite_difference_check`. The
extra factorization of `Converged` is not timed on its own: it is taken as
sensitivity_ddm(conv) − sensitivity_ddm(last) (the extra K_t: Jacobian assembly +
factorization), the per-parameter part as sensitivity_ddm(last) / k, and checked against
the primal's mean factorization + Jacobian assembly per call (run `last`, whose
factorizations are all the primal's).

Two responses are added to the channel (which has none) so that the DDM includes response
derivatives: `plastic_power` (Plastic Power) and `inlet_pressure` (Mean Pressure on the
case's loaded boundary, the inlet).
The full-run FD derivatives of those are compared with the DDM's.

usage:
  scripts/python bench/sensitivity_bench.py [FLOWFORM] [--sizes 40,81,163,230]
      [--element tri|quad] [--full-fd-max-dofs 200000] [--budget-seconds 3600]
      [--out /tmp/sensitivity_bench]
  scripts/python bench/sensitivity_bench.py --report OUT/sensitivity_bench.json

Runs go through python/flowform_tools (benchmark.run_case: one case under /usr/bin/time -v);
every number is read from summary.json. The exit status is 0 when every run exited 0.
"""
import argparse
import json
import math
import os
import sys
import time

from flowform_tools import default_flowform, repo_path
from flowform_tools.benchmark import (ELEMENTS, NO_OUTPUT, channel_dofs, channel_size,
                                      require_tools, run_case)
from flowform_tools.case import Case
from flowform_tools.machine import machine_info, uptime
from flowform_tools.summary import lookup

PARAMETERS = ["Yield Stress", "Rate Exponent", "Rate Constant"]
DEFAULT_SIZES = [40, 81, 163, 230]  # 9 963, 40 098, 160 884, 319 473 dofs; 408: 1 002 459
FACTORIZATION_EXPONENT = 1.65  # KLU2 factorization time ~ dofs^1.65 (docs/BENCHMARKS.md §1)


def sensitivity_overrides(jacobian, check):
    return ["Sensitivity/Parameters={" + ", ".join(PARAMETERS) + "}",
            f"Sensitivity/Jacobian={jacobian}",
            f"Sensitivity/Finite Difference Check={'true' if check else 'false'}"]


def responses(case):
    """Plastic power, and the mean pressure on the case's loaded boundary (the channel's inlet)."""
    inlet = Case(case).loaded_groups()[0]
    return ["Responses/plastic_power/Type=Plastic Power",
            f"Responses/{inlet}_pressure/Type=Mean Pressure",
            f"Responses/{inlet}_pressure/Boundary={inlet}"]


def timed_run(flowform, case, outdir, overrides, label):
    """run_case (with the load average before and after); prints one progress line."""
    os.makedirs(outdir, exist_ok=True)
    r = run_case(flowform, case, outdir, overrides)
    s = r.get("summary") or {}
    t = s.get("timings", {})
    print(f"    {label}: status {r['status']}, solve {t.get('solve', float('nan')):.2f} s, "
          f"ddm {t.get('sensitivity_ddm', 0):.3f} s, fd check {t.get('finite_difference_check', 0):.2f} s, "
          f"wall {r['wall']:.1f} s, load {r['load'][0]:.2f}/{r['load'][1]:.2f}", flush=True)
    if r["status"] not in (0,):
        print("      " + (r.get("stderr") or "").strip()[-1500:].replace("\n", "\n      "), flush=True)
    return {k: v for k, v in r.items() if k not in ("stderr", "log")} | {"stderr_tail": (r.get("stderr") or "")[-1500:]}


def run_size(flowform, case, out, elem, n, full_fd):
    """Every run of one mesh size; returns the raw results (summaries included)."""
    base = channel_size(n, elem) + responses(case) + NO_OUTPUT
    d = os.path.join(out, f"{elem}_N{n}")
    size = {"N": n, "elem": elem, "dofs": channel_dofs(n), "runs": {}}
    print(f"  {elem} N={n} ({channel_dofs(n)} dofs)", flush=True)
    size["runs"]["conv"] = timed_run(flowform, case, os.path.join(d, "conv"),
                                     base + sensitivity_overrides("Converged", True), "conv")
    size["runs"]["last"] = timed_run(flowform, case, os.path.join(d, "last"),
                                     base + sensitivity_overrides("Last Newton Iterate", False), "last")
    if full_fd:
        # The check's own h and δ (δ = step·|h| for σ0, γ, n), so both FDs difference alike.
        summary = size["runs"]["conv"].get("summary") or {}
        fd_params = summary.get("sensitivity", {}).get("finite_difference", {}).get("parameters", [])
        for p in fd_params:
            for sign, tag in ((1, "plus"), (-1, "minus")):
                value = p["value"] + sign * p["delta"]
                size["runs"][f"fd:{p['parameter']}:{tag}"] = timed_run(
                    flowform, case, os.path.join(d, f"fd_{p['parameter'].replace(' ', '_')}_{tag}"),
                    base + [f"Material/{p['parameter']}={value:.17g}"],
                    f"full FD {p['parameter']} {'+' if sign > 0 else '-'}δ")
    return size


def get(run, *path):
    """summary.json of a run (as stored in the JSON) at a key path; None when missing."""
    return lookup(run.get("summary") or {}, path, None)


def analyse(size):
    """The table row of one size (times in s, fractions of the primal in %)."""
    runs = size["runs"]
    conv, last = runs["conv"], runs["last"]
    k = len(PARAMETERS)
    primal_conv, primal_last = get(conv, "timings", "solve"), get(last, "timings", "solve")
    ddm_conv, ddm_last = get(conv, "timings", "sensitivity_ddm"), get(last, "timings", "sensitivity_ddm")
    fd_check = get(conv, "timings", "finite_difference_check")
    row = {"N": size["N"], "elem": size["elem"], "dofs": get(conv, "dofs") or size["dofs"],
           "status": {name: r["status"] for name, r in runs.items()},
           "load": {name: r["load"] for name, r in runs.items()},
           "newton": get(last, "newton_iterations"),
           "primal_conv": primal_conv, "primal_last": primal_last,
           "primal_factorizations": None, "ddm_conv": ddm_conv, "ddm_last": ddm_last,
           "fd_check": fd_check, "fd_check_newton": get(conv, "sensitivity", "finite_difference",
                                                         "newton_iterations"),
           "ddm_factorizations": [get(conv, "sensitivity", "factorizations"),
                                  get(last, "sensitivity", "factorizations")],
           "jacobian_offset_last": get(last, "sensitivity", "jacobian_offset")}
    facts, jacs = get(last, "linear_solver", "factorizations"), get(last, "linear_solver", "jacobians")
    if facts is not None:
        row["primal_factorizations"] = facts - (get(last, "sensitivity", "factorizations") or 0)
    fact_t, ajac_t = get(last, "timings", "factorization"), get(last, "timings", "assembly_jacobian")
    if facts and jacs and fact_t is not None and ajac_t is not None:
        row["primal_kt_per_call"] = fact_t / facts + ajac_t / jacs
    pct = lambda a, b: 100.0 * a / b if a is not None and b else None  # noqa: E731
    if ddm_conv is not None and ddm_last is not None:
        row["extra_kt"] = ddm_conv - ddm_last
        row["extra_kt_pct"] = pct(ddm_conv - ddm_last, primal_conv)
        row["marginal_pct"] = pct(ddm_last / k, primal_last)
    row["ddm_conv_pp_pct"] = pct(ddm_conv / k, primal_conv) if ddm_conv is not None else None
    row["ddm_last_pp_pct"] = pct(ddm_last / k, primal_last) if ddm_last is not None else None
    row["fd_check_pp_pct"] = pct(fd_check / k, primal_conv) if fd_check is not None else None
    # Full-run FD: the two runs' flow solves (setup and output not counted) over the primal.
    primals = [p for p in (primal_conv, primal_last) if p]
    primal = sum(primals) / len(primals) if primals else None
    row["primal_mean"] = primal
    full = {}
    for name in PARAMETERS:
        plus, minus = runs.get(f"fd:{name}:plus"), runs.get(f"fd:{name}:minus")
        if not plus or not minus:
            continue
        tp, tm = get(plus, "timings", "solve"), get(minus, "timings", "solve")
        entry = {"solve_plus": tp, "solve_minus": tm,
                 "newton": [get(plus, "newton_iterations"), get(minus, "newton_iterations")],
                 "wall": [plus["wall"], minus["wall"]], "pct": pct((tp or 0) + (tm or 0), primal),
                 "rel_diff": {}}
        delta = next((p["delta"] for p in get(conv, "sensitivity", "finite_difference", "parameters") or []
                      if p["parameter"] == name), None)
        for resp, ddm in (get(conv, "sensitivities") or {}).items():
            fp, fm = get(plus, "functionals", resp), get(minus, "functionals", resp)
            if fp is None or fm is None or not delta or name not in ddm:
                continue
            fd = (fp - fm) / (2 * delta)
            entry["rel_diff"][resp] = abs(fd - ddm[name]) / max(abs(fd), abs(ddm[name]), 1e-300)
        full[name] = entry
    row["full_fd"] = full
    # Converged vs Last Newton Iterate: the largest relative difference of dφ/dh per response.
    row["conv_vs_last"] = {}
    for resp, by_param in (get(conv, "sensitivities") or {}).items():
        other = get(last, "sensitivities", resp) or {}
        diffs = [abs(v - other[name]) / max(abs(v), abs(other[name]), 1e-300)
                 for name, v in by_param.items() if name in other]
        if diffs:
            row["conv_vs_last"][resp] = max(diffs)
    if len(full) == k and all(e["pct"] is not None for e in full.values()):
        row["full_fd_pp_pct"] = sum(e["pct"] for e in full.values()) / k
        row["full_fd_measured"] = True
    elif primal:
        row["full_fd_pp_pct"] = 200.0  # two primal runs per parameter
        row["full_fd_measured"] = False
    return row


def fmt(v, f="{:.3g}"):
    return "-" if v is None else f.format(v)


def one_parameter_pct(row):
    """The DDM (Converged) for a single parameter, derived: extra K_t + one parameter's share."""
    a, b = row.get("extra_kt_pct"), row.get("marginal_pct")
    return a + b if a is not None and b is not None else None


def print_tables(rows, info):
    k = len(PARAMETERS)
    print(f"\nchannel (xml/channel.xml, σ0 = 0.5, n = 5), {rows[0]['elem'] if rows else ''}, "
          f"k = {k} parameters {{{', '.join(PARAMETERS)}}}; per-parameter % = time / k / primal")
    head = ["dofs", "primal s", "fact. in primal", "DDM conv s", "DDM conv %/param", "extra K_t s (% primal)",
            "solves+resp. s (= DDM last)", "DDM last %/param", "FD check %/param", "full-run FD %/param", "load"]
    print("| " + " | ".join(head) + " |")
    print("|" + "---|" * len(head))
    for r in rows:
        load = max(max(l) for l in r["load"].values())
        full = fmt(r.get("full_fd_pp_pct"), "{:.0f}") + ("" if r.get("full_fd_measured") else " (est.)")
        print("| " + " | ".join([
            str(r["dofs"]), fmt(r["primal_conv"], "{:.2f}"), fmt(r["primal_factorizations"], "{}"),
            fmt(r["ddm_conv"], "{:.3f}"), fmt(r["ddm_conv_pp_pct"], "{:.2f}"),
            f"{fmt(r.get('extra_kt'), '{:.3f}')} ({fmt(r.get('extra_kt_pct'), '{:.2f}')})",
            fmt(r["ddm_last"], "{:.3f}"), fmt(r["ddm_last_pp_pct"], "{:.3f}"),
            fmt(r["fd_check_pp_pct"], "{:.1f}"), full, f"≤ {load:.2f}"]) + " |")
    print("\nper size: exit statuses; primal of run `last`; primal's mean K_t (Jacobian assembly + "
          "factorization) per call vs the extra K_t; Newton iterations of the FD check (all 2k runs); "
          "‖q − q_J‖/‖q‖ of `last`")
    for r in rows:
        bad = {n: s for n, s in r["status"].items() if s != 0}
        print(f"  {r['dofs']}: statuses {'all 0' if not bad else bad}; primal(last) "
              f"{fmt(r['primal_last'], '{:.2f}')} s, {r['newton']} Newton; K_t per call "
              f"{fmt(r.get('primal_kt_per_call'), '{:.3f}')} s vs extra {fmt(r.get('extra_kt'), '{:.3f}')} s; "
              f"FD check {r['fd_check_newton']} Newton; offset {fmt(r['jacobian_offset_last'], '{:.1e}')}; "
              f"DDM conv with one parameter (extra K_t + one solve) ≈ "
              f"{fmt(one_parameter_pct(r), '{:.2f}')} % of the primal")
        print("    dφ/dh, Converged vs Last Newton Iterate (max over parameters): " + ", ".join(
            f"{resp} {v:.1e}" for resp, v in sorted(r.get("conv_vs_last", {}).items())))
        for name, e in r["full_fd"].items():
            rd = ", ".join(f"{resp} {v:.1e}" for resp, v in sorted(e["rel_diff"].items()))
            print(f"    full FD {name}: solve {e['solve_plus']:.2f} + {e['solve_minus']:.2f} s "
                  f"({e['pct']:.0f} % of primal {r['primal_mean']:.2f}), Newton {e['newton']}; "
                  f"|FD − DDM|/max: {rd}")
    # Growth between consecutive sizes: d log(time) / d log(dofs).
    print("\nlog-log slopes between consecutive sizes (time ~ dofs^slope)")
    for a, b in zip(rows, rows[1:]):
        def slope(key):
            x, y = a.get(key), b.get(key)
            return (math.log(y / x) / math.log(b["dofs"] / a["dofs"])) if x and y and x > 0 and y > 0 else None
        print(f"  {a['dofs']} → {b['dofs']}: primal {fmt(slope('primal_conv'), '{:.2f}')}, extra K_t "
              f"{fmt(slope('extra_kt'), '{:.2f}')}, DDM last (solves+resp.) {fmt(slope('ddm_last'), '{:.2f}')}, "
              f"FD check {fmt(slope('fd_check'), '{:.2f}')}")
    if info.get("uptime_after"):
        print(f"\nuptime before: {info.get('uptime_before')}\nuptime after:  {info['uptime_after']}")


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("flowform", nargs="?", default=default_flowform())
    p.add_argument("--case", default=repo_path("xml", "channel.xml"))
    p.add_argument("--sizes", default=",".join(map(str, DEFAULT_SIZES)), help="N values (cells across)")
    p.add_argument("--element", default="tri", choices=sorted(ELEMENTS))
    p.add_argument("--full-fd-max-dofs", type=int, default=200000,
                   help="full-run FD (2 runs from scratch per parameter) up to this size; estimated beyond")
    p.add_argument("--budget-seconds", type=float, default=3600,
                   help="skip a size when the time spent plus its projected cost (primal ~ dofs^1.65) exceeds this")
    p.add_argument("--out", default="/tmp/sensitivity_bench")
    p.add_argument("--report", metavar="JSON", help="print the tables of an earlier run's JSON; run nothing")
    args = p.parse_args()

    if args.report:
        with open(args.report) as f:
            data = json.load(f)
        print_tables([analyse(s) for s in data["sizes"]], data["machine"])
        return 0

    flowform = require_tools(args.flowform, "sensitivity_bench.py")
    os.makedirs(args.out, exist_ok=True)
    info = machine_info()
    info["flowform"] = flowform
    info["uptime_before"] = uptime()
    info["command"] = " ".join(sys.argv)
    print("flowform sensitivity benchmark (issue #4)")
    for key in ("date", "commit", "Model name", "CPU(s)", "memory", "flowform", "uptime_before"):
        if key in info:
            print(f"  {key}: {info[key]}")
    sizes = [int(s) for s in args.sizes.split(",")]
    results, start, last_primal = [], time.monotonic(), None
    json_path = os.path.join(args.out, "sensitivity_bench.json")
    for n in sizes:
        dofs = channel_dofs(n)
        full_fd = dofs <= args.full_fd_max_dofs
        if last_primal:
            # conv ≈ primal · (1 + FD check ≈ 0.5), last ≈ primal, full FD = 2k primals
            primal = last_primal[1] * (dofs / last_primal[0]) ** FACTORIZATION_EXPONENT
            projected = primal * (2.5 + (2 * len(PARAMETERS) if full_fd else 0))
            spent = time.monotonic() - start
            if spent + projected > args.budget_seconds:
                print(f"  skip N={n} ({dofs} dofs): projected {projected:.0f} s + spent {spent:.0f} s "
                      f"> budget {args.budget_seconds:.0f} s", flush=True)
                break
        size = run_size(flowform, args.case, args.out, args.element, n, full_fd)
        results.append(size)
        t = get(size["runs"]["last"], "timings", "solve")
        if t:
            last_primal = (dofs, t)
        info["uptime_after"] = uptime()
        with open(json_path, "w") as f:
            json.dump({"machine": info, "sizes": results}, f, indent=1)
    info["uptime_after"] = uptime()
    info["elapsed_seconds"] = time.monotonic() - start
    with open(json_path, "w") as f:
        json.dump({"machine": info, "sizes": results}, f, indent=1)
    print_tables([analyse(s) for s in results], info)
    print(f"\nelapsed {info['elapsed_seconds']:.0f} s; everything in {json_path}")
    bad = [r for s in results for r in s["runs"].values() if r["status"] != 0]
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
