"""The free-surface loop's cost (docs/theory.md §3): per scene and mesh, the surface updates, the
Newton iterations (all, and per re-solve after an update), the time split (first solve with
its status loop, surface updates + mesh motion, re-solves), the value the scene is about, and
how all of it grows with refinement; with Anderson's acceleration (the default), Aitken's
relaxation and without either (the paper's plain update): Free Surface/Relaxation.

usage: scripts/python bench/free_surface_bench.py [FLOWFORM] [--workdir /tmp/flowform_fs_bench] [--repeat 3]
                                   [--quick] [--relaxations Anderson,Aitken,None] [--no-cutting]

Scenes: the Newtonian die swell, planar and axisymmetric (h = 0.2, 0.1, 0.05, 0.025; hc = h/5),
the planar swell at n = 5 (h = 0.2, 0.1, 0.05), the extrusion with a separating die land on
the paper's grading (h = 0.1, hc = 0.025, 0.0125, 0.00625), and the cutting scene (ν = 0.2,
without its error estimate: the straight chip at h = 0.1 and 0.05, the free chip at h = 0.1;
Maximum Iterations 300, one run each: they take 15–200 s). Times are medians of --repeat runs
(machine load printed); the updates and iterations do not vary between repeats.
"""
import argparse
import os
import statistics
import sys
import time

from flowform_tools import launcher, machine, summary

NO_FILES = ["Output/Write Solution=false", "Output/Boundary CSV=false"]


def scenes(quick, cutting):
    hs = ("0.2", "0.1", "0.05") if quick else ("0.2", "0.1", "0.05", "0.025")
    rows = [("die swell planar", "xml/die_swell.xml", f"h={h}", [f"Mesh/Geo Parameters/h={h}"], "swell") for h in hs]
    rows += [("die swell axisym", "xml/die_swell_axisym.xml", f"h={h}", [f"Mesh/Geo Parameters/h={h}"], "swell")
             for h in hs]
    rows += [("die swell n=5", "xml/die_swell.xml", f"h={h}", [f"Mesh/Geo Parameters/h={h}", "Material/Rate Exponent=5.0"],
              "swell") for h in ("0.2", "0.1", "0.05")]
    rows += [("separating land", "xml/extrusion_separation.xml", f"hc={hc}",
              ["Adaptivity/Enabled=false", f"Mesh/Geo Parameters/hc={hc}"], "ram_force")
             for hc in ("0.025", "0.0125", "0.00625")]
    if cutting:
        base = ["Error Estimation/Method=None", "Free Surface/Maximum Iterations=300", "Mesh/Uniform Refinements=0"]
        rows += [("cutting straight chip", "xml/cutting.xml", f"h={h}", base + [f"Mesh/Geo Parameters/h={h}"],
                  "chip_ratio") for h in ("0.1",) + (() if quick else ("0.05",))]
        rows += [("cutting free chip", "xml/cutting.xml", "h=0.1",
                  base + ["Boundary Conditions/chip_outlet/Release After Free Surfaces=true"], "chip_ratio")]
    return rows


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap = argparse.ArgumentParser()
    ap.add_argument("flowform", nargs="?", default=os.path.join(root, "build/flowform"))
    ap.add_argument("--workdir", default="/tmp/flowform_fs_bench")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--quick", action="store_true", help="no h = 0.025 die swell, no h = 0.05 cutting")
    ap.add_argument("--relaxations", default="Anderson,Aitken,None")
    ap.add_argument("--no-cutting", action="store_true")
    a = ap.parse_args()
    info = machine.machine_info()
    print(f"# {info.get('date')}, commit {info.get('commit')}, {info.get('Model name')} x {info.get('CPU(s)')}, "
          f"load {machine.load():.2f}")
    print("| scene | mesh | dofs | relaxation | updates | Newton (all) | Newton per re-solve | first solve s "
          "| updates+motion s | re-solves s | total s | value | max u.n/u |")
    print("|---|---|---:|---|---:|---:|---|---:|---:|---:|---:|---:|---:|")
    for name, case, mesh, sets, value in scenes(a.quick, not a.no_cutting):
        for relaxation in a.relaxations.split(","):
            times, s = [], {}
            for r in range(1 if name.startswith("cutting") else a.repeat):
                out = os.path.join(a.workdir, f"{name}_{mesh}_{relaxation}".replace(" ", "_").replace("=", ""))
                start = time.monotonic()
                run = launcher.run(a.flowform, os.path.join(root, case), out,
                                   NO_FILES + sets + [f"Free Surface/Relaxation={relaxation}"], quiet=True, clean=True)
                elapsed = time.monotonic() - start
                s = summary.load(out) or {}
                if run.status != 0:
                    break
                fs = s.get("free_surface") or {}
                total = (s.get("timings") or {}).get("total", elapsed)
                solve = (s.get("timings") or {}).get("solve", 0.0)
                times.append((solve - fs.get("seconds", 0.0), fs.get("motion_seconds", 0.0),
                              fs.get("resolve_seconds", 0.0), total))
            if not times:
                print(f"| {name} | {mesh} | | {relaxation} | exit {run.status}: {s.get('message', '')[:80]} |")
                continue
            fs = s["free_surface"]
            per = [h["newton_iterations"] for h in fs["history"]]
            if len(per) > 12:  # a long loop: its first and last few
                per = f"{per[:5]} … {per[-3:]}"
            med = [statistics.median(t[i] for t in times) for i in range(4)]
            print(f"| {name} | {mesh} | {s['dofs']} | {relaxation} | {s['free_surface_iterations']} "
                  f"| {s['newton_iterations']} | {per} | {med[0]:.2f} | {med[1]:.2f} | {med[2]:.2f} | {med[3]:.2f} "
                  f"| {s['functionals'][value]:.5f} | {fs['flow_angle']:.1e} |")
    print(f"# load after: {machine.load():.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
