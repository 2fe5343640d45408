"""Friction sweep of the extrusion scene (docs/theory.md §6.2, docs/extrusion.md).

Runs flowform once per friction coefficient ν, setting
"Boundary Conditions/<wall>/Friction Coefficient" = ν on every Contact Wall group of the case
(container, die_face, die_land in xml/extrusion.xml), each run into OUT/nu_<ν>/. Collects from
each summary.json the functionals (the case's responses first, in the case's order: ram_force,
ram_pressure, dead_zone; then any other), the converged flag, Newton iterations, contact
changes and timings into OUT/sweep.csv, and prints a table. A run that does not converge (exit 3) is kept and flagged (converged = 0);
a run that fails otherwise (bad input, crash) is listed with its exit status and no values.

One extra column, <force>_p (ram_force_p) = ∫_ram p ds (× 2πr when axisymmetric), is computed
here from the CSV of the boundary of the case's first Boundary Force response (boundary_ram.csv):
on the ram the prescribed velocity is uniform, so D_nn = 0 there and the normal stress is −p;
it is an independent check of the solver's ram_force (it agrees up to the discretization error
of the boundary pressure).

usage:
  scripts/python scripts/sweep_friction.py [--flowform build/flowform] [--case xml/extrusion.xml]
                            [--nu 0,0.05,0.1,0.2,0.3,0.5] [--out out/sweep]
                            [--set P=V ...] [--walls container,die_face,die_land]
                            [--param PATH ...] [--jobs N] [--timeout S] [--quiet]

  --nu       comma-separated values, or START:STOP:STEP (STOP included)
  --set      passed on to every run (e.g. --set "Mesh/Geo Parameters/h=0.05")
  --walls    the contact-wall groups whose Friction Coefficient is swept (default: every
             Contact Wall group of the case)
  --param    sweep these parameter paths instead of the walls' Friction Coefficient (for
             other sweeps, e.g. --param "Material/Rate Exponent"; repeatable); the value
             column is still called "nu"
  --jobs     runs at a time (default 1)
  --timeout  seconds after which a run is killed and listed as failed (exit_status -9);
             default none

Exit status: 0 when every run converged, 3 when some did not converge, 2 when some run
failed (bad input or crash) or nothing ran.
Needs only the Python standard library (Debian's /usr/bin/python3) and python/flowform_tools.
"""
import argparse
import concurrent.futures
import os
import sys

from flowform_tools import REPO, csvio, launcher
from flowform_tools.case import FIXED_MESH
from flowform_tools.case import Case, Scene
from flowform_tools.sweep import label, parse_values, write


def resolve(path):
    """A path as given if it exists (relative to the current directory), else relative to
    the repository."""
    if os.path.isabs(path) or os.path.exists(path):
        return os.path.abspath(path)
    alt = os.path.join(REPO, path)
    return alt if os.path.exists(alt) else os.path.abspath(path)


def force_from_pressure(run_dir, tool, axisymmetric):
    """∫_tool p ds (plane strain, per unit depth) or ∫_tool p 2πr ds (axisymmetric), by the
    trapezoidal rule on boundary_<tool>.csv; None when the file is missing or too short."""
    if not tool or not os.path.exists(csvio.path(run_dir, tool)):
        return None
    if len(csvio.rows(run_dir, tool)) < 2:
        return None
    return csvio.integral(run_dir, tool, "p", axisymmetric)


def run_one(args, value):
    run_dir = os.path.join(args.out, label(value))
    os.makedirs(run_dir, exist_ok=True)
    sets = ["%s=%r" % (path, value) for path in args.param] + list(args.set)
    # flowform's own log goes next to its results (flowform writes nothing else there on
    # bad input, so the log is the only file then).
    log_path = os.path.join(run_dir, "flowform.log")
    run = launcher.run(args.flowform, args.case, run_dir, FIXED_MESH + list(sets), log=log_path,
                       timeout=args.timeout or None)
    returncode = run.status
    if run.timed_out:
        with open(log_path, "a") as log:
            log.write("\nflowform: killed by sweep_friction.py after --timeout %g s\n" % args.timeout)
        returncode = -9

    row = {"nu": value, "exit_status": returncode, "wall_seconds": round(run.wall, 3),
           "dir": os.path.relpath(run_dir, args.out)}
    summary = run.summary
    functionals = {}
    if returncode in (0, 3) and summary is not None:
        row["converged"] = int(bool(summary.get("converged")))
        row["newton_iterations"] = summary.get("newton_iterations")
        row["contact_changes"] = summary.get("contact_changes")
        row["dofs"] = summary.get("dofs")
        timings = summary.get("timings", {})
        for key in ("total", "assembly", "factorization", "linear_solve"):
            if key in timings:
                row["time_" + key] = round(timings[key], 4)
        functionals = summary.get("functionals", {}) or {}
        if args.force:
            row[args.force + "_p"] = force_from_pressure(run_dir, args.tool,
                                                          Scene.from_summary(summary).axisymmetric)
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
    ap.add_argument("--walls", default=None)
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
    try:
        scene = Case(args.case)
    except Exception as e:  # flowform itself would say exactly what is wrong (exit 2)
        sys.exit("sweep_friction: cannot read the case %s: %s" % (args.case, e))
    walls = args.walls.split(",") if args.walls else scene.contact_walls()
    if args.param is None:
        args.param = ["Boundary Conditions/%s/Friction Coefficient" % w for w in walls if w]
    # the tool force (ram_force) and its boundary (ram), for the ∫ p ds column
    args.force = scene.response("Boundary Force", required=False)
    args.tool = scene.responses()[args.force]["Boundary"] if args.force else None
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

    names = list(scene.responses())
    for _, functionals in results.values():
        for k in functionals:
            if k not in names:
                names.append(k)
    check = [args.force + "_p"] if args.force else []
    columns = (["nu", "converged", "exit_status"] + names + check + ["newton_iterations",
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
    write(csv_path, columns, rows)

    shown = ["nu", "converged", "exit_status"] + names + check + ["newton_iterations", "contact_changes",
                                                                  "time_total"]
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
