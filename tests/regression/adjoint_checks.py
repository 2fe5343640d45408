"""The adjoint sensitivities and friction fields (docs/sensitivity.md "Adjoint", docs/contact.md
"Friction fields").

usage: adjoint_checks.py SUBCOMMAND FLOWFORM SOURCE_DIR WORK_DIR

subcommands
  agree   the same case solved twice, Sensitivity/Method = Direct and = Adjoint: every response's
          derivative by every parameter equal to round-off (|adjoint − direct| <= 1e-8 of the
          response's largest derivative). Both runs solve the same equations to the same x bit for
          bit; the two derivatives differ only by the linear solves' round-off, κ(K_t) ε ~ 1e-10 of
          the largest entry for these systems (measured below 1e-11 on each scene). Scenes:
          the extrusion with the responses of every kind (reactions, pressure, cell integrals,
          wall powers, point values, flow rates) by ν of one wall, σ0, n, the ram speed and the die
          opening (a Geo Parameter); the hot extrusion's temperatures and heat flows by the
          activation energy, the conductivity, the billet temperature and the container's ν;
          the die swell's free surface on its converged shape (Shape Derivative = Frozen).
  field   xml/extrusion.xml with a Friction Field of five stations on the container, all at the
          case's ν = 0.1: the same solution as the uniform ν (ram force equal to 1e-12); Σ_j
          dF/dν_j = dF/dν of the uniform container (the stations' hat functions add up to 1 at
          every node: equal to 1e-9, the linear solves' round-off); each dF/dν_j by DDM against the
          built-in central differences < 1e-5 (as for ν, sensitivity_checks.py: truncation and the
          solver's error over δ are ~1e-6), or flagged one-sided where a node switches between
          stick and slip inside ±δ; the adjoint equal to the DDM as in `agree`; a field that
          rises towards the die (lubricant failing there) raises the force, and each station's
          derivative is positive.
"""
import argparse
import os
import sys

from flowform_tools import launcher, summary

ROUND_OFF = 1e-8  # relative to the largest derivative of the response (see above)
FD_TOL = 1e-5


class Checker:
    def __init__(self):
        self.failed = 0

    def check(self, ok, what):
        print(("ok   " if ok else "FAIL ") + what)
        self.failed += 0 if ok else 1


def run(flowform, case, outdir, sets, expect=0):
    r = launcher.run(flowform, case, outdir, list(sets), quiet=True)
    if r.status != expect:
        raise SystemExit(f"flowform exited {r.status}, expected {expect}: {launcher.command_line(r.command)}")
    return summary.load(outdir, missing_ok=False)


def params_set(names):
    return "Sensitivity/Parameters={" + ", ".join(names) + "}"


def compare(c, scene, direct, adjoint, parameters):
    d, a = direct["sensitivities"], adjoint["sensitivities"]
    c.check(sorted(d) == sorted(a), f"{scene}: the same responses differentiated ({len(d)})")
    c.check(adjoint["sensitivity"]["method"] == "adjoint" and direct["sensitivity"]["method"] == "direct",
            f"{scene}: the summaries name the method")
    worst = 0.0
    for response in d:
        scale = max(abs(v) for v in d[response].values()) or 1.0
        for p in parameters:
            diff = abs(a[response][p] - d[response][p]) / scale
            worst = max(worst, diff)
            if diff > ROUND_OFF:
                c.check(False, f"{scene}: d{response}/d{p}: direct {d[response][p]:.12g}, adjoint {a[response][p]:.12g}")
    c.check(worst <= ROUND_OFF, f"{scene}: adjoint = direct for {len(d)} responses x {len(parameters)} parameters, "
                                f"largest difference {worst:.2e} of the response's largest derivative <= {ROUND_OFF}")
    solves_a, solves_d = adjoint["sensitivity"]["solves"], direct["sensitivity"]["solves"]
    c.check(solves_a == len(d) and solves_d == len(parameters),
            f"{scene}: {solves_a} transposed back-substitutions (one per response), {solves_d} direct (one per parameter)")


EXTRUSION_RESPONSES = [
    "Responses/plastic_power/Type=Plastic Power",
    "Responses/stabilization_power/Type=Stabilization Power",
    "Responses/container_friction/Type=Friction Power", "Responses/container_friction/Boundary=container",
    "Responses/land_force/Type=Wall Force", "Responses/land_force/Boundary=die_land",
    "Responses/exit_speed_axis/Type=Point Value", "Responses/exit_speed_axis/Field=Velocity X",
    "Responses/exit_speed_axis/X=1.2", "Responses/exit_speed_axis/Y=0.05",
    "Responses/exit_pressure/Type=Point Value", "Responses/exit_pressure/Field=Pressure",
    "Responses/exit_pressure/X=0.3", "Responses/exit_pressure/Y=0.3",
    "Responses/outflow/Type=Flow Rate", "Responses/outflow/Boundary=outlet",
]


def agree(args, c):
    scenes = [
        ("extrusion", "extrusion.xml",
         ["Adaptivity/Enabled=false"] + EXTRUSION_RESPONSES,
         ["Friction Coefficient:container", "Friction Coefficient:die_land", "Yield Stress", "Rate Exponent",
          "Boundary Value:ram/Velocity X", "Geo Parameter:exit"]),
        ("hot_extrusion", "hot_extrusion.xml", ["Adaptivity/Enabled=false"],
         ["Activation Energy", "Thermal:Conductivity", "Boundary Value:ram/Temperature",
          "Friction Coefficient:container"]),
        ("die_swell", "die_swell.xml", ["Sensitivity/Shape Derivative=Frozen"], ["Rate Exponent", "Yield Stress"]),
    ]
    for scene, case, sets, parameters in scenes:
        path = os.path.join(args.source, "xml", case)
        common = sets + [params_set(parameters), "Error Estimation/Method=None"]
        direct = run(args.flowform, path, os.path.join(args.work, scene + "_direct"), common)
        adjoint = run(args.flowform, path, os.path.join(args.work, scene + "_adjoint"),
                      common + ["Sensitivity/Method=Adjoint"])
        same = direct["functionals"] == adjoint["functionals"]
        c.check(same, f"{scene}: the two runs have the same responses (the same solve)")
        compare(c, scene, direct, adjoint, parameters)


def field(args, c):
    case = os.path.join(args.source, "xml", "extrusion.xml")
    stations = 5
    base = ["Adaptivity/Enabled=false", "Error Estimation/Method=None"]
    uniform = run(args.flowform, case, os.path.join(args.work, "uniform"),
                  base + [params_set(["Friction Coefficient:container"])])
    names = [f"Friction Field:container/{j}" for j in range(stations)]
    as_field = base + ["Boundary Conditions/container/Friction Field={" + ", ".join(["0.1"] * stations) + "}"]
    direct = run(args.flowform, case, os.path.join(args.work, "field_direct"),
                 as_field + [params_set(names), "Sensitivity/Finite Difference Check=true"])
    adjoint = run(args.flowform, case, os.path.join(args.work, "field_adjoint"),
                  as_field + [params_set(names), "Sensitivity/Method=Adjoint"])
    force = "ram_force"
    f_u, f_f = uniform["functionals"][force], direct["functionals"][force]
    c.check(abs(f_u - f_f) <= 1e-12 * abs(f_u),
            f"a field of equal values is the uniform ν: F {f_f:.15g} vs {f_u:.15g}")
    stations_xy = direct["friction_fields"]["container"]["stations"]
    c.check(len(stations_xy) == stations and abs(stations_xy[0][0]) < 1e-12 and abs(stations_xy[-1][0] + 1.5) < 1e-12,
            f"summary.json lists the stations, from the die (x = 0) to the ram (x = -1.5): {stations_xy}")
    total = sum(direct["sensitivities"][force][n] for n in names)
    dnu = uniform["sensitivities"][force]["Friction Coefficient:container"]
    c.check(abs(total - dnu) <= 1e-9 * abs(dnu),
            f"sum of dF/dnu_j {total:.12g} = dF/dnu of the uniform container {dnu:.12g}")
    for n in names:
        e = direct["fd_check"][force][n]
        what = f"dF/d{n}: DDM {e['ddm']:.8g}, FD {e['fd']:.8g}, rel. difference {e['rel_diff']:.2e}"
        if e["one_sided"]:
            c.check(len(e["changed_nodes"]) > 0, what + " - one-sided (a node switches; excluded)")
        else:
            c.check(e["rel_diff"] < FD_TOL, what + f" < {FD_TOL}")
        c.check(e["ddm"] > 0, f"dF/d{n} > 0: more friction anywhere on the container, more force")
    compare(c, "field", direct, adjoint, names)
    failing = run(args.flowform, case, os.path.join(args.work, "field_failing"),
                  base + ["Boundary Conditions/container/Friction Field={0.3, 0.2, 0.1, 0.1, 0.1}"])
    c.check(failing["functionals"][force] > f_u,
            f"lubricant failing near the die raises the force: {failing['functionals'][force]:.6g} > {f_u:.6g}")


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("subcommand", choices=["agree", "field"])
    p.add_argument("flowform")
    p.add_argument("source")
    p.add_argument("work")
    args = p.parse_args()
    os.makedirs(args.work, exist_ok=True)
    c = Checker()
    {"agree": agree, "field": field}[args.subcommand](args, c)
    print(f"{c.failed} failed")
    return 1 if c.failed else 0


if __name__ == "__main__":
    sys.exit(main())
