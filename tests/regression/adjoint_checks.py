"""The adjoint sensitivities and friction fields (docs/sensitivity.md "Adjoint", docs/contact.md
"Friction fields").

usage: adjoint_checks.py SUBCOMMAND FLOWFORM SOURCE_DIR WORK_DIR

subcommands
  agree   the same case solved twice, Sensitivity/Method = Direct and = Adjoint: every response's
          derivative by every parameter equal to round-off (|adjoint − direct| <= 1e-8 of the
          response's largest derivative). Both runs solve the same equations to the same x bit for
          bit; the two derivatives differ only by the linear solves' round-off, κ(K_t) ε of the
          largest entry (measured 6e-11 on the extrusion, 3e-15 on the others). Scenes:
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
  identify  xml/extrusion_identify_friction_field.xml, the container's five-station field from a
          ram force, four pressure taps and three exit speeds made at a hidden field with noise:
          the optimizer converges in at most 15 solves (measured 8); the data resolve four
          directions and leave station 0 (the die corner, in the dead-metal zone) unresolved, which
          independent runs confirm: station 0 raised from its value to 0.4 moves no measured
          response by more than 1 % of its error (measured 3e-6 relative: its nodes stick); each resolved station's hidden value
          lies within 1.96 standard errors of the found one (the noise added is one draw, so a 95 %
          interval); an independent run from scratch at the found field has the reported misfit
          to 0.01 (J is in squared standard errors; measured 8e-4: the warm-started final solve and a
          cold one settle the contact statuses within their tolerances, ~1e-6 of each response);
          the found design is the misfit's minimum: independent runs with stations 1-4
          moved by ±0.01 each have a larger misfit; the same problem solved with Method = Direct
          takes the same solves to the same design (1e-8).
"""
import argparse
import os
import sys
import xml.etree.ElementTree as ET

from flowform_tools import checks, launcher, summary

ROUND_OFF = 1e-8  # relative to the largest derivative of the response (see above)
FD_TOL = 1e-5


class Checker:
    """Counts the failures of checks.check."""

    def __init__(self):
        self.failed = 0

    def check(self, ok, what):
        self.failed += checks.check(ok, what)


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
         ["Adaptivity/Enabled=false", "Mesh/Geo Parameters/exit=0.5"] + EXTRUSION_RESPONSES,
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


HIDDEN_FIELD = [0.2, 0.16, 0.12, 0.08, 0.05]


def misfit(s, optimization):
    return 0.5 * sum(((s["functionals"][name] - m["measured"]) / m["error"]) ** 2
                     for name, m in optimization["measured"].items())


def identify(args, c):
    case = os.path.join(args.source, "xml", "extrusion_identify_friction_field.xml")
    s = run(args.flowform, case, os.path.join(args.work, "identify"), [])
    o = s["optimization"]
    names = [f"Friction Field:container/{j}" for j in range(len(HIDDEN_FIELD))]
    found = [o["design"][n] for n in names]
    c.check(o["converged"] and o["solves"] <= 15, f"converged in {o['solves']} solves (<= 15)")
    res = o["resolution"]
    c.check(res["resolved_directions"] == 4 and res["unresolved_share"][names[0]] > 0.99,
            f"4 directions resolved, station 0 not ({res['unresolved_share'][names[0]]:.3f} of it unresolved)")
    for j in range(1, len(names)):
        se = res["resolved_standard_error"][names[j]]
        c.check(abs(found[j] - HIDDEN_FIELD[j]) <= 1.96 * se,
                f"station {j}: found {found[j]:.4f}, hidden {HIDDEN_FIELD[j]} within 1.96 x {se:.4f}")
    field_of = lambda values: "Boundary Conditions/container/Friction Field={" + ", ".join(repr(v) for v in values) + "}"
    # The same case as one ordinary run (no Optimization sublist, the Base Case's path made absolute).
    tree = ET.parse(case)
    root = tree.getroot()
    root.remove(next(e for e in root if e.tag == "ParameterList" and e.get("name") == "Optimization"))
    base_case = next(e for e in root if e.tag == "Parameter" and e.get("name") == "Base Case")
    base_case.set("value", os.path.abspath(os.path.join(os.path.dirname(case), base_case.get("value"))))
    mesh = ET.SubElement(root, "ParameterList", name="Mesh")  # relative paths follow the case file
    ET.SubElement(mesh, "Parameter", name="File", type="string",
                  value=os.path.abspath(os.path.join(args.source, "meshes", "extrusion.geo")))
    single = os.path.join(args.work, "identify_single_run.xml")
    tree.write(single, encoding="utf-8", xml_declaration=True)
    case = single
    plain = []
    base = run(args.flowform, case, os.path.join(args.work, "at_found"), plain + [field_of(found)])
    raised = run(args.flowform, case, os.path.join(args.work, "station0_raised"),
                 plain + [field_of([0.4] + found[1:])])
    worst = max(abs(raised["functionals"][n] - base["functionals"][n]) / m["error"] for n, m in o["measured"].items())
    c.check(worst <= 0.01, f"station 0 raised to 0.4: the measured responses move by {worst:.1e} of their errors "
                           f"(<= 0.01: the data cannot see it)")
    j_found = misfit(base, o)
    c.check(abs(j_found - o["objective"]) <= 0.01,
            f"an independent run at the found field has the reported misfit: {j_found:.6f} vs {o['objective']:.6f}")
    for j in range(1, len(names)):
        for step in (-0.01, 0.01):
            moved = list(found)
            moved[j] += step
            r = run(args.flowform, case, os.path.join(args.work, f"moved_{j}_{step}"), plain + [field_of(moved)])
            c.check(misfit(r, o) > j_found, f"station {j} {step:+}: misfit {misfit(r, o):.4f} > {j_found:.4f}")
    direct = run(args.flowform, os.path.join(args.source, "xml", "extrusion_identify_friction_field.xml"),
                 os.path.join(args.work, "identify_direct"), ["Sensitivity/Method=Direct"])
    od = direct["optimization"]
    same = od["solves"] == o["solves"] and all(abs(od["design"][n] - o["design"][n]) <= 1e-8 for n in names)
    c.check(same, f"Method = Direct: {od['solves']} solves to the same design")


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("subcommand", choices=["agree", "field", "identify"])
    p.add_argument("flowform")
    p.add_argument("source")
    p.add_argument("work")
    args = p.parse_args()
    os.makedirs(args.work, exist_ok=True)
    c = Checker()
    {"agree": agree, "field": field, "identify": identify}[args.subcommand](args, c)
    return checks.verdict(c.failed)


if __name__ == "__main__":
    sys.exit(main())
