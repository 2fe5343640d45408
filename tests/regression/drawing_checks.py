"""Wire drawing through a conical die (xml/drawing.xml, docs/drawing.md) against what flowform did
not compute: the balances, the classical drawing stresses (flowform_tools/drawing_theory.py:
homogeneous work, Sachs's slab method, Avitzur's upper bound), the rigid-plastic limit, the dead
zone and the total derivatives against re-meshed, re-converged runs. Asserted (the measured
values and why each tolerance in docs/drawing.md §4):

- the shipped case: drawing power F·v = plastic + friction + penalty + stabilization power to
  1e-8 (Newton's tolerance); the volume entering within 2 % of the volume leaving (measured
  1.25 %: the cone's normal penalty lets that much through); no dead zone at 8°;
- total derivatives (through the moving mesh and the re-converged free surface) of the drawing
  force and the die pressure by ν and alpha: against the finite-difference check (the mesh moved
  to the .geo meshed at h ± δ on the same topology, the surface re-converged) to 1e-3 (measured
  ≤ 6e-5: the surface's Move Tolerance 1e-5 over δ); the force's against independent runs, at
  ν ± 1e-3 on the same mesh to 2e-3 (measured 1.7e-4) and re-meshed from scratch at alpha ± 1°
  to 3 % (measured 0.7 %; another triangulation each, whose noise ~1e-3 of F is why the step is
  1°: at ± 0.5° the same difference is 7 % off);
- the rigid-plastic limit as n grows: the drawing stress at n = 20, 40, 80 converges at first
  order in 1/n (the ratio of successive differences in [1.6, 2.4]), its limit by Richardson
  extrapolation; frictionless: homogeneous work <= limit <= the upper bound with m = 0; Tresca
  m = 0.1: frictionless limit < limit <= the upper bound with m = 0.1; Coulomb ν = 0.05: Sachs
  <= limit, and the limit within 5 % of Sachs + the frictionless redundant work (limit − ideal)
  (measured 2.0 %: Sachs's slabs ignore how friction and redundant shear interact);
- the angle of least drawing stress (Tresca m = 0.1, n = 40) lies inside the sweep 6°, 8°, 10°,
  and the parabola's vertex lies within 3° below the upper bound's optimum (measured 1.6°: the
  bound's field overstates the redundant work's growth with the angle);
- a dead zone at 60° with sticking friction at a 40 % reduction (the wire surface held in place,
  the streamline surface does not reach a cone it leaves): dead_zone > 0.01 (measured 0.029),
  none without friction.

usage: drawing_checks.py FLOWFORM SOURCE_DIR OUTDIR
"""
import math
import os
import sys

from flowform_tools import launcher
from flowform_tools.checks import check, verdict
from flowform_tools.drawing_theory import (ideal_stress, optimal_angle_upper_bound, sachs_stress,
                                           upper_bound_stress)

R0, R1 = 1.0, 0.894427191  # xml/drawing.xml's geometry (drawing.geo's defaults)
ALPHA = math.radians(8.0)
NO_SENSITIVITY = ["Sensitivity/Parameters={}"]


def friction(law, value=None):
    sets = []
    for wall in ("die_cone", "die_land"):
        sets.append(f"Boundary Conditions/{wall}/Friction Law={law}")
        if law == "Coulomb":
            sets.append(f"Boundary Conditions/{wall}/Friction Coefficient={value}")
        elif law == "Tresca":
            sets.append(f"Boundary Conditions/{wall}/Shear Factor={value}")
    return sets


def fixed_surface_case(source, outdir):
    """The shipped case with the wire's surface before the die traction-free in place."""
    with open(os.path.join(source, "xml", "drawing.xml")) as f:
        text = f.read()
    free = ('      <Parameter name="Type" type="string" value="Free Surface"/>\n'
            '      <Parameter name="Start Group" type="string" value="entry"/>\n')
    if text.count(free) != 1:
        raise SystemExit("xml/drawing.xml's wire_surface is no longer the free surface this check replaces")
    text = text.replace(free, '      <Parameter name="Type" type="string" value="Traction"/>\n')
    text = text.replace('"../meshes/drawing.geo"', '"' + os.path.join(source, "meshes", "drawing.geo") + '"')
    os.makedirs(outdir, exist_ok=True)
    path = os.path.join(outdir, "drawing_fixed_surface.xml")
    with open(path, "w") as f:
        f.write(text)
    return path


def main():
    flowform, source, outdir = sys.argv[1], os.path.abspath(sys.argv[2]), sys.argv[3]
    case = os.path.join(source, "xml", "drawing.xml")

    def run(name, sets, on=case):
        r = launcher.run(flowform, on, os.path.join(outdir, name), sets, quiet=True, clean=True)
        if r.status != 0:
            raise SystemExit(f"flowform exited {r.status} on {on} {sets}")
        return r.summary

    failed = 0
    base = run("shipped", ["Sensitivity/Finite Difference Check=true"])
    f = base["functionals"]
    power = f["plastic_power"] + f["friction_power"] + f["penalty_power"] + f["stabilization_power"]
    diff = abs(f["drawing_force"] - power) / f["drawing_force"]
    failed += check(diff <= 1e-8, f"drawing power {f['drawing_force']:.10f} = plastic + friction + penalty + "
                                  f"stabilization {power:.10f} ({diff:.1e} <= 1e-8)")
    leak = (f["exit_flux"] + f["entry_flux"]) / f["exit_flux"]
    failed += check(0.0 <= leak <= 0.02, f"volume in {-f['entry_flux']:.6f}, out {f['exit_flux']:.6f}: "
                                         f"{leak:.2%} lost (<= 2 %)")
    failed += check(f["dead_zone"] == 0.0, f"no dead zone at 8° (dead_zone {f['dead_zone']})")

    # Total derivatives against the finite-difference check and against independent runs.
    for response in ("drawing_force", "die_pressure"):
        for parameter, entry in base["fd_check"][response].items():
            failed += check(entry["rel_diff_total_shape"] <= 1e-3,
                            f"d{response}/d({parameter}) total {entry['ddm_total_shape']:.6g} = FD check, surface "
                            f"re-converged, {entry['fd_moving_shape']:.6g} ({entry['rel_diff_total_shape']:.1e} <= 1e-3)")
    total = base["sensitivities_total_shape"]["drawing_force"]
    for parameter, path, value, step, tolerance in (("Friction Coefficient", None, 0.05, 1e-3, 2e-3),
                                                    ("Geo Parameter:alpha", "Mesh/Geo Parameters/alpha", 8.0, 1.0, 0.03)):
        forces = []
        for sign, tag in ((1, "plus"), (-1, "minus")):
            sets = NO_SENSITIVITY + (friction("Coulomb", value + sign * step) if path is None
                                     else [f"{path}={value + sign * step}"])
            forces.append(run(f"{parameter.split(':')[-1].replace(' ', '_')}_{tag}", sets)["functionals"]["drawing_force"])
        fd = (forces[0] - forces[1]) / (2 * step)
        rel = abs(total[parameter] - fd) / abs(fd)
        failed += check(rel <= tolerance, f"dF/d({parameter}) total {total[parameter]:.6g} = independent runs' FD "
                                          f"{fd:.6g} ({rel:.1e} <= {tolerance:g})")

    # The rigid-plastic limit and the classical drawing stresses.
    def limit(name, sets, first=None):
        stresses = [first] if first is not None else []
        for n in (20, 40, 80)[len(stresses):]:
            stresses.append(run(f"{name}_n{n}", NO_SENSITIVITY + sets + [f"Material/Rate Exponent={n}"])
                            ["functionals"]["drawing_stress"])
        d1, d2 = stresses[1] - stresses[0], stresses[2] - stresses[1]
        ratio = d1 / d2
        nonlocal failed
        failed += check(1.6 <= ratio <= 2.4, f"{name}: drawing stress at n = 20, 40, 80: "
                                             f"{', '.join(f'{s:.5f}' for s in stresses)}, first order in 1/n "
                                             f"(difference ratio {ratio:.2f} in [1.6, 2.4])")
        return stresses[2] + d2, stresses  # Richardson, order 1 in 1/n

    ideal = ideal_stress(R0, R1)
    frictionless, _ = limit("frictionless", friction("None"))
    ub0 = upper_bound_stress(ALPHA, R0, R1, 0.0)
    failed += check(ideal <= frictionless <= ub0, f"frictionless limit {frictionless:.5f} between the homogeneous "
                                                  f"work {ideal:.5f} and the upper bound {ub0:.5f}")
    tresca, tresca_stresses = limit("tresca_m0.1", friction("Tresca", 0.1))
    ub = upper_bound_stress(ALPHA, R0, R1, 0.1)
    failed += check(frictionless < tresca <= ub, f"Tresca m = 0.1 limit {tresca:.5f} above the frictionless "
                                                 f"{frictionless:.5f}, below the upper bound {ub:.5f}")
    coulomb, _ = limit("coulomb", [], first=f["drawing_stress"])
    sachs = sachs_stress(0.05, ALPHA, R0, R1)
    sachs_redundant = sachs + frictionless - ideal
    rel = abs(coulomb - sachs_redundant) / coulomb
    failed += check(sachs <= coulomb and rel <= 0.05,
                    f"Coulomb ν = 0.05 limit {coulomb:.5f} >= Sachs {sachs:.5f}, within 5 % of Sachs + the "
                    f"redundant work {sachs_redundant:.5f} ({rel:.1%})")

    # The optimal angle (Tresca m = 0.1, n = 40).
    sweep = {8.0: tresca_stresses[1]}
    for angle in (6.0, 10.0):
        sweep[angle] = run(f"tresca_alpha{angle:g}", NO_SENSITIVITY + friction("Tresca", 0.1) +
                           ["Material/Rate Exponent=40", f"Mesh/Geo Parameters/alpha={angle}"])["functionals"]["drawing_stress"]
    a, b, c = sweep[6.0], sweep[8.0], sweep[10.0]
    vertex = 8.0 + 2.0 * (a - c) / (2.0 * (a - 2.0 * b + c))
    best_ub = math.degrees(optimal_angle_upper_bound(0.1, R0, R1))
    failed += check(b < a and b < c and best_ub - 3.0 <= vertex <= best_ub,
                    f"least drawing stress inside 6°-10° ({a:.5f}, {b:.5f}, {c:.5f}), at {vertex:.2f}°, within 3° "
                    f"below the upper bound's optimum {best_ub:.2f}°")

    # The dead zone at a large angle.
    fixed = fixed_surface_case(source, outdir)
    large = NO_SENSITIVITY + ["Mesh/Geo Parameters/R1=0.7745966692", "Mesh/Geo Parameters/alpha=60"]
    sticking = run("dead_zone_sticking", large + friction("Tresca", 1.0), on=fixed)["functionals"]["dead_zone"]
    smooth = run("dead_zone_frictionless", large + friction("None"), on=fixed)["functionals"]["dead_zone"]
    failed += check(sticking > 0.01 and smooth == 0.0, f"60°, 40 % reduction: dead zone {sticking:.4f} with sticking "
                                                       f"friction (> 0.01), {smooth} without")
    return verdict(failed)


if __name__ == "__main__":
    sys.exit(main())
