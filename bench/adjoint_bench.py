"""The adjoint against the direct differentiation for many parameters (issue #29's item 2;
docs/BENCHMARKS.md "Adjoint").

xml/extrusion.xml on a fixed mesh (adaptivity off, no error estimate) with the container's friction
a Friction Field of N stations (all at the case's ν = 0.1), differentiated by every station:
Sensitivity/Method = Direct (one back-substitution per station, each response's tangent along
dq/dh) against Method = Adjoint (one transposed back-substitution per response, ∂φ/∂h − λ·∂R/∂h per
station), for the ram force and mean ram pressure (2 responses). Each row: the sensitivity's
seconds (summary.json timings.sensitivity, the median of --repeats runs), its back-substitutions,
the whole run's seconds, and the largest difference between the two methods' derivatives (relative
to the response's largest). The machine's load before and after is printed.

usage: scripts/python bench/adjoint_bench.py [FLOWFORM] [--stations 5,11,21,41] [--meshes 0.1:0.025,0.05:0.01]
       [--repeats 3] [--workdir DIR]
"""
import argparse
import os
import statistics

from flowform_tools import default_flowform, launcher, machine, repo_path, tables


def run(flowform, outdir, sets):
    r = launcher.run(flowform, repo_path("xml", "extrusion.xml"), outdir, sets, quiet=True)
    if r.status != 0:
        raise SystemExit(f"flowform exited {r.status}: {launcher.command_line(r.command)}")
    return r.summary


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("flowform", nargs="?", default=default_flowform())
    p.add_argument("--stations", default="5,11,21,41")
    p.add_argument("--meshes", default="0.1:0.025,0.05:0.01")
    p.add_argument("--repeats", type=int, default=3)
    p.add_argument("--workdir", default="/tmp/flowform_adjoint_bench")
    args = p.parse_args()
    print(f"load before: {machine.uptime()}")
    rows = []
    for mesh in args.meshes.split(","):
        h, hc = mesh.split(":")
        for n in [int(s) for s in args.stations.split(",")]:
            names = [f"Friction Field:container/{j}" for j in range(n)]
            sets = ["Adaptivity/Enabled=false", "Error Estimation/Method=None",
                    "Output/Write Solution=false", "Output/Boundary CSV=false",
                    f"Mesh/Geo Parameters/h={launcher.lit(float(h))}", f"Mesh/Geo Parameters/hc={launcher.lit(float(hc))}",
                    "Boundary Conditions/container/Friction Field={" + ", ".join(["0.1"] * n) + "}",
                    "Sensitivity/Parameters={" + ", ".join(names) + "}",
                    "Sensitivity/Responses={ram_force, ram_pressure}"]
            result = {}
            for method in ("Direct", "Adjoint"):
                seconds, totals, last = [], [], None
                for k in range(args.repeats):
                    s = run(args.flowform, os.path.join(args.workdir, f"{h}_{n}_{method}_{k}"),
                            sets + [f"Sensitivity/Method={method}"])
                    seconds.append(s["timings"]["sensitivity"])
                    totals.append(s["timings"]["total"])
                    last = s
                result[method] = (statistics.median(seconds), statistics.median(totals), last)
            d, a = result["Direct"][2]["sensitivities"], result["Adjoint"][2]["sensitivities"]
            worst = max(abs(a[r][q] - d[r][q]) / max(abs(v) for v in d[r].values()) for r in d for q in d[r])
            rows.append([f"({h}, {hc})", str(result["Direct"][2]["dofs"]), str(n),
                         f"{result['Direct'][0]:.3f}", str(result["Direct"][2]["sensitivity"]["solves"]),
                         f"{result['Adjoint'][0]:.3f}", str(result["Adjoint"][2]["sensitivity"]["solves"]),
                         f"{result['Direct'][0] / result['Adjoint'][0]:.1f}",
                         f"{result['Direct'][1]:.2f} / {result['Adjoint'][1]:.2f}", f"{worst:.1e}"])
            print(rows[-1], flush=True)
    print(tables.markdown(["(h, hc)", "dofs", "stations", "direct s", "solves", "adjoint s", "solves",
                           "direct/adjoint", "run s (direct / adjoint)", "max |adj - dir|"], rows))
    print(f"load after: {machine.uptime()}")


if __name__ == "__main__":
    main()
