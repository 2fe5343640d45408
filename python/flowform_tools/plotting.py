"""matplotlib helpers shared by scripts/plot_extrusion.py and scripts/plot_sensitivity.py.

    plt = plotting.pyplot()                      # matplotlib with the Agg backend (no display)
    walls = plotting.walls_of_run(run_dir)       # the contact walls, in flow order
    for wall, S, data in plotting.chain_walls(run_dir, walls): ...
    drawn = plotting.values_with_estimates(ax, x, y, eta, slope)   # error bars, DDM tangents

Needs numpy and matplotlib (Debian: python3-numpy python3-matplotlib; h5py for fields).
"""
import os
import sys

import numpy as np

from . import case as case_module
from . import csvio, h5io, summary as summary_module


def pyplot():
    """matplotlib.pyplot on the Agg backend (PNG files, no display needed)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def save(fig, path, dpi=130):
    """tight_layout, write the PNG, close the figure."""
    fig.tight_layout()
    fig.savefig(path, dpi=dpi)
    pyplot().close(fig)


def grid(*axes):
    for ax in axes:
        ax.grid(alpha=0.3)


# ------------------------------------------------------------------------------------------
# values against a parameter, with their error estimates and derivatives


def tangent_half_width(x):
    """Half the x-extent of a tangent segment drawn through each of the points x: 0.3 of the
    smallest spacing of the distinct finite values, else 5 % of their magnitude (0.05 for a
    single value 0)."""
    xs = np.unique(np.asarray(x, dtype=float)[np.isfinite(x)])
    if len(xs) > 1:
        return 0.3 * float(np.min(np.diff(xs)))
    return 0.05 * max(abs(float(xs[0])), 1.0) if len(xs) else 0.05


def values_with_estimates(ax, x, y, eta=None, slope=None, color="C0", label=None, half_width=None,
                          marker="o", mfc=None, mec=None):
    """Draws the points (x, y) with error bars ±|eta| and, through each point, a short segment
    of slope `slope` (the derivative dy/dx: the DDM tangent), x ± half_width (default
    tangent_half_width(x)). A point whose eta (slope) is nan or None gets no bar (no segment).
    Returns what it drew: {"points": n, "error_bars": ErrorbarContainer or None, "bars": n,
    "tangents": LineCollection or None, "segments": n}."""
    from matplotlib.collections import LineCollection
    x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)

    def column(v):
        if v is None:
            return np.full(len(x), np.nan)
        return np.array([np.nan if e is None else float(e) for e in v])
    eta, slope = column(eta), column(slope)
    shown = np.isfinite(x) & np.isfinite(y)
    drawn = {"points": int(shown.sum()), "error_bars": None, "bars": 0, "tangents": None, "segments": 0}
    # small markers under the bars: a 0.5 % bar is a few pixels on a plot of the whole sweep
    ax.plot(x[shown], y[shown], marker, ls="none", ms=4, color=color, mfc=mfc, mec=mec, label=label, zorder=2)
    barred = shown & np.isfinite(eta)
    if barred.any():
        drawn["error_bars"] = ax.errorbar(x[barred], y[barred], yerr=np.abs(eta[barred]), fmt="none",
                                          ecolor=color, elinewidth=1.0, capsize=3, zorder=3,
                                          label="± |error estimate|" if label else None)
        drawn["bars"] = int(barred.sum())
    tangent = shown & np.isfinite(slope)
    if tangent.any():
        w = tangent_half_width(x) if half_width is None else half_width
        segments = [[(xi - w, yi - si * w), (xi + w, yi + si * w)]
                    for xi, yi, si in zip(x[tangent], y[tangent], slope[tangent])]
        drawn["tangents"] = ax.add_collection(LineCollection(segments, colors="k", linewidths=1.0, zorder=2.5,
                                                             label="DDM tangent" if label else None))
        drawn["segments"] = len(segments)
        ax.autoscale_view()
    return drawn


# ------------------------------------------------------------------------------------------
# boundary curves


def read_wall(run_dir, wall):
    """The columns of boundary_<wall>.csv as numpy arrays; None if absent or empty."""
    return csvio.columns(run_dir, wall, numpy=True, missing_ok=True)


def _ends(run_dir, group, digits=9):
    d = csvio.columns(run_dir, group, missing_ok=True)
    if d is None:
        return None
    return {(round(d["x"][0], digits), round(d["y"][0], digits)), (round(d["x"][-1], digits), round(d["y"][-1], digits))}


def flow_order(run_dir, walls, inflow=None):
    """The walls as one chain of curves that starts at the inflow boundary (e.g. the ram):
    container -> die_face -> die_land for the extrusion, whatever order they come in. Falls
    back to the given order when the CSVs do not form such a chain."""
    ends = {w: _ends(run_dir, w) for w in walls}
    ends = {w: e for w, e in ends.items() if e}
    inflow_ends = _ends(run_dir, inflow) if inflow else None
    if len(ends) < 2 or not inflow_ends:
        return list(walls)
    start = [w for w in ends if ends[w] & inflow_ends]
    if len(start) != 1:
        return list(walls)
    chain, remaining = [start[0]], set(ends) - {start[0]}
    tail = ends[start[0]] - inflow_ends
    while remaining and len(tail) == 1:
        point = next(iter(tail))
        following = [w for w in remaining if point in ends[w]]
        if len(following) != 1:
            return list(walls)
        chain.append(following[0])
        remaining.remove(following[0])
        tail = ends[following[0]] - {point}
    if remaining:
        return list(walls)
    return chain + [w for w in walls if w not in ends]


def walls_of_run(run_dir):
    """The Contact Wall groups of a run (from its summary.json), in flow order from the
    boundary of its first Boundary Force response (the ram)."""
    s = summary_module.load(run_dir)
    if s is None:
        return []
    scene = case_module.Scene.from_summary(s)
    inflow = scene.tool_boundary() if scene.response("Boundary Force", required=False) else None
    return flow_order(run_dir, scene.contact_walls(), inflow)


def chain_walls(run_dir, walls):
    """The walls in the given (flow) order, each oriented so that it starts where the
    previous one ends; returns [(wall, S, data)] with S the cumulative arc length and
    data['u_t'] the velocity along the chain direction."""
    curves = [(w, read_wall(run_dir, w)) for w in walls]
    curves = [(w, d) for w, d in curves if d is not None]
    if not curves:
        return []

    def ends(d):
        return (np.array([d["x"][0], d["y"][0]]), np.array([d["x"][-1], d["y"][-1]]))

    def flip(d):
        out = {k: v[::-1].copy() for k, v in d.items()}
        out["s"] = d["s"][-1] - out["s"]
        out["u_t"] = -out["u_t"]  # the tangent turns round; u_n keeps its sign
        return out

    oriented = []
    for i, (w, d) in enumerate(curves):
        a, b = ends(d)
        if i == 0:
            if len(curves) > 1:
                na, nb = ends(curves[1][1])
                # the end shared with the next wall must come last
                da = min(np.linalg.norm(a - na), np.linalg.norm(a - nb))
                db = min(np.linalg.norm(b - na), np.linalg.norm(b - nb))
                if da < db:
                    d = flip(d)
        else:
            prev_end = ends(oriented[-1][1])[1]
            if np.linalg.norm(b - prev_end) < np.linalg.norm(a - prev_end):
                d = flip(d)
            gap = np.linalg.norm(ends(d)[0] - prev_end)
            if gap > 1e-9 * (1 + np.linalg.norm(prev_end)):
                print("warning: %s does not start where %s ends (gap %.3g) in %s"
                      % (w, oriented[-1][0], gap, run_dir), file=sys.stderr)
        oriented.append((w, d))
    out, offset = [], 0.0
    for w, d in oriented:
        out.append((w, offset + d["s"], d))
        offset += d["s"][-1]
    return out


def oriented_column(run_dir, walls, column):
    """A CSV column along the chained walls, its sign following chain_walls' orientation of
    u_t (a tangential component turns round with the wall). (None, None) if a wall lacks it."""
    chain = chain_walls(run_dir, walls)
    S, values = [], []
    for w, s, d in chain:
        raw = read_wall(run_dir, w)
        if column not in raw:
            return None, None
        flipped = not np.isclose(raw["x"][0], d["x"][0]) or not np.isclose(raw["y"][0], d["y"][0])
        v = raw[column][::-1] if flipped else raw[column]
        S.append(s)
        values.append(-v if flipped else v)
    return np.concatenate(S), np.concatenate(values)


# ------------------------------------------------------------------------------------------
# fields


def read_solution(run_dir):
    """(xy, topology, fields) of solution.h5."""
    s = h5io.read(run_dir)
    return s.xy, s.topology, s.fields


def triangulate(xy, topo):
    """matplotlib Triangulation; quadrilaterals are split along their 0-2 diagonal. Returns
    the triangulation and, per triangle, the index of its cell."""
    import matplotlib.tri as mtri
    if topo.shape[1] == 3:
        tris, cell = topo, np.arange(len(topo))
    elif topo.shape[1] == 4:
        tris = np.vstack([topo[:, [0, 1, 2]], topo[:, [0, 2, 3]]])
        cell = np.concatenate([np.arange(len(topo))] * 2)
    else:
        raise ValueError("topology with %d nodes per cell" % topo.shape[1])
    return mtri.Triangulation(xy[:, 0], xy[:, 1], tris), cell


def run_summary(run_dir):
    """summary.json of a run as a dict ({} when absent)."""
    return summary_module.load(run_dir) or {}


def is_axisymmetric(run_dir):
    return case_module.Scene.from_summary(run_summary(run_dir)).axisymmetric


def out_dir(path):
    os.makedirs(path, exist_ok=True)
    return path
