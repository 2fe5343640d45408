"""The rolling scene's cost and estimated errors (issue #27's benchmark; docs/BENCHMARKS.md
"Rolling: run time and estimated errors"): xml/rolling.xml as shipped (R = 10, h0 = 1, h1 = 0.75,
ν = 0.2, Coulomb on the contact force, both strip surfaces free, the DDM derivatives by ν, R and h1
through them and the Two-Level estimate; --case xml/rolling_flat.xml: the flat surfaces) on the
default mesh and refinements of it, h = 0.05 → 0.035 → 0.025 with hc = h/2.5. Per mesh: dofs, wall
nodes, the run time (summary.json timings.total, and the error estimate's share), the Newton
iterations, the Rigid Inflow's balance re-solves, and for roll_force, roll_torque, neutral_angle,
forward_slip, contact_length the value, the run's own two-level estimate η (relative; ≈ exact −
computed) and the distance to the Richardson extrapolation of the three meshes (observed order
clamped to [0.5, 2], flagged when the values do not converge monotonically).

usage: scripts/python bench/rolling_bench.py [FLOWFORM] [--h 0.05,0.035,0.025] [--estimate-first]
                                             [--case xml/rolling.xml] [--workdir DIR] [--sets P=V ...]

The estimate runs on every mesh; --estimate-first keeps it on the first mesh only (the refined
meshes then run about 3 times faster). The machine is shared: the load average
before and after each run is printed beside it.
"""
import argparse
import os
import sys

from flowform_tools import launcher, machine, sweep, tables
from flowform_tools import default_flowform, repo_path
from flowform_tools.numerics import extrapolate_three as extrapolate

VALUES = ("roll_force", "roll_torque", "neutral_angle", "forward_slip", "contact_length")
NO_FILES = ["Output/Write Solution=false", "Output/Boundary CSV=false"]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("flowform", nargs="?", default=default_flowform())
    ap.add_argument("--h", type=sweep.parse_values, default=[0.05, 0.035, 0.025])
    ap.add_argument("--estimate-first", action="store_true")
    ap.add_argument("--workdir", default="/tmp/flowform_rolling_bench")
    ap.add_argument("--case", default="xml/rolling.xml", help="the case, relative to the repository")
    ap.add_argument("--sets", nargs="*", default=[])
    a = ap.parse_args()
    flowform = launcher.require_executable(a.flowform, "rolling_bench.py")
    info = machine.machine_info()
    print(f"# {info.get('date')}, commit {info.get('commit')}, {info.get('Model name')} x {info.get('CPU(s)')}")
    rows = []
    for i, h in enumerate(a.h):
        sets = NO_FILES + [f"Mesh/Geo Parameters/h={launcher.lit(h)}", f"Mesh/Geo Parameters/hc={launcher.lit(h / 2.5)}"]
        if a.estimate_first and i > 0:
            sets.append("Error Estimation/Method=None")
        before = machine.load()
        r = launcher.run(flowform, repo_path(*a.case.split("/")), os.path.join(a.workdir, f"h{h:g}"), sets + a.sets,
                         quiet=True, capture=True, clean=True)
        s = r.summary or {}
        t = s.get("timings") or {}
        rows.append({"h": h, "exit": r.status, "wall": r.wall, "load": (before, machine.load()), "dofs": s.get("dofs"),
                     "total": t.get("total"),
                     "estimate": t.get("error_estimation"), "newton": s.get("newton_iterations"),
                     "inflow": (s.get("rigid_inflow") or {}).get("solves"),
                     "values": s.get("functionals") or {}, "eta": s.get("functionals_error_estimate") or {}})
        print(f"# h = {h:g}: exit {r.status}, {r.wall:.1f} s wall, load {before:.2f} -> {machine.load():.2f}", flush=True)
    ok = [r for r in rows if r["exit"] == 0]
    limits = {}
    if len(ok) >= 3:
        for name in VALUES:
            limits[name] = extrapolate([r["h"] for r in ok], [r["values"][name] for r in ok])
    head = ["h", "hc", "exit", "dofs", "Newton", "inflow re-solves", "s (estimate s)", "load"]
    body = []
    for r in rows:
        body.append([f"{r['h']:g}", f"{r['h'] / 2.5:g}", str(r["exit"]), tables.fmt(r["dofs"], "{}"),
                     tables.fmt(r["newton"], "{}"), tables.fmt(r["inflow"], "{}"),
                     f"{tables.fmt(r['total'], '{:.1f}')} ({tables.fmt(r['estimate'], '{:.1f}')})",
                     f"{r['load'][0]:.1f}–{r['load'][1]:.1f}"])
    print(tables.markdown(head, body, "---:"))
    head = ["h"] + [c for n in VALUES for c in (n, "η (2-level)", "seq.")]
    body = []
    for r in rows:
        cells = [f"{r['h']:g}"]
        for name in VALUES:
            v, eta = r["values"].get(name), r["eta"].get(name)
            cells.append(tables.fmt(v, "{:.5f}"))
            cells.append("-" if eta is None or v is None else f"{eta / abs(v) * 100:+.2f} %")
            if name in limits and v is not None:
                vinf, p, mono = limits[name]
                cells.append(f"{(v - vinf) / abs(vinf) * 100:+.2f} %" + ("" if mono else " (n.m.)"))
            else:
                cells.append("-")
        body.append(cells)
    print(tables.markdown(head, body, "---:"))
    for name, (vinf, p, mono) in limits.items():
        print(f"# {name}: extrapolated {vinf:.5f}, observed order {p:.2f}{'' if mono else ' (not monotone: p = 1 assumed)'}")
    return 0 if all(r["exit"] == 0 for r in rows) else 1


if __name__ == "__main__":
    sys.exit(main())
