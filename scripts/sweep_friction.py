#!/usr/bin/python3
"""Friction sweep of the extrusion scene (SPEC §6.2, docs/extrusion.md).

Runs flowform once per friction coefficient ν, setting
"Boundary Conditions/<wall>/Friction Coefficient" = ν on every contact wall (container,
die_face, die_land), each run into OUT/nu_<ν>/. Collects from each summary.json the
functionals (ram_force, ram_pressure, dead_zone, and any other the case defines), the
converged flag, Newton iterations, contact changes and timings into OUT/sweep.csv, and
prints a table. A run that does not converge (exit 3) is kept and flagged (converged = 0);
a run that fails otherwise (bad input, crash) is listed with its exit status and no values.

One extra column, ram_force_p = ∫_ram p ds (× 2πr when axisymmetric), is computed here from
boundary_ram.csv: on the ram the prescribed velocity is uniform, so D_nn = 0 there and the
normal stress is −p; it is an independent check of the solver's ram_force (it agrees up to
the discretization error of the boundary pressure).

usage:
  scripts/sweep_friction.py [--flowform build/flowform] [--case xml/extrusion.xml]
                            [--nu 0,0.05,0.1,0.2,0.3,0.5] [--out out/sweep]
                            [--set P=V ...] [--walls container,die_face,die_land]
                            [--param PATH ...] [--jobs N] [--timeout S] [--quiet]

  --nu       comma-separated values, or START:STOP:STEP (STOP included)
  --set      passed on to every run (e.g. --set "Mesh/Geo Parameters/h=0.05")
  --walls    the contact-wall groups whose Friction Coefficient is swept
  --param    sweep these parameter paths instead of the walls' Friction Coefficient (for
             other sweeps, e.g. --param "Material/Rate Exponent"; repeatable); the value
             column is still called "nu"
  --jobs     runs at a time (default 1)
  --timeout  seconds after which a run is killed and listed as failed (exit_status -9);
             default none

Exit status: 0 when every run converged, 3 when some did not converge, 2 when some run
failed (bad input or crash) or nothing ran.
Needs only the Python standard library (Debian's /usr/bin/python3).
"""
import argparse
import concurrent.futures
import csv
import json
import math
import os
import subprocess
import sys
import time

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
WALLS = ("container", "die_face", "die_land")
FIRST_FUNCTIONALS = ("ram_force", "ram_pressure", "dead_zone")


def parse_values(text):
    """'0,0.05,0.1' or '0:0.5:0.1' -> list of floats."""
    text = text.strip()
    if ":" in text:
        parts = [float(p) for p in text.split(":")]
        if len(parts) != 3 or parts[2] <= 0 or parts[1] < parts[0]:
            raise argparse.ArgumentTypeError("expected START:STOP:STEP with STEP > 0")
        start, stop, step = parts
        count = int(math.floor((stop - start) / step + 1e-9)) + 1
        return [round(start + k * step, 12) for k in range(count)]
    try:
        values = [float(v) for v in text.split(",") if v.strip()]
    except ValueError as e:
        raise argparse.ArgumentTypeError(str(e))
    if not values:
        raise argparse.ArgumentTypeError("no values")
    return values


def resolve(path):
    """A path as given if it exists (relative to the current directory), else relative to
    the repository."""
    if os.path.isabs(path) or os.path.exists(path):
        return os.path.abspath(path)
    alt = os.path.join(REPO, path)
    return alt if os.path.exists(alt) else os.path.abspath(path)


def label(value):
    return "nu_%s" % format(value, "g")


def ram_force_from_pressure(run_dir, axisymmetric):
    """∫_ram p ds (plane strain, per unit depth) or ∫_ram p 2πr ds (axisymmetric), by the
    trapezoidal rule on boundary_ram.csv; None when the file is missing."""
    path = os.path.join(run_dir, "boundary_ram.csv")
    if not os.path.exists(path):
        return None
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if len(rows) < 2:
        return None
    total = 0.0
    for a, b in zip(rows[:-1], rows[1:]):
        ds = float(b["s"]) - float(a["s"])
        fa, fb = float(a["p"]), float(b["p"])
        if axisymmetric:
            fa *= 2 * math.pi * float(a["x"])
            fb *= 2 * math.pi * float(b["x"])
        total += 0.5 * ds * (fa + fb)
    return total


def run_one(args, value):
    run_dir = os.path.join(args.out, label(value))
    os.makedirs(run_dir, exist_ok=True)
    cmd = [args.flowform, args.case, "-o", run_dir]
    for path in args.param:
        cmd += ["--set", "%s=%r" % (path, value)]
    for s in args.set:
        cmd += ["--set", s]
    # flowform's own log goes next to its results (flowform writes nothing else there on
    # bad input, so the log is the only file then).
    log_path = os.path.join(run_dir, "flowform.log")
    start = time.monotonic()
    with open(log_path, "w") as log:
        log.write("$ " + " ".join(repr(c) if " " in c else c for c in cmd) + "\n")
        log.flush()
        try:
            proc = subprocess.run(cmd, stdout=log, stderr=subprocess.STDOUT,
                                  timeout=args.timeout or None)
            returncode = proc.returncode
        except subprocess.TimeoutExpired:  # subprocess.run kills the child
            log.write("\nflowform: killed by sweep_friction.py after --timeout %g s\n"
                      % args.timeout)
            returncode = -9
    wall = time.monotonic() - start

    row = {"nu": value, "exit_status": returncode, "wall_seconds": round(wall, 3),
           "dir": os.path.relpath(run_dir, args.out)}
    summary_path = os.path.join(run_dir, "summary.json")
    functionals = {}
    if returncode in (0, 3) and os.path.exists(summary_path):
        with open(summary_path) as f:
            summary = json.load(f)
        row["converged"] = int(bool(summary.get("converged")))
        row["newton_iterations"] = summary.get("newton_iterations")
        row["contact_changes"] = summary.get("contact_changes")
        row["dofs"] = summary.get("dofs")
        timings = summary.get("timings", {})
        for key in ("total", "assembly", "factorization", "linear_solve"):
            if key in timings:
                row["time_" + key] = round(timings[key], 4)
        functionals = summary.get("functionals", {}) or {}
        geometry = (summary.get("parameters", {}).get("Problem", {}) or {}).get("Geometry", "")
        row["ram_force_p"] = ram_force_from_pressure(run_dir, geometry == "Axisymmetric")
    else:
        row["converged"] = 0
        with open(log_path) as f:
            lines = [l.strip() for l in f.read().splitlines()[1:] if l.strip()]
        # flowform's messages start with "flowform:"; the last such line says what went wrong
        said = [l for l in lines if l.startswith("flowform:")] or lines or ["no output"]
        row["message"] = said[-1][:300]
    return row, functionals


def fmt(v):
    if v is None or v == "":
        return "-"
    if isinstance(v, float):
        return "%.6g" % v
    return str(v)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog=__doc__.split("\n", 1)[1])
    ap.add_argument("--flowform", default="build/flowform")
    ap.add_argument("--case", default="xml/extrusion.xml")
    ap.add_argument("--nu", type=parse_values, default=[0, 0.05, 0.1, 0.2, 0.3, 0.5])
    ap.add_argument("--out", default="out/sweep")
    ap.add_argument("--set", action="append", default=[], metavar="P=V")
    ap.add_argument("--walls", default=",".join(WALLS))
    ap.add_argument("--param", action="append", default=None, metavar="PATH")
    ap.add_argument("--jobs", type=int, default=1)
    ap.add_argument("--timeout", type=float, default=0)
    ap.add_argument("--quiet", action="store_true")
    args = ap.parse_args()

    case_given = args.case
    args.flowform = resolve(args.flowform)
    args.case = resolve(args.case)
    args.out = os.path.abspath(args.out)
    if not os.access(args.flowform, os.X_OK):
        sys.exit("sweep_friction: no flowform executable at %s (build it, or give --flowform)"
                 % args.flowform)
    if not os.path.exists(args.case):
        sys.exit("sweep_friction: no case file %s" % args.case)
    if args.param is None:
        args.param = ["Boundary Conditions/%s/Friction Coefficient" % w
                      for w in args.walls.split(",") if w]
    os.makedirs(args.out, exist_ok=True)

    if not args.quiet:
        print("sweep of %s over %s: %s" % (case_given, ", ".join(args.param),
                                             ", ".join(format(v, "g") for v in args.nu)))
    results = {}
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        futures = {pool.submit(run_one, args, v): v for v in args.nu}
        for fut in concurrent.futures.as_completed(futures):
            v = futures[fut]
            results[v] = fut.result()
            row = results[v][0]
            if not args.quiet:
                state = {0: "converged", 3: "NOT converged"}.get(row["exit_status"],
                                                                 "FAILED (exit %d)" % row["exit_status"])
                print("  nu = %-6g %s in %.1f s%s" % (v, state, row["wall_seconds"],
                      (": " + row["message"]) if "message" in row else ""), flush=True)

    names = list(FIRST_FUNCTIONALS)
    for _, functionals in results.values():
        for k in functionals:
            if k not in names:
                names.append(k)
    columns = (["nu", "converged", "exit_status"] + names + ["ram_force_p", "newton_iterations",
               "contact_changes", "dofs", "time_total", "time_assembly", "time_factorization",
               "time_linear_solve", "wall_seconds", "dir", "message"])
    rows = []
    for v in args.nu:
        row, functionals = results[v]
        row = dict(row)
        for k in names:
            row[k] = functionals.get(k)
        rows.append(row)
    csv_path = os.path.join(args.out, "sweep.csv")
    with open(csv_path + ".tmp", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=columns, extrasaction="ignore")
        w.writeheader()
        for row in rows:
            w.writerow({k: ("" if row.get(k) is None else
                            (repr(row[k]) if isinstance(row[k], float) else row[k]))
                        for k in columns})
    os.replace(csv_path + ".tmp", csv_path)

    shown = ["nu", "converged", "exit_status"] + names + ["ram_force_p", "newton_iterations",
                                           "contact_changes", "time_total"]
    table = [[fmt(row.get(k)) for k in shown] for row in rows]
    widths = [max(len(h), *(len(r[i]) for r in table)) for i, h in enumerate(shown)]
    print("  ".join(h.rjust(w) for h, w in zip(shown, widths)))
    for r in table:
        print("  ".join(c.rjust(w) for c, w in zip(r, widths)))
    print("table: %s" % csv_path)

    if any(r["exit_status"] not in (0, 3) for r in rows):
        return 2
    return 3 if any(r["exit_status"] == 3 for r in rows) else 0


if __name__ == "__main__":
    sys.exit(main())
