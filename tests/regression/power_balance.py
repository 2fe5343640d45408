"""The discrete power balance of a converged run, which holds to solver tolerance:

    Σ_tools Boundary Power = Plastic + Friction + Penalty + Stabilization Power

(multiply the momentum equations by u and the continuity equation by p and add: every
term of the residual appears once). An independent check of the reaction (ram) force,
the contact terms and the assembly. |F| <= 1e-10 at convergence bounds the power error by
|F| |u| ~ 1e-9 of the ram power here; 1e-8 is asserted.

usage: power_balance.py FLOWFORM CASE.xml OUTDIR TOOL [--set P=V ...]
"""
import sys

from flowform_tools import launcher

TOL = 1e-8


def main():
    flowform, case, outdir, tool = sys.argv[1:5]
    extra = sys.argv[5:]
    responses = {"plastic": "Plastic Power", "friction": "Friction Power", "penalty": "Penalty Power",
                 "stabilization": "Stabilization Power", "tool_power": "Boundary Power"}
    sets = [f"Responses/tool_power/Boundary={tool}"] + [f"Responses/{name}/Type={kind}"
                                                         for name, kind in responses.items()]
    run = launcher.run(flowform, case, outdir, sets[:1], args=extra + launcher.set_args(sets[1:]), quiet=True)
    if run.status != 0:
        print(f"flowform exited {run.status}")
        return 1
    values = run.summary["functionals"]
    dissipated = sum(values[n] for n in ("plastic", "friction", "penalty", "stabilization"))
    mismatch = abs(values["tool_power"] - dissipated) / abs(values["tool_power"])
    for name in responses:
        print(f"{name:14s} {values[name]:.12e}  ({values[name] / values['tool_power']:.4%} of the tool power)")
    print(f"relative mismatch {mismatch:.3e} (tolerance {TOL:g})")
    return 0 if mismatch <= TOL else 1


if __name__ == "__main__":
    sys.exit(main())
