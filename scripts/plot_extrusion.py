#!/usr/bin/python3
"""Plots of the extrusion scene (SPEC §6.2, docs/extrusion.md) from flowform's outputs.

  force_vs_nu.png      ram force (and the ∫p ds check), ram pressure and dead zone against
                       the swept value, from SWEEP/sweep.csv (scripts/sweep_friction.py);
                       runs that did not converge are drawn as open red markers
  wall_velocity.png    tangential velocity u_t (in the direction of the material flow) and
                       pressure p along the tool walls container -> die_face -> die_land,
                       against the arc length from the ram, one curve per run (paper fig. 3a
                       plots |u| there; on a wall u_n ≈ 0, so |u_t| ≈ |u|)
  fields_<run>.png     |velocity| with streamlines, and the equivalent strain rate (log
                       scale) of one run, from its solution.h5

usage:
  scripts/plot_extrusion.py [--sweep out/sweep] [--runs DIR ...] [--map-run DIR]
                            [--out DIR] [--walls container,die_face,die_land] [--mesh]
                            [--xlabel TEXT]

  --sweep    a sweep directory (sweep.csv and its run directories); default out/sweep
  --runs     run directories for the wall plot (default: every run of the sweep that wrote
             results); each is labelled with its ν from sweep.csv, else with the container's
             Friction Coefficient from its summary.json, else with its name
  --map-run  the run whose fields are mapped (default: the converged run with ν nearest 0.1)
  --out      where the PNGs go (default: the sweep directory, else the current directory)
  --mesh     draw the mesh edges on the strain-rate map
  --xlabel   x label of force_vs_nu.png (default "friction coefficient ν")

Each CSV boundary_<wall>.csv runs counter-clockwise (material on its left); the walls are
oriented here by matching their end points, so the order of the --walls list (the flow
order) is all that matters, in plane strain and in the transposed axisymmetric section.
Needs numpy, matplotlib, h5py (Debian: python3-numpy python3-matplotlib python3-h5py).
"""
import argparse
import csv
import json
import os
import sys

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.tri as mtri  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402
from matplotlib.colors import LogNorm  # noqa: E402

WALLS = ("container", "die_face", "die_land")


# ------------------------------------------------------------------------------------------
# reading

def read_sweep(sweep_dir):
    path = os.path.join(sweep_dir, "sweep.csv")
    if not os.path.exists(path):
        return None
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        r["dir"] = os.path.join(sweep_dir, r["dir"])
    return rows


def num(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return float("nan")


def read_summary(run_dir):
    path = os.path.join(run_dir, "summary.json")
    if not os.path.exists(path):
        return {}
    with open(path) as f:
        return json.load(f)


def run_label(run_dir, sweep_rows):
    for r in sweep_rows or []:
        if os.path.abspath(r["dir"]) == os.path.abspath(run_dir):
            return "ν = %g" % num(r["nu"]), num(r["nu"])
    bc = read_summary(run_dir).get("parameters", {}).get("Boundary Conditions", {})
    nu = (bc.get("container") or {}).get("Friction Coefficient")
    if nu is not None:
        return "ν = %g" % nu, float(nu)
    return os.path.basename(os.path.normpath(run_dir)), float("nan")


def read_wall(run_dir, wall):
    path = os.path.join(run_dir, "boundary_%s.csv" % wall)
    if not os.path.exists(path):
        return None
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        return None
    return {k: np.array([num(r[k]) for r in rows]) for k in rows[0]}


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
                print("plot_extrusion: warning: %s does not start where %s ends (gap %.3g) in %s"
                      % (w, oriented[-1][0], gap, run_dir), file=sys.stderr)
        oriented.append((w, d))
    out, offset = [], 0.0
    for w, d in oriented:
        out.append((w, offset + d["s"], d))
        offset += d["s"][-1]
    return out


def read_solution(run_dir):
    import h5py
    with h5py.File(os.path.join(run_dir, "solution.h5"), "r") as f:
        xy = np.asarray(f["mesh/coordinates"])[:, :2]
        topo = np.asarray(f["mesh/topology"], dtype=np.int64)
        fields = {name: np.asarray(f["fields/" + name]) for name in f["fields"]}
    return xy, topo, fields


def triangulate(xy, topo):
    """matplotlib Triangulation; quadrilaterals are split along their 0-2 diagonal. Returns
    the triangulation and, per triangle, the index of its cell."""
    if topo.shape[1] == 3:
        tris, cell = topo, np.arange(len(topo))
    elif topo.shape[1] == 4:
        tris = np.vstack([topo[:, [0, 1, 2]], topo[:, [0, 2, 3]]])
        cell = np.concatenate([np.arange(len(topo))] * 2)
    else:
        raise ValueError("topology with %d nodes per cell" % topo.shape[1])
    return mtri.Triangulation(xy[:, 0], xy[:, 1], tris), cell


# ------------------------------------------------------------------------------------------
# plots

def plot_force(rows, out_png, xlabel):
    axisym = any(read_summary(r["dir"]).get("parameters", {}).get("Problem", {})
                 .get("Geometry") == "Axisymmetric" for r in rows[:1])
    nu = np.array([num(r["nu"]) for r in rows])
    conv = np.array([r.get("converged") == "1" for r in rows])
    have = [k for k in ("ram_force", "ram_pressure", "dead_zone")
            if any(np.isfinite(num(r.get(k))) for r in rows)]
    check = np.array([num(r.get("ram_force_p")) for r in rows])
    panels = have or ["ram_force_p"]
    fig, axes = plt.subplots(1, len(panels), figsize=(4.6 * len(panels), 3.8), squeeze=False)
    if axisym:
        titles = {"ram_force": "ram force (whole ram, 2πr)", "ram_force_p": "ram force ∫ p 2πr ds",
                  "ram_pressure": "mean ram pressure", "dead_zone": "dead zone volume"}
    else:
        titles = {"ram_force": "ram force (per unit depth, half section)",
                  "ram_force_p": "ram force ∫ p ds",
                  "ram_pressure": "mean ram pressure", "dead_zone": "dead zone area"}
    order = np.argsort(nu)
    for ax, key in zip(axes[0], panels):
        y = np.array([num(r.get(key)) for r in rows])
        ax.plot(nu[order], y[order], "-", color="C0", lw=1)
        ax.plot(nu[conv], y[conv], "o", color="C0", label=key)
        if (~conv).any():
            ax.plot(nu[~conv], y[~conv], "o", mfc="none", mec="red", label="not converged")
        if key == "ram_force" and np.isfinite(check).any():
            ax.plot(nu[order], check[order], "--", color="C1", lw=1, label="∫ p %sds on the ram" % ("2πr " if axisym else ""))
        ax.set_xlabel(xlabel)
        ax.set_title(titles.get(key, key), fontsize=10)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out_png, dpi=130)
    plt.close(fig)


def plot_walls(runs, walls, out_png):
    fig, (ax_u, ax_p) = plt.subplots(2, 1, figsize=(9, 7), sharex=True)
    cmap = plt.get_cmap("viridis")
    junctions = None
    released_shown = False
    for k, (run_dir, label, converged) in enumerate(runs):
        chain = chain_walls(run_dir, walls)
        if not chain:
            print("plot_extrusion: no wall CSVs in %s" % run_dir, file=sys.stderr)
            continue
        color = cmap(k / max(1, len(runs) - 1))
        S = np.concatenate([c[1] for c in chain])
        ut = np.concatenate([c[2]["u_t"] for c in chain])
        p = np.concatenate([c[2]["p"] for c in chain])
        style = "-" if converged else ":"
        name = label + ("" if converged else " (not converged)")
        ax_u.plot(S, ut, style, color=color, lw=1.2, label=name)
        ax_p.plot(S, p, style, color=color, lw=1.2)
        if all("contact_status" in c[2] for c in chain):  # released (free) wall nodes
            free = np.concatenate([c[2]["contact_status"] for c in chain]) == 0
            if free.any():
                ax_u.plot(S[free], ut[free], "x", color=color, ms=4,
                          label=None if released_shown else "free (released) node")
                ax_p.plot(S[free], p[free], "x", color=color, ms=4)
                released_shown = True
        if junctions is None:
            junctions = [(c[0], c[1][0], c[1][-1]) for c in chain]
    for ax in (ax_u, ax_p):
        ax.grid(alpha=0.3)
        for w, s0, s1 in junctions or []:
            ax.axvline(s1, color="0.5", lw=0.8, ls="--")
    if junctions:
        for w, s0, s1 in junctions:
            ax_u.text(0.5 * (s0 + s1), 1.02, w, transform=ax_u.get_xaxis_transform(),
                      ha="center", va="bottom", fontsize=9)
    ax_u.set_ylabel("u_t along the flow")
    ax_p.set_ylabel("pressure p")
    ax_p.set_xlabel("arc length along the walls from the ram corner ("
                    + " → ".join(walls) + ")")
    ax_u.legend(fontsize=8, ncol=2)
    fig.tight_layout()
    fig.savefig(out_png, dpi=130)
    plt.close(fig)


def plot_fields(run_dir, label, out_png, show_mesh, axisymmetric):
    xy, topo, fields = read_solution(run_dir)
    tri, cell = triangulate(xy, topo)
    vel = fields["velocity"][:, :2]
    speed = np.hypot(vel[:, 0], vel[:, 1])
    rate = fields["strain_rate"][cell]
    width = np.ptp(xy[:, 0])
    height = np.ptp(xy[:, 1])
    wide = width >= height
    if wide:
        fig, axes = plt.subplots(2, 1, figsize=(10, 2 * 8.3 * height / width + 1.4))
    else:
        fig, axes = plt.subplots(1, 2, figsize=(2 * 6.3 * width / height + 3.4, 7))
    names = ("r", "z") if axisymmetric else ("x", "y")

    ax = axes[0]
    m = ax.tripcolor(tri, speed, shading="gouraud", cmap="viridis")
    fig.colorbar(m, ax=ax, label="|u|", shrink=0.9)
    # streamlines: the velocity interpolated on a grid (masked outside the mesh)
    gx = np.linspace(xy[:, 0].min(), xy[:, 0].max(), 300)
    gy = np.linspace(xy[:, 1].min(), xy[:, 1].max(), 300)
    GX, GY = np.meshgrid(gx, gy)
    U = mtri.LinearTriInterpolator(tri, vel[:, 0])(GX, GY)
    V = mtri.LinearTriInterpolator(tri, vel[:, 1])(GX, GY)
    try:
        ax.streamplot(gx, gy, U.filled(np.nan), V.filled(np.nan), color="w", linewidth=0.5,
                      density=1.2, arrowsize=0.6)
    except ValueError as e:  # e.g. all-zero field
        print("plot_extrusion: no streamlines: %s" % e, file=sys.stderr)
    ax.set_title("%s: |velocity| and streamlines" % label, fontsize=10)

    ax = axes[1]
    positive = rate[rate > 0]
    vmin = max(positive.min(), 1e-4 * positive.max()) if positive.size else 1e-6
    m = ax.tripcolor(tri, facecolors=np.maximum(rate, vmin), cmap="magma",
                     norm=LogNorm(vmin=vmin, vmax=max(rate.max(), vmin * 10)),
                     edgecolors="none")
    if show_mesh:  # the cells as they are (quadrilaterals unsplit)
        ax.add_collection(PolyCollection(xy[topo], facecolors="none", edgecolors="w",
                                         linewidths=0.15, alpha=0.6))
    fig.colorbar(m, ax=ax, label="equivalent strain rate e", shrink=0.9)
    ax.set_title("%s: equivalent strain rate (cell values, log scale)" % label, fontsize=10)
    for ax in axes:
        ax.set_aspect("equal")
        ax.set_xlabel(names[0])
        ax.set_ylabel(names[1])
        ax.set_xlim(xy[:, 0].min(), xy[:, 0].max())
        ax.set_ylim(xy[:, 1].min(), xy[:, 1].max())
    fig.tight_layout()
    fig.savefig(out_png, dpi=140)
    plt.close(fig)


# ------------------------------------------------------------------------------------------

def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog=__doc__.split("\n", 1)[1])
    ap.add_argument("--sweep", default="out/sweep")
    ap.add_argument("--runs", nargs="+")
    ap.add_argument("--map-run")
    ap.add_argument("--out")
    ap.add_argument("--walls", default=",".join(WALLS))
    ap.add_argument("--mesh", action="store_true")
    ap.add_argument("--xlabel", default="friction coefficient ν")
    args = ap.parse_args()
    walls = [w for w in args.walls.split(",") if w]

    rows = read_sweep(args.sweep)
    if rows is None and not args.runs and not args.map_run:
        sys.exit("plot_extrusion: no %s/sweep.csv; give --sweep, --runs or --map-run"
                 % args.sweep)
    out = args.out or (args.sweep if rows is not None else ".")
    os.makedirs(out, exist_ok=True)
    written = []

    if rows:
        png = os.path.join(out, "force_vs_nu.png")
        plot_force(rows, png, args.xlabel)
        written.append(png)

    if args.runs:
        run_dirs = args.runs
    else:
        run_dirs = [r["dir"] for r in rows or [] if r["exit_status"] in ("0", "3")]
    runs = []
    for d in run_dirs:
        label, nu = run_label(d, rows)
        conv = bool(read_summary(d).get("converged", False))
        runs.append((d, label, conv, nu))
    runs.sort(key=lambda r: (np.isnan(r[3]), r[3]))
    if runs:
        png = os.path.join(out, "wall_velocity.png")
        plot_walls([r[:3] for r in runs], walls, png)
        written.append(png)

    map_run = args.map_run
    if map_run is None and runs:
        converged = [r for r in runs if r[2]] or runs
        map_run = min(converged, key=lambda r: abs(r[3] - 0.1) if np.isfinite(r[3]) else 1e9)[0]
    if map_run:
        label, _ = run_label(map_run, rows)
        summary = read_summary(map_run)
        axisym = summary.get("parameters", {}).get("Problem", {}).get("Geometry") == "Axisymmetric"
        tag = label.replace("ν = ", "nu_").replace(" ", "_")
        png = os.path.join(out, "fields_%s.png" % tag)
        plot_fields(map_run, label, png, args.mesh, axisym)
        written.append(png)

    for p in written:
        print(p)
    return 0


if __name__ == "__main__":
    sys.exit(main())
