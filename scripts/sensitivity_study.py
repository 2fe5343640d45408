"""Reproduces the measurements of docs/sensitivity.md: DDM against the built-in central
differences on the extrusion and the channel.

usage: scripts/python scripts/sensitivity_study.py [--flowform build/flowform] [--out out/sensitivity_study]
                                    [--only nu,step,jacobian,scales,axisym]

Each study prints a markdown table; the runs stay under --out (one directory each).
  nu        extrusion, ν = 0 ... 0.5: F, dF/dν by DDM and FD (δ = 2e-4), rel. differences, flags
  step      extrusion (ν = 0.1) and channel: rel. difference against the FD step δ
  jacobian  extrusion: DDM with the converged K_t vs the factors Newton leaves, at three
            Newton tolerances
  scales    extrusion: FD with the penalty scales held (as the DDM) vs recomputed at h ± δ
  axisym    axisymmetric extrusion: every parameter and response
"""
import argparse
import os

from flowform_tools import REPO, default_flowform, launcher, summary
from flowform_tools.case import FIXED_MESH, Case


def run(args, case, name, sets):
    out = os.path.join(args.out, name)
    launcher.run(args.flowform, os.path.join(args.root, "xml", case), out, FIXED_MESH + list(sets),
                 quiet=True)
    return summary.load(out, missing_ok=False)


def scene(args, case="extrusion.xml"):
    return Case(os.path.join(args.root, "xml", case))


def walls(args, case="extrusion.xml"):
    """The Contact Wall groups of a case in xml/ (the extrusion's container, die_face, die_land)."""
    return scene(args, case).contact_walls()


def force(args, case="extrusion.xml"):
    """The case's tool force response (ram_force)."""
    return scene(args, case).tool_force()


def check(*params, step=None, extra=()):
    sets = ["Sensitivity/Parameters={" + ", ".join(params) + "}", "Sensitivity/Finite Difference Check=true"]
    if step:
        sets.append(f"Sensitivity/Finite Difference Step={step}")
    return sets + list(extra)


def flag(e):
    return "*" if e.get("one_sided") else ""


def study_nu(args):
    print("\n| ν | F | dF/dν DDM | dF/dν FD | rel. diff F | rel. diff u | rel. diff p | switching nodes |")
    print("|---|---|---|---|---|---|---|---|")
    for nu in ["0", "0.05", "0.1", "0.2", "0.3", "0.5"]:
        sets = [f"Boundary Conditions/{w}/Friction Coefficient={nu}" for w in walls(args)]
        s = run(args, "extrusion.xml", f"nu_{nu}", check("Friction Coefficient", extra=sets))
        e = s["fd_check"][force(args)]["Friction Coefficient"]
        u = s["fd_check"]["velocity_field"]["Friction Coefficient"]
        p = s["fd_check"]["pressure_field"]["Friction Coefficient"]
        print(f"| {nu} | {s['functionals'][force(args)]:.5f} | {e['ddm']:.7f} | {e['fd']:.7f} | {e['rel_diff']:.1e}{flag(e)} "
              f"| {u['rel_diff']:.1e} | {p['rel_diff']:.1e} | {len(e['changed_nodes'])} |")


def study_step(args):
    print("\n| δ | ext. F, ν | ext. u, ν | ext. F, σ0 | ext. F, n | channel u, σ0 | channel u, n | channel p, n |")
    print("|---|---|---|---|---|---|---|---|")
    for step in ["1e-3", "4e-4", "2e-4", "1e-4", "5e-5", "1e-5"]:
        s = run(args, "extrusion.xml", f"step_ext_{step}",
                check("Friction Coefficient", "Yield Stress", "Rate Exponent", step=step))
        c = run(args, "channel.xml", f"step_ch_{step}", check("Yield Stress", "Rate Exponent", step=step))
        f, F = s["fd_check"], force(args)

        def cell(entry):
            return f"{entry['rel_diff']:.1e}{flag(entry)}"
        print(f"| {step} | {cell(f[F]['Friction Coefficient'])} | {cell(f['velocity_field']['Friction Coefficient'])} "
              f"| {cell(f[F]['Yield Stress'])} | {cell(f[F]['Rate Exponent'])} "
              f"| {cell(c['fd_check']['velocity_field']['Yield Stress'])} "
              f"| {cell(c['fd_check']['velocity_field']['Rate Exponent'])} "
              f"| {cell(c['fd_check']['pressure_field']['Rate Exponent'])} |")


def study_jacobian(args):
    print("\n| Newton tolerances | ‖q − q_J‖/‖q‖ | factorizations (conv. / last) | dF/dν | dF/dσ0 | dF/dn |")
    print("|---|---|---|---|---|---|")
    params = ["Friction Coefficient", "Yield Stress", "Rate Exponent"]
    for tol in ["1e-8", "1e-5", "1e-3"]:
        tols = [f"Solver/Update Tolerance={tol}", f"Solver/Relative Residual Tolerance={tol}",
                "Sensitivity/Parameters={" + ", ".join(params) + "}"]
        a = run(args, "extrusion.xml", f"jac_{tol}_converged", tols)
        b = run(args, "extrusion.xml", f"jac_{tol}_last", tols + ["Sensitivity/Jacobian=Last Newton Iterate"])
        diffs = []
        for p in params:
            x, y = a["sensitivities"][force(args)][p], b["sensitivities"][force(args)][p]
            diffs.append(f"{abs(x - y) / abs(x):.1e}")
        print(f"| {tol} | {b['sensitivity']['jacobian_offset']:.1e} | {a['sensitivity']['factorizations']} / "
              f"{b['sensitivity']['factorizations']} | " + " | ".join(diffs) + " |")


def study_scales(args):
    params = ["Friction Coefficient", "Yield Stress", "Rate Constant", "Rate Exponent"]
    print("\n| h | F: held | F: recomputed | u: held | u: recomputed | p: held | p: recomputed |")
    print("|---|---|---|---|---|---|---|")
    held = run(args, "extrusion.xml", "scales_held", check(*params))
    rec = run(args, "extrusion.xml", "scales_recomputed",
              check(*params, extra=["Sensitivity/Finite Difference Scales=Recomputed"]))
    for p in params:
        row = []
        for r in [force(args), "velocity_field", "pressure_field"]:
            row += [f"{held['fd_check'][r][p]['rel_diff']:.1e}", f"{rec['fd_check'][r][p]['rel_diff']:.1e}"]
        print(f"| {p} | " + " | ".join(row) + " |")


def study_axisym(args):
    case = scene(args, "extrusion_axisym.xml")
    F = case.tool_force()
    params = ["Friction Coefficient", f"Friction Coefficient:{case.contact_walls()[-1]}", "Yield Stress",
              "Rate Constant", "Rate Exponent"]
    s = run(args, "extrusion_axisym.xml", "axisym", check(*params))
    responses = [F, case.response("Mean Pressure", boundary=case.tool_boundary()), "velocity_field", "pressure_field"]
    print("\n| h | dF/dh (DDM) | " + " | ".join(responses) + " |")
    print("|---|---|" + "---|" * len(responses))
    for p in params:
        cells = [f"{s['fd_check'][r][p]['rel_diff']:.1e}{flag(s['fd_check'][r][p])}" for r in responses]
        print(f"| {p} | {s['sensitivities'][F][p]:.6g} | " + " | ".join(cells) + " |")
    t = s["timings"]
    print(f"\ntimes: flow solve {t['solve']:.2f} s, DDM {t['sensitivity_ddm']:.3f} s "
          f"({len(params)} parameters), FD check {t['finite_difference_check']:.2f} s")


def main():
    root = REPO
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--flowform", default=default_flowform())
    parser.add_argument("--out", default=os.path.join("out", "sensitivity_study"))
    parser.add_argument("--only", default="nu,step,jacobian,scales,axisym")
    args = parser.parse_args()
    args.root = root
    os.makedirs(args.out, exist_ok=True)
    studies = {"nu": study_nu, "step": study_step, "jacobian": study_jacobian, "scales": study_scales,
               "axisym": study_axisym}
    for name in args.only.split(","):
        print(f"\n## {name}")
        studies[name](args)


if __name__ == "__main__":
    main()
