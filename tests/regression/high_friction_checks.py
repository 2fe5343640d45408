"""The extrusion at friction far above the shear strength (Coulomb ν = 1, 2 on every wall), where
the die land has two contact states and a state carried from another mesh may belong to a branch
this mesh does not have (docs/contact.md "Two contact states of the die land").

    high_friction_checks.py PART FLOWFORM SOURCE_DIR OUT_DIR

PART `two_level` (default run): ν = 2 on the shipped mesh with the two-level estimate. The refined
solve's start from the coarse state fails; it must then solve from its own start, exactly as a
run from scratch on the refined mesh does: exit 0, an estimate, and the refined mesh's ram force
equal to that run's to 1e-9 relative (the same path: only round-off of a different
interpolated start could differ, and there is none once the fallback restores the start).

PART `adaptive` (label slow): the shipped case as it is (adaptivity, target 0.5 %) at ν = 1 and 2:
both must converge and meet the target (exit 0; before the fallback each ended in exit 3).

Prints one line per run; exits 1 when a check fails.
"""
import os
import sys

from flowform_tools import launcher
from stress_checks import EX, walls


def walls_at(source, nu):
    return walls(os.path.join(source, EX), "Friction Coefficient", nu)


def two_level(flowform, source, out):
    failures = []
    sets = walls_at(source, 2.0) + ["Adaptivity/Enabled=false"]
    est = launcher.run(flowform, os.path.join(source, EX), os.path.join(out, "two_level"),
                       sets + ["Error Estimation/Method=Two-Level"], quiet=True, timeout=900, clean=True)
    fresh = launcher.run(flowform, os.path.join(source, EX), os.path.join(out, "refined_from_scratch"),
                         sets + ["Mesh/Uniform Refinements=1"], quiet=True, timeout=900, clean=True)
    s, f = est.summary or {}, fresh.summary or {}
    refined = ((s.get("error_estimation") or {}).get("refined_functionals") or {}).get("ram_force")
    scratch = (f.get("functionals") or {}).get("ram_force")
    print(f"two-level at nu = 2: exit {est.status}, F = {(s.get('functionals') or {}).get('ram_force')}, "
          f"refined F = {refined}; from scratch on the refined mesh: exit {fresh.status}, F = {scratch}")
    if est.status != 0 or fresh.status != 0:
        failures.append(f"exit statuses {est.status} (estimate) and {fresh.status} (refined from scratch), expected 0")
    elif refined is None or scratch is None:
        failures.append("no refined ram_force in error_estimation, or none from the refined run")
    elif abs(refined - scratch) > 1e-9 * abs(scratch):
        failures.append(f"the refined solve's ram force {refined!r} differs from the run from scratch's {scratch!r}")
    return failures


def adaptive(flowform, source, out):
    failures = []
    for nu in (1.0, 2.0):
        r = launcher.run(flowform, os.path.join(source, EX), os.path.join(out, f"adaptive_nu_{nu:g}"),
                         walls_at(source, nu), quiet=True, timeout=1800, clean=True)
        s = r.summary or {}
        a = s.get("adaptivity") or {}
        cycles = a.get("cycles") or []
        last = cycles[-1] if cycles else {}
        print(f"adaptive at nu = {nu:g}: exit {r.status}, target met {a.get('target_met')}, cycles {len(cycles)}, "
              f"dofs {last.get('dofs')}, F = {(s.get('functionals') or {}).get('ram_force')}, "
              f"estimated relative error {(last.get('relative_error_estimate') or {}).get('ram_force')}")
        if r.status != 0 or a.get("target_met") is not True:
            failures.append(f"nu = {nu:g}: exit {r.status}, target met {a.get('target_met')}: {s.get('message')}")
    return failures


def main():
    if len(sys.argv) != 5 or sys.argv[1] not in ("two_level", "adaptive"):
        sys.exit(__doc__)
    part, flowform, source, out = sys.argv[1:5]
    failures = (two_level if part == "two_level" else adaptive)(flowform, source, out)
    for f in failures:
        print("FAIL " + f)
    print("ok" if not failures else f"{len(failures)} check(s) failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
