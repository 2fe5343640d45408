#!/usr/bin/python3
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
  bench/extrusion_bench.py [FLOWFORM] [--cases plane,axisym] [--meshes 0.2,0.1,0.05,0.025]
                           [--repeats 3] [--repeat-below S] [--max-run-seconds S]
                           [--timeout S] [--out DIR] [--json OUT.json]
  bench/extrusion_bench.py --report OUT.json [OUT.json ...]

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

Needs Debian's /usr/bin/python3 (numpy; h5py through tests/regression/extrusion_checks.py,
whose lit(), observed_order() and richardson() are used) and /usr/bin/time (package time).
Exit status 0 when every run converged (exit 0), 1 otherwise.
"""
import argparse
import datetime
import json
import math
import os
import re
import statistics
import subprocess
import sys
import time

import numpy as np

from channel_bench import REPO, TIME, machine_info, parse_time_v, require_tools

sys.path.insert(0, os.path.join(REPO, "tests", "regression"))
from extrusion_checks import lit, observed_order, richardson  # noqa: E402

CASES = {  # name: (case file, axisymmetric)
    "plane": ("xml/extrusion.xml", False),
    "axisym": ("xml/extrusion_axisym.xml", True),
}
DEFAULT_MESHES = "0.2,0.1,0.05,0.025"
WALLS = ("container", "die_face", "die_land")
TIMING_KEYS = ("setup", "assembly_residual", "assembly_jacobian", "factorization", "linear_solve",
               "solve", "output", "total")


# ------------------------------------------------------------------------------------------
# One run


def run_flowform(flowform, case, outdir, h, timeout):
    """Runs flowform (log kept in outdir/flowform.log); returns status, wall, peak RSS, summary."""
    os.makedirs(outdir, exist_ok=True)
    command = [TIME, "-v", flowform, case, "-o", outdir,
               "--set", f"Mesh/Geo Parameters/h={lit(h)}", "--set", f"Mesh/Geo Parameters/hc={lit(h / 4)}"]
    log_path = os.path.join(outdir, "flowform.log")
    built = datetime.datetime.fromtimestamp(os.path.getmtime(flowform), datetime.timezone.utc)
    start = time.monotonic()
    with open(log_path, "w") as log:
        try:
            proc = subprocess.run(command, stdout=log, stderr=subprocess.PIPE, text=True, timeout=timeout)
            status, err = proc.returncode, proc.stderr
        except subprocess.TimeoutExpired:
            status, err = "timeout", ""
    # the binary's time stamp at the start: a rebuild during the benchmark shows up here
    result = {"status": status, "wall": time.monotonic() - start, "rss": parse_time_v(err)[0],
              "binary_built": built.strftime("%Y-%m-%d %H:%M:%S UTC"),
              "command": command[2:], "dir": outdir,
              "stderr": "\n".join(l for l in err.splitlines() if not l.startswith("\t"))}
    try:
        with open(os.path.join(outdir, "summary.json")) as f:
            result["summary"] = json.load(f)
    except (OSError, ValueError):
        result["summary"] = None
    result["solves"] = parse_solves(log_path)
    return result


NEWTON_LINE = re.compile(r"^\s+newton\s+\d+\s")


def parse_solves(log_path):
    """Newton iterations of each flow solve, from the log: the first solve (predictor and
    continuation stages) and one re-solve after each "contact: wall ..." status change.
    Also the number of re-solves that failed and restarted from the predictor."""
    solves, restarts = [], 0
    try:
        with open(log_path) as f:
            for line in f:
                if line.startswith("flowform:") and "dofs" in line and not solves:
                    solves.append(0)
                elif line.startswith("contact: wall "):
                    solves.append(0)
                elif NEWTON_LINE.match(line) and solves:
                    solves[-1] += 1
                elif "re-solve failed" in line:
                    restarts += 1
    except OSError:
        pass
    return {"newton_per_solve": solves, "restarts": restarts}


# ------------------------------------------------------------------------------------------
# Fluxes from the boundary CSVs


def read_curve(outdir, group):
    data = np.genfromtxt(os.path.join(outdir, f"boundary_{group}.csv"), delimiter=",", names=True)
    return data[np.argsort(data["s"])]


def flux(outdir, group, axisymmetric):
    """∫ u_n ds (× 2πr, r = x, when axisymmetric) over the group, trapezoid rule in s."""
    c = read_curve(outdir, group)
    weight = 2 * math.pi * c["x"] if axisymmetric else 1.0
    return float(np.trapz(c["u_n"] * weight, c["s"]))


def mass_balance(outdir, axisymmetric, h):
    q_in = -flux(outdir, "ram", axisymmetric)
    q_out = flux(outdir, "outlet", axisymmetric)
    walls = {w: flux(outdir, w, axisymmetric) / q_in for w in WALLS}
    leak = 1.0 - q_out / q_in
    # the die-lip node: the die_face end shared with die_land
    face = read_curve(outdir, "die_face")
    land = read_curve(outdir, "die_land")
    land_xy = {(round(x, 9), round(y, 9)) for x, y in zip(land["x"], land["y"])}
    lip = [i for i, (x, y) in enumerate(zip(face["x"], face["y"])) if (round(x, 9), round(y, 9)) in land_xy]
    return {"q_in": q_in, "q_out": q_out, "leak": leak, "leak_over_hc": leak / (h / 4),
            "wall_flux": walls, "lip_u_n": float(face["u_n"][lip[0]]) if lip else None}


# ------------------------------------------------------------------------------------------
# Rows


def median(values):
    values = [v for v in values if v is not None]
    return statistics.median(values) if values else None


def row_of(case, h, runs, axisymmetric):
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
            row.update(mass_balance(first["dir"], axisymmetric, h))
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


def fmt(v, form="{:.3g}"):
    if v is None:
        return "-"
    if isinstance(v, str):
        return v
    return form.format(v)


def markdown(header, rows):
    out = "| " + " | ".join(header) + " |\n|" + "|".join("---" for _ in header) + "|\n"
    for r in rows:
        out += "| " + " | ".join(r) + " |\n"
    return out


def count_table(rows):
    header = ["h", "dofs", "exit", "F (ram_force)", "Newton", "Newton 1st solve", "Newton in re-solves",
              "flow solves", "Newton/re-solve mean, median (max)", "factorizations", "contact changes"]
    body = []
    for r in rows:
        body.append([fmt(r["h"], "{:g}"), fmt(r["dofs"], "{}"), ",".join(str(s) for s in r["status"]),
                     fmt(r["ram_force"], "{:.5f}"), fmt(r["newton"], "{}"), fmt(r["first_solve_newton"], "{}"),
                     fmt(r["resolve_newton_total"], "{}"),
                     fmt(r["solves"], "{}") + (f" ({r['restarts']} restarted)" if r["restarts"] else ""),
                     (fmt(r["resolve_newton_mean"], "{:.1f}") + ", " + fmt(r["resolve_newton_median"], "{:g}") +
                      " (" + fmt(r["resolve_newton_max"], "{}") + ")"),
                     fmt(r["factorizations"], "{}"), fmt(r["contact_changes"], "{}")])
    return markdown(header, body)


def time_table(rows):
    header = ["h", "setup", "asm_res", "asm_jac", "fact", "fact/call ms", "linsolve", "other", "total",
              "fact/total", "peak RSS MiB", "total, each repeat"]
    body = []
    for r in rows:
        other = per_call = None
        if r["solve"] is not None:
            other = r["solve"] - (r["assembly_residual"] + r["assembly_jacobian"] + r["factorization"] +
                                  r["linear_solve"])
        if r["factorization"] is not None and r["factorizations"]:
            per_call = 1e3 * r["factorization"] / r["factorizations"]
        body.append([fmt(r["h"], "{:g}"), fmt(r["setup"], "{:.3g}"), fmt(r["assembly_residual"], "{:.3g}"),
                     fmt(r["assembly_jacobian"], "{:.3g}"), fmt(r["factorization"], "{:.4g}"),
                     fmt(per_call, "{:.3g}"), fmt(r["linear_solve"], "{:.3g}"), fmt(other, "{:.3g}"),
                     fmt(r["total"], "{:.4g}"), fmt(r["fact_share"], "{:.0%}"),
                     fmt(r["rss"] / 2**20 if r["rss"] else None, "{:.0f}"),
                     ", ".join(fmt(t, "{:.3g}") for t in r["total_all"])])
    return markdown(header, body)


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


def wp_table(rows):
    header = ["h", "dofs", "F", "error vs F_R", "total s (median)", "repeats", "load before/after"]
    body = [[fmt(r["h"], "{:g}"), fmt(r["dofs"], "{}"), fmt(r["ram_force"], "{:.5f}"),
             fmt(r.get("error_richardson"), "{:.2e}"), fmt(r["total"], "{:.4g}"), str(r["repeats"]),
             ", ".join(f"{a:.1f}/{b:.1f}" for a, b in zip(r["load_before"], r["load_after"]))] for r in rows]
    return markdown(header, body)


def leak_table(rows):
    header = ["h", "hc", "Q_in", "Q_out", "leak 1 − Q_out/Q_in", "leak / hc", "u_n at die lip",
              "die_face flux / Q_in", "die_face flux / (hc Q_in)", "container", "die_land"]
    body = []
    for r in rows:
        if "leak" not in r:
            body.append([fmt(r["h"], "{:g}"), fmt(r["hc"], "{:g}")] + ["-"] * 9)
            continue
        w = r["wall_flux"]
        body.append([fmt(r["h"], "{:g}"), fmt(r["hc"], "{:g}"), fmt(r["q_in"], "{:.5f}"),
                     fmt(r["q_out"], "{:.5f}"), fmt(r["leak"], "{:.4f}"), fmt(r["leak_over_hc"], "{:.3f}"),
                     fmt(r["lip_u_n"], "{:.3f}"), fmt(w["die_face"], "{:.4f}"), fmt(w["die_face"] / r["hc"], "{:.3f}"),
                     fmt(w["container"], "{:.1e}"),
                     fmt(w["die_land"], "{:.1e}")])
    return markdown(header, body)


def print_case(case, entry):
    rows, wp, title = entry["rows"], entry["richardson"], f"{case} ({entry['case']})"
    print(f"\n### cost, {title}: counts\n\n" + count_table(rows))
    print(f"\n### cost, {title}: seconds (medians over the repeats)\n\n" + time_table(rows))
    print(f"\n### work–precision of the ram force, {title}\n")
    if "F_R" in wp:
        print(f"three finest meshes h = {', '.join(f'{h:g}' for h in wp['h'])}: differences "
              f"{wp['differences'][0]:+.5f}, {wp['differences'][1]:+.5f}; observed order p = {wp['order']:.3f}; "
              f"F_R = {wp['F_R']:.5f}")
        for t in wp.get("triples", []):
            print(f"  triple h = {', '.join(f'{h:g}' for h in t['h'])}: p = {t['order']:.3f}, F_R = {t['F_R']:.5f}")
        print()
    else:
        print(f"no extrapolation: {wp.get('error')}\n")
    print(wp_table(rows))
    print(f"\n### mass leak, {title} (Q over ram / outlet / walls, trapezoid in s"
          f"{', × 2πr (r = x)' if entry.get('axisymmetric', CASES[case][1]) else ''})\n\n" + leak_table(rows))
    leaks = [(r["h"], r["leak"]) for r in rows if r.get("leak", 0) > 0]
    orders = [math.log(a[1] / b[1]) / math.log(a[0] / b[0]) for a, b in zip(leaks, leaks[1:])]
    if orders:
        print("observed order of the leak between successive meshes: " + ", ".join(f"{q:.2f}" for q in orders))
    built = sorted({b for r in rows for b in r.get("binary_built", [])})
    if len(built) > 1:
        print(f"note: the binary changed during the runs (time stamps {', '.join(built)})")
    sys.stdout.flush()


# ------------------------------------------------------------------------------------------


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    p.add_argument("flowform", nargs="?", default=os.path.join(REPO, "build", "flowform"))
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
            print_case(case, entry)
        return 0

    flowform = require_tools(args.flowform, "extrusion_bench.py")
    cases = [c.strip() for c in args.cases.split(",") if c.strip()]
    for c in cases:
        if c not in CASES:
            sys.exit(f"extrusion_bench.py: unknown case '{c}' ({', '.join(CASES)})")
    meshes = sorted((float(h) for h in args.meshes.split(",")), reverse=True)

    info = machine_info()
    info["binary_built"] = datetime.datetime.fromtimestamp(os.path.getmtime(flowform), datetime.timezone.utc) \
        .strftime("%Y-%m-%d %H:%M UTC")
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
        case_path = os.path.join(REPO, case_file)
        rows, skip = [], False
        for h in meshes:
            if skip:
                print(f"  skip {case} h={h:g}: the previous run took over {args.max_run_seconds:g} s", flush=True)
                continue
            runs = []
            for k in range(args.repeats):
                outdir = os.path.join(args.out, f"{case}_h{h:g}_r{k}")
                load_before = os.getloadavg()[0]
                r = run_flowform(flowform, case_path, outdir, h, args.timeout)
                r["load"] = (load_before, os.getloadavg()[0])
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
                    print("    " + (s.get("message") or r["stderr"].strip()[-1500:]).replace("\n", "\n    "))
                if r["status"] not in (0, 3) or r["wall"] > args.repeat_below:
                    break
            row = row_of(case, h, runs, axisymmetric)
            if row["newton"] is not None and row["log_newton"] != row["newton"]:
                print(f"    note: the log has {row['log_newton']} Newton lines, summary.json {row['newton']}")
            if not row["repeats_identical"]:
                print("    note: the repeats differ in the functionals or Newton iterations")
            rows.append(row)
            if runs[-1]["status"] == "timeout" or runs[-1]["wall"] > args.max_run_seconds:
                skip = True
        results["cases"][case] = {"case": case_file, "axisymmetric": axisymmetric, "rows": rows,
                                  "richardson": work_precision(rows)}
        print_case(case, results["cases"][case])

    path = args.json or os.path.join(args.out, "extrusion_bench.json")
    with open(path, "w") as f:
        json.dump(results, f, indent=1, default=str)
    print(f"\nresults: {path}; runs in {args.out}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
