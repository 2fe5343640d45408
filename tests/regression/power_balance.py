"""The discrete power balance of a converged run, which holds to solver tolerance:

    Σ_tools Boundary Power + Σ_moving Tool Power = Plastic + Friction + Penalty + Stabilization Power

(multiply the momentum equations by u and the continuity equation by p and add: every
term of the residual appears once). An independent check of the reaction (ram) force,
the contact terms and the assembly. |F| <= 1e-10 at convergence bounds the power error by
|F| |u| ~ 1e-9 of the ram power here; 1e-8 is asserted.

With moving contact walls (Tool Motion) their Tool Power, the power each delivers, enters the
left side (docs/theory.md §2 "Moving tools"); Friction and Penalty Power are then on the
velocity relative to the tool.

usage: power_balance.py FLOWFORM CASE.xml OUTDIR TOOL [--moving-wall WALL ...] [--set P=V ...]
"""
import sys

from flowform_tools import launcher

TOL = 1e-8


def main():
    flowform, case, outdir, tool = sys.argv[1:5]
    extra, moving = [], []
    args = iter(sys.argv[5:])
    for a in args:
        if a == "--moving-wall":
            moving.append(next(args))
        else:
            extra.append(a)
    responses = {"plastic": "Plastic Power", "friction": "Friction Power", "penalty": "Penalty Power",
                 "stabilization": "Stabilization Power", "tool_power": "Boundary Power"}
    responses.update({f"moving_{w}": "Tool Power" for w in moving})
    sets = [f"Responses/tool_power/Boundary={tool}"] + [f"Responses/{name}/Type={kind}"
                                                         for name, kind in responses.items()]
    sets += [f"Responses/moving_{w}/Boundary={w}" for w in moving]
    run = launcher.run(flowform, case, outdir, sets[:1], args=extra + launcher.set_args(sets[1:]), quiet=True)
    if run.status != 0:
        print(f"flowform exited {run.status}")
        return 1
    values = run.summary["functionals"]
    dissipated = sum(values[n] for n in ("plastic", "friction", "penalty", "stabilization"))
    put_in = values["tool_power"] + sum(values[f"moving_{w}"] for w in moving)
    mismatch = abs(put_in - dissipated) / abs(put_in)
    for name in responses:
        print(f"{name:14s} {values[name]:.12e}  ({values[name] / values['tool_power']:.4%} of the tool power)")
    print(f"relative mismatch {mismatch:.3e} (tolerance {TOL:g})")
    return 0 if mismatch <= TOL else 1


if __name__ == "__main__":
    sys.exit(main())
