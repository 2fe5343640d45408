#!/usr/bin/env python3
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
  /usr/bin/python3 bench/ordering_bench.py [FLOWFORM] [--sizes 40,81,163,230,408]
      [--element tri|quad] [--json OUT.json]

Reuses bench/channel_bench.py (element names, machine information, one run under time -v).
The exit status is 0 when every run exited 0.
"""
import argparse
import json
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from channel_bench import ELEMENTS, MATERIALS, REPO, channel_dofs, machine_info, require_tools, run_case  # noqa: E402

ORDERINGS = ["Nested Dissection", "AMD"]
RESPONSES = ["Responses/plastic_power/Type=Plastic Power",
             "Responses/inlet_pressure/Type=Mean Pressure",
             "Responses/inlet_pressure/Boundary=inlet"]
NO_OUTPUT = ["Output/Write Solution=false", "Output/Boundary CSV=false"]


def relative_difference(a, b):
    return abs(a - b) / max(abs(a), abs(b), 1e-300)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("flowform", nargs="?", default=os.path.join(REPO, "build", "flowform"))
    p.add_argument("--case", default=os.path.join(REPO, "xml", "channel.xml"))
    p.add_argument("--sizes", default="40,81,163,230,408", help="N values (cells across)")
    p.add_argument("--element", default="tri", choices=sorted(ELEMENTS))
    p.add_argument("--json", help="write the raw results here")
    args = p.parse_args()
    flowform = require_tools(args.flowform, "ordering_bench.py")

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
                overrides = ([f"Mesh/Geo Parameters/N={float(n)}", f"Mesh/Element Type={ELEMENTS[args.element]}",
                              f"Solver/Linear Solver/Ordering={ordering}"]
                             + MATERIALS["newtonian"] + RESPONSES + NO_OUTPUT)
                r = run_case(flowform, args.case, os.path.join(tmp, f"N{n}_{ordering.replace(' ', '_')}"), overrides)
                s = r.get("summary") or {}
                if r["status"] != 0 or not s:
                    ok = False
                    print(f"  N={n} {ordering}: exit {r['status']}\n{r.get('stderr', '')[-800:]}", flush=True)
                    continue
                row[ordering] = {"factorization": s["timings"]["factorization"], "total": s["timings"]["total"],
                                 "rss": r["rss"], "responses": s.get("functionals", {}),
                                 "load": os.getloadavg()[0]}
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
