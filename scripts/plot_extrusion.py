"""Plots of the extrusion scene (docs/theory.md §6.2, docs/extrusion.md) from flowform's outputs.

  force_vs_nu.png      ram force (and the ∫p ds check), ram pressure and dead zone against
                       the swept value, from SWEEP/sweep.csv (scripts/sweep_friction.py):
                       each value with its error bar ± |error estimate| (the column
                       <response>_error_estimate) and its DDM tangent, a short segment of
                       slope d<response>/dν (the column <response>_dnu) through the point
                       (the paper's fig. 4); a value without them (a --fixed-mesh sweep, or
                       the dead zone, which has no derivative) is drawn bare; runs that did
                       not converge are drawn as open red markers
  wall_velocity.png    tangential velocity u_t (in the direction of the material flow) and
                       pressure p along the tool walls container -> die_face -> die_land,
                       against the arc length from the ram, one curve per run (paper fig. 3a
                       plots |u| there; on a wall u_n ≈ 0, so |u_t| ≈ |u|)
  fields_<run>.png     |velocity| with streamlines, and the equivalent strain rate (log
                       scale) of one run, from its solution.h5

usage:
  scripts/python scripts/plot_extrusion.py [--sweep out/sweep] [--runs DIR ...] [--map-run DIR]
                            [--out DIR] [--walls container,die_face,die_land] [--mesh]
                            [--xlabel TEXT]

  --sweep    a sweep directory (sweep.csv and its run directories); default out/sweep
  --runs     run directories for the wall plot (default: every run of the sweep that wrote
             results); each is labelled with its ν from sweep.csv, else with the container's
             Friction Coefficient from its summary.json, else with its name
  --map-run  the run whose fields are mapped (default: the converged run with ν nearest 0.1)
  --out      where the PNGs go (default: the sweep directory, else the current directory)
  --walls    the walls of the wall plot, in flow order (default: the runs' Contact Wall groups,
             chained from the boundary of their Boundary Force response, the ram)
  --mesh     draw the mesh edges on the strain-rate map
  --xlabel   x label of force_vs_nu.png (default "friction coefficient ν")

Each CSV boundary_<wall>.csv runs counter-clockwise (material on its left); the walls are
oriented here by matching their end points, so the order of the --walls list (the flow
order) is all that matters, in plane strain and in the transposed axisymmetric section.
Response names (the force, pressure and dead-zone panels) are taken from the runs'
summary.json by their Type (Boundary Force, Mean Pressure, Dead Zone).
Needs numpy, matplotlib, h5py (Debian: python3-numpy python3-matplotlib python3-h5py) and
python/flowform_tools (plotting helpers).
"""
import argparse
import os
import sys

import numpy as np

from flowform_tools import plotting
from flowform_tools.case import Scene
from flowform_tools.plotting import chain_walls, read_solution, run_summary as read_summary, triangulate
from flowform_tools.sweep import num, read as read_sweep

plt = plotting.pyplot()
import matplotlib.tri as mtri  # noqa: E402 (after plotting.pyplot() chose the Agg backend)
from matplotlib.collections import PolyCollection  # noqa: E402
from matplotlib.colors import LogNorm  # noqa: E402


def run_label(run_dir, sweep_rows, walls=None):
    """"ν = <value>" from sweep.csv, else from the first wall's Friction Coefficient in the
    run's summary.json, else the directory name; and the value (nan if none)."""
    for r in sweep_rows or []:
        if os.path.abspath(r["dir"]) == os.path.abspath(run_dir):
            return "ν = %g" % num(r["nu"]), num(r["nu"])
    scene = Scene.from_summary(read_summary(run_dir))
    first = (walls or scene.contact_walls() or [None])[0]
    nu = scene.group(first).get("Friction Coefficient") if first else None
    if nu is not None:
        return "ν = %g" % nu, float(nu)
    return os.path.basename(os.path.normpath(run_dir)), float("nan")


def response_names(run_dir):
    """Role -> response name of a run: force (Boundary Force), pressure (Mean Pressure on the
    force's boundary), dead_zone (Dead Zone); a role the case lacks is left out."""
    scene = Scene.from_summary(read_summary(run_dir))
    out = {}
    force = scene.response("Boundary Force", required=False)
    if force:
        out["force"] = force
        out["pressure"] = scene.response("Mean Pressure", boundary=scene.tool_boundary(), required=False)
    out["dead_zone"] = scene.response("Dead Zone", required=False)
    return {k: v for k, v in out.items() if v}


# ------------------------------------------------------------------------------------------
# plots

def force_figure(rows, xlabel):
    """The figure of force_vs_nu.png and, per panel (response), what was drawn
    (plotting.values_with_estimates: points, error bars, DDM tangents)."""
    first = next((r["dir"] for r in rows if read_summary(r["dir"])), rows[0]["dir"])
    axisym = Scene.from_summary(read_summary(first)).axisymmetric
    names = response_names(first)  # e.g. force: ram_force, pressure: ram_pressure, dead_zone
    force = names.get("force", "ram_force")
    nu = np.array([num(r["nu"]) for r in rows])
    conv = np.array([r.get("converged") == "1" for r in rows])
    have = [names[k] for k in ("force", "pressure", "dead_zone")
            if k in names and any(np.isfinite(num(r.get(names[k]))) for r in rows)]
    check = np.array([num(r.get(force + "_p")) for r in rows])
    panels = have or [force + "_p"]
    fig, axes = plt.subplots(1, len(panels), figsize=(4.6 * len(panels), 3.8), squeeze=False)
    pressure, dead_zone = names.get("pressure"), names.get("dead_zone")
    if axisym:
        titles = {force: "ram force (whole ram, 2πr)", force + "_p": "ram force ∫ p 2πr ds",
                  pressure: "mean ram pressure", dead_zone: "dead zone volume"}
    else:
        titles = {force: "ram force (per unit depth, half section)",
                  force + "_p": "ram force ∫ p ds",
                  pressure: "mean ram pressure", dead_zone: "dead zone area"}
    order = np.argsort(nu)
    half_width = plotting.tangent_half_width(nu)
    drawn = {}
    for ax, key in zip(axes[0], panels):
        y = np.array([num(r.get(key)) for r in rows])
        eta = np.array([num(r.get(key + "_error_estimate")) for r in rows])
        slope = np.array([num(r.get(key + "_dnu")) for r in rows])
        ax.plot(nu[order], y[order], "-", color="C0", lw=1)
        drawn[key] = plotting.values_with_estimates(ax, nu[conv], y[conv], eta[conv], slope[conv], color="C0",
                                                    label=key, half_width=half_width)
        if (~conv).any():
            late = plotting.values_with_estimates(ax, nu[~conv], y[~conv], eta[~conv], slope[~conv], color="red",
                                                  label="not converged", half_width=half_width, mfc="none",
                                                  mec="red")
            for k in ("points", "bars", "segments"):
                drawn[key][k] += late[k]
        if key == force and np.isfinite(check).any():
            ax.plot(nu[order], check[order], "--", color="C1", lw=1, label="∫ p %sds on the ram" % ("2πr " if axisym else ""))
        ax.set_xlabel(xlabel)
        ax.set_title(titles.get(key, key), fontsize=10)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    return fig, drawn


def plot_force(rows, out_png, xlabel):
    """Writes force_vs_nu.png; prints, per panel, the points, error bars and tangents drawn."""
    fig, drawn = force_figure(rows, xlabel)
    plotting.save(fig, out_png, dpi=130)
    for key, d in drawn.items():
        print("%s: %s: %d points, %d error bars, %d DDM tangents"
              % (os.path.basename(out_png), key, d["points"], d["bars"], d["segments"]))
    return drawn


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
    plotting.save(fig, out_png, dpi=130)


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
    plotting.save(fig, out_png, dpi=140)


# ------------------------------------------------------------------------------------------

def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog=__doc__.split("\n", 1)[1])
    ap.add_argument("--sweep", default="out/sweep")
    ap.add_argument("--runs", nargs="+")
    ap.add_argument("--map-run")
    ap.add_argument("--out")
    ap.add_argument("--walls", default=None)
    ap.add_argument("--mesh", action="store_true")
    ap.add_argument("--xlabel", default="friction coefficient ν")
    args = ap.parse_args()
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
    if args.walls:
        walls = [w for w in args.walls.split(",") if w]
    else:  # the runs' contact walls in flow order (container, die_face, die_land)
        walls = next((plotting.walls_of_run(d) for d in run_dirs if read_summary(d)), [])
    runs = []
    for d in run_dirs:
        label, nu = run_label(d, rows, walls)
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
        label, _ = run_label(map_run, rows, walls)
        axisym = plotting.is_axisymmetric(map_run)
        tag = label.replace("ν = ", "nu_").replace(" ", "_")
        png = os.path.join(out, "fields_%s.png" % tag)
        plot_fields(map_run, label, png, args.mesh, axisym)
        written.append(png)

    for p in written:
        print(p)
    return 0


if __name__ == "__main__":
    sys.exit(main())
