"""boundary_<group>.csv, one per named boundary curve of a run (docs/theory.md §5).

Columns: s (arc length), x, y, u_t, u_n, p, contact_status on contact walls, and
du_t_d<h>, du_n_d<h>, dp_d<h> (plus the _fd ones) with sensitivities. Each curve runs
counter-clockwise around the domain (material on its left); u_n is along the outward normal.
Standard library only (numpy is used by columns() if asked).
"""
import csv
import math
import os


def path(outdir, group):
    return os.path.join(outdir, f"boundary_{group}.csv")


def header(path_or_outdir, group=None):
    """The column names of a CSV (a path, or an output directory and a group)."""
    p = path(path_or_outdir, group) if group else path_or_outdir
    with open(p) as f:
        return f.readline().strip().split(",")


def rows(outdir, group, sort=False):
    """The rows as dicts of floats, in file order (sorted by s if sort)."""
    with open(path(outdir, group), newline="") as f:
        out = [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]
    if sort:
        out.sort(key=lambda r: r["s"])
    return out


def columns(outdir, group, numpy=False, missing_ok=False):
    """Column name -> list of floats (numpy arrays if numpy); None if missing_ok and the file
    is absent or empty."""
    p = path(outdir, group)
    if missing_ok and not os.path.exists(p):
        return None
    data = rows(outdir, group)
    if not data:
        if missing_ok:
            return None
        raise ValueError(f"{p}: no rows")
    out = {k: [r[k] for r in data] for k in data[0]}
    if numpy:
        import numpy as np
        out = {k: np.array(v) for k, v in out.items()}
    return out


def integral(outdir, group, column, axisymmetric=False, weight=None):
    """∫ column ds over the curve by the trapezoid rule in s (exact for a P1 trace), times
    2πr (r = x) when axisymmetric, times weight(row) if given."""
    data = rows(outdir, group, sort=True)
    total = 0.0
    for a, b in zip(data, data[1:]):
        fa, fb = a[column], b[column]
        if axisymmetric:
            fa *= 2 * math.pi * a["x"]
            fb *= 2 * math.pi * b["x"]
        if weight is not None:
            fa *= weight(a)
            fb *= weight(b)
        total += 0.5 * (b["s"] - a["s"]) * (fa + fb)
    return total


def flux(outdir, group, axisymmetric=False):
    """∫ u·n ds: the volume flux out through the curve (negative where material enters)."""
    return integral(outdir, group, "u_n", axisymmetric)


def shared_points(outdir, group_a, group_b, digits=9):
    """The points (x, y) that two curves share (their common end points), rounded to digits."""
    a = {(round(r["x"], digits), round(r["y"], digits)) for r in rows(outdir, group_a)}
    return sorted(p for p in ((round(r["x"], digits), round(r["y"], digits)) for r in rows(outdir, group_b))
                  if p in a)


def status_column(outdir, group):
    """The contact_status column as text, exactly as written (for state comparisons)."""
    with open(path(outdir, group)) as f:
        head = f.readline().strip().split(",")
        k = head.index("contact_status")
        return [line.strip().split(",")[k] for line in f]
