"""Wire drawing (xml/drawing.xml): run time against error on a family of meshes (docs/BENCHMARKS.md
"Wire drawing"). For h = 0.05 (the shipped mesh), 0.035, 0.025, 0.0175 (hc = h/3): dofs, Newton
and free-surface iterations, wall seconds and the two-level estimate's share, the drawing stress
and the die pressure with their estimated errors η, and each value's distance to the Richardson
extrapolation of the last three meshes (the observed order printed).

usage: scripts/python bench/drawing_bench.py [FLOWFORM] [--workdir DIR]
The machine's load before and after is printed.
"""
import argparse
import os

from flowform_tools import default_flowform, launcher, machine, repo_path, tables
from flowform_tools.numerics import extrapolate_three

MESHES = [0.05, 0.035, 0.025, 0.0175]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("flowform", nargs="?", default=default_flowform())
    ap.add_argument("--workdir", default="out/bench_drawing")
    args = ap.parse_args()
    info = machine.machine_info()
    print(f"# {info.get('date')}, commit {info.get('commit')}, {info.get('Model name')} x {info.get('CPU(s)')}")
    before = machine.load()
    runs = []
    for h in MESHES:
        r = launcher.run(args.flowform, repo_path("xml", "drawing.xml"), os.path.join(args.workdir, f"h{h}"),
                         [f"Mesh/Geo Parameters/h={launcher.lit(h)}", "Sensitivity/Parameters={}",
                          "Error Estimation/Method=Two-Level", "Output/Write Solution=false"], quiet=True, clean=True)
        s = r.summary or {}
        runs.append({"h": h, "exit": r.status, "dofs": s.get("dofs"), "newton": s.get("newton_iterations"),
                     "surface": s.get("free_surface_iterations"), "total": (s.get("timings") or {}).get("total"),
                     "estimate": (s.get("error_estimation") or {}).get("seconds"),
                     "values": s.get("functionals") or {}, "eta": s.get("functionals_error_estimate") or {}})
    rows = []
    limits = {}
    for name in ("drawing_stress", "die_pressure"):
        values = [r["values"].get(name) for r in runs[-3:]]
        if None not in values:
            limits[name] = extrapolate_three([r["h"] for r in runs[-3:]], values)
    for r in runs:
        row = [f"{r['h']:g}", str(r["exit"]), str(r["dofs"]), str(r["newton"]), str(r["surface"]),
               tables.fmt(r["total"], "{:.1f}"), tables.fmt(r["estimate"], "{:.1f}")]
        for name in ("drawing_stress", "die_pressure"):
            v, eta = r["values"].get(name), r["eta"].get(name)
            limit = limits.get(name)
            row += [tables.fmt(v, "{:.5f}"), "–" if eta is None or v is None else f"{eta / v:+.2%}",
                    "–" if limit is None or v is None else f"{(v - limit[0]) / limit[0]:+.2%}"]
        rows.append(row)
    print(tables.markdown(["h", "exit", "dofs", "Newton", "surface updates", "s", "estimate s",
                           "drawing stress", "η", "− extrapolation", "die pressure", "η", "− extrapolation"], rows,
                          "---:"))
    for name, limit in limits.items():
        print(f"{name}: extrapolation {limit[0]:.5f} (observed order {limit[1]:.2f}, monotone: {limit[2]})")
    print(f"# load {before:.2f} -> {machine.load():.2f}")


if __name__ == "__main__":
    main()
