"""The rolling scene against the slab method (docs/rolling.md §7, docs/rolling_theory.md):
xml/rolling_flat.xml (the strip's surfaces flat) with Coulomb on the contact force (τ = ν σ_n, the slab's law), on the coarse mesh
h = 0.1, hc = 0.04 (≈ 1240 dofs), compared with rolling_theory.solve (Coulomb, exact arc, σ̄ at the
mean strain rate) at the run's own pass through flowform_tools.rolling_compare.

usage: rolling_slab_checks.py SUBCOMMAND FLOWFORM SOURCE_DIR OUTDIR [--perturbed]

Tolerances: the FE departs from the slab method by a systematic amount (shear through the
thickness, the entry corner, the rate term), which is what is measured, not zero. Each check
asserts that the departure d = FE/slab − 1 lies in a band: the range of d measured on the mesh
family h = 0.1, 0.05, 0.035 (hc = h/2.5; `scripts/rolling_study.py --parts mesh`), widened on
each side by the last change of d between h = 0.05 and 0.035 (an estimate of the discretization
error still in the finest d) and by 0.5 % (headroom, a choice: a tenth of the change of the torque's
departure from ν = 0.2 to 0.3). The measured values are in BANDS' comments. A change of the FE's physics by a few per cent (the friction law, the flow
stress, the arc) leaves the band: --perturbed compares the ν = 0.2 run with the slab method at
1.5 ν and must fail (ctest rolling_slab_perturbed, WILL_FAIL).

nu      (default run, 2 coarse runs, ν = 0.2 and 0.3 at R = 10, h0 = 1, h1 = 0.75)
  1. Roll force and torque within their bands at both ν.
  2. Trends: force, torque, neutral angle and forward slip all grow from ν = 0.2 to 0.3, in the FE
     and in the slab method (the signs must agree).
  3. The friction hill's peak (the largest roll pressure p_n = p − s_nn on the exit-side 60 % of
     the arc, away from the entry corner's own peak) lies in the neutral zone: the wall nodes that
     stick (|v/(ωR) − 1| <= 1e-3; from ν ≈ 0.25 the FE's neutral "point" is a stick zone, 1.6° wide
     at ν = 0.3) and the Neutral Angle, widened by two wall segments on each side (0.23° each on
     this mesh: the peak is a node value refined by the parabola through three nodes, the neutral
     angle is interpolated between two). The slab's hill peaks exactly at its neutral point.
  4. Hill's (1950) roll-force formula (a fit to Bland & Ford's slab loads, rolling_theory.hill_force,
     σ̄ at the mean rate as the slab's): FE/Hill − 1 within the force band widened by 3 % on each
     side, Hill's own accuracy against the slab method (docs/rolling_theory.md §13: ≤ 2.5 %, asserted
     3 %). Measured −0.3 % (ν = 0.2), −5.3 % (ν = 0.3).
  5. Mass: the inlet and outlet fluxes differ by what enters through the flat, fixed entry
     surface (docs/rolling.md §5), not hidden: (Q_in − Q_out)/Q_out is negative, above −1 %,
     and the entry surface carries at least 90 % of it (measured −0.50 % and 99.6 %).
geometry  (slow: 3 coarse runs, ν = 0.3: R = 10, R = 20, and h1 = 0.9 (10 %))
  Force and torque within their bands at R = 20 and at 10 %; force and torque grow with R/h0 and
  with the reduction (10 → 25 %) in the FE and in the slab method; Hill's force as in nu 4
  (measured −6.1 % at R = 20, −9.6 % at 10 %). (40 % is not used: on the
  coarse mesh its inflow balance stalls on a jump of F, exit 3; on h = 0.05 it converges.)
sticking  (slow: ν = 2, Coulomb on the contact force)
  Force and torque against the slab method with sticking friction (Orowan's cap τ = min(ν p, k),
  = Tresca m = 1 over the arc) within their bands. Sims's (1954) sticking-friction formulas
  (rolling_theory.sims_force, sims_neutral_angle: Orowan's inhomogeneity w = π/4, small angles):
  the force within ±2 % (measured +0.4 %: the FE's −14 % against the homogeneous sticking slab is
  Orowan's inhomogeneity; 2 % = the ν = 0.3 pass's force change h = 0.1 → 0.05, 1.0 %, doubled),
  the neutral angle within ±0.5° (measured 3.64° against 3.69°; two wall segments of this mesh).
  Sims's torque 2R²k(α/2 − φ_n) is printed, not asserted: a difference of two nearly equal angles,
  it moves by 6 % for the 0.05° between the neutral angles and the FE's shear on the arc is not k
  everywhere (measured FE +15.6 %; the homogeneous sticking slab's torque is within +0.5 %).
"""
import math
import os
import sys

from flowform_tools import checks, rolling_compare, rolling_theory

COARSE = ["Error Estimation/Method=None", "Sensitivity/Parameters={}", "Mesh/Geo Parameters/h=0.1",
          "Mesh/Geo Parameters/hc=0.04", "Boundary Conditions/roll/Coulomb Normal Force=Contact Force"]

# (pass) -> {response: (low, high)} of d = FE/slab − 1 (module doc). Measured d on h = 0.1, 0.05, 0.035:
BANDS = {
    # ν = 0.2: force −1.3 %, −2.0 %, −2.1 % (last change 0.1 %); torque +11.2 %, +9.7 %, +9.3 % (0.4 %)
    (10.0, 0.75, 0.2): {"roll_force": (-0.027, -0.007), "roll_torque": (0.084, 0.121)},
    # ν = 0.3: force −5.3 %, −6.3 %, −6.4 % (0.1 %); torque +6.9 %, +5.2 %, +4.8 % (0.4 %)
    (10.0, 0.75, 0.3): {"roll_force": (-0.070, -0.047), "roll_torque": (0.039, 0.078)},
    # R = 20, ν = 0.3: force −6.9 %, −7.6 %, −7.8 % (0.2 %); torque +1.7 %, +0.4 %, +0.1 % (0.3 %)
    # (h = 0.05, 0.035 with the roll bilateral: the statuses cycle there, not on h = 0.1)
    (20.0, 0.75, 0.3): {"roll_force": (-0.085, -0.062), "roll_torque": (-0.007, 0.025)},
    # 10 %, ν = 0.3: force −9.8 %, −11.0 % on h = 0.1, 0.05; torque +12.1 %, +9.6 % (no h = 0.035:
    # widened by the h = 0.1 → 0.05 change, 1.2 % and 2.5 %, and 0.5 %)
    (10.0, 0.9, 0.3): {"roll_force": (-0.127, -0.081), "roll_torque": (0.066, 0.151)},
    # ν = 2 against the sticking slab (Orowan's cap m = 1), the roll bilateral (the statuses cycle):
    # force −14.3 %, torque +0.5 % on h = 0.1 (widened by the ν = 0.3 pass's h = 0.1 → 0.05 change,
    # 1.0 % and 1.7 %, and 0.5 %)
    (10.0, 0.75, 2.0): {"roll_force": (-0.158, -0.128), "roll_torque": (-0.017, 0.027)},
}
STICK = 1e-3             # |v/(ωR) − 1| of a node counted as sticking (check 3)
HILL_FIT = 0.03          # Hill's formula against the slab method (docs/rolling_theory.md §13)
SIMS_FORCE = 0.02        # FE/Sims − 1 of the force (sticking; module doc)
SIMS_ANGLE = 0.5         # |FE − Sims| of the neutral angle, degrees (two wall segments)
PEAK_SEGMENTS = 2        # the peak's allowance in wall segments (check 3)


def run(flowform, source, outdir, R=10.0, h1=0.75, nu=0.3):
    d = os.path.join(outdir, f"R{R:g}_h1_{h1:g}_nu{nu:g}")
    r, bilateral = rolling_compare.run_pass(flowform, os.path.join(source, "xml/rolling_flat.xml"), d,
                                            COARSE + rolling_compare.pass_sets(R=R, h1=h1, nu=nu))
    if bilateral:
        print(f"R = {R:g}, h1 = {h1:g}, ν = {nu:g}: the statuses cycled; solved with the roll bilateral")
    if r.status != 0:
        print(f"flowform exited {r.status} on {d}:\n{(r.stderr or '')[-2000:]}")
        sys.exit(1)
    return rolling_compare.compare(d, r.summary, flow_stress=False)


def against_slab(c, key, perturbed, sticking=False):
    """Force and torque departures within BANDS[key]; the slab at 1.5 ν when perturbed."""
    slab = c.slab
    if sticking:
        slab = c.ps.slab(friction="orowan", m=1.0)
    elif perturbed:
        slab = c.ps.slab(nu=1.5 * c.ps.nu)
    failed = 0
    for name, attr in (("roll_force", "force"), ("roll_torque", "torque")):
        d = c.fe[name] / getattr(slab, attr) - 1.0
        lo, hi = BANDS[key][name]
        failed += checks.check(lo <= d <= hi, f"R = {c.ps.R:g}, h1 = {c.ps.h1:g}, ν = {c.ps.nu:g}: {name} FE "
                               f"{c.fe[name]:.5f}, slab{' (sticking)' if sticking else ''} {getattr(slab, attr):.5f}: "
                               f"FE/slab − 1 = {d:+.2%} in [{lo:+.1%}, {hi:+.1%}]")
    return failed


def against_hill(c, key):
    """Hill's force formula: FE/Hill − 1 within the force band widened by HILL_FIT on each side."""
    hill = rolling_theory.hill_force(c.ps.R, c.ps.h0, c.ps.h1, c.slab.k, c.ps.nu)
    d = c.fe["roll_force"] / hill - 1.0
    lo, hi = BANDS[key]["roll_force"]
    return checks.check(lo - HILL_FIT <= d <= hi + HILL_FIT,
                        f"R = {c.ps.R:g}, h1 = {c.ps.h1:g}, ν = {c.ps.nu:g}: roll_force FE {c.fe['roll_force']:.5f}, "
                        f"Hill {hill:.5f}: FE/Hill − 1 = {d:+.2%} in [{lo - HILL_FIT:+.1%}, {hi + HILL_FIT:+.1%}]")


def trend(a, b, what):
    """FE and slab change the same way (both up) from pass a to pass b."""
    failed = 0
    for name, attr in (("roll_force", "force"), ("roll_torque", "torque"), ("neutral_angle", "neutral_angle"),
                       ("forward_slip", "forward_slip")):
        if what != "ν" and name in ("neutral_angle", "forward_slip"):
            continue
        dfe, dslab = b.fe[name] - a.fe[name], getattr(b.slab, attr) - getattr(a.slab, attr)
        failed += checks.check(dfe > 0 and dslab > 0, f"{name} grows with {what}: FE {a.fe[name]:.5f} -> "
                               f"{b.fe[name]:.5f}, slab {getattr(a.slab, attr):.5f} -> {getattr(b.slab, attr):.5f}")
    return failed


def hill_and_mass(c):
    arc = rolling_compare.arc_profile(c.run_dir, c.summary)
    alpha = math.radians(c.slab.bite_angle)
    deg = [math.degrees(f) for f in arc["phi"]]
    window = (arc["phi"] <= 0.6 * alpha) & (arc["status"] > 0.5)
    peak = math.degrees(rolling_compare.peak_angle(arc["phi"][window], arc["p_n"][window]))
    phin = c.fe["neutral_angle"]
    zone = [f for f, s in zip(deg, arc["slip"]) if abs(s) <= STICK] + [phin]
    segment = (deg[-1] - deg[0]) / (len(deg) - 1)
    lo, hi = min(zone) - PEAK_SEGMENTS * segment, max(zone) + PEAK_SEGMENTS * segment
    failed = checks.check(lo <= peak <= hi,
                          f"ν = {c.ps.nu:g}: the friction hill's peak at {peak:.3f}° lies in the neutral zone "
                          f"[{min(zone):.3f}°, {max(zone):.3f}°] (|slip| <= {STICK:g} and the neutral angle "
                          f"{phin:.3f}°) ± {PEAK_SEGMENTS} segments of {segment:.3f}° (slab: {c.slab.neutral_angle:.3f}°; "
                          f"the recovered roll force {arc['arc_force']:.4f} against the solver's {c.fe['roll_force']:.4f})")
    mismatch = c.flux_mismatch
    share = -c.flux_entry_surface / (c.flux_out - c.flux_in) if c.flux_out != c.flux_in else 0.0
    failed += checks.check(-0.01 < mismatch < 0 and share >= 0.9,
                           f"ν = {c.ps.nu:g}: Q_in {c.flux_in:.5f}, Q_out {c.flux_out:.5f}: (Q_in − Q_out)/Q_out = "
                           f"{mismatch:+.3%} in (−1 %, 0), {share:.1%} of it through the flat entry surface (>= 90 %)")
    return failed


def nu(flowform, source, outdir, perturbed):
    a = run(flowform, source, outdir, nu=0.2)
    if perturbed:             # one run: the slab at 1.5 ν must leave the bands
        return against_slab(a, (10.0, 0.75, 0.2), perturbed)
    b = run(flowform, source, outdir, nu=0.3)
    failed = against_slab(a, (10.0, 0.75, 0.2), perturbed) + against_slab(b, (10.0, 0.75, 0.3), perturbed)
    failed += trend(a, b, "ν")
    for c in (a, b):
        failed += hill_and_mass(c)
    failed += against_hill(a, (10.0, 0.75, 0.2)) + against_hill(b, (10.0, 0.75, 0.3))
    return failed


def geometry(flowform, source, outdir, perturbed):
    base = run(flowform, source, outdir, nu=0.3)
    big = run(flowform, source, outdir, R=20.0, nu=0.3)
    light = run(flowform, source, outdir, h1=0.9, nu=0.3)
    failed = against_slab(big, (20.0, 0.75, 0.3), perturbed) + against_slab(light, (10.0, 0.9, 0.3), perturbed)
    failed += trend(base, big, "R/h0") + trend(light, base, "the reduction")
    failed += against_hill(big, (20.0, 0.75, 0.3)) + against_hill(light, (10.0, 0.9, 0.3))
    return failed


def sticking(flowform, source, outdir, perturbed):
    c = run(flowform, source, outdir, nu=2.0)
    failed = against_slab(c, (10.0, 0.75, 2.0), perturbed, sticking=not perturbed)
    if perturbed:
        return failed
    R, h0, h1, k = c.ps.R, c.ps.h0, c.ps.h1, c.slab.k
    sims = rolling_theory.sims_force(R, h0, h1, k)
    d = c.fe["roll_force"] / sims - 1.0
    failed += checks.check(abs(d) <= SIMS_FORCE, f"ν = 2: roll_force FE {c.fe['roll_force']:.5f}, Sims {sims:.5f}: "
                           f"FE/Sims − 1 = {d:+.2%} within ±{SIMS_FORCE:.0%}")
    phi = math.degrees(rolling_theory.sims_neutral_angle(R, h0, h1))
    failed += checks.check(abs(c.fe["neutral_angle"] - phi) <= SIMS_ANGLE,
                           f"ν = 2: neutral angle FE {c.fe['neutral_angle']:.3f}°, Sims {phi:.3f}° (within {SIMS_ANGLE}°)")
    torque = rolling_theory.sims_torque(R, h0, h1, k)
    print(f"ν = 2: roll_torque FE {c.fe['roll_torque']:.5f}, Sims {torque:.5f} (FE/Sims − 1 = "
          f"{c.fe['roll_torque'] / torque - 1:+.2%}; not asserted, module doc)")
    return failed


def main():
    sub, flowform, source, outdir = sys.argv[1:5]
    perturbed = "--perturbed" in sys.argv[5:]
    failed = {"nu": nu, "geometry": geometry, "sticking": sticking}[sub](flowform, source, outdir, perturbed)
    return checks.verdict(failed)


if __name__ == "__main__":
    sys.exit(main())
