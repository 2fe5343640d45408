"""Plots of the friction sensitivity of the extrusion (paper figs. 3b and 4, docs/sensitivity.md)
from a friction sweep run with sensitivities and their finite-difference check:

  scripts/python scripts/sweep_friction.py --out out/sweep_ddm --set "Sensitivity/Parameters={Friction Coefficient}" \\
      --set "Sensitivity/Finite Difference Check=true"
  scripts/python scripts/plot_sensitivity.py --sweep out/sweep_ddm

  force_sensitivity.png   ram force F and dF/dν against ν: DDM (line) and central differences
                          (open markers; red where the check found a node switching state)
  wall_sensitivity.png    du_t/dν along the walls container -> die_face -> die_land (u_t along
                          the material flow), DDM full and FD dotted, one colour per ν

usage: scripts/python scripts/plot_sensitivity.py [--sweep out/sweep] [--out DIR] [--parameter NAME]
                                   [--response NAME] [--walls W1,W2,...]

  --response  default: the runs' Boundary Force response (ram_force)
  --walls     default: the runs' Contact Wall groups in flow order (container, die_face,
              die_land), as in scripts/plot_extrusion.py
Needs numpy, matplotlib (Debian's /usr/bin/python3) and python/flowform_tools.
"""
import argparse
import os
import sys

import numpy as np

from flowform_tools import plotting
from flowform_tools.case import Scene
from flowform_tools.plotting import oriented_column, run_summary as read_summary
from flowform_tools.sweep import num, read as read_sweep

plt = plotting.pyplot()


def short(parameter):
    """ν, m, σ0, γ, n for the axis labels."""
    names = {"Friction Coefficient": "ν", "Shear Factor": "m", "Yield Stress": "σ0", "Rate Constant": "γ",
             "Rate Exponent": "n"}
    base, _, wall = parameter.partition(":")
    return names.get(base, base) + ("(%s)" % wall if wall else "")


def symbol_of(summary, parameter):
    for p in summary.get("sensitivity", {}).get("parameters", []):
        if p["name"] == parameter:
            return p["symbol"]
    return None


def plot_force(rows, parameter, response, out_png):
    nus, F, ddm, fd, one_sided = [], [], [], [], []
    for r in rows:
        s = read_summary(r["dir"])
        entry = s.get("fd_check", {}).get(response, {}).get(parameter)
        d = s.get("sensitivities", {}).get(response, {}).get(parameter)
        if d is None or not s.get("converged"):
            continue
        nus.append(num(r["nu"]))
        F.append(s["functionals"][response])
        ddm.append(d)
        fd.append(entry["fd"] if entry and entry.get("fd") is not None else np.nan)
        one_sided.append(bool(entry and entry.get("one_sided")))
    if not nus:
        print("plot_sensitivity: no run with %s sensitivities of %s" % (parameter, response), file=sys.stderr)
        return
    order = np.argsort(nus)
    nus, F, ddm, fd, one_sided = (np.array(a)[order] for a in (nus, F, ddm, fd, one_sided))
    fig, (ax_f, ax_d) = plt.subplots(2, 1, figsize=(7, 7), sharex=True)
    ax_f.plot(nus, F, "o-", color="C0")
    ax_f.set_ylabel(response)
    ax_d.plot(nus, ddm, "-", color="C0", label="DDM")
    ok = ~one_sided
    ax_d.plot(nus[ok], fd[ok], "o", mfc="none", color="k", label="central differences")
    if one_sided.any():
        ax_d.plot(nus[one_sided], fd[one_sided], "o", mfc="none", color="red", label="one-sided (a node switches)")
    ax_d.set_ylabel("d %s / d%s" % (response, short(parameter)))
    ax_d.set_xlabel("friction coefficient ν")
    ax_d.legend(fontsize=9)
    plotting.grid(ax_f, ax_d)
    plotting.save(fig, out_png, dpi=130)


def plot_walls(rows, parameter, walls, out_png):
    fig, ax = plt.subplots(figsize=(9, 4.5))
    cmap = plt.get_cmap("viridis")
    drawn = 0
    for k, r in enumerate(rows):
        s = read_summary(r["dir"])
        sym = symbol_of(s, parameter)
        if not sym or not s.get("converged"):
            continue
        color = cmap(k / max(1, len(rows) - 1))
        S, ddm = oriented_column(r["dir"], walls, "du_t_d" + sym)
        if S is None:
            continue
        ax.plot(S, ddm, "-", color=color, lw=1.2, label="ν = %g" % num(r["nu"]))
        S, fd = oriented_column(r["dir"], walls, "du_t_d" + sym + "_fd")
        if S is not None:
            ax.plot(S, fd, ":", color="k", lw=1.0, label="central differences" if drawn == 0 else None)
        drawn += 1
    ax.set_xlabel("arc length along the walls from the ram corner (" + " → ".join(walls) + ")")
    ax.set_ylabel("du_t / d%s along the flow" % short(parameter))
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, ncol=2)
    plotting.save(fig, out_png, dpi=130)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sweep", default=os.path.join("out", "sweep"))
    parser.add_argument("--out", default=None)
    parser.add_argument("--parameter", default="Friction Coefficient")
    parser.add_argument("--response", default=None)
    parser.add_argument("--walls", default=None)
    args = parser.parse_args()
    rows = read_sweep(args.sweep)
    if not rows:
        print("plot_sensitivity: no sweep.csv in %s" % args.sweep, file=sys.stderr)
        return 2
    out = args.out or args.sweep
    os.makedirs(out, exist_ok=True)
    first = next((r["dir"] for r in rows if read_summary(r["dir"])), None)
    walls = args.walls.split(",") if args.walls else (plotting.walls_of_run(first) if first else [])
    response = args.response or (Scene.from_summary(read_summary(first)).tool_force() if first else "ram_force")
    plot_force(rows, args.parameter, response, os.path.join(out, "force_sensitivity.png"))
    plot_walls(rows, args.parameter, walls, os.path.join(out, "wall_sensitivity.png"))
    print("plots in %s" % out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
