"""Parameter sweeps: the value list of --nu-style options and the sweep.csv that
scripts/sweep_friction.py writes and the plot scripts read.

Besides each response's value, a row of sweep.csv carries (estimate_columns):

  <response>_error_estimate          the run's estimate η of the response's discretization
                                     error (summary.json functionals_error_estimate; signed,
                                     ≈ exact − computed), empty when the run did not estimate
  <response>_dnu                     the response's derivative by the swept value (DDM:
                                     summary.json sensitivities, summed over the sensitivity
                                     parameters the swept value moves together)
  <response>_dnu_error_estimate      that derivative's η (sensitivities_error_estimate)

and what the whole run cost (summary.adaptive_totals): cycles, target_met,
newton_iterations_total, contact_changes_total, time_error_estimation.
"""
import argparse
import csv
import math
import os

from . import summary as summary_module


def parse_values(text):
    """'0,0.05,0.1' or 'START:STOP:STEP' (STOP included) -> list of floats. Raises
    argparse.ArgumentTypeError, so it can be an argparse type."""
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


def label(value):
    """The run directory name of one sweep value: nu_<value>."""
    return "nu_%s" % format(value, "g")


def read(sweep_dir):
    """The rows of SWEEP/sweep.csv (text values) with "dir" made a path; None if absent."""
    p = os.path.join(sweep_dir, "sweep.csv")
    if not os.path.exists(p):
        return None
    with open(p, newline="") as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        r["dir"] = os.path.join(sweep_dir, r["dir"])
    return rows


def write(path, columns, rows):
    """Writes rows (dicts) to a CSV with these columns, atomically (PATH.tmp, then rename);
    floats as repr, None as empty."""
    with open(path + ".tmp", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=columns, extrasaction="ignore")
        w.writeheader()
        for row in rows:
            w.writerow({k: ("" if row.get(k) is None else
                            (repr(row[k]) if isinstance(row[k], float) else row[k]))
                        for k in columns})
    os.replace(path + ".tmp", path)


def num(text):
    """A CSV cell as a float (nan when empty or not a number)."""
    try:
        return float(text)
    except (TypeError, ValueError):
        return float("nan")


def sensitivity_names(paths, contact_walls):
    """The flowform sensitivity parameter names (docs/sensitivity.md) whose derivatives add up
    to the derivative by a value that the sweep writes into every parameter path of `paths`:
    ["Friction Coefficient"] when the paths are the Friction Coefficient of every contact wall,
    else one name per path ("Boundary Conditions/<wall>/Friction Coefficient" ->
    "Friction Coefficient:<wall>", likewise Shear Factor; "Material/<name>" -> "<name>").
    None when some path has no sensitivity parameter (e.g. a mesh size)."""
    friction = {"Boundary Conditions/%s/Friction Coefficient" % w for w in contact_walls}
    if contact_walls and set(paths) == friction and len(paths) == len(friction):
        return ["Friction Coefficient"]
    names = []
    for path in paths:
        parts = path.split("/")
        if len(parts) == 3 and parts[0] == "Boundary Conditions" and parts[2] in ("Friction Coefficient",
                                                                                   "Shear Factor"):
            names.append("%s:%s" % (parts[2], parts[1]))
        elif len(parts) == 2 and parts[0] == "Material":
            names.append(parts[1])
        else:
            return None
    return names


def estimate_column_names(responses):
    """The estimate and derivative columns of these responses, in the order of estimate_columns."""
    out = []
    for name in responses:
        out += [name + "_error_estimate", name + "_dnu", name + "_dnu_error_estimate"]
    return out


RUN_COLUMNS = ["cycles", "target_met", "newton_iterations_total", "contact_changes_total",
               "time_error_estimation"]


def estimate_columns(summary, responses, parameters):
    """The row entries of estimate_column_names(responses) and RUN_COLUMNS from one run's
    summary.json (a dict). parameters: the sensitivity names whose derivatives are summed into
    <response>_dnu (sensitivity_names); a derivative is given only when the run has every one of
    them, and its estimate only when every one has an estimate. None for what is missing."""
    s = summary or {}
    eta = s.get("functionals_error_estimate") or {}
    sens = s.get("sensitivities") or {}
    sens_eta = s.get("sensitivities_error_estimate") or {}
    row = {}
    for name in responses:
        row[name + "_error_estimate"] = eta.get(name)
        d = [(sens.get(name) or {}).get(p) for p in parameters or []]
        e = [(sens_eta.get(name) or {}).get(p) for p in parameters or []]
        row[name + "_dnu"] = math.fsum(d) if d and None not in d else None
        row[name + "_dnu_error_estimate"] = math.fsum(e) if e and None not in e else None
    totals = summary_module.adaptive_totals(s)
    row["cycles"] = totals["cycles"]
    row["target_met"] = None if totals["target_met"] is None else int(bool(totals["target_met"]))
    row["newton_iterations_total"] = totals["newton_iterations"]
    row["contact_changes_total"] = totals["contact_changes"]
    row["time_error_estimation"] = totals["estimate_seconds"]
    return row
