"""Stress battery of the nonlinear solve: cases at the edges of the parameter ranges a user
may set, each of which must converge (exit 0, converged: true) and give finite responses.
Each case is one line of CASES: a name, the case file and its --set overrides. A group
(`channel`, `extrusion`, `rolling` (xml/rolling_flat.xml), `rolling_free` (xml/rolling.xml as
shipped, free strip surfaces), `grid` — the last two under the slow label) is one ctest test
(tests/regression/Stress.cmake).

    stress_checks.py GROUP FLOWFORM SOURCE_DIR OUT_DIR

Prints one line per case (exit status, Newton iterations, contact changes, seconds, the
first response) and a closing 'N passed, N failed' line; exit status 1 when any failed.
"""
import math
import os
import sys
import time

from flowform_tools import launcher
from flowform_tools.case import Case

CH = "xml/channel.xml"
EX = "xml/extrusion.xml"
COARSE = ["Mesh/Geo Parameters/h=0.2", "Mesh/Geo Parameters/hc=0.05"]  # extrusion, seconds per run


def channel(name, *sets):
    return (name, CH, ["Mesh/Geo Parameters/N=8.0"] + list(sets))


def walls(case_file, key, value):
    """`Boundary Conditions/<wall>/<key>=<value>` for every contact wall of the case."""
    return [f"Boundary Conditions/{w}/{key}={value}" for w in Case(case_file).contact_walls()]


def extrusion(name, source, *sets, walls_set=None):
    extra = walls(os.path.join(source, EX), *walls_set) if walls_set else []
    return (name, EX, COARSE + list(sets) + extra)


def rolling(name, *sets, R=10.0, h1=0.75, case="xml/rolling_flat.xml"):
    """A rolling case without its estimate and sensitivities, the inflow started at ωR h1/h0."""
    return (name, case, ["Error Estimation/Method=None", "Sensitivity/Parameters={}",
                       f"Mesh/Geo Parameters/R={R!r}", f"Mesh/Geo Parameters/h1={h1!r}",
                       f"Boundary Conditions/inlet/Velocity X={R * h1!r}"] + list(sets))


def rolling_battery(case):
    """docs/rolling.md §9: ν 0.1, 0.5, 2; reductions 5 %, 40 %; R/h0 5, 20, 50; back and front tension."""
    return [rolling("nu_0.1", "Boundary Conditions/roll/Friction Coefficient=0.1", case=case),
            rolling("nu_0.5", "Boundary Conditions/roll/Friction Coefficient=0.5", case=case),
            rolling("reduction_5", h1=0.95, case=case),
            rolling("reduction_40", h1=0.6, case=case),
            rolling("R_5", R=5.0, case=case),
            rolling("R_20", R=20.0, case=case),
            rolling("R_50", R=50.0, case=case),
            rolling("nu_2_sticking", "Boundary Conditions/roll/Friction Coefficient=2.0", case=case),
            rolling("back_tension_0.2", "Boundary Conditions/inlet/Traction X=-0.2", case=case),
            rolling("front_tension_0.3", "Boundary Conditions/outlet/Traction X=0.3", case=case)]


def groups(source):
    return {
        "channel": [
            channel("gamma_1e-3", "Material/Rate Constant=1e-3"),
            channel("gamma_1e3", "Material/Rate Constant=1e3"),
            channel("e0_1e-6", "Material/Strain Rate Cutoff=1e-6"),
            channel("e0_1e-2", "Material/Strain Rate Cutoff=1e-2"),
            channel("n_1", "Material/Rate Exponent=1.0"),
            channel("n_100", "Material/Rate Exponent=100.0"),
            ("stall_n7_e0_1e-5", CH, ["Mesh/Geo Parameters/N=32.0", "Material/Yield Stress=0.3",
                                      "Material/Rate Constant=2.0", "Material/Rate Exponent=7.0",
                                      "Material/Strain Rate Cutoff=1e-5",
                                      "Boundary Conditions/inlet/Traction X=5.2"]),
        ],
        "extrusion": [
            extrusion("sigma0_0", source, "Material/Yield Stress=0.0"),
            extrusion("n_100", source, "Material/Rate Exponent=100.0"),
            extrusion("e0_1e-5", source, "Material/Strain Rate Cutoff=1e-5"),
            extrusion("kappa_t_1e2", source, walls_set=("Tangential Penalty Factor", "100.0")),
            extrusion("kappa_t_1e4", source, walls_set=("Tangential Penalty Factor", "1e4")),
            extrusion("kappa_t_1e6", source, walls_set=("Tangential Penalty Factor", "1e6")),
            extrusion("kappa_t_1e8", source, walls_set=("Tangential Penalty Factor", "1e8")),
            # friction far above the material's shear strength: the first solve fails from
            # frictionless walls and converges from walls that stick at rest (docs/contact.md)
            extrusion("nu_2", source, walls_set=("Friction Coefficient", "2.0")),
            extrusion("nu_5", source, walls_set=("Friction Coefficient", "5.0")),
            # on the shipped mesh with the paper's status loop (a tight first solve) the first two
            # starts cycle between stick and slip at the die land; continuation in the friction
            # coefficients converges (docs/contact.md)
            ("nu_2_shipped_mesh_status_loop", EX, ["Contact/Status Update=Certain Iterate"]
             + walls(os.path.join(source, EX), "Friction Coefficient", "2.0")),
            ("default_mesh_kappa_t_100_nu_0.2", EX,
             ["Mesh/Geo Parameters/hc=0.005"] + walls(os.path.join(source, EX), "Tangential Penalty Factor", "100.0")
             + walls(os.path.join(source, EX), "Friction Coefficient", "0.2")),
            channel("gamma_1e6", "Material/Rate Constant=1e6"),
        ],
        # Rolling (docs/rolling.md §9): ν from just above the steady limit (0.085–0.09) to 0.5 and
        # the sticking limit 2, reductions 5–40 %, R/h0 5, 20, 50, back and front tension.
        "rolling": rolling_battery("xml/rolling_flat.xml"),
        "rolling_free": rolling_battery("xml/rolling.xml"),
        # The grids of issue #10 (slow label): the channel over γ × e0 × n, the extrusion over
        # ν × κ_t, plane and axisymmetric.
        "grid": [channel(f"channel_gamma_{g}_e0_{e}_n_{n}", f"Material/Rate Constant={g}",
                         f"Material/Strain Rate Cutoff={e}", f"Material/Rate Exponent={n}")
                 for g in ("1e-3", "1.0", "1e3", "1e6") for e in ("1e-6", "1e-4", "1e-2") for n in ("1.0", "5.0", "100.0")]
                + [(f"{tag}_nu_{nu}_kappa_t_{k}", case, COARSE + walls(os.path.join(source, case), "Friction Coefficient", nu)
                    + walls(os.path.join(source, case), "Tangential Penalty Factor", k))
                   for tag, case in (("plane", EX), ("axisym", "xml/extrusion_axisym.xml"))
                   for nu in ("0.0", "0.5", "1.0", "2.0", "5.0") for k in ("10.0", "1e4", "1e8")],
    }


def main():
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    group, flowform, source, out = sys.argv[1:5]
    cases = groups(source).get(group)
    if cases is None:
        sys.exit(f"stress_checks.py: unknown group '{group}'; known: {', '.join(groups(source))}")
    passed = failed = 0
    for name, case, sets in cases:
        start = time.time()
        # Each case's own mesh, solved once (the extrusion scenes adapt by default).
        r = launcher.run(flowform, os.path.join(source, case), os.path.join(out, name),
                         ["Adaptivity/Enabled=false"] + list(sets), quiet=True,
                         timeout=900)
        s = r.summary or {}
        values = list((s.get("functionals") or {}).values())
        finite = all(isinstance(v, (int, float)) and math.isfinite(v) for v in values)
        ok = r.status == 0 and s.get("converged") is True and finite
        passed += ok
        failed += not ok
        first = f"{values[0]:.6g}" if values else "-"
        print(f"{'ok  ' if ok else 'FAIL'} {name:36s} exit {r.status}  newton {s.get('newton_iterations', '-'):>4}  "
              f"contact changes {s.get('contact_changes', '-'):>3}  {time.time() - start:6.1f} s  first response {first}"
              + ("" if ok else f"  message: {s.get('message', '(no summary)')}"))
    print(f"{passed} passed, {failed} failed")
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
