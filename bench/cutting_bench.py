"""The cutting scene's cost against its accuracy (docs/cutting.md §6, docs/BENCHMARKS.md §13):
the scene (xml/cutting.xml: ν = 0.2, hc = h/4) on unrefined meshes of size h; per mesh
the dofs, the surface updates, the Newton iterations, the run time (median of --repeat), the
cutting force F_c, the drive force, the chip ratio t/t_c, and their error estimates, two of them:

- "2-level": the two-level estimate (Error Estimation/Method = Two-Level: the mesh refined once,
  its loop started from the converged chip; docs/theory.md §7), relative to the value, with the
  run time including it; each --h mesh is solved as made (Uniform Refinements = 0). Made on the first mesh only (--estimate-all: on every mesh; the refined
  meshes' estimates solve on 4x their dofs), the others run with Method = None.
- "seq.": the distance to the Richardson extrapolation of the meshes' values (below).

usage: scripts/python bench/cutting_bench.py [FLOWFORM] [--h 0.1,0.07,0.05] [--repeat 1] [--workdir DIR]
                              [--estimate-all] [--sets PATH=VALUE ...]

The sequence estimate of a value on mesh i is its distance to the Richardson extrapolation of the
three finest meshes, v_inf = v_3 + (v_3 - v_2) / ((h_2/h_3)^p - 1) with the observed order p
(from the three values, clamped to [0.5, 2]; p = 1 when the differences change sign, and then
the estimate is flagged: the values do not yet converge monotonically).
"""
import argparse
import os
import statistics
import sys
import time

from flowform_tools import launcher, machine, summary, sweep
from flowform_tools.numerics import extrapolate_three as extrapolate

NO_FILES = ["Output/Write Solution=false", "Output/Boundary CSV=false"]
VALUES = ("cutting_force", "drive_force", "chip_ratio")
# --h is the size of the mesh solved: as made, not refined (the scene ships h = 0.2 refined once).
UNREFINED = ["Mesh/Uniform Refinements=0"]


def other_level_updates(s):
    """The free-surface updates of the estimate's other level (refined, or coarser)."""
    e = s.get("error_estimation") or {}
    return e.get("refined_free_surface_iterations", e.get("coarser_free_surface_iterations"))


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap = argparse.ArgumentParser()
    ap.add_argument("flowform", nargs="?", default=os.path.join(root, "build/flowform"))
    ap.add_argument("--h", type=sweep.parse_values, default=[0.1, 0.07, 0.05])
    ap.add_argument("--repeat", type=int, default=1)
    ap.add_argument("--workdir", default="/tmp/flowform_cutting_bench")
    ap.add_argument("--estimate-all", action="store_true")
    ap.add_argument("--sets", nargs="*", default=[])
    a = ap.parse_args()
    info = machine.machine_info()
    print(f"# {info.get('date')}, commit {info.get('commit')}, {info.get('Model name')} x {info.get('CPU(s)')}, "
          f"load {machine.load():.2f}")
    rows = []
    for i, h in enumerate(a.h):
        estimate = ["Error Estimation/Method=" + ("Two-Level" if i == 0 or a.estimate_all else "None")]
        times, s, status = [], {}, None
        for _ in range(a.repeat):
            out = os.path.join(a.workdir, f"h{h:g}")
            start = time.monotonic()
            run = launcher.run(a.flowform, os.path.join(root, "xml/cutting.xml"), out,
                               NO_FILES + UNREFINED + [f"Mesh/Geo Parameters/h={h}"] + estimate + list(a.sets),
                               quiet=True, clean=True)
            times.append(time.monotonic() - start)
            status, s = run.status, summary.load(out) or {}
        rows.append({"h": h, "exit": status, "seconds": statistics.median(times), "dofs": s.get("dofs"),
                     "updates": s.get("free_surface_iterations"), "newton": s.get("newton_iterations"),
                     "values": s.get("functionals") or {}, "estimates": s.get("functionals_error_estimate") or {},
                     "refined_updates": other_level_updates(s)})
    ok = [r for r in rows if r["exit"] == 0]
    limits = {}
    if len(ok) >= 3:
        for name in VALUES:
            limits[name] = extrapolate([r["h"] for r in ok], [r["values"][name] for r in ok])
    print("| h | exit | dofs | updates (refined) | Newton | s | "
          + " | ".join(f"{n} | 2-level | seq." for n in VALUES) + " |")
    print("|---:|---:|---:|---:|---:|---:|" + "---:|---:|---:|" * len(VALUES))
    for r in rows:
        cells = []
        for name in VALUES:
            v = r["values"].get(name)
            if v is None:
                cells += ["-", "-", "-"]
                continue
            eta = r["estimates"].get(name)
            two_level = f"{eta / abs(v) * 100:+.2f} %" if eta is not None else "-"
            est = "-"
            if name in limits:
                vinf, p, monotone = limits[name]
                est = f"{abs(v - vinf) / abs(vinf) * 100:.2f} %" + ("" if monotone else " (not monotone)")
            cells += [f"{v:.5f}", two_level, est]
        updates = f"{r['updates']}" + (f" ({r['refined_updates']})" if r["refined_updates"] is not None else "")
        print(f"| {r['h']:g} | {r['exit']} | {r['dofs']} | {updates} | {r['newton']} | {r['seconds']:.1f} | "
              + " | ".join(cells) + " |")
    for name, (vinf, p, monotone) in limits.items():
        print(f"# {name}: extrapolated {vinf:.5f}, observed order {p:.2f}{'' if monotone else ' (not monotone: p = 1 assumed)'}")
    return 0 if all(r["exit"] == 0 for r in rows) else 1


if __name__ == "__main__":
    sys.exit(main())
