"""What meshing in a process of its own costs (docs/BENCHMARKS.md, "The mesher process").

Runs each scene with two flowform binaries, alternated, ROUNDS times: BASELINE (a build that
calls gmsh inside flowform, e.g. one made at aabdb74) and CANDIDATE (this tree's, which starts
flowform-mesh for every mesh). Prints per scene the median wall time of each, their ratio
measured in the same run, the meshes made (1 + adaptivity cycles) and the response values of
both (they must agree: the same mesh, the same solve). The load average is printed before and
after; compare only ratios measured on an idle machine.

usage:
  scripts/python bench/mesher_bench.py BASELINE [CANDIDATE] [--rounds 5] [--scenes channel,...]
"""
import argparse
import os
import statistics
import sys
import tempfile
import time

from flowform_tools import default_flowform, launcher, repo_path
from flowform_tools.machine import machine_info
from flowform_tools.tables import markdown

SCENES = {  # scene -> overrides: each run makes the meshes the scene asks for
    "channel": ["Responses/plastic_power/Type=Plastic Power"],
    "die_swell": [],
    "extrusion": [],                       # adaptive: one mesh per cycle
    "extrusion_axisym": [],
    "cutting": ["Error Estimation/Method=None"],
}


def one_run(flowform, scene, sets, outdir):
    start = time.perf_counter()
    run = launcher.run(flowform, repo_path("xml", scene + ".xml"), outdir, sets, quiet=True, clean=True,
                       capture=True, timeout=1800)
    wall = time.perf_counter() - start
    s = run.summary or {}
    meshes = 1 + max(len(s.get("adaptivity", {}).get("cycles", [])) - 1, 0)
    return run.status, wall, meshes, s.get("functionals", {})


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("baseline")
    p.add_argument("candidate", nargs="?", default=default_flowform())
    p.add_argument("--rounds", type=int, default=5)
    p.add_argument("--scenes", default=",".join(SCENES))
    a = p.parse_args()
    info = machine_info()
    print("machine:", ", ".join(f"{k} {v}" for k, v in info.items()))
    print("load before:", open("/proc/loadavg").read().split()[:3])
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for scene in a.scenes.split(","):
            walls = {"baseline": [], "candidate": []}
            values = {}
            meshes = None
            for r in range(a.rounds):
                for label in (("baseline", "candidate") if r % 2 == 0 else ("candidate", "baseline")):
                    binary = a.baseline if label == "baseline" else a.candidate
                    status, wall, m, f = one_run(binary, scene, SCENES[scene], os.path.join(work, label))
                    if status != 0:
                        sys.exit(f"{scene}: {label} exited {status}")
                    walls[label].append(wall)
                    values[label] = f
                    meshes = m
            b, c = statistics.median(walls["baseline"]), statistics.median(walls["candidate"])
            name = next(iter(values["baseline"]), "")
            same = all(abs(values["baseline"][k] - values["candidate"][k]) <= 1e-12 * max(1.0, abs(values["baseline"][k]))
                       for k in values["baseline"])
            rows.append([scene, str(meshes), f"{b:.2f}", f"{c:.2f}", f"{c - b:+.2f}", f"{c / b:.3f}",
                         f"{name} {values['candidate'].get(name, float('nan')):.6g}", "yes" if same else "NO"])
    print(markdown(["scene", "meshes", "baseline s (median)", "candidate s (median)", "Δ s", "ratio",
                          "a response (candidate)", "values equal (1e-12)"], rows))
    print("load after:", open("/proc/loadavg").read().split()[:3])


if __name__ == "__main__":
    main()
