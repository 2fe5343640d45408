"""Parameter sweeps: the value list of --nu-style options and the sweep.csv that
scripts/sweep_friction.py writes and the plot scripts read."""
import argparse
import csv
import math
import os


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
