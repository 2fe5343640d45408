"""The cutting scene's pictures (docs/cutting.md; the paper's figs. 5-7) from one run of
xml/cutting.xml:

  cutting_mesh.png         the converged (moved) mesh, and |u| on it (fig. 5)
  cutting_fields.png       |u| and the equivalent strain rate (log scale) near the tool (fig. 6)
  cutting_sensitivity.png  |du/dν| by DDM beside |du/dν| by finite differences (fig. 7), on the
                           converged shape (the frozen-shape derivative: the fields the run writes
                           when asked for Sensitivity/Parameters = {Friction Coefficient} with the
                           Finite Difference Check)

usage:
  scripts/python scripts/plot_cutting.py RUN [--out DIR] [--zoom X0,X1,Y0,Y1]

  RUN     a run directory of xml/cutting.xml (summary.json and solution.h5)
  --out   where the PNGs go (default: RUN)
  --zoom  the window, in the section's coordinates (default -3,1,-1,4)
"""
import argparse
import os
import sys

import numpy as np

from flowform_tools import h5io, plotting


def window(text):
    try:
        values = [float(v) for v in text.split(",")]
    except ValueError:
        values = []
    if len(values) != 4 or values[0] >= values[1] or values[2] >= values[3]:
        raise argparse.ArgumentTypeError("expected X0,X1,Y0,Y1 with X0 < X1 and Y0 < Y1")
    return values


def triangles(topology):
    """Cells as triangles (quadrilaterals split along a diagonal) for matplotlib."""
    if topology.shape[1] == 3:
        return topology
    return np.vstack([topology[:, [0, 1, 2]], topology[:, [0, 2, 3]]])


def main():
    ap = argparse.ArgumentParser(description="Pictures of a cutting run (docs/cutting.md).")
    ap.add_argument("run")
    ap.add_argument("--out", default=None)
    ap.add_argument("--zoom", type=window, default=[-3.0, 1.0, -1.0, 4.0])
    a = ap.parse_args()
    if not os.path.exists(h5io.path(a.run)):
        print(f"plot_cutting.py: {h5io.path(a.run)} does not exist (run xml/cutting.xml with Output/Write "
              f"Solution = true)", file=sys.stderr)
        return 2
    out = a.out or a.run
    os.makedirs(out, exist_ok=True)
    plt = plotting.pyplot()
    from matplotlib.colors import LogNorm
    from matplotlib.tri import Triangulation

    s = h5io.read(a.run)
    xy, topo = s.xy, s.topology
    tri = Triangulation(xy[:, 0], xy[:, 1], triangles(topo))
    speed = np.hypot(s.fields["velocity"][:, 0], s.fields["velocity"][:, 1])
    x0, x1, y0, y1 = a.zoom

    def frame(ax, title):
        ax.set_xlim(x0, x1)
        ax.set_ylim(y0, y1)
        ax.set_aspect("equal")
        ax.set_title(title)

    fig, axes = plt.subplots(1, 2, figsize=(11, 6))
    axes[0].triplot(tri, lw=0.2, color="0.3")
    frame(axes[0], "converged mesh")
    t = axes[1].tripcolor(tri, speed, shading="gouraud", cmap="viridis")
    fig.colorbar(t, ax=axes[1], label="|u|")
    frame(axes[1], "|u|")
    plotting.save(fig, os.path.join(out, "cutting_mesh.png"))

    fig, axes = plt.subplots(1, 2, figsize=(11, 6))
    t = axes[0].tripcolor(tri, speed, shading="gouraud", cmap="viridis")
    axes[0].tricontour(tri, speed, levels=12, colors="k", linewidths=0.4)
    fig.colorbar(t, ax=axes[0], label="|u|")
    frame(axes[0], "|u| (contours)")
    e = np.asarray(s.fields["strain_rate"]).ravel()
    cells = triangles(topo)
    if len(e) == len(topo):
        e = np.concatenate([e, e]) if topo.shape[1] == 4 else e
        t = axes[1].tripcolor(Triangulation(xy[:, 0], xy[:, 1], cells), facecolors=np.maximum(e, 1e-4),
                              norm=LogNorm(1e-3, max(1.0, e.max())), cmap="magma")
    else:
        t = axes[1].tripcolor(tri, np.maximum(e, 1e-4), norm=LogNorm(1e-3, max(1.0, e.max())), cmap="magma")
    fig.colorbar(t, ax=axes[1], label="equivalent strain rate")
    frame(axes[1], "equivalent strain rate (the shear zone)")
    plotting.save(fig, os.path.join(out, "cutting_fields.png"))

    if "du_dnu" in s.fields and "du_dnu_fd" in s.fields:
        ddm = np.hypot(s.fields["du_dnu"][:, 0], s.fields["du_dnu"][:, 1])
        fd = np.hypot(s.fields["du_dnu_fd"][:, 0], s.fields["du_dnu_fd"][:, 1])
        top = max(ddm.max(), fd.max())
        levels = np.linspace(0.0, top, 13)
        fig, axes = plt.subplots(1, 2, figsize=(11, 6))
        for ax, field, name in ((axes[0], fd, "finite differences"), (axes[1], ddm, "DDM")):
            t = ax.tricontourf(tri, field, levels=levels, cmap="viridis")
            ax.tricontour(tri, field, levels=levels, colors="k", linewidths=0.3)
            frame(ax, f"|du/dν| by {name}")
        fig.colorbar(t, ax=axes, label="|du/dν|", shrink=0.8)
        fig.savefig(os.path.join(out, "cutting_sensitivity.png"), dpi=130)
        plt.close(fig)
    else:
        print("plot_cutting.py: no du_dnu and du_dnu_fd fields in the run (ask for Sensitivity/Parameters = "
              "{Friction Coefficient} with the Finite Difference Check): cutting_sensitivity.png not drawn")
    print(f"plots in {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
