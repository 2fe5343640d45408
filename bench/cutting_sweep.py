"""The cutting scene (xml/cutting.xml, docs/cutting.md) over the friction coefficient: per ν the
chip ratio t/t_c, the shear angle, the tool's forces, the contact length, the balances, the
specific cutting force against Merchant's, the shear plane's equilibrium at the run's own φ
(the band's angle and mean stress, tests/regression/cutting/shear_plane.py), and the derivatives d/dν by DDM (frozen shape and
total, through the converged free surfaces) against central finite differences (frozen shape and
with the surfaces re-converged); the cost of each run.

usage: scripts/python bench/cutting_sweep.py [FLOWFORM] [--nu 0,0.1,0.2,0.3,0.5] [--h 0.1] [--workdir DIR]
                              [--sets PATH=VALUE ...] [--plot DIR] [--reuse]

The runs skip the case's two-level error estimate (--sets "Error Estimation/Method=Two-Level"
makes it: about 75 s more per ν with the sensitivities). Writes DIR/sweep.json and prints a markdown table (docs/cutting.md §5). --plot DIR draws
cutting_sweep.png there: t/t_c and F_c/(k t) against ν with the Lee-Shaffer and Merchant curves,
the DDM's total derivative as a tangent at each point and the re-converged FD as markers.

k, the shear flow stress at the shear zone's rate: the plastic power over ∫ e dΩ (the rate-
weighted mean flow stress σ̄ of the deforming material) over √3.
"""
import argparse
import json
import math
import os
import sys
import time

import numpy as np

from cutting import rules, shear_plane
from flowform_tools import h5io, launcher, machine, plotting, summary, sweep
from flowform_tools.tables import markdown


def strain_rate_integral(outdir):
    """∫ e dΩ over the converged (moved) mesh: cell-wise strain rates times the cells' areas."""
    s = h5io.read(outdir, ["strain_rate"])
    xy, topo = s.xy, s.topology
    e = np.asarray(s.fields["strain_rate"]).ravel()
    total = 0.0
    for c, cell in enumerate(topo):
        p = xy[cell]
        area = 0.0
        for i in range(len(cell)):  # shoelace: triangles and quadrilaterals
            j = (i + 1) % len(cell)
            area += p[i][0] * p[j][1] - p[j][0] * p[i][1]
        total += 0.5 * abs(area) * (e[c] if len(e) == len(topo) else np.mean(e[cell]))
    return total


def derivative(s, name):
    fd = ((s.get("fd_check") or {}).get(name) or {}).get("Friction Coefficient") or {}
    return {"ddm": fd.get("ddm"), "fd": fd.get("fd"), "ddm_total": fd.get("ddm_total_shape"),
            "fd_moving": fd.get("fd_moving_shape"), "one_sided": fd.get("one_sided")}


def run_one(flowform, case, workdir, nu, h, extra, reuse=False):
    out = os.path.join(workdir, sweep.label(nu))
    previous = summary.load(out) if reuse else None
    sets = [f"Boundary Conditions/rake/Friction Coefficient={nu}", f"Mesh/Geo Parameters/h={h}", "Mesh/Uniform Refinements=0",
            "Sensitivity/Parameters={Friction Coefficient}", "Sensitivity/Finite Difference Check=true",
            "Sensitivity/Finite Difference Step=2e-4", "Error Estimation/Method=None"] + list(extra)
    if previous and previous.get("exit_status") == 0:
        s, status = previous, 0  # --reuse: a converged run of an earlier sweep
        seconds = (s.get("timings") or {}).get("total", 0.0)
    else:
        start = time.monotonic()
        status = launcher.run(flowform, case, out, sets, quiet=True, clean=True).status
        seconds = time.monotonic() - start
        s = summary.load(out) or {}
    f = s.get("functionals") or {}
    row = {"nu": nu, "exit": status, "seconds": seconds, "dir": out,
           "updates": s.get("free_surface_iterations"), "newton": s.get("newton_iterations"),
           "timings": s.get("timings"), "functionals": f}
    if status == 0:
        dissipation = sum(f[k] for k in ("plastic_power", "friction_power", "penalty_power", "stabilization_power"))
        row["power_residual"] = (f["drive_power"] - dissipation) / f["drive_power"]
        k = f["plastic_power"] / strain_rate_integral(out) / math.sqrt(3.0)
        row["k"] = k
        row["specific_force"] = f["cutting_force"] / k
        row["specific_drive_force"] = f["drive_force"] / k
        row["band"] = shear_plane.plane_state(out, f)
        row["d"] = {name: derivative(s, name) for name in ("chip_ratio", "cutting_force", "thrust_force",
                                                           "drive_force", "shear_angle")}
    return row


def fmt(x, spec=".4f"):
    return "-" if x is None else format(x, spec)


def table(rows):
    print("| ν | exit | updates | s | t/t_c | Lee-Shaffer | Merchant | φ° | F_c | F_t | F_t/F_c | contact length "
          "| chip flux | power residual | k | F_c/(k t) | drive/(k t) | Merchant 2(√(1+ν²)+ν) |")
    print("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for r in rows:
        f = r["functionals"]
        if r["exit"] != 0:
            print(f"| {r['nu']} | {r['exit']} | {r['updates']} | {r['seconds']:.0f} |" + " - |" * 14)
            continue
        print(f"| {r['nu']} | 0 | {r['updates']} | {r['seconds']:.0f} | {f['chip_ratio']:.4f} | "
              f"{rules.lee_shaffer_chip_ratio(r['nu']):.4f} | {rules.merchant_chip_ratio(r['nu']):.4f} | {f['shear_angle']:.2f} | "
              f"{f['cutting_force']:.4f} | {f['thrust_force']:.4f} | {f['thrust_force'] / f['cutting_force']:.4f} | "
              f"{f['contact_length']:.3f} | {f['chip_flux']:.4f} | {r['power_residual']:.1e} | {r['k']:.4f} | "
              f"{r['specific_force']:.3f} | {r['specific_drive_force']:.3f} | {rules.merchant_force(r['nu']):.3f} |")
    print()
    body = []
    for r in rows:
        if r["exit"] != 0:
            continue
        c, F = r["d"]["chip_ratio"], r["d"]["cutting_force"]
        nu = r["nu"]
        body.append([f"{nu}", fmt(c["ddm_total"]), fmt(c["fd_moving"]), f"{rules.merchant_chip_ratio_derivative(nu):.4f}",
                     f"{rules.lee_shaffer_chip_ratio_derivative(nu):.4f}", fmt(F["ddm"]), fmt(F["fd"]), fmt(F["ddm_total"]),
                     fmt(F["fd_moving"])])
    print(markdown(["ν", "d(t/t_c)/dν total DDM", "FD re-converged", "Merchant", "Lee-Shaffer", "dF_c/dν frozen DDM",
                    "frozen FD", "total DDM", "FD re-converged"], body, "---:"), end="")
    print()
    print("The shear plane at the model's own φ (tests/regression/cutting/shear_plane.py): the band read off the strain "
          "rate, its mean stress p over k = σ̄/√3 there against tan(φ + θ), tan θ = F_t / drive force, and the drive "
          "force against the plane's cos θ / (sin φ cos(φ + θ)); Lee-Shaffer's and Merchant's planes would carry "
          "p/k = tan(45°) = 1 and tan(45° + λ/2).")
    print()
    body = []
    for r in rows:
        if r["exit"] != 0:
            continue
        b, nu = r["band"], r["nu"]
        merchant_plane = rules.merchant_normal_stress_ratio(nu)
        body.append([f"{nu}", f"{r['functionals']['shear_angle']:.2f}", f"{b['angle']:.2f}", f"{b['theta']:.2f}",
                     f"{b['k']:.4f}", f"{b['p_over_k']:.4f}", f"{b['p_over_k_plane']:.4f}", f"{merchant_plane:.4f}",
                     f"{b['drive_over_kt']:.3f}", f"{b['drive_over_kt_plane']:.3f}"])
    print(markdown(["ν", "φ° (chip ratio)", "band angle°", "θ°", "k (band)", "p/k band", "tan(φ + θ)",
                    "Merchant's plane p/k", "drive/(k t)", "plane's cos θ/(sin φ cos(φ+θ))"], body, "---:"), end="")
    print()
    print("The derivatives' sizes: the plane's force relation differentiated with the run's own dφ/dν (from the "
          "total DDM d(t/t_c)/dν) and dθ/dν (from dF_t/dν and d(drive)/dν), against the DDM's d(drive)/dν "
          "(shear_plane.force_derivative; Merchant's rule has dφ/dν = −1/(2(1+ν²))).")
    print()
    body = []
    for r in rows:
        d = r.get("d") or {}
        total = {n: (d.get(n) or {}).get("ddm_total") for n in ("chip_ratio", "drive_force", "thrust_force")}
        if r["exit"] != 0 or any(v is None for v in total.values()):
            continue
        nu = r["nu"]
        dphi, dtheta, plane = shear_plane.run_derivatives(r["functionals"], total)
        body.append([f"{nu}", f"{dphi:.4f}", f"{rules.merchant_shear_angle_derivative(nu):.4f}", f"{dtheta:.4f}",
                     f"{rules.friction_angle_derivative(nu):.4f}",
                     f"{total['drive_force']:.4f}", f"{plane:.4f}", f"{100.0 * (plane / total['drive_force'] - 1.0):+.1f} %"])
    print(markdown(["ν", "dφ/dν (rad)", "Merchant's rule", "dθ/dν", "full sliding", "d(drive)/dν total DDM",
                    "the plane's", ""], body, "---:"), end="")


def plot(rows, outdir):
    plt = plotting.pyplot()
    ok = [r for r in rows if r["exit"] == 0]
    nus = np.linspace(0.0, max(r["nu"] for r in rows) + 0.05, 100)
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    ax = axes[0]
    ax.plot(nus, [rules.lee_shaffer_chip_ratio(n) for n in nus], "k--", label="Lee-Shaffer (1-ν)/(1+ν)")
    ax.plot(nus, [rules.merchant_chip_ratio(n) for n in nus], "k:", label="Merchant √(1+ν²)-ν")
    ax.plot([r["nu"] for r in ok], [r["functionals"]["chip_ratio"] for r in ok], "o-", label="flowform")
    for r in ok:
        d = r["d"]["chip_ratio"]
        if d["ddm_total"] is not None:
            x = np.array([r["nu"] - 0.04, r["nu"] + 0.04])
            ax.plot(x, r["functionals"]["chip_ratio"] + d["ddm_total"] * (x - r["nu"]), "r-", lw=2)
        if d["fd_moving"] is not None:
            ax.plot(r["nu"] + 0.04, r["functionals"]["chip_ratio"] + d["fd_moving"] * 0.04, "kx")
    ax.set_xlabel("ν")
    ax.set_ylabel("t / t_c")
    ax.set_title("chip ratio (red: DDM total derivative, x: FD re-converged)")
    ax.legend(fontsize=8)
    ax = axes[1]
    ax.plot(nus, [rules.merchant_force(n) for n in nus], "k:", label="Merchant 2(√(1+ν²)+ν)")
    ax.plot([r["nu"] for r in ok], [r["specific_force"] for r in ok], "o-", label="F_c/(k t) at the rake")
    ax.plot([r["nu"] for r in ok], [r["specific_drive_force"] for r in ok], "s-", label="drive force/(k t)")
    for r in ok:
        d = r["d"]["cutting_force"]
        if d["ddm_total"] is not None:
            x = np.array([r["nu"] - 0.04, r["nu"] + 0.04])
            ax.plot(x, r["specific_force"] + d["ddm_total"] / r["k"] * (x - r["nu"]), "r-", lw=2)
        if d["fd_moving"] is not None:
            ax.plot(r["nu"] + 0.04, r["specific_force"] + d["fd_moving"] / r["k"] * 0.04, "kx")
    ax.set_xlabel("ν")
    ax.set_ylabel("F / (k t)")
    ax.set_title("specific cutting force")
    ax.legend(fontsize=8)
    for a in axes:
        plotting.grid(a)
    os.makedirs(outdir, exist_ok=True)
    plotting.save(fig, os.path.join(outdir, "cutting_sweep.png"))


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap = argparse.ArgumentParser()
    ap.add_argument("flowform", nargs="?", default=os.path.join(root, "build/flowform"))
    ap.add_argument("--nu", type=sweep.parse_values, default=[0.0, 0.1, 0.2, 0.3, 0.5])
    ap.add_argument("--h", default="0.1")
    ap.add_argument("--workdir", default="/tmp/flowform_cutting_sweep")
    ap.add_argument("--sets", nargs="*", default=[])
    ap.add_argument("--plot", default=None)
    ap.add_argument("--reuse", action="store_true",
                    help="keep the converged runs already in --workdir (their time is flowform's own total)")
    a = ap.parse_args()
    info = machine.machine_info()
    print(f"# {info.get('date')}, commit {info.get('commit')}, {info.get('Model name')} x {info.get('CPU(s)')}, "
          f"load {machine.load():.2f}, h = {a.h}")
    rows = [run_one(a.flowform, os.path.join(root, "xml/cutting.xml"), a.workdir, nu, a.h, a.sets, a.reuse)
            for nu in a.nu]
    os.makedirs(a.workdir, exist_ok=True)
    with open(os.path.join(a.workdir, "sweep.json"), "w") as f:
        json.dump(rows, f, indent=1)
    table(rows)
    if a.plot:
        plot(rows, a.plot)
    return 0 if all(r["exit"] == 0 for r in rows) else 1


if __name__ == "__main__":
    sys.exit(main())
