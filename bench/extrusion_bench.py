"""Cost and work–precision benchmark of flowform on the extrusion scene (issue #3).

Runs the flowform binary on xml/extrusion.xml (plane strain) and xml/extrusion_axisym.xml
over a mesh sequence (Mesh/Geo Parameters/h, and hc = h/4 at the die corners), each run
under /usr/bin/time -v with its log kept, and prints per case:

  * cost: dofs, ram force, total wall time and its split (summary.json "timings"), Newton
    iterations, flow solves (the continuation solve + one re-solve per contact status
    change), Newton iterations per solve, factorizations, contact changes, peak RSS;
  * work–precision: |F(h) − F_R| / F_R against the run time, F_R the Richardson
    extrapolation of the ram force from the three finest meshes (observed order p from the
    same three);
  * mass leak: 1 − Q_out / Q_in, Q = ∫ u_n ds over boundary_outlet.csv / boundary_ram.csv
    (trapezoid rule in s; × 2πr, r = x, when axisymmetric), and the flux through the
    die_face wall, which carries the leak: the die-lip node (0, exit), a 270° re-entrant
    corner of the material, moves with the exit flow, so ≈ u_lip · hc / 2 per unit length
    (≈ 0.97 hc of the throughput in plane strain) crosses the first die-face segment.

usage:
  scripts/python bench/extrusion_bench.py [FLOWFORM] [--cases plane,axisym] [--meshes 0.2,0.1,0.05,0.025]
                           [--repeats 3] [--repeat-below S] [--max-run-seconds S]
                           [--timeout S] [--out DIR] [--json OUT.json]
  scripts/python bench/extrusion_bench.py --report OUT.json [OUT.json ...]

  FLOWFORM              the flowform executable (default: build/flowform of this repository)
  --meshes              bulk mesh sizes h (hc = h/4); the Richardson extrapolation uses
                        the three finest and needs a constant ratio between them
  --repeats N           runs per (case, h) (default 3); the times are the medians
  --repeat-below S      repeat only while a run takes less than S seconds (default 120):
                        the finest meshes run once
  --max-run-seconds S   in each case, skip the finer meshes once a run took longer (default
                        3600)
  --out DIR             run directories (kept), DIR/<case>_h<h>_r<k>/ with flowform.log
                        (default /tmp/extrusion_bench)
  --json OUT.json       every row, the extrapolation and the machine (default
                        OUT/extrusion_bench.json)
  --report OUT.json ... run nothing: print the tables of earlier --json files again, the
                        repeats of the same case and h in several files merged (medians over all)

The wall, tool and outlet names come from each case file (python/flowform_tools/case.py);
runs go through python/flowform_tools (launcher). Every number is read from summary.json and
the boundary CSVs (the Newton iterations of each flow solve and the restarts: summary.json
"solves"). Needs Debian's /usr/bin/python3 (numpy) and /usr/bin/time
(package time). Exit status 0 when every run converged (exit 0), 1 otherwise.
"""
import argparse
import json
import os
import statistics
import sys

import numpy as np

from flowform_tools import csvio, default_flowform, launcher, repo_path
from flowform_tools.benchmark import require_tools
from flowform_tools.case import FIXED_MESH, Case
from flowform_tools.launcher import lit
from flowform_tools.machine import binary_built, load, machine_info
from flowform_tools.numerics import median, observed_order, richardson

from extrusion_tables import fmt, print_case

CASES = {  # name: (case file, axisymmetric)
    "plane": ("xml/extrusion.xml", False),
    "axisym": ("xml/extrusion_axisym.xml", True),
}
DEFAULT_MESHES = "0.2,0.1,0.05,0.025"
TIMING_KEYS = ("setup", "assembly_residual", "assembly_jacobian", "factorization", "linear_solve",
               "solve", "output", "total")


# ------------------------------------------------------------------------------------------
# One run


def run_flowform(flowform, case, outdir, h, timeout):
    """Runs flowform (log kept in outdir/flowform.log); returns status, wall, peak RSS, summary."""
    os.makedirs(outdir, exist_ok=True)
    log_path = os.path.join(outdir, "flowform.log")
    # the binary's time stamp at the start: a rebuild during the benchmark shows up here
    built = binary_built(flowform, seconds=True)
    before = load()
    r = launcher.run(flowform, case, outdir, FIXED_MESH +
                     [f"Mesh/Geo Parameters/h={lit(h)}", f"Mesh/Geo Parameters/hc={lit(h / 4)}"],
                     log=log_path, timeout=timeout, peak_memory=True)
    return {"status": "timeout" if r.timed_out else r.status, "wall": r.wall, "rss": r.peak_rss,
            "binary_built": built, "command": r.command, "dir": outdir, "load": (before, load()),
            "log_tail": r.log_tail(20), "summary": r.summary, "solves": solves_of(r.summary)}


def solves_of(summary):
    """Newton iterations of each flow solve (the first, then one re-solve per contact status
    change) and the re-solves that restarted from the predictor, from summary.json "solves"."""
    solves = (summary or {}).get("solves", {})
    return {"newton_per_solve": solves.get("newton_iterations", []), "restarts": solves.get("restarts", 0)}


# ------------------------------------------------------------------------------------------
# Fluxes from the boundary CSVs


def mass_balance(outdir, case_file, axisymmetric, h):
    """Fluxes over the tool boundary (in), the outlet (the Traction group) and each wall, over
    Q_in; the leak 1 − Q_out/Q_in; u_n at the die lip (the end shared by the last two walls in
    flow order, die_face and die_land), on the wall before the lip (lip_wall)."""
    scene = Case(case_file)
    walls, tool, outlet = scene.contact_walls(), scene.tool_boundary(), scene.groups("Traction")[0]
    q_in = -csvio.flux(outdir, tool, axisymmetric)
    q_out = csvio.flux(outdir, outlet, axisymmetric)
    flux = {w: csvio.flux(outdir, w, axisymmetric) / q_in for w in walls}
    leak = 1.0 - q_out / q_in
    lip_wall, land = walls[-2], walls[-1]
    lip = csvio.shared_points(outdir, lip_wall, land)
    face = csvio.rows(outdir, lip_wall, sort=True)
    lip_u_n = [r["u_n"] for r in face if lip and (round(r["x"], 9), round(r["y"], 9)) == lip[0]]
    return {"q_in": q_in, "q_out": q_out, "leak": leak, "leak_over_hc": leak / (h / 4),
            "wall_flux": flux, "lip_wall": lip_wall, "lip_u_n": lip_u_n[0] if lip_u_n else None}


# ------------------------------------------------------------------------------------------
# Rows


def row_of(case, h, runs, case_file, axisymmetric):
    """One (case, h) row from its repeats: counts from the first run (checked identical in
    the others), times as medians over the repeats."""
    first = runs[0]
    s = first.get("summary") or {}
    row = {"case": case, "h": h, "hc": h / 4, "status": [r["status"] for r in runs],
           "repeats": len(runs), "converged": s.get("converged"), "dofs": s.get("dofs"),
           "ram_force": (s.get("functionals") or {}).get("ram_force"),
           "newton": s.get("newton_iterations"), "contact_changes": s.get("contact_changes"),
           "factorizations": (s.get("linear_solver") or {}).get("factorizations"),
           "stages_newton": sum(st.get("newton_iterations", 0) for st in s.get("stages", [])),
           "message": s.get("message"), "dirs": [r["dir"] for r in runs],
           "load_before": [r["load"][0] for r in runs], "load_after": [r["load"][1] for r in runs],
           "binary_built": sorted({r.get("binary_built") for r in runs if r.get("binary_built")})}
    for key in TIMING_KEYS:
        row[key] = median([((r.get("summary") or {}).get("timings") or {}).get(key) for r in runs])
        row[key + "_all"] = [((r.get("summary") or {}).get("timings") or {}).get(key) for r in runs]
    row["fact_share"] = median([r["summary"]["timings"]["factorization"] / r["summary"]["timings"]["total"]
                                for r in runs if r.get("summary")])
    row["rss_all"] = [r.get("rss") for r in runs]
    row["rss"] = median(row["rss_all"])
    same = all((r.get("summary") or {}).get("functionals") == s.get("functionals") and
               (r.get("summary") or {}).get("newton_iterations") == s.get("newton_iterations") for r in runs)
    row["repeats_identical"] = same
    per = first["solves"]["newton_per_solve"]
    row["solves"] = len(per)
    row["restarts"] = first["solves"]["restarts"]
    row["log_newton"] = sum(per)
    row["first_solve_newton"] = per[0] if per else None
    re_ = per[1:]
    row["resolve_newton_mean"] = sum(re_) / len(re_) if re_ else None
    row["resolve_newton_median"] = statistics.median(re_) if re_ else None
    row["resolve_newton_max"] = max(re_) if re_ else None
    row["resolve_newton_total"] = sum(re_)
    if first["status"] in (0, 3) and s:
        try:
            row.update(mass_balance(first["dir"], case_file, axisymmetric, h))
        except (OSError, ValueError, IndexError) as e:
            row["mass_error"] = str(e)
    return row


def merge_rows(a, b):
    """Two rows of the same (case, h) from separate invocations as one row with the repeats
    of both: times are the medians over all of them."""
    m = dict(a)
    for key in ("status", "dirs", "load_before", "load_after"):
        m[key] = a[key] + b[key]
    m["repeats"] = a["repeats"] + b["repeats"]
    m["binary_built"] = sorted(set(a.get("binary_built", [])) | set(b.get("binary_built", [])))
    for key in TIMING_KEYS:
        m[key + "_all"] = a[key + "_all"] + b[key + "_all"]
        m[key] = median(m[key + "_all"])
    m["fact_share"] = median([f / t for f, t in zip(m["factorization_all"], m["total_all"]) if f and t])
    m["rss_all"] = a.get("rss_all", [a["rss"]]) + b.get("rss_all", [b["rss"]])
    m["rss"] = median(m["rss_all"])
    m["repeats_identical"] = (a["repeats_identical"] and b["repeats_identical"] and
                              all(a[k] == b[k] for k in ("ram_force", "newton", "contact_changes", "solves")))
    return m


def work_precision(rows):
    """Observed order and Richardson value from the three finest converged meshes."""
    ok = [r for r in rows if r["converged"] and r["ram_force"] is not None]
    info = {"meshes": [r["h"] for r in ok]}
    if len(ok) < 3:
        info["error"] = f"only {len(ok)} converged mesh(es): no Richardson extrapolation"
        return info
    fine = ok[-3:]
    ratios = [fine[0]["h"] / fine[1]["h"], fine[1]["h"] / fine[2]["h"]]
    if abs(ratios[0] - ratios[1]) > 1e-9 * ratios[0]:
        info["error"] = f"the three finest meshes have ratios {ratios}: no constant refinement ratio"
        return info
    F = [r["ram_force"] for r in fine]
    d = np.diff(F)
    p = observed_order(F, ratios[0])[-1]
    info.update(h=[r["h"] for r in fine], F=F, differences=d.tolist(), order=p,
                monotone=bool(d[0] * d[1] > 0), ratio=ratios[0])
    if not d[0] * d[1] > 0 or p <= 0:
        info["error"] = f"differences {d[0]:+.4g}, {d[1]:+.4g}: not monotone and contracting"
        return info
    info["F_R"] = richardson(F, p, ratios[0])
    # every triple of consecutive meshes with the same ratio, coarsest first: how settled F_R is
    info["triples"] = []
    for j in range(len(ok) - 2):
        hs, Fj = [r["h"] for r in ok[j:j + 3]], [r["ram_force"] for r in ok[j:j + 3]]
        q = hs[0] / hs[1]
        dj = np.diff(Fj)
        if abs(hs[1] / hs[2] - q) < 1e-9 * q and dj[0] * dj[1] > 0 and abs(dj[1]) < abs(dj[0]):
            pj = observed_order(Fj, q)[-1]
            info["triples"].append({"h": hs, "order": pj, "F_R": richardson(Fj, pj, q)})
    for r in rows:
        if r["ram_force"] is not None:
            r["error_richardson"] = abs(r["ram_force"] - info["F_R"]) / abs(info["F_R"])
    return info


# ------------------------------------------------------------------------------------------


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    p.add_argument("flowform", nargs="?", default=default_flowform())
    p.add_argument("--cases", default="plane,axisym")
    p.add_argument("--meshes", default=DEFAULT_MESHES)
    p.add_argument("--repeats", type=int, default=3)
    p.add_argument("--repeat-below", type=float, default=120)
    p.add_argument("--max-run-seconds", type=float, default=3600)
    p.add_argument("--timeout", type=float, default=5400, help="kill a run after this (s)")
    p.add_argument("--out", default="/tmp/extrusion_bench")
    p.add_argument("--json", help="default OUT/extrusion_bench.json")
    p.add_argument("--report", metavar="JSON", nargs="+",
                   help="only print the tables of earlier runs' JSON files (the repeats of the same "
                        "case and h merged)")
    args = p.parse_args()

    if args.report:
        merged = {}
        for path in args.report:
            with open(path) as f:
                results = json.load(f)
            print(f"{path}:")
            for k, v in results["machine"].items():
                print(f"  {k}: {v}")
            for case, entry in results["cases"].items():
                target = merged.setdefault(case, {"case": entry["case"], "rows": {}})
                for r in entry["rows"]:
                    key = r["h"]
                    target["rows"][key] = merge_rows(target["rows"][key], r) if key in target["rows"] else r
        for case, entry in merged.items():
            entry["rows"] = [entry["rows"][h] for h in sorted(entry["rows"], reverse=True)]
            for r in entry["rows"]:
                if not r["repeats_identical"]:
                    print(f"note: {case} h={r['h']:g}: the repeats differ in F, Newton iterations or solves")
            entry["richardson"] = work_precision(entry["rows"])
            print_case(case, entry, CASES[case][1])
        return 0

    flowform = require_tools(args.flowform, "extrusion_bench.py")
    cases = [c.strip() for c in args.cases.split(",") if c.strip()]
    for c in cases:
        if c not in CASES:
            sys.exit(f"extrusion_bench.py: unknown case '{c}' ({', '.join(CASES)})")
    meshes = sorted((float(h) for h in args.meshes.split(",")), reverse=True)

    info = machine_info()
    info["binary_built"] = binary_built(flowform)
    print("flowform extrusion benchmark")
    print(f"  binary:  {flowform} (built {info['binary_built']}; the commit below is the work tree's now)")
    for k in ("date", "commit", "Model name", "CPU(s)", "memory"):
        if k in info:
            print(f"  {k}: {info[k]}")
    print(f"  meshes h = {', '.join(f'{h:g}' for h in meshes)}, hc = h/4; up to {args.repeats} repeats "
          f"while a run takes < {args.repeat_below:g} s; times in seconds from summary.json timings "
          f"(medians over the repeats); load = 1-minute load average before/after each run", flush=True)

    os.makedirs(args.out, exist_ok=True)
    results = {"machine": info, "cases": {}}
    failed = False
    for case in cases:
        case_file, axisymmetric = CASES[case]
        case_path = repo_path(case_file)
        rows, skip = [], False
        for h in meshes:
            if skip:
                print(f"  skip {case} h={h:g}: the previous run took over {args.max_run_seconds:g} s", flush=True)
                continue
            runs = []
            for k in range(args.repeats):
                outdir = os.path.join(args.out, f"{case}_h{h:g}_r{k}")
                r = run_flowform(flowform, case_path, outdir, h, args.timeout)
                runs.append(r)
                s = r.get("summary") or {}
                t = (s.get("timings") or {}).get("total")
                print(f"  {case} h={h:g} run {k}: exit {r['status']}, {s.get('dofs')} dofs, "
                      f"F = {fmt((s.get('functionals') or {}).get('ram_force'), '{:.6f}')}, "
                      f"Newton {s.get('newton_iterations')}, changes {s.get('contact_changes')}, "
                      f"total {fmt(t, '{:.2f}')} s (wall {r['wall']:.1f} s), "
                      f"load {r['load'][0]:.2f}/{r['load'][1]:.2f}", flush=True)
                if r["status"] != 0:
                    failed = True
                    print("    " + (s.get("message") or r["log_tail"].strip()[-1500:]).replace("\n", "\n    "))
                if r["status"] not in (0, 3) or r["wall"] > args.repeat_below:
                    break
            row = row_of(case, h, runs, case_path, axisymmetric)
            if row["newton"] is not None and row["log_newton"] != row["newton"]:
                print(f"    note: the log has {row['log_newton']} Newton lines, summary.json {row['newton']}")
            if not row["repeats_identical"]:
                print("    note: the repeats differ in the functionals or Newton iterations")
            rows.append(row)
            if runs[-1]["status"] == "timeout" or runs[-1]["wall"] > args.max_run_seconds:
                skip = True
        results["cases"][case] = {"case": case_file, "axisymmetric": axisymmetric, "rows": rows,
                                  "richardson": work_precision(rows)}
        print_case(case, results["cases"][case], axisymmetric)

    path = args.json or os.path.join(args.out, "extrusion_bench.json")
    with open(path, "w") as f:
        json.dump(results, f, indent=1, default=str)
    print(f"\nresults: {path}; runs in {args.out}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
