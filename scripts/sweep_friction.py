"""Friction sweep of the extrusion scene (docs/theory.md §6.2, docs/extrusion.md).

Runs flowform once per friction coefficient ν, setting
"Boundary Conditions/<wall>/Friction Coefficient" = ν on every Contact Wall group of the case
(container, die_face, die_land in xml/extrusion.xml), each run into OUT/nu_<ν>/.

Every run has the case's own accuracy: its Adaptivity section (the adaptive loop refines until
the estimated relative error of the ram force is below Adaptivity/Target Relative Error), so
every response comes with its error estimate; and every run asks for the derivative by ν by
direct differentiation (Sensitivity/Parameters = {Friction Coefficient}: the paper's fig. 4).
--fixed-mesh solves the case's mesh once instead (Adaptivity/Enabled = false: the paper's
mesh, ram force ≈ 3 % low, no estimate unless the case or --set asks for one).

Collects from each summary.json the functionals (the case's responses first, in the case's
order: ram_force, ram_pressure, dead_zone; then any other), their error estimates
(<response>_error_estimate), their derivatives by ν (<response>_dnu) and the derivatives'
estimates (<response>_dnu_error_estimate), the converged flag, Newton iterations and contact
changes (of the last adaptive cycle, and _total over the cycles), the cycles, whether the
target was met, dofs and timings (the last cycle's; time_error_estimation too: summary.json
gives no earlier cycle's) and the whole run's wall seconds into OUT/sweep.csv, and prints a
table. A run that does not converge (exit 3) is kept and flagged (converged = 0); a run that
fails otherwise (bad input, crash) is listed with its exit status and no values.

One extra column, <force>_p (ram_force_p) = ∫_ram p ds (× 2πr when axisymmetric), is computed
here from the CSV of the boundary of the case's first Boundary Force response (boundary_ram.csv):
on the ram the prescribed velocity is uniform, so D_nn = 0 there and the normal stress is −p;
it is an independent check of the solver's ram_force (it agrees up to the discretization error
of the boundary pressure).

usage:
  scripts/python scripts/sweep_friction.py [--flowform build/flowform] [--case xml/extrusion.xml]
                            [--nu 0,0.05,0.1,0.2,0.3,0.5] [--out out/sweep]
                            [--set P=V ...] [--walls container,die_face,die_land]
                            [--param PATH ...] [--fixed-mesh] [--target E] [--no-sensitivity]
                            [--jobs N] [--timeout S] [--quiet]

  --nu       comma-separated values, or START:STOP:STEP (STOP included)
  --set      passed on to every run (e.g. --set "Mesh/Geo Parameters/h=0.05")
  --walls    the contact-wall groups whose Friction Coefficient is swept (default: every
             Contact Wall group of the case)
  --param    sweep these parameter paths instead of the walls' Friction Coefficient (for
             other sweeps, e.g. --param "Material/Rate Exponent"; repeatable); the value
             column is still called "nu"
  --fixed-mesh      the case's mesh solved once (Adaptivity/Enabled=false), not adapted
  --target E        Adaptivity/Target Relative Error of every run (default: the case's)
  --no-sensitivity  no DDM derivative (by default the sensitivity parameters of the swept
                    paths are asked for: Friction Coefficient for the walls; the Material
                    parameter for --param "Material/<name>"; none for other paths). A
                    --set "Sensitivity/Parameters=..." of your own replaces ours.
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
from flowform_tools.launcher import lit
from flowform_tools.sweep import (RUN_COLUMNS, estimate_column_names, estimate_columns, label, parse_values,
                                  sensitivity_names, write)


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
    sets = args.accuracy + ["%s=%r" % (path, value) for path in args.param] + list(args.set)
    # flowform's own log goes next to its results (flowform writes nothing else there on
    # bad input, so the log is the only file then).
    log_path = os.path.join(run_dir, "flowform.log")
    run = launcher.run(args.flowform, args.case, run_dir, sets, log=log_path,
                       timeout=args.timeout or None)
    returncode = run.status
    if run.timed_out:
        with open(log_path, "a") as log:
            log.write("\nflowform: killed by sweep_friction.py after --timeout %g s\n" % args.timeout)
        returncode = -9

    row = {"nu": value, "exit_status": returncode, "wall_seconds": round(run.wall, 3),
           "dir": os.path.relpath(run_dir, args.out)}
    summary = run.summary
    functionals = None
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
    return row, functionals, summary if functionals is not None else None


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
    ap.add_argument("--fixed-mesh", action="store_true")
    ap.add_argument("--target", type=float)
    ap.add_argument("--no-sensitivity", action="store_true")
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
    if args.fixed_mesh and args.target is not None:
        ap.error("--target is the adaptive loop's: not with --fixed-mesh")
    if args.target is not None and not args.target > 0:
        ap.error("--target must be > 0")
    # how accurate every run is: the case's adaptive loop (to --target), or its mesh once
    args.accuracy = list(FIXED_MESH) if args.fixed_mesh else []
    if args.target is not None:
        args.accuracy.append("Adaptivity/Target Relative Error=%s" % lit(args.target))
    # the derivative by the swept value (DDM), unless the user's --set asks for other ones
    args.sensitivity = None if args.no_sensitivity else sensitivity_names(args.param, scene.contact_walls())
    own = any(s.split("=", 1)[0].strip() == "Sensitivity/Parameters" for s in args.set)
    if args.sensitivity and not own:
        args.accuracy.append("Sensitivity/Parameters={%s}" % ", ".join(args.sensitivity))
    elif args.sensitivity is None and not args.no_sensitivity and not args.quiet:
        print("sweep_friction: no sensitivity parameter for %s: no derivative columns" % ", ".join(args.param))
    # the tool force (ram_force) and its boundary (ram), for the ∫ p ds column
    args.force = scene.response("Boundary Force", required=False)
    args.tool = scene.responses()[args.force]["Boundary"] if args.force else None
    os.makedirs(args.out, exist_ok=True)

    if not args.quiet:
        print("sweep of %s over %s: %s (%s)" % (case_given, ", ".join(args.param),
                                                  ", ".join(format(v, "g") for v in args.nu),
                                                  "the case's mesh, once" if args.fixed_mesh else
                                                  "adaptive to %s" % (format(args.target, "g") if args.target
                                                                      else "the case's target")))
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
    for _, functionals, _ in results.values():
        for k in functionals or {}:
            if k not in names:
                names.append(k)
    check = [args.force + "_p"] if args.force else []
    columns = (["nu", "converged", "exit_status"] + names + check + estimate_column_names(names) +
               ["newton_iterations", "contact_changes", "dofs"] + RUN_COLUMNS +
               ["time_total", "time_assembly", "time_factorization", "time_linear_solve", "wall_seconds", "dir",
                "message"])
    rows = []
    for v in args.nu:
        row, functionals, summary = results[v]
        row = dict(row)
        for k in names:
            row[k] = (functionals or {}).get(k)
        if summary is not None:
            row.update(estimate_columns(summary, names, args.sensitivity))
        rows.append(row)
    csv_path = os.path.join(args.out, "sweep.csv")
    write(csv_path, columns, rows)

    force = [args.force + "_error_estimate", args.force + "_dnu"] if args.force else []
    shown = (["nu", "converged", "exit_status"] + names + check + force +
             ["dofs", "cycles", "newton_iterations_total", "contact_changes_total", "wall_seconds"])
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
