"""Scaling benchmark of flowform on the channel scene (xml/channel.xml).

Runs the flowform binary over a range of mesh sizes (Mesh/Geo Parameters/N: N cells across
the height, 2N along; dofs = 3 (N+1)(2N+1)), for triangles and quadrilaterals, with the
channel's nonlinear material (σ0 = 0.5, n = 5) and with a Newtonian one (n = 1, σ0 = 0),
each run under /usr/bin/time -v in a temporary directory, and prints one table per
material: Newton iterations, assembly, factorization and solve times from summary.json,
peak resident memory and bytes per dof (gross, and net of a tiny N = 2 run's peak).

usage:
  scripts/python bench/channel_bench.py [FLOWFORM] [--quick] [--sizes N,N,...] [--elements tri,quad]
                         [--materials nonlinear,newtonian] [--max-run-seconds S]
                         [--json OUT.json] [--mpi NP --mpi-size N]

  FLOWFORM              the flowform executable (default: build/flowform of this repository)
  --quick               a small run: N = 8, 16, 32 (about 10^3 to 10^4 dofs)
  --sizes               explicit N values (default: 40 .. 408, about 10^4 .. 10^6 dofs)
  --max-run-seconds S   in each series (element, material), skip the larger sizes once one
                        run took longer than S (default 300)
  --mpi NP              also run one size (--mpi-size, default 115) serially and on NP ranks
                        with mpirun and compare the velocity fields (max abs difference)

Every number comes from summary.json (and the peak memory from /usr/bin/time -v); runs go
through python/flowform_tools (launcher, benchmark). Needs /usr/bin/time (Debian package
`time`). h5py, if importable, is used to compare solution.h5; otherwise the boundary CSVs are
compared.
"""
import argparse
import json
import os
import shutil
import sys
import tempfile

from flowform_tools import REPO, csvio, default_flowform, h5io, machine, summary
from flowform_tools.benchmark import (CHANNEL_MATERIALS as MATERIALS, ELEMENTS, channel_dofs,
                                      channel_size, require_tools, run_case)

DEFAULT_SIZES = [40, 57, 81, 115, 163, 230, 325, 408]
QUICK_SIZES = [8, 16, 32]


def row_of(elem, material, n, result):
    s = result.get("summary") or summary.Summary()
    t = s.get("timings", {})
    dofs = s.get("dofs", channel_dofs(n))
    jac_n = s.number("linear_solver.jacobians", "linear_solver.factorizations")
    res_n = s.number("linear_solver.residuals")
    ar, aj, fa = t.get("assembly_residual"), t.get("assembly_jacobian"), t.get("factorization")
    ratio_jr = None
    if ar and aj and jac_n and res_n:
        ratio_jr = (aj / jac_n) / (ar / res_n)
    ratio_af = (ar + aj) / fa if ar is not None and aj is not None and fa else None
    rss = result.get("rss")
    return {
        "elem": elem, "material": material, "N": n, "dofs": dofs,
        "status": result["status"], "converged": s.get("converged"),
        "newton": s.get("newton_iterations"), "jacobians": jac_n, "residuals": res_n,
        "asm_res": ar, "asm_jac": aj, "asm_res_call": ar / res_n if ar and res_n else None,
        "asm_jac_call": aj / jac_n if aj and jac_n else None,
        "jac_res_ratio": ratio_jr, "asm_fact_ratio": ratio_af, "fact": fa,
        "linsolve": t.get("linear_solve"), "setup": t.get("setup"), "solve": t.get("solve"),
        "total": t.get("total"), "wall": result.get("wall"), "rss": rss,
        "bytes_per_dof": rss / dofs if rss and dofs else None,
        "net_bytes_per_dof": (rss - BASELINE["rss"]) / dofs if rss and dofs and BASELINE.get("rss")
        else None,
    }


COLUMNS = [  # header, key, format
    ("elem", "elem", "{}"), ("N", "N", "{}"), ("dofs", "dofs", "{}"), ("st", "status", "{}"),
    ("newton", "newton", "{}"), ("jac", "jacobians", "{}"), ("res", "residuals", "{}"),
    ("asm_res[s]", "asm_res", "{:.3f}"), ("asm_jac[s]", "asm_jac", "{:.3f}"),
    ("jac/res per call", "jac_res_ratio", "{:.2f}"), ("asm/fact", "asm_fact_ratio", "{:.3f}"),
    ("fact[s]", "fact", "{:.3f}"), ("linsolve[s]", "linsolve", "{:.3f}"),
    ("setup[s]", "setup", "{:.2f}"), ("solve[s]", "solve", "{:.2f}"), ("total[s]", "total", "{:.2f}"),
    ("peakRSS[MiB]", "rss", "{:.0f}"), ("B/dof", "bytes_per_dof", "{:.0f}"),
    ("net B/dof", "net_bytes_per_dof", "{:.0f}"),
]
# Peak RSS of a tiny run (N = 2: libraries, MPI, gmsh); "net B/dof" is what each dof adds.
BASELINE = {}


def fmt(row, key, form):
    v = row.get(key)
    if v is None:
        return "-"
    if key == "rss":
        v = v / 2**20
    return form.format(v)


def print_table(rows, title, out=sys.stdout):
    out.write(f"\n{title}\n")
    cells = [[h for h, _, _ in COLUMNS]] + [[fmt(r, k, f) for _, k, f in COLUMNS] for r in rows]
    widths = [max(len(c[i]) for c in cells) for i in range(len(COLUMNS))]
    out.write("| " + " | ".join(c.rjust(w) for c, w in zip(cells[0], widths)) + " |\n")
    out.write("|" + "|".join("-" * (w + 2) for w in widths) + "|\n")
    for c in cells[1:]:
        out.write("| " + " | ".join(x.rjust(w) for x, w in zip(c, widths)) + " |\n")
    out.flush()


# ------------------------------------------------------------------------------------------
# serial vs parallel


def read_velocity_h5(outdir):
    return h5io.nodal_map(outdir, "velocity")


def read_velocity_csv(outdir):
    """(group, x, y) -> (u_t, u_n) over every boundary CSV (a fallback when h5py is missing)."""
    values = {}
    for name in sorted(os.listdir(outdir)):
        if not (name.startswith("boundary_") and name.endswith(".csv")):
            continue
        group = name[len("boundary_"):-len(".csv")]
        for rec in csvio.rows(outdir, group):
            values[(name, rec["x"], rec["y"])] = (rec["u_t"], rec["u_n"])
    return values


def compare_parallel(flowform, case, n, elem, material, np, workdir):
    overrides = channel_size(n, elem) + MATERIALS[material]
    results = {}
    for ranks in (1, np):
        outdir = os.path.join(workdir, f"mpi_{elem}_{material}_{n}_np{ranks}")
        r = run_case(flowform, case, outdir, overrides, np=ranks)
        results[ranks] = (outdir, r)
        print(f"  np={ranks}: status {r['status']}, wall {r['wall']:.1f} s, "
              f"total {((r.get('summary') or {}).get('timings') or {}).get('total', float('nan')):.2f} s, "
              f"newton {(r.get('summary') or {}).get('newton_iterations')}, "
              f"peak RSS {(r.get('rss') or 0) / 2**20:.0f} MiB (largest single process)", flush=True)
        if r["status"] != 0:
            print(r.get("stderr", "")[-2000:])
            return None
    try:
        reader, what = read_velocity_h5, "solution.h5 /fields/velocity"
        a, b = reader(results[1][0]), reader(results[np][0])
    except ImportError:
        reader, what = read_velocity_csv, "boundary CSVs (u_t, u_n)"
        a, b = reader(results[1][0]), reader(results[np][0])
    if set(a) != set(b):
        print(f"  the two runs have different node sets ({len(a)} vs {len(b)} points)")
        return None
    diff = max(max(abs(p - q) for p, q in zip(a[k], b[k])) for k in a)
    scale = max(max(abs(p) for p in a[k]) for k in a)
    print(f"  velocity ({what}, {len(a)} points): max |serial - np{np}| = {diff:.3e}, "
          f"max |u| = {scale:.4g}")
    t1 = results[1][1]["summary"]["timings"]
    tn = results[np][1]["summary"]["timings"]
    print("  timings serial vs np{}: ".format(np) + ", ".join(
        f"{k} {t1.get(k, 0):.2f}/{tn.get(k, 0):.2f}" for k in
        ("total", "setup", "assembly_residual", "assembly_jacobian", "factorization", "linear_solve")))
    return diff


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    p.add_argument("flowform", nargs="?", default=default_flowform())
    p.add_argument("--case", default=os.path.join(REPO, "xml", "channel.xml"))
    p.add_argument("--quick", action="store_true")
    p.add_argument("--sizes", help="comma-separated N values")
    p.add_argument("--elements", default="tri,quad")
    p.add_argument("--materials", default="newtonian,nonlinear")
    p.add_argument("--max-run-seconds", type=float, default=300)
    p.add_argument("--timeout", type=float, default=1800, help="kill a run after this (s)")
    p.add_argument("--json", help="write every row (and the machine) to this file")
    p.add_argument("--mpi", type=int, default=0, metavar="NP")
    p.add_argument("--mpi-size", type=int, default=115, metavar="N")
    p.add_argument("--mpi-element", default="quad", choices=sorted(ELEMENTS))
    p.add_argument("--mpi-material", default="nonlinear", choices=sorted(MATERIALS))
    p.add_argument("--no-table", action="store_true", help="only the --mpi comparison")
    p.add_argument("--keep", action="store_true", help="keep the output directories")
    args = p.parse_args()

    flowform = require_tools(args.flowform, "channel_bench.py")
    sizes = ([int(s) for s in args.sizes.split(",")] if args.sizes
             else QUICK_SIZES if args.quick else DEFAULT_SIZES)
    elements = [e.strip() for e in args.elements.split(",") if e.strip()]
    materials = [m.strip() for m in args.materials.split(",") if m.strip()]
    for e in elements:
        if e not in ELEMENTS:
            sys.exit(f"channel_bench.py: unknown element '{e}' (tri, quad)")
    for m in materials:
        if m not in MATERIALS:
            sys.exit(f"channel_bench.py: unknown material '{m}' (nonlinear, newtonian)")

    info = machine.machine_info()
    print("flowform channel benchmark")
    info["binary_built"] = machine.binary_built(flowform)
    print(f"  binary:  {flowform} (built {info['binary_built']}; the commit below is the work "
          f"tree's now, not necessarily the binary's)")
    print(f"  case:    {args.case}")
    for k in ("date", "commit", "Model name", "CPU(s)", "memory"):
        if k in info:
            print(f"  {k}: {info[k]}")
    print("  times in seconds from summary.json (timings); jac/res per call needs the residual "
          "count in summary.json ('-' when absent); asm/fact = (assembly_residual + "
          "assembly_jacobian) / factorization; peak RSS from /usr/bin/time -v", flush=True)

    workdir = tempfile.mkdtemp(prefix="flowform_bench_")
    rows = []
    try:
        base = {} if args.no_table else run_case(
            flowform, args.case, os.path.join(workdir, "baseline"),
            ["Mesh/Geo Parameters/N=2.0"] + MATERIALS["newtonian"], timeout=args.timeout)
        if base.get("status") == 0 and base.get("rss"):
            BASELINE["rss"] = base["rss"]
            info["baseline_rss_bytes"] = base["rss"]
            print(f"  baseline peak RSS (N = 2, {channel_dofs(2)} dofs): {base['rss'] / 2**20:.0f} MiB",
                  flush=True)
        if not args.no_table:
            for material in materials:
                table = []
                for elem in elements:
                    skip = False
                    for n in sizes:
                        if skip:
                            print(f"  skip {material} {elem} N={n} ({channel_dofs(n)} dofs): "
                                  f"previous run over {args.max_run_seconds:g} s", flush=True)
                            continue
                        outdir = os.path.join(workdir, f"{material}_{elem}_{n}")
                        overrides = channel_size(n, elem) + MATERIALS[material]
                        # Other work on the machine skews the times: the 1-minute load
                        # average is printed with each run (about 1 = this run alone).
                        r = run_case(flowform, args.case, outdir, overrides, timeout=args.timeout)
                        row = row_of(elem, material, n, r)
                        table.append(row)
                        rows.append(row)
                        print(f"  {material} {elem} N={n}: {row['dofs']} dofs, status {row['status']}, "
                              f"newton {row['newton']}, wall {r['wall']:.1f} s, "
                              f"peak RSS {(row['rss'] or 0) / 2**20:.0f} MiB, "
                              f"load before/after {r['load'][0]:.2f}/{r['load'][1]:.2f}", flush=True)
                        if r["status"] not in (0, 3):
                            print("    " + r.get("stderr", "").strip()[-1500:].replace("\n", "\n    "))
                        if not args.keep:
                            shutil.rmtree(outdir, ignore_errors=True)
                        if r["status"] == "timeout" or r["wall"] > args.max_run_seconds:
                            skip = True
                desc = ("nonlinear: σ0 = 0.5, n = 5 (channel.xml)" if material == "nonlinear"
                        else "Newtonian: n = 1, σ0 = 0")
                print_table(table, f"{desc}")
        if args.mpi > 1:
            print(f"\nserial vs mpirun -np {args.mpi}: {args.mpi_material} {args.mpi_element} "
                  f"N={args.mpi_size} ({channel_dofs(args.mpi_size)} dofs)", flush=True)
            diff = compare_parallel(flowform, args.case, args.mpi_size, args.mpi_element,
                                    args.mpi_material, args.mpi, workdir)
            info["mpi_max_abs_velocity_difference"] = diff
    finally:
        if args.keep:
            print(f"\noutputs kept in {workdir}")
        else:
            shutil.rmtree(workdir, ignore_errors=True)
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"machine": info, "rows": rows}, f, indent=2)
    bad = [r for r in rows if r["status"] not in (0,)]
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
