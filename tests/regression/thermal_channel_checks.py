"""The temperature field against the exact fully developed channel (docs/verification.md §19).

xml/thermal_channel.xml: the power-law channel |y| <= H = 1 (σ̄ = σ0 + (e_r/γ)^(1/n), σ0 = 0.5,
γ = 1, n = 5, e_r = sqrt(e² + e0²), e0 = 1e-3) driven by the pressure gradient G = 1, walls at
T_w = 1, inlet and outlet insulated, all the plastic power heating the metal (η = 1), k = ρc = 1.

The exact solution (derived here, not by flowform). Fully developed: u = u(y) e_x, T = T(y), so
u·∇T = 0 and the energy balance is k T'' = −η q(y), T(±H) = T_w, T'(0) = 0. The shear stress is
|s_xy| = G|y| (equilibrium) and |s_xy| = σ̄(e_r) e / (√3 e_r) with e = |u'|/√3 (the law), so at
each y the rate e solves √3 G|y| = σ̄(e_r) e / e_r (monotone in e: bisection), and the plastic
power density is q = s:D = σ̄ e² / e_r. Then

    T(y) = T_w + (η/k) ∫_|y|^H Q(t) dt,   Q(t) = ∫_0^t q(s) ds,

integrated by the trapezoid rule on 40 001 points (relative error ~1e-9, far below the FE's).
With e0 → 0 this is the closed form T_w + (η γ/(k 3G²)) [(S^(n+3) − s^(n+3))/((n+2)(n+3)) +
σ0 (S^(n+2) − s^(n+2))/((n+1)(n+2))], s = √3G|y| − σ0, S = √3GH − σ0 (the docs' formula; at
e0 = 1e-3 the two differ by 5e-4 of the rise, which is why the regularized one is the reference).

Asserted (subcommand convergence, N = 8, 16, 32 cells across the height):
- the largest nodal error max|T_h − T| falls with order >= 1.8 on the finest pair: the velocity's
  L2 order is 2 (docs/verification.md §3) and T integrates q twice; 0.2 below 2 covers the
  pre-asymptotic spread (measured orders in docs/verification.md §19);
- at N = 32 the largest error is at most 2e-2 of the temperature rise T(0) − T_w (measured 1.6e-2);
- the heat leaving through the walls balances the plastic heat: |Q_top + Q_bottom − η P| <=
  1e-3 η P. The discrete identity is Σ Q = ∫ q − ∫ a·∇T_h (HeatFlow.hpp): the second term
  vanishes for the exact T and is a discretization error of T_h (measured 5e-5 at N = 16);
- the two walls' heat flows are equal to 1e-8 (the problem is symmetric in y; the mesh too).

Subcommand adiabatic (the adiabatic limit): the same channel with its walls insulated and the
inlet held at T_in = 1 (the shipped case edited: the walls' Temperature moved to the inlet).
No heat leaves through the walls, so the product's mean (flux-weighted) exit temperature rise is
(η P − Q_in) / (ρc Q), P the plastic power, Q_in the heat conducted back out through the inlet
(its Heat Flow), Q the flux. Asserted at N = 8, 16, 32 for ρc = 1 (42 % of the heat conducted
back out at the inlet) and ρc = 100 (1 %): the relative difference falls with order >= 1.5 on
the finest pair and is at most 1e-3 (ρc = 1) and 5e-3 (ρc = 100) at N = 32 (measured 4.4e-4 and
2.5e-3, orders 2.0 and 2.1: the lumped mean temperature and ∫ a·∇T_h are second order).

Subcommand transfer (heat transfer to the surroundings): the walls' prescribed temperature replaced
by a Heat Transfer Coefficient h = 2 to an Ambient Temperature T_a = 1. The wall then passes the
heat made in the half-channel, −k T'(H) = η Q(H) = h (T(H) − T_a), so the exact profile is the
held-wall one shifted by η Q(H)/h. Asserted as in convergence: finest-pair order >= 1.8 and the
N = 32 error at most 2e-2 of the rise (measured in docs/verification.md §19), the walls' Heat Flow
(now ∫ h (T − T_a)) equal to the plastic heat within 1e-3.

Subcommand isothermal: xml/channel.xml has 3 dofs per node (no Temperature field without
Material/Thermal), and the same flow with the field has 4 and the same velocities to 1e-10 (the
flow does not read T).

usage: thermal_channel_checks.py {convergence|adiabatic|transfer|isothermal} FLOWFORM SOURCE_DIR OUTDIR
"""
import json
import math
import os
import sys

import numpy as np

from flowform_tools import h5io, launcher
from flowform_tools.checks import check, verdict

G, H, SIGMA0, GAMMA, N_EXP, E0 = 1.0, 1.0, 0.5, 1.0, 5.0, 1e-3
K, ETA, T_WALL = 1.0, 1.0, 1.0


def flow_stress(er):
    return SIGMA0 + (er / GAMMA) ** (1.0 / N_EXP)


def strain_rate_profile(points=40001):
    """(y, e(y)) on [0, H]: the fully developed channel's equivalent strain rate, from
    √3 G y = σ̄(e_r) e / e_r by bisection (monotone in e)."""
    y = np.linspace(0.0, H, points)
    target = math.sqrt(3.0) * G * y
    lo, hi = np.zeros_like(y), np.full_like(y, 1e3)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        er = np.sqrt(mid * mid + E0 * E0)
        above = flow_stress(er) * mid / er > target
        hi = np.where(above, mid, hi)
        lo = np.where(above, lo, mid)
    return y, 0.5 * (lo + hi)


def exact_profile(points=40001):
    """(y, T(y)) on [0, H] for the regularized law, and the plastic power per unit length ∫ q dy over |y| <= H."""
    y, e = strain_rate_profile(points)
    er = np.sqrt(e * e + E0 * E0)
    q = flow_stress(er) * e * e / er
    dy = np.diff(y)
    Q = np.concatenate([[0.0], np.cumsum(0.5 * (q[1:] + q[:-1]) * dy)])
    inner = np.concatenate([[0.0], np.cumsum(0.5 * (Q[1:] + Q[:-1]) * dy)])
    T = T_WALL + ETA / K * (inner[-1] - inner)
    return y, T, 2.0 * Q[-1]


def run(flowform, case, outdir, n, extra=()):
    r = launcher.run(flowform, case, outdir, [f"Mesh/Geo Parameters/N={n}"], args=list(extra), quiet=True)
    if r.status != 0:
        raise SystemExit(f"flowform exited {r.status} on N = {n}")
    return r


H_TRANSFER = 2.0


def edited_case(source, outdir, name, wall_entry):
    """The shipped case with each wall's '<Temperature 1>' replaced by `wall_entry` (XML lines),
    the mesh path made absolute."""
    with open(os.path.join(source, "xml", "thermal_channel.xml")) as f:
        text = f.read()
    held = '      <Parameter name="Temperature" type="double" value="1.0"/>      <!-- T_w -->\n'
    if text.count(held) != 2:
        raise SystemExit("xml/thermal_channel.xml no longer has the two wall temperatures this check edits")
    text = text.replace(held, wall_entry)
    text = text.replace('"../meshes/channel.geo"', '"' + os.path.join(source, "meshes", "channel.geo") + '"')
    path = os.path.join(outdir, name)
    with open(path, "w") as f:
        f.write(text)
    return path


def convergence(flowform, source, outdir, transfer=False):
    case = os.path.join(source, "xml", "thermal_channel.xml")
    y, T, _ = exact_profile()
    if transfer:
        case = edited_case(source, outdir, "transfer_channel.xml",
                           f'      <Parameter name="Heat Transfer Coefficient" type="double" value="{H_TRANSFER}"/>\n'
                           '      <Parameter name="Ambient Temperature" type="double" value="1.0"/>\n')
        _, _, plastic_per_length = exact_profile()
        T = T + ETA * 0.5 * plastic_per_length / H_TRANSFER  # the wall's own rise η Q(H)/h
    rise = T[0] - T_WALL
    failed, errors = 0, []
    for n in (8, 16, 32):
        r = run(flowform, case, os.path.join(outdir, f"N{n}"), n)
        sol = h5io.read(os.path.join(outdir, f"N{n}"), ["temperature"])
        Th = sol.fields["temperature"].ravel()
        err = np.abs(Th - np.interp(np.abs(sol.xy[:, 1]), y, T)).max()
        errors.append(err)
        f = r.summary["functionals"]
        # The channel is 4 long: the plastic heat per unit depth is 4 ∫ q dy.
        heat, plastic = f["heat_top"] + f["heat_bottom"], f["plastic_power"]
        order = math.log2(errors[-2] / err) if len(errors) > 1 else float("nan")
        print(f"N = {n:3d}: max|T_h - T| = {err:.4e} ({err / rise:.3e} of the rise {rise:.5f}), order {order:.2f}; "
              f"heat out {heat:.8f}, plastic heat {ETA * plastic:.8f}, mismatch {abs(heat - ETA * plastic) / (ETA * plastic):.2e}; "
              f"Newton {r.summary['newton_iterations']}")
        failed += check(abs(heat - ETA * plastic) <= 1e-3 * ETA * plastic, f"N = {n}: energy balance within 1e-3")
        failed += check(abs(f["heat_top"] - f["heat_bottom"]) <= 1e-8 * abs(f["heat_top"]), f"N = {n}: symmetric heat flows")
    order = math.log2(errors[-2] / errors[-1])
    failed += check(order >= 1.8, f"finest-pair order {order:.2f} >= 1.8")
    failed += check(errors[-1] <= 2e-2 * rise, f"N = 32 error {errors[-1] / rise:.3e} of the rise <= 2e-2")
    return failed


def adiabatic_case(source, outdir):
    """The shipped case with its walls insulated and the inlet held at T_w."""
    path = edited_case(source, outdir, "adiabatic_channel.xml", "")
    with open(path) as f:
        text = f.read()
    inlet = '    <ParameterList name="inlet">\n      <Parameter name="Type" type="string" value="Velocity"/>\n'
    if text.count(inlet) != 1:
        raise SystemExit("xml/thermal_channel.xml no longer has the inlet this check edits")
    text = text.replace(inlet, inlet + '      <Parameter name="Temperature" type="double" value="1.0"/>\n')
    with open(path, "w") as f:
        f.write(text)
    return path


def adiabatic(flowform, source, outdir):
    case = adiabatic_case(source, outdir)
    responses = ["Responses/inlet_heat/Type=Heat Flow", "Responses/inlet_heat/Boundary=inlet",
                 "Responses/exit_temperature/Type=Mean Temperature", "Responses/exit_temperature/Boundary=outlet",
                 "Responses/flux/Type=Flow Rate", "Responses/flux/Boundary=outlet"]
    failed = 0
    for rho_c, bound in ((1.0, 1e-3), (100.0, 5e-3)):
        differences = []
        for n in (8, 16, 32):
            out = os.path.join(outdir, f"rc{rho_c:g}_N{n}")
            r = run(flowform, case, out, n, launcher.set_args(responses + [f"Material/Thermal/Density={rho_c}"]))
            f = r.summary["functionals"]
            predicted = (ETA * f["plastic_power"] - f["inlet_heat"]) / (rho_c * f["flux"])
            rise = f["exit_temperature"] - T_WALL
            differences.append(abs(rise / predicted - 1.0))
            print(f"rho c = {rho_c:g}, N = {n:3d}: exit rise {rise:.8f}, (eta P - Q_in)/(rho c Q) {predicted:.8f}, "
                  f"difference {differences[-1]:.3e}; {f['inlet_heat'] / (ETA * f['plastic_power']):.1%} of the heat "
                  f"back out through the inlet")
        order = math.log2(differences[-2] / differences[-1])
        failed += check(order >= 1.5, f"rho c = {rho_c:g}: finest-pair order {order:.2f} >= 1.5")
        failed += check(differences[-1] <= bound, f"rho c = {rho_c:g}: N = 32 difference {differences[-1]:.2e} <= {bound:g}")
    return failed


def isothermal(flowform, source, outdir):
    failed = 0
    plain = run(flowform, os.path.join(source, "xml", "channel.xml"), os.path.join(outdir, "plain"), 16)
    thermal = run(flowform, os.path.join(source, "xml", "thermal_channel.xml"), os.path.join(outdir, "thermal"), 16)
    nodes = plain.summary["mesh"]["nodes"]
    failed += check(plain.summary["dofs"] == 3 * nodes, f"channel.xml: {plain.summary['dofs']} dofs = 3 x {nodes} nodes")
    failed += check(thermal.summary["dofs"] == 4 * nodes, f"thermal_channel.xml: {thermal.summary['dofs']} dofs = 4 x {nodes}")
    u0 = h5io.read(os.path.join(outdir, "plain"), ["velocity"]).fields["velocity"]
    u1 = h5io.read(os.path.join(outdir, "thermal"), ["velocity"]).fields["velocity"]
    diff = np.abs(u0 - u1).max() / np.abs(u0).max()
    failed += check(diff <= 1e-10, f"the same velocities with the field: {diff:.2e} <= 1e-10")
    return failed


def main():
    what, flowform, source, outdir = sys.argv[1:5]
    os.makedirs(outdir, exist_ok=True)
    checks = {"convergence": convergence, "adiabatic": adiabatic, "isothermal": isothermal,
              "transfer": lambda *a: convergence(*a, transfer=True)}
    failed = checks[what](flowform, source, outdir)
    return verdict(failed)


if __name__ == "__main__":
    sys.exit(main())
