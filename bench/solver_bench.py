"""Direct solvers KLU2 vs MUMPS (issue #10): one factorization, ranks and BLAS threads, and
the nonlinear extrusion with its contact loop.

  (a) Newtonian channel (xml/channel.xml, n = 1, σ0 = 0: one factorization) per size N, KLU2
      and MUMPS (both Nested Dissection) back to back: factorization and total time, factor
      entries, peak RSS, KB/dof (also net of a tiny N = 2 run), KLU2/MUMPS of the
      factorization within each pair, largest relative difference of the responses;
  (b) MUMPS with np = 1 and OPENBLAS_NUM_THREADS = 1, 2, and `mpirun -np 2` with 1 thread:
      factorization, total, peak RSS (largest rank), responses against np = 1;
  (c) extrusion (plane, axisym) on (h, hc) meshes per --types and --variant column: Newton
      iterations, factorizations, contact changes, restarts, time split, peak RSS, ram force
      and its relative difference from the first column. A mesh is skipped when its
      projected time, (previous run of the column) × (dofs / its dofs)^--growth, dofs
      from meshing the .geo with gmsh (3 per node), exceeds --max-run-seconds.

usage:
  solver_bench.py [FLOWFORM] [--parts a,b,c] [--sizes 40,128,230,408] [--mpi-sizes 230,408]
      [--types KLU2,MUMPS] [--set P=V ...] [--variant NAME=P=V ...] [--max-run-seconds 300] ...
  solver_bench.py --report OUT.json ...   # earlier runs' tables (parts merged), nothing run

--set applies to every run of (c); --variant NAME=P=V (repeatable; one NAME collects several
settings) adds a column per variant and type (an old and a new contact method in one run).
Repeats run back to back; times are medians (repeated while a run is shorter than
--repeat-below s). Each run first waits (≤ --wait-max s) for a 1-minute load below
--wait-load; the load before/after is recorded. Numbers from summary.json and time -v only.
Runs, logs in --out. Exit status 0 when every run exited 0.
"""
import argparse
import json
import os
import re
import subprocess
import sys
import tempfile
import time

from flowform_tools import default_flowform, launcher, repo_path
from flowform_tools.benchmark import (CHANNEL_MATERIALS, NO_OUTPUT, channel_size,
                                      require_tools)
from flowform_tools.case import FIXED_MESH, Case
from flowform_tools.launcher import lit
from flowform_tools.machine import binary_built, load, machine_info
from flowform_tools.numerics import median, relative_difference

CASES = {"plane": "xml/extrusion.xml", "axisym": "xml/extrusion_axisym.xml"}
TYPE = "Solver/Linear Solver/Type="
ND = "Solver/Linear Solver/Ordering=Nested Dissection"
MPI_ENV = {"OMPI_MCA_rmaps_base_oversubscribe": "1"}  # + the root variables (launcher)
B_CONFIGS = [("np1 T1", 1, 1), ("np1 T2", 1, 2), ("np2 T1", 2, 1)]  # label, ranks, BLAS threads
STATUSES = []  # exit status of every run of this invocation
KEEP = ("dofs", "converged", "newton_iterations", "contact_changes", "timings", "linear_solver",
        "functionals", "solves", "ranks", "message")


def wait_idle(args):
    """Waits (≤ --wait-max s) for a 1-minute load below --wait-load; returns the wait."""
    start = time.monotonic()
    while load() >= args.wait_load and time.monotonic() - start < args.wait_max:
        time.sleep(10)
    return round(time.monotonic() - start)


def run(args, case, outdir, sets, np=1, threads=None, timeout=None):
    """One flowform run under /usr/bin/time -v; a record with the summary's numbers only."""
    waited = wait_idle(args)
    env = dict(os.environ)
    if threads is not None:
        env["OPENBLAS_NUM_THREADS"] = str(threads)
    if np > 1:
        env.update(MPI_ENV)
    before = load()
    r = launcher.run(args.flowform, case, outdir, FIXED_MESH + list(sets), np=np, env=env, quiet=True, peak_memory=True,
                     log=os.path.join(outdir + ".log"), timeout=timeout or args.timeout, clean=True)
    s = r.summary or {}
    rec = {"status": "timeout" if r.timed_out else r.status, "wall": r.wall, "rss": r.peak_rss,
           "load": [round(before, 2), round(load(), 2)], "waited": waited, "np": np,
           "threads": env.get("OPENBLAS_NUM_THREADS", "unset"), "sets": list(sets)}
    rec.update({k: s.get(k) for k in KEEP})
    t = rec.get("timings") or {}
    rec.update(fact=t.get("factorization"), total=t.get("total"), linsolve=t.get("linear_solve"),
               asm=t.get("assembly_residual", 0) + t.get("assembly_jacobian", 0) if t else None,
               entries=(rec.get("linear_solver") or {}).get("factor_entries"),
               mib=r.peak_rss / 2**20 if r.peak_rss else None)
    STATUSES.append(rec["status"])
    if rec["status"] != 0:
        rec["log_tail"] = r.log_tail(8)
    print(f"    exit {rec['status']}, {r.wall:.1f} s (fact {f(rec['fact'])}), "
          f"peak {(r.peak_rss or 0) / 2**20:.0f} MiB, load {rec['load'][0]:.2f}->{rec['load'][1]:.2f}"
          + (f" (waited {waited} s)" if waited else ""), flush=True)
    return rec


def repeats(args, first_wall):
    return args.repeats if first_wall < args.repeat_below else 1


def channel_sets(n, solver):
    inlet = Case(repo_path("xml", "channel.xml")).loaded_groups()[0]
    return (channel_size(n, "tri") + CHANNEL_MATERIALS["newtonian"] + NO_OUTPUT + [TYPE + solver, ND,
            "Responses/plastic_power/Type=Plastic Power", f"Responses/{inlet}_pressure/Type=Mean Pressure",
            f"Responses/{inlet}_pressure/Boundary={inlet}"])


def series(args, out, part, sizes, configs):
    """Per channel size, every (label, type, ranks, BLAS threads) config back to back, repeated."""
    rows = []
    for n in sizes:
        row = {"N": n, "runs": {c[0]: [] for c in configs}}
        k, count = 0, 1
        while k < count:
            for label, solver, np, threads in configs:
                print(f"  N={n} {solver}{'' if label == solver else ' ' + label} r{k}")
                row["runs"][label].append(run(args, repo_path("xml", "channel.xml"), os.path.join(
                    out, f"{part}_N{n}_{label.replace(' ', '_')}_r{k}"), channel_sets(n, solver), np, threads))
            count = count if k else repeats(args, max(v[0]["wall"] for v in row["runs"].values()))
            k += 1
        rows.append(row)
    return rows


def part_a(args, out):
    print("(a) Newtonian channel, KLU2 vs MUMPS, nested dissection", flush=True)
    configs = [(t, t, 1, None) for t in ("KLU2", "MUMPS")]
    tiny = {c[0]: series(args, out, "a_tiny", [2], [c])[0]["runs"][c[0]][0] for c in configs}
    return {"tiny": tiny, "rows": series(args, out, "a", args.sizes, configs)}


def part_b(args, out):
    print("(b) MUMPS: ranks and OpenBLAS threads", flush=True)
    return {"rows": series(args, out, "b", args.mpi_sizes, [(c[0], "MUMPS", c[1], c[2]) for c in B_CONFIGS])}


def geo_dofs(case_file, sets):
    """Dofs of a .geo case (3 per node) from the gmsh command; None if that is not possible."""
    scene = Case(case_file)
    geo = dict(scene.sublist("Mesh", "Geo Parameters"))
    geo.update(m.groups() for m in (re.match(r"Mesh/Geo Parameters/([^=]+)=(.*)", x) for x in sets) if m)
    with tempfile.TemporaryDirectory() as tmp:
        msh = os.path.join(tmp, "m.msh")
        cmd = ["gmsh", "-2", scene.mesh_file(), "-o", msh, "-v", "0"]
        for k, v in geo.items():
            cmd += ["-setnumber", k, str(v)]
        try:
            subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=300, check=True)
            with open(msh) as fh:
                for text in fh:
                    if text.startswith("$Nodes"):
                        return 3 * int(next(fh).split()[1])
        except (OSError, subprocess.SubprocessError, ValueError, StopIteration):
            return None
    return None


def columns(args):
    """(label, overrides) per column of (c): each variant × each type."""
    variants = {}
    for v in args.variant:
        name, _, setting = v.partition("=")
        variants.setdefault(name, []).append(setting)
    variants = variants or {"": []}
    return [((f"{name} " if name else "") + t, args.set + sets + [TYPE + t])
            for name, sets in variants.items() for t in args.types]


def part_c(args, out):
    print("(c) extrusion: contact loop per solver type", flush=True)
    result = {}
    for case in args.cases:
        case_file = repo_path(CASES[case])
        last = {}  # column -> (wall, dofs) of its previous run
        rows = []
        for h, hc in args.meshes:
            mesh_sets = [f"Mesh/Geo Parameters/h={lit(h)}", f"Mesh/Geo Parameters/hc={lit(hc)}"]
            dofs = geo_dofs(case_file, args.set + mesh_sets)
            row = {"h": h, "hc": hc, "dofs_geo": dofs, "cols": {}}
            for label, sets in columns(args):
                prev = last.get(label)
                if prev and prev[0] is None:
                    row["cols"][label] = {"skipped": "a coarser run of this column failed or timed out"}
                    continue
                if prev and dofs:
                    projected = prev[0] * (dofs / prev[1]) ** args.growth
                    if projected > args.max_run_seconds:
                        row["cols"][label] = {"skipped": f"projected {projected:.0f} s > {args.max_run_seconds:.0f} s",
                                              "projected": projected}
                        print(f"  {case} h={h} hc={hc} {label}: skipped, projected {projected:.0f} s")
                        continue
                runs = []
                while not runs or (len(runs) < repeats(args, runs[0]["wall"]) and runs[0]["status"] == 0):
                    print(f"  {case} h={h} hc={hc} ({dofs} dofs) {label} r{len(runs)}")
                    runs.append(run(args, case_file, os.path.join(out, f"c_{case}_h{h}_hc{hc}_{label.replace(' ', '_')}"
                                                                   f"_r{len(runs)}"), sets + mesh_sets,
                                    timeout=min(args.timeout, 3 * args.max_run_seconds)))
                ok = runs[0]["status"] in (0, 3)
                last[label] = (median([r["wall"] for r in runs]) if ok else None, runs[0].get("dofs") or dofs)
                row["cols"][label] = {"runs": runs}
            rows.append(row)
        result[case] = {"case": CASES[case], "force": Case(case_file).tool_force(), "rows": rows}
    return result


def med(runs, key):
    return median([r.get(key) for r in runs])


def f(x, fmt=".2f"):
    return "-" if x is None else format(x, fmt)


def line(*cells):
    print("| " + " | ".join(str(c) for c in cells) + " |")


def max_diff(a, b):
    fa, fb = (a or {}).get("functionals") or {}, (b or {}).get("functionals") or {}
    d = [relative_difference(fa[k], fb[k]) for k in fa if k in fb and isinstance(fa[k], (int, float))]
    return max(d) if d else None


def loads(runs):
    vals = [x for r in runs for x in r["load"]]
    return f"{min(vals):.2f}–{max(vals):.2f}"


def kb_per_dof(runs, tiny):
    """KB/dof of the median peak RSS, total and net of the tiny run's."""
    rss, dofs = med(runs, "rss"), runs[0].get("dofs")
    if not rss or not dofs:
        return None, None
    return rss / dofs / 1024, (rss - tiny["rss"]) / dofs / 1024 if tiny.get("rss") else None


def pair_ratio(row):
    """Median over the pairs of fact(KLU2) / fact(MUMPS), each pair run back to back."""
    return median([x["fact"] / y["fact"] for x, y in zip(row["runs"]["KLU2"], row["runs"]["MUMPS"])
                   if x.get("fact") and y.get("fact")])


def table_a(a):
    print("\n(a) Newtonian channel, P1, KLU2 (ND) vs MUMPS (ND); medians over the repeats")
    line("N", "dofs", "reps", "fact KLU2 s", "fact MUMPS s", "KLU2/MUMPS", "total KLU2 s", "total MUMPS s",
         "L+U KLU2", "factors MUMPS", "RSS KLU2 MiB", "RSS MUMPS MiB", "KB/dof KLU2 (net)", "KB/dof MUMPS (net)",
         "max rel. diff.", "load")
    print("|" + "---|" * 16)
    for row in a["rows"]:
        k, m = row["runs"]["KLU2"], row["runs"]["MUMPS"]
        kb = ["%s (%s)" % tuple(f(x) for x in kb_per_dof(runs, a["tiny"][s])) for runs, s in ((k, "KLU2"), (m, "MUMPS"))]
        line(row["N"], k[0].get("dofs"), len(k), f(med(k, "fact"), ".3f"), f(med(m, "fact"), ".3f"), f(pair_ratio(row)),
             f(med(k, "total")), f(med(m, "total")), f(med(k, "entries"), ".3g"), f(med(m, "entries"), ".3g"),
             f(med(k, "mib"), ".0f"), f(med(m, "mib"), ".0f"), *kb, f(max_diff(k[0], m[0]), ".1e"), loads(k + m))
    print("tiny runs (N = 2): " + ", ".join(f"{s} {f(r.get('mib'), '.0f')} MiB" for s, r in a["tiny"].items()))


def table_b(b):
    print("\n(b) MUMPS (ND): ranks × OpenBLAS threads; medians; rel. diff. of the responses vs np1 T1")
    line("N", "dofs", "config", "reps", "fact s", "total s", "peak RSS MiB (max rank)", "max rel. diff.", "load")
    print("|" + "---|" * 9)
    for row in b["rows"]:
        ref = row["runs"]["np1 T1"][0]
        for label, runs in row["runs"].items():
            line(row["N"], runs[0].get("dofs"), label, len(runs), f(med(runs, "fact"), ".3f"), f(med(runs, "total")),
                 f(med(runs, "mib"), ".0f"), f(max_diff(ref, runs[0]), ".1e") if runs[0] is not ref else "-", loads(runs))


def table_c(c):
    for res in c.values():
        print(f"\n(c) {res['case']}: medians over the repeats; ram force '{res['force']}', rel. diff. vs the first column")
        line("h", "hc", "dofs", "column", "exit", "reps", "newton", "fact #", "contact changes", "restarts", "asm s",
             "fact s", "linsolve s", "total s", "peak RSS MiB", "ram force", "rel. diff.", "load")
        print("|" + "---|" * 18)
        for row in res["rows"]:
            ref = None
            for label, col in row["cols"].items():
                if "skipped" in col:
                    line(row["h"], row["hc"], row["dofs_geo"] or "-", label, "skipped: " + col["skipped"], *[""] * 13)
                    continue
                runs = col["runs"]
                r0 = runs[0]
                ref = ref or r0
                line(row["h"], row["hc"], r0.get("dofs") or row["dofs_geo"], label, ",".join(str(r["status"]) for r in runs),
                     len(runs), r0.get("newton_iterations"), (r0.get("linear_solver") or {}).get("factorizations"),
                     r0.get("contact_changes"), (r0.get("solves") or {}).get("restarts", "-"), f(med(runs, "asm")),
                     f(med(runs, "fact")), f(med(runs, "linsolve")), f(med(runs, "total")), f(med(runs, "mib"), ".0f"),
                     f((r0.get("functionals") or {}).get(res["force"]), ".6f"),
                     f(max_diff(ref, r0), ".1e") if r0 is not ref else "-", loads(runs))


def targets(a, b):
    """The issue's targets, measured."""
    print("\nTargets:")
    for row in (a or {}).get("rows", []):
        m = row["runs"]["MUMPS"]
        dofs, ratio = m[0].get("dofs") or 0, pair_ratio(row)
        if dofs >= 9e4 and ratio:
            print(f"  {dofs} dofs: KLU2/MUMPS factorization {ratio:.2f} (≥ 3: {'met' if ratio >= 3 else 'missed'})")
        if dofs >= 9e5:
            tot, (kb, net) = med(m, "total"), kb_per_dof(m, a["tiny"]["MUMPS"])
            print(f"  {dofs} dofs MUMPS: total {f(tot)} s (< 30 s: {'met' if tot and tot < 30 else 'missed'}); "
                  f"{f(kb)} KB/dof, net {f(net)} (< 2: {'met' if kb and kb < 2 else 'missed'} total, "
                  f"{'met' if net and net < 2 else 'missed'} net)")
    for row in (b or {}).get("rows", []):
        one, two = med(row["runs"]["np1 T1"], "fact"), med(row["runs"]["np2 T1"], "fact")
        if one and two:
            print(f"  N={row['N']}: factorization np2 {two:.2f} s vs np1 {one:.2f} s (T1): "
                  f"{'faster' if two < one else 'not faster'} (np1/np2 {one / two:.2f})")


def report(data):
    for info in data.get("infos") or [data.get("info", {})]:
        print(f"flowform solver benchmark: {json.dumps(info, ensure_ascii=False)}")
    for part, table in (("a", table_a), ("b", table_b), ("c", table_c)):
        if data.get(part):
            table(data[part])
    targets(data.get("a"), data.get("b"))


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0], epilog=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("flowform", nargs="?", default=default_flowform())
    p.add_argument("--parts", default="a,b,c")
    p.add_argument("--sizes", default="40,128,230,408", help="(a): channel N")
    p.add_argument("--mpi-sizes", default="230,408", help="(b): channel N")
    p.add_argument("--repeats", type=int, default=3)
    p.add_argument("--repeat-below", type=float, default=120, help="repeat runs shorter than this (s)")
    p.add_argument("--cases", default="plane,axisym")
    p.add_argument("--meshes", default="0.1:0.025,0.1:0.005,0.05:0.002,0.025:0.001", help="(c): h:hc,...")
    p.add_argument("--types", default="KLU2,MUMPS", help="(c): Solver/Linear Solver/Type values")
    p.add_argument("--set", action="append", default=[], metavar="P=V", help="(c): override for every run")
    p.add_argument("--variant", action="append", default=[], metavar="NAME=P=V", help="(c): a column's override")
    p.add_argument("--max-run-seconds", type=float, default=300, help="(c): skip meshes projected longer")
    p.add_argument("--growth", type=float, default=2.5, help="(c): projected time ∝ dofs^growth")
    p.add_argument("--timeout", type=float, default=1800, help="kill a run after this (s)")
    p.add_argument("--wait-load", type=float, default=1.5, help="wait while the load is higher")
    p.add_argument("--wait-max", type=float, default=900, help="wait at most this long (s)")
    p.add_argument("--out", default="/tmp/solver_bench", help="run directories and logs (kept)")
    p.add_argument("--json", help="results (default OUT/solver_bench.json)")
    p.add_argument("--binary-commit", default="", help="the binary's commit (recorded)")
    p.add_argument("--report", nargs="+", metavar="JSON", help="print earlier runs' tables (parts merged)")
    args = p.parse_args()
    if args.report:
        data = {"infos": []}
        for path in args.report:
            with open(path) as fh:
                d = json.load(fh)
            data["infos"].append(d.pop("info"))
            data.update(d)
        report(data)
        return 0
    args.flowform = require_tools(args.flowform, "solver_bench.py")
    args.sizes, args.mpi_sizes = ([int(x) for x in v.split(",") if x] for v in (args.sizes, args.mpi_sizes))
    args.types, args.cases = ([x.strip() for x in v.split(",") if x.strip()] for v in (args.types, args.cases))
    args.meshes = [tuple(float(x) for x in m.split(":")) for m in args.meshes.split(",") if m]
    parts = set(args.parts.split(","))
    os.makedirs(args.out, exist_ok=True)
    info = machine_info()
    info.update({"flowform": args.flowform, "binary_built": binary_built(args.flowform, seconds=True),
                 "binary_commit": args.binary_commit, "OPENBLAS_NUM_THREADS": os.environ.get("OPENBLAS_NUM_THREADS", "unset"),
                 "blas": os.path.realpath("/usr/lib/x86_64-linux-gnu/libblas.so.3"), "argv": sys.argv[1:]})
    print("flowform solver benchmark")
    for k, v in info.items():
        print(f"  {k}: {v}")
    data = {"info": info}
    json_path = args.json or os.path.join(args.out, "solver_bench.json")
    for part, fn in (("a", part_a), ("b", part_b), ("c", part_c)):
        if part in parts:
            data[part] = fn(args, args.out)
            info["finished"] = time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())
            with open(json_path, "w") as fh:  # after each part: a later failure keeps the earlier ones
                json.dump(data, fh, indent=1)
    report(data)
    print(f"\nresults: {json_path}")
    return 0 if all(x == 0 for x in STATUSES) else 1


if __name__ == "__main__":
    sys.exit(main())
