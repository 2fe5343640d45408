"""Fill-reducing ordering of the direct solver: nested dissection vs AMD (docs/BENCHMARKS.md §6).

For each channel size (xml/channel.xml, N cells across the height, dofs = 3 (N+1)(2N+1)),
runs the Newtonian channel (n = 1, σ0 = 0: a linear problem, one assembly, one
factorization, one solve) once with each `Solver/Linear Solver/Ordering`:

  Nested Dissection   METIS_NodeND + KLU2 (flowform's KluNestedDissection), the default;
  AMD                 Amesos2's KLU2 as shipped (block-triangular form + AMD).

and prints the factorization time (summary.json `timings.factorization`: ordering, symbolic
and numeric factorization), the ratio AMD / nested dissection measured on the same mesh
back to back, the peak resident memory of each run (/usr/bin/time -v), and the relative
difference of two responses between the orderings (plastic power, mean inlet pressure):
both solve the same matrix, so they may differ only by round-off.

usage:
  scripts/python bench/ordering_bench.py [FLOWFORM] [--sizes 40,81,163,230,408]
      [--element tri|quad] [--json OUT.json]

Runs go through python/flowform_tools (benchmark.run_case: one run under time -v); every
number is read from summary.json. The exit status is 0 when every run exited 0.
"""
import argparse
import json
import os
import sys
import tempfile

from flowform_tools import default_flowform, repo_path
from flowform_tools.case import Case
from flowform_tools.benchmark import (CHANNEL_MATERIALS as MATERIALS, ELEMENTS, NO_OUTPUT,
                                      channel_dofs, channel_size, require_tools, run_case)
from flowform_tools.machine import machine_info
from flowform_tools.numerics import relative_difference

ORDERINGS = ["Nested Dissection", "AMD"]


def responses(case):
    """Plastic power, and the mean pressure on the case's loaded boundary (the channel's inlet)."""
    inlet = Case(case).loaded_groups()[0]
    return ["Responses/plastic_power/Type=Plastic Power",
            f"Responses/{inlet}_pressure/Type=Mean Pressure",
            f"Responses/{inlet}_pressure/Boundary={inlet}"]


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("flowform", nargs="?", default=default_flowform())
    p.add_argument("--case", default=repo_path("xml", "channel.xml"))
    p.add_argument("--sizes", default="40,81,163,230,408", help="N values (cells across)")
    p.add_argument("--element", default="tri", choices=sorted(ELEMENTS))
    p.add_argument("--json", help="write the raw results here")
    args = p.parse_args()
    flowform = require_tools(args.flowform, "ordering_bench.py")
    extra = responses(args.case)

    info = machine_info()
    print("flowform ordering benchmark")
    for k, v in info.items():
        print(f"  {k}: {v}")
    print(f"  load before: {os.getloadavg()[0]:.2f}", flush=True)
    rows, ok = [], True
    with tempfile.TemporaryDirectory(prefix="ordering_bench_") as tmp:
        for n in (int(s) for s in args.sizes.split(",")):
            row = {"N": n, "dofs": channel_dofs(n)}
            for ordering in ORDERINGS:
                overrides = (channel_size(n, args.element) + [f"Solver/Linear Solver/Ordering={ordering}"]
                             + MATERIALS["newtonian"] + extra + NO_OUTPUT)
                r = run_case(flowform, args.case, os.path.join(tmp, f"N{n}_{ordering.replace(' ', '_')}"), overrides)
                s = r.get("summary") or {}
                if r["status"] != 0 or not s:
                    ok = False
                    print(f"  N={n} {ordering}: exit {r['status']}\n{r.get('stderr', '')[-800:]}", flush=True)
                    continue
                row[ordering] = {"factorization": s["timings"]["factorization"], "total": s["timings"]["total"],
                                 "rss": r["rss"], "responses": s.get("functionals", {}),
                                 "load": r["load"][1]}
                print(f"  N={n} ({row['dofs']} dofs) {ordering}: factorization "
                      f"{row[ordering]['factorization']:.3f} s, peak RSS {r['rss'] / 2**20:.0f} MiB", flush=True)
            rows.append(row)

    print("\n| elem | dofs | fact ND s | fact AMD s | AMD/ND | peak RSS ND MiB | peak RSS AMD MiB "
          "| B/dof ND | B/dof AMD | max rel. diff. of responses | load after |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for row in rows:
        nd, amd = row.get(ORDERINGS[0]), row.get(ORDERINGS[1])
        if not nd or not amd:
            continue
        diff = max((relative_difference(nd["responses"][k], amd["responses"][k])
                    for k in nd["responses"] if isinstance(nd["responses"][k], (int, float))), default=float("nan"))
        print(f"| {args.element} | {row['dofs']} | {nd['factorization']:.3f} | {amd['factorization']:.3f} "
              f"| {amd['factorization'] / nd['factorization']:.2f} | {nd['rss'] / 2**20:.0f} | {amd['rss'] / 2**20:.0f} "
              f"| {nd['rss'] / row['dofs']:.0f} | {amd['rss'] / row['dofs']:.0f} | {diff:.1e} | {amd['load']:.2f} |")
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"machine": info, "element": args.element, "rows": rows}, f, indent=1)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
