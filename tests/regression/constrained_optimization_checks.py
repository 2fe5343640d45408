"""Constrained decisions (docs/optimization.md §4, §5): the hot extrusion's largest ram speed under
an exit-temperature and a ram-force limit, and the best point of its extrusion window (speed and
billet temperature), each checked against runs the optimizer did not make.

xml/hot_extrusion_max_speed.xml — the speed V* with T_exit <= 740 K, F <= 4500 N/mm:
- converged (exit 0) in at most 10 solves (measured 7, the final one included);
- the temperature limit is active and met to its Constraint Tolerance (|T − 740| <= 7.4 mK), the
  force limit inactive (its shadow price 0);
- independent runs at V* ∓ 0.05 mm/s bracket the limit: T(V* − 0.05) < 740 < T(V* + 0.05)
  (dT/dV ≈ 0.44 K per mm/s there: ± 0.02 K, a hundred times the solves' scatter);
- the shadow price is the optimum's derivative by the limit: against the optimizations with the
  limit at 739 and 741 K (central difference) to 2 % (measured 0.3 %: the speed's curvature in
  the limit over ± 1 K).

xml/hot_extrusion_window.xml — the speed and billet temperature (V*, T_b*) of largest flux:
- converged in at most 12 solves (measured 8); both limits active and met to their tolerance;
- it is the corner of the window, checked by independent runs: at T_b* the speed V* ± 1 mm/s
  has both limits met below and both exceeded above; at V* a billet 2 K hotter leaves the product
  above 740 K and one 2 K colder needs more than 4500 N/mm. The steps are set by the force's
  noise: independent starts of one design read the ram force up to 3 N/mm (6e-4) apart (the
  contact pattern's discrete states), its slopes are ≈ 15 N/mm per mm/s and ≈ 12 N/mm per K, so
  ± 1 mm/s and ± 2 K move it by 5–8 times that noise;
- both shadow prices positive (a KKT point of a maximum: relaxing either limit raises the flux).

usage: constrained_optimization_checks.py FLOWFORM SOURCE_DIR OUTDIR
"""
import os
import sys

from flowform_tools import launcher
from flowform_tools.checks import check, verdict

SPEED = "Boundary Value:ram/Velocity X"
BILLET = "Boundary Value:ram/Temperature"
T_LIMIT, F_LIMIT = 740.0, 4500.0


def main():
    flowform, source, outdir = sys.argv[1], os.path.abspath(sys.argv[2]), sys.argv[3]
    failed = 0

    def run(name, case, sets=()):
        r = launcher.run(flowform, os.path.join(source, "xml", case), os.path.join(outdir, name),
                         list(sets) + ["Output/Write Solution=false", "Output/Boundary CSV=false"],
                         quiet=True, clean=True)
        if r.status != 0:
            raise SystemExit(f"flowform exited {r.status} on {case} {list(sets)}")
        return r.summary

    def at(name, speed, billet=723.0):
        """An ordinary run of the hot extrusion (no optimization, no sensitivities)."""
        return run(name, "hot_extrusion.xml", [f"Boundary Conditions/ram/Velocity X={speed!r}",
                                               f"Boundary Conditions/ram/Temperature={billet!r}"])["functionals"]

    # The largest speed under the two limits.
    s = run("max_speed", "hot_extrusion_max_speed.xml")
    o = s["optimization"]
    v = o["design"][SPEED]
    c = o["constraints"]
    temperature, force = c["exit_temperature"], c["ram_force"]
    failed += check(o["converged"] and o["solves"] <= 10,
                    f"max speed: converged ({o['status']}) at V* = {v:.4f} mm/s in {o['solves']} solves (<= 10)")
    failed += check(temperature["active"] and abs(temperature["value"] - T_LIMIT) <= 1e-5 * T_LIMIT
                    and not force["active"] and force["met"] and force["shadow_price"] == 0.0,
                    f"the temperature limit active (T = {temperature['value']:.5f} K), the force inactive "
                    f"(F = {force['value']:.1f} N/mm, shadow price {force['shadow_price']})")
    below, above = at("below", v - 0.05)["exit_temperature"], at("above", v + 0.05)["exit_temperature"]
    failed += check(below < T_LIMIT < above,
                    f"independent runs bracket the limit: T(V* - 0.05) = {below:.4f} K < 740 < T(V* + 0.05) = {above:.4f} K")
    fluxes = [run(f"limit_{limit:g}", "hot_extrusion_max_speed.xml",
                  [f"Optimization/Constraint Upper Bounds={{{limit!r}, {F_LIMIT!r}}}"])["optimization"]["objective"]
              for limit in (T_LIMIT - 1.0, T_LIMIT + 1.0)]
    difference = (fluxes[1] - fluxes[0]) / 2.0
    price = temperature["shadow_price"]
    rel = abs(price - difference) / abs(difference)
    failed += check(rel <= 0.02,
                    f"the shadow price {price:.3f} mm²/s per K = the optimum's central difference by the limit "
                    f"{difference:.3f} ({rel:.1e} <= 0.02)")

    # The best point of the window.
    w = run("window", "hot_extrusion_window.xml")["optimization"]
    v, tb = w["design"][SPEED], w["design"][BILLET]
    c = w["constraints"]
    failed += check(w["converged"] and w["solves"] <= 12 and all(c[n]["active"] and c[n]["met"] for n in c),
                    f"window: converged ({w['status']}) at V* = {v:.4f} mm/s, T_b* = {tb:.3f} K in {w['solves']} "
                    f"solves (<= 12), both limits active (T = {c['exit_temperature']['value']:.5f} K, "
                    f"F = {c['ram_force']['value']:.2f} N/mm)")
    slower, faster = at("slower", v - 1.0, tb), at("faster", v + 1.0, tb)
    failed += check(slower["exit_temperature"] < T_LIMIT and slower["ram_force"] < F_LIMIT
                    and faster["exit_temperature"] > T_LIMIT and faster["ram_force"] > F_LIMIT,
                    f"at T_b*: V* - 1 meets both (T {slower['exit_temperature']:.3f} K, F {slower['ram_force']:.1f}), "
                    f"V* + 1 exceeds both (T {faster['exit_temperature']:.3f} K, F {faster['ram_force']:.1f})")
    hotter, colder = at("hotter", v, tb + 2.0), at("colder", v, tb - 2.0)
    failed += check(hotter["exit_temperature"] > T_LIMIT and colder["ram_force"] > F_LIMIT,
                    f"at V*: a billet 2 K hotter leaves at {hotter['exit_temperature']:.3f} K > 740, one 2 K colder "
                    f"needs {colder['ram_force']:.1f} N/mm > 4500")
    prices = [c[n]["shadow_price"] for n in ("exit_temperature", "ram_force")]
    failed += check(all(p > 0 for p in prices),
                    f"both shadow prices positive: {prices[0]:.3f} mm²/s per K, {prices[1]:.4f} mm²/s per N/mm")
    return verdict(failed)


if __name__ == "__main__":
    sys.exit(main())
