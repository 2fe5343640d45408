"""A Temperature field on a moving free surface: the extrudate of xml/die_swell.xml cooling in air
(docs/theory.md §10: heat transfer on any group, a Free Surface included). The billet enters at
T = 1, the free surface gives heat h (T − 0) to the air (h = 1, k = 0.1, ρc = 1), no heating
(η = 0) and the power law does not read T: the coupling is one way. Asserted, against what the
temperature field did not compute:

- the flow is the isothermal one: the swell and the flow rates equal the run without
  Material/Thermal to 1e-10 relative (the same free-surface iterations: the temperature rows do not
  enter the surface update or the flow);
- the summary's energy balance (docs/theory.md §10): the imbalance (what Newton leaves) below 1e-8
  of the balance's scale, and the enthalpy the extrudate loses equals the heat the surface gives to
  the air within 1e-3 (measured 3.3e-4: the lumped boundary quadrature's O(h²), the flow's mass
  loss being 1e-7 here);
- the heat goes the right way: the surface gives heat (> 0) and the mean exit temperature lies
  between the air's and the billet's. (The 1e-10: both runs converge to the solver tolerance, their
  last iterates differing; measured 1.1e-11.)

usage: cooling_extrudate_checks.py FLOWFORM SOURCE_DIR OUTDIR
"""
import os
import sys

from flowform_tools import launcher
from flowform_tools.checks import check, verdict

THERMAL = ["Material/Thermal/Conductivity=0.1", "Material/Thermal/Heat Fraction=0",
           "Boundary Conditions/inlet/Temperature=1",
           "Boundary Conditions/free_surface/Heat Transfer Coefficient=1",
           "Boundary Conditions/free_surface/Ambient Temperature=0",
           "Responses/surface_heat/Type=Heat Flow", "Responses/surface_heat/Boundary=free_surface",
           "Responses/exit_temperature/Type=Mean Temperature", "Responses/exit_temperature/Boundary=outlet"]


def main():
    flowform, source, outdir = sys.argv[1:4]
    case = os.path.join(source, "xml", "die_swell.xml")
    runs = {}
    for name, sets in (("isothermal", []), ("cooling", THERMAL)):
        r = launcher.run(flowform, case, os.path.join(outdir, name), sets, quiet=True)
        if r.status != 0:
            raise SystemExit(f"flowform exited {r.status} on {case} {sets}")
        runs[name] = r.summary
    iso, cool = runs["isothermal"]["functionals"], runs["cooling"]["functionals"]
    failed = 0
    for response in ("swell", "inflow", "outflow"):
        diff = abs(cool[response] - iso[response]) / abs(iso[response])
        failed += check(diff <= 1e-10, f"{response} {cool[response]:.12g} = the isothermal run's "
                                       f"{iso[response]:.12g} ({diff:.1e} <= 1e-10)")
    failed += check(runs["cooling"]["free_surface_iterations"] == runs["isothermal"]["free_surface_iterations"],
                    f"the same free-surface iterations ({runs['cooling']['free_surface_iterations']})")
    balance = runs["cooling"]["energy_balance"]
    failed += check(abs(balance["relative_imbalance"]) <= 1e-8,
                    f"energy balance: imbalance {balance['relative_imbalance']:.1e} of its scale <= 1e-8")
    failed += check(abs(balance["enthalpy_closure"]) <= 1e-3,
                    f"energy balance: the enthalpy lost equals the heat given to the air to "
                    f"{balance['enthalpy_closure']:.1e} <= 1e-3 (heat {balance['heat_out']['free_surface']:.6f}, "
                    f"enthalpy out {sum(balance['enthalpy_flow'].values()):.6f})")
    failed += check(cool["surface_heat"] > 0.0, f"the free surface gives {cool['surface_heat']:.6f} to the air")
    failed += check(0.0 < cool["exit_temperature"] < 1.0,
                    f"mean exit temperature {cool['exit_temperature']:.6f} between the air's 0 and the billet's 1")
    return verdict(failed)


if __name__ == "__main__":
    sys.exit(main())
