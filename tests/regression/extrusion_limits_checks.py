"""scripts/extrusion_limits.py (docs/theory.md §10.3): the largest ram speed for an exit-temperature
limit and for a ram-force limit at one billet temperature (723 K) of xml/hot_extrusion.xml, by
Newton in ln V on the DDM derivative. Asserted:
- both converge (|φ − φ_max| <= 1e-4 φ_max) in at most 8 Newton steps (measured 4 and 6; before
  the walls' friction heat was in the scene 4 and 8: on the way to the force limit the solve at
  V = 36.67 mm/s landed on the other contact state of the die corner — its node released, F 8 %
  lower — which cost three steps; docs/theory.md §10.3);
- each speed is a true crossing, checked by runs this check makes itself without sensitivities:
  φ(0.99 V) < φ_max < φ(1.01 V) (φ grows with V; a 1 % bracket is 100× the Newton tolerance's
  effect on V here, |Δφ / (V φ')| ~ 1e-4 / 0.05);
- the diagram's files exist (limits.csv, limits.json, the PNG larger than an empty figure).

usage: extrusion_limits_checks.py FLOWFORM SOURCE_DIR OUTDIR
"""
import json
import os
import sys

from flowform_tools import launcher
from flowform_tools.checks import check, pictures_drawn, verdict


def main():
    flowform, source, outdir = sys.argv[1:4]
    script = os.path.join(source, "scripts", "extrusion_limits.py")
    case = os.path.join(source, "xml", "hot_extrusion.xml")
    r = launcher.run_command([sys.executable, script, "--flowform", flowform, "--billet", "723", "--no-estimate",
                              "--out", outdir])
    failed = check(r.status == 0, f"extrusion_limits.py exits {r.status}")
    with open(os.path.join(outdir, "limits.json")) as f:
        rows = json.load(f)
    limits = {"exit_temperature": 740.0, "ram_force": 4500.0}
    for row in rows:
        response, speed = row["response"], row.get("speed")
        failed += check(row["converged"] and row["iterations"] <= 8,
                        f"{response} = {limits[response]:g}: V = {speed} in {row.get('iterations')} step(s) <= 8")
        if not row["converged"]:
            continue
        around = []
        for factor in (0.99, 1.01):
            run = launcher.run(flowform, case, os.path.join(outdir, f"{response}_{factor:g}"),
                               [f"Boundary Conditions/ram/Velocity X={launcher.lit(factor * speed)}",
                                "Output/Write Solution=false", "Output/Boundary CSV=false"], quiet=True)
            around.append(run.summary["functionals"][response] if run.status == 0 else float("nan"))
        failed += check(around[0] < limits[response] < around[1],
                        f"{response}: phi(0.99 V) = {around[0]:.4f} < {limits[response]:g} < phi(1.01 V) = {around[1]:.4f}")
    failed += check(all(os.path.isfile(os.path.join(outdir, n)) for n in ("limits.csv", "limits.json"))
                    and pictures_drawn([os.path.join(outdir, "extrusion_limits.png")]), "limits.csv, .json and the diagram")
    return verdict(failed)


if __name__ == "__main__":
    sys.exit(main())
