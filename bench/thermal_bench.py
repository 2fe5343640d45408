"""The coupled temperature field's cost and accuracy (issue #28's benchmark; docs/BENCHMARKS.md
"Hot extrusion: the coupled solve"), on xml/hot_extrusion.xml (AA6063, real units):

1. cost: the coupled run against the isothermal one (the same case without Material/Thermal, the
   law at 723 K; made by tests/regression/hot_extrusion_checks.py's edit) on the meshes h = 0.1,
   0.05, 0.025 (hc = h/4), --repeat runs each, alternated; median wall time (timings.total),
   their ratio, Newton iterations, dofs (goal: coupled ≤ 1.5 × isothermal);
2. Péclet: the Newton iterations of the coupled run with the conductivity set so that
   Pe = V H ρc / k (V the ram speed 5 mm/s, H the container half-height 50 mm, ρc = 2.43 MPa/K)
   is 10, 10², … 10⁵ (k = 60.75 … 0.006 N/(s K)), on the default mesh;
3. work against error of the exit temperature: the meshes h = 0.2, 0.1, 0.05, 0.025 with the
   exit temperature, the run time, and the distance to the Richardson extrapolation of the last
   three (extrapolate_three);
4. strain: xml/hot_extrusion_hensel_spittel.xml (Hensel–Spittel at each cell's temperature and
   strain) against the same case read at the uniform strain 1 without the Strain field
   (strain_field_checks.py's edit), on h = 0.1, 0.05, 0.025: median wall times, their ratio,
   Newton iterations, dofs, the ram force and the product's mean strain.

usage: scripts/python bench/thermal_bench.py [FLOWFORM] [--repeat 3] [--parts cost,peclet,work,strain]
                                             [--workdir DIR]
The machine's load before and after each part is printed.
"""
import argparse
import os

import hot_extrusion_checks
import strain_field_checks
from flowform_tools import default_flowform, launcher, machine, repo_path, tables
from flowform_tools.numerics import extrapolate_three, median

NO_FILES = ["Output/Write Solution=false", "Output/Boundary CSV=false"]
V, H, RHO_C = 5.0, 50.0, 2.43


def mesh(h):
    return [f"Mesh/Geo Parameters/h={launcher.lit(h)}", f"Mesh/Geo Parameters/hc={launcher.lit(h / 4)}"]


def run(flowform, case, outdir, sets):
    r = launcher.run(flowform, case, outdir, NO_FILES + sets, quiet=True, clean=True)
    s = r.summary or {}
    return {"exit": r.status, "total": (s.get("timings") or {}).get("total"), "newton": s.get("newton_iterations"),
            "dofs": s.get("dofs"), "values": s.get("functionals") or {}}


def paired(flowform, workdir, repeat, cases, extra=()):
    """Two cases (name, path) alternated on h = 0.1, 0.05, 0.025, `repeat` times each: per mesh the
    dofs, median wall times and their ratio (second / first), Newton iterations, ram forces, and the
    second run's `extra` responses."""
    (a, case_a), (b, case_b) = cases
    rows = []
    for h in (0.1, 0.05, 0.025):
        times = {a: [], b: []}
        last = {}
        for _ in range(repeat):
            for name, case in cases:
                last[name] = run(flowform, case, os.path.join(workdir, f"{name}_{h:g}"), mesh(h))
                times[name].append(last[name]["total"])
        t_a, t_b = median(times[a]), median(times[b])
        rows.append([f"{h:g}", str(last[a]["dofs"]), str(last[b]["dofs"]), f"{t_a:.2f}", f"{t_b:.2f}",
                     f"{t_b / t_a:.2f}", f"{last[a]['newton']} / {last[b]['newton']}",
                     f"{last[a]['values'].get('ram_force', float('nan')):.1f} / "
                     f"{last[b]['values'].get('ram_force', float('nan')):.1f}"] +
                    [f"{last[b]['values'].get(r, float('nan')):.4f}" for r in extra])
    print(tables.markdown(["h", f"dofs {a}", f"dofs {b}", f"{a} s (median)", f"{b} s (median)", "ratio",
                           f"Newton {a} / {b}", f"ram force {a} / {b}"] + list(extra), rows, "---:"))


def cost(flowform, workdir, repeat):
    os.makedirs(workdir, exist_ok=True)
    iso = hot_extrusion_checks.isothermal_case(repo_path(), workdir)
    paired(flowform, workdir, repeat, [("iso", iso), ("coupled", repo_path("xml", "hot_extrusion.xml"))])


def peclet(flowform, workdir):
    rows = []
    for pe in (10.0, 1e2, 1e3, 1e4, 1e5):
        k = V * H * RHO_C / pe
        r = run(flowform, repo_path("xml", "hot_extrusion.xml"), os.path.join(workdir, f"pe{pe:g}"),
                [f"Material/Thermal/Conductivity={launcher.lit(k)}"])
        v = r["values"]
        rows.append([f"{pe:g}", f"{k:.4g}", str(r["exit"]), str(r["newton"]), tables.fmt(r["total"], "{:.2f}"),
                     tables.fmt(v.get("exit_temperature"), "{:.2f}"), tables.fmt(v.get("max_temperature"), "{:.2f}"),
                     tables.fmt(v.get("ram_force"), "{:.1f}")])
    print(tables.markdown(["Pe = V H rho c / k", "k", "exit", "Newton", "s", "exit T", "max T", "ram force"], rows,
                          "---:"))


def work(flowform, workdir):
    hs, values, rows = [], [], []
    for h in (0.2, 0.1, 0.05, 0.025):
        r = run(flowform, repo_path("xml", "hot_extrusion.xml"), os.path.join(workdir, f"work_{h:g}"), mesh(h))
        hs.append(h)
        values.append(r["values"].get("exit_temperature"))
        rows.append((h, r))
    t_inf, order, monotone = extrapolate_three(hs, values)
    out = []
    for h, r in rows:
        t = r["values"].get("exit_temperature")
        out.append([f"{h:g}", str(r["dofs"]), str(r["newton"]), f"{r['total']:.2f}", f"{t:.4f}",
                    f"{t - t_inf:+.4f}", f"{(t - t_inf) / (t_inf - hot_extrusion_checks.T_BILLET):+.2%}"])
    print(tables.markdown(["h", "dofs", "Newton", "s", "exit T [K]", "T - T_inf [K]", "of the rise"], out, "---:"))
    print(f"extrapolated exit temperature {t_inf:.4f} K (observed order {order:.2f}, monotone: {monotone})")


def strain(flowform, workdir, repeat):
    os.makedirs(workdir, exist_ok=True)
    uniform = strain_field_checks.without_strain_field(repo_path(), workdir, 1.0)
    paired(flowform, workdir, repeat,
           [("uniform", uniform), ("field", repo_path("xml", "hot_extrusion_hensel_spittel.xml"))], ["exit_strain"])


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("flowform", nargs="?", default=default_flowform())
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--parts", default="cost,peclet,work,strain")
    ap.add_argument("--workdir", default="/tmp/flowform_thermal_bench")
    a = ap.parse_args()
    flowform = launcher.require_executable(a.flowform, "thermal_bench.py")
    info = machine.machine_info()
    print(f"# {info.get('date')}, commit {info.get('commit')}, {info.get('Model name')} x {info.get('CPU(s)')}")
    for part in a.parts.split(","):
        before = machine.load()
        {"cost": lambda: cost(flowform, a.workdir, a.repeat), "peclet": lambda: peclet(flowform, a.workdir),
         "work": lambda: work(flowform, a.workdir), "strain": lambda: strain(flowform, a.workdir, a.repeat)}[part]()
        print(f"# {part}: load {before:.2f} -> {machine.load():.2f}\n", flush=True)


if __name__ == "__main__":
    main()
