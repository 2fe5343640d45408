"""Plots of runs with free surfaces (docs/theory.md §3) from flowform's outputs.

  free_surface_<run>.png   |u| on the converged (moved) mesh with the free surfaces drawn over it,
                           and the loop's history: max |u.n|/|u| and the largest node move per
                           surface update (log scale)
  surfaces.png             the converged surfaces of all the runs together (e.g. the swell for
                           n = 1, 2, 5), with the surface as meshed (dashed), labelled by --labels
                           or the runs' names

usage:
  scripts/python scripts/plot_free_surface.py RUN [RUN ...] [--out DIR] [--labels A,B,...] [--zoom X0,X1,Y0,Y1]

  RUN      a run directory (summary.json, solution.h5 and the boundary CSVs)
  --out    where the PNGs go (default: the first run's directory)
  --zoom   the window of the |u| maps, in the section's coordinates (default: the whole mesh)

The free surfaces are the groups of Type Free Surface and the contact walls whose Released
Nodes are Free Surface (read from each run's summary.json parameters). Needs numpy,
matplotlib, h5py (Debian: python3-numpy python3-matplotlib python3-h5py).
"""
import argparse
import os
import sys

import numpy as np

from flowform_tools import plotting


def surface_groups(summary):
    groups = []
    for name, bc in ((summary.get("parameters") or {}).get("Boundary Conditions") or {}).items():
        if not isinstance(bc, dict):
            continue
        if bc.get("Type") == "Free Surface" or bc.get("Released Nodes") == "Free Surface":
            groups.append(name)
    return groups


def field_map(run, out, zoom):
    plt = plotting.pyplot()
    summary = plotting.run_summary(run)
    xy, topo, fields = plotting.read_solution(run)
    tri, _ = plotting.triangulate(xy, topo)
    speed = np.hypot(fields["velocity"][:, 0], fields["velocity"][:, 1])
    fig, (ax, hist) = plt.subplots(1, 2, figsize=(13, 4.2), gridspec_kw={"width_ratios": [2.2, 1]})
    im = ax.tripcolor(tri, speed, shading="gouraud", cmap="viridis")
    fig.colorbar(im, ax=ax, label="|u|")
    for group in surface_groups(summary):
        wall = plotting.read_wall(run, group)
        if wall is not None:
            ax.plot(wall["x"], wall["y"], "w-", lw=1.5, label=group)
    ax.set_aspect("equal")
    if zoom:
        ax.set_xlim(zoom[0], zoom[1])
        ax.set_ylim(zoom[2], zoom[3])
    ax.set_title(f"{os.path.basename(os.path.normpath(run))}: |u| on the converged mesh")
    history = (summary.get("free_surface") or {}).get("history") or []
    if history:
        k = np.arange(len(history))
        hist.semilogy(k, [max(h["flow_angle"], 1e-16) for h in history], "o-", label="max |u·n|/|u|")
        hist.semilogy(k, [max(h["move"], 1e-16) for h in history], "s-", label="node move")
        hist.set_xlabel("surface update")
        hist.legend()
        hist.grid(True, which="both", alpha=0.3)
    hist.set_title(f"{summary.get('free_surface_iterations')} updates")
    plotting.save(fig, os.path.join(out, f"free_surface_{os.path.basename(os.path.normpath(run))}.png"))


def profiles(runs, labels, out):
    plt = plotting.pyplot()
    fig, ax = plt.subplots(figsize=(8, 4))
    for run, label in zip(runs, labels):
        summary = plotting.run_summary(run)
        for group in surface_groups(summary):
            wall = plotting.read_wall(run, group)
            if wall is None:
                continue
            axisym = plotting.is_axisymmetric(run)
            along, across = (wall["y"], wall["x"]) if axisym else (wall["x"], wall["y"])
            order = np.argsort(along)
            ax.plot(along[order], across[order], "-", label=f"{label} ({group})")
    ax.set_xlabel("z" if runs and plotting.is_axisymmetric(runs[0]) else "x")
    ax.set_ylabel("r" if runs and plotting.is_axisymmetric(runs[0]) else "y")
    ax.grid(True, alpha=0.3)
    ax.legend()
    ax.set_title("converged free surfaces")
    plotting.save(fig, os.path.join(out, "surfaces.png"))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("runs", nargs="+")
    parser.add_argument("--out")
    parser.add_argument("--labels")
    parser.add_argument("--zoom")
    args = parser.parse_args()
    out = plotting.out_dir(args.out or args.runs[0])
    labels = args.labels.split(",") if args.labels else [os.path.basename(os.path.normpath(r)) for r in args.runs]
    zoom = [float(v) for v in args.zoom.split(",")] if args.zoom else None
    for run in args.runs:
        field_map(run, out, zoom)
    profiles(args.runs, labels, out)
    print(f"plots in {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
