"""Whole-run checks of the sensitivity analysis (docs/theory.md §4, docs/sensitivity.md).

usage: sensitivity_checks.py SUBCOMMAND FLOWFORM SOURCE_DIR WORK_DIR [options]

subcommands
  channel     channel (Q1, N = 16, n = 5, σ0 = 0.5): du/dσ0 and du/dn (and dp/dh) by DDM vs the
              built-in central differences, relative difference (max norm) < 1e-5; one
              factorization for both parameters and one back-substitution each; the fields in
              solution.h5 and the columns in the boundary CSVs.
  extrusion   xml/extrusion.xml at ν in --nu (default 0.05,0.1,0.3) on every contact wall of the
              case: dF/dν and d(mean ram pressure)/dν vs central differences < 1e-5 where no
              node switches (a switch must be flagged one_sided with the nodes listed, and is
              then excluded).
  external    dF/dν by DDM against a central difference of two independent full runs at ν ± 2e-4
              (from scratch, the whole contact loop each), at ν in --nu; both must end in the
              base run's contact state.
  one-sided   the extrusion at ν = 0.05 with δ = 8e-4: a node of the first contact wall (the
              container) goes from slip to stick at ν + δ; the entries must say one_sided, list
              that node, and name the side on which nothing changed.
  sellars-tegart  xml/channel_sellars_tegart.xml (the channel with the Sellars–Tegart law,
              docs/theory.md §1): du/dh and dp/dh for h = Q, T, α, A, n by DDM vs the built-in
              central differences < 1e-5 (relative steps of --step; the test passes 5e-5); one
              factorization for the five; Q and T enter only through Q/T, so T |du/dT| = Q |du/dQ|
              (1e-8). Q and T move ln Z by (Q/(R T)) δ = 24.9 δ, so their truncation is ~600× that of
              a step δ in the other parameters: measured 4.1e-6 (Q, velocity) at δ = 2e-4, hence
              5e-5 (~2.6e-7 by δ², the others ≤ 2e-7; the solver error grows 4× to ≲ 1e-9).
  hensel-spittel  xml/channel_hensel_spittel.xml (every term of the law on): du/dh and
              dp/dh for its eleven parameters by DDM vs the built-in central differences < 1e-5
              (relative steps: for the small θ coefficients m5, m8 δ = 4e-8, 1e-8 moves log σ̄ by θ δ ~ 3e-5,
              enough above the solves' 1e-10 noise: measured 1e-9 and 4e-10); ε A |d/dA| = |d/dm7| (1e-8:
              σ̄ depends on A and m7 only through A e^(m7 ε)).
  shape       shape parameters ("Geo Parameter:<name>", docs/sensitivity.md §10): the extrusion's die
              opening `exit` and land length `Le` (dF/dh by DDM on the mesh moved along V = dX/dh
              vs the built-in central differences, the .geo meshed again at h ± δ): |difference|
              × h / F < 2e-5 (measured 3.9e-6, 2.5e-6: the differences in the node positions lose
              a few 1e-6 of F to round-off, 4.4e-4 of the small dF/dLe); signs: the force falls as the opening grows and rises
              with the land. The die swell's die length `Ld` through the free surface (the
              total derivative with the surface re-converged at Ld ± δ): d(swell)/dLd and the
              flow rates < 3e-4 (measured 2.8e-5 and 2e-6: the finite-difference runs converge
              their surfaces to 1e-4 of the case's move tolerance).
  no-work     the channel without a Sensitivity list, with one (DDM only), and with an empty
              Parameters array: the first and last do no sensitivity work (no factorization,
              solve, field or column beyond the flow solve's), the second exactly one
              factorization and one solve per parameter more.

Tolerances. The central difference errs by truncation (δ²/6)|φ'''| plus the nonlinear solver's
error divided by δ. The runs converge to ||F|| <= 1e-10 and ||Δx|| <= 1e-8 ||x|| with Newton's
quadratic rate, so the solver error in φ is ~1e-14 |φ'| δ (measured: the rel. difference keeps
falling as δ² down to δ = 1e-5, docs/sensitivity.md); with δ = 2e-4 (absolute on ν, relative
on σ0, n) the truncation measured is <= 1.2e-6 (dF/dν) and <= 2e-7 (channel fields), so 1e-5
holds with a margin of 8 or more.
"""
import argparse
import os
import sys

from flowform_tools import case as case_module, csvio, h5io, launcher, summary

TOL = 1e-5


def run(flowform, case, outdir, sets, expect=0):
    # The case's own mesh, solved once (the extrusion scene adapts by default).
    r = launcher.run(flowform, case, outdir, ["Adaptivity/Enabled=false"] + list(sets), quiet=True)
    if r.status != expect:
        raise SystemExit(f"flowform exited {r.status}, expected {expect}: {launcher.command_line(r.command)}")
    return summary.load(outdir, missing_ok=False)


class Checker:
    def __init__(self):
        self.failed = 0

    def check(self, ok, what):
        print(("ok   " if ok else "FAIL ") + what)
        self.failed += 0 if ok else 1


def extrusion_case(args):
    """xml/extrusion.xml, its Contact Wall groups, and its tool force and mean tool pressure responses."""
    case = os.path.join(args.source, "xml", "extrusion.xml")
    scene = case_module.Case(case)
    force = scene.tool_force()
    pressure = scene.response("Mean Pressure", boundary=scene.tool_boundary())
    return case, scene.contact_walls(), force, pressure


def channel(args, c):
    case = os.path.join(args.source, "xml", "channel.xml")
    s = run(args.flowform, case, os.path.join(args.work, "channel"),
            ["Sensitivity/Parameters={Yield Stress, Rate Exponent}", "Sensitivity/Finite Difference Check=true",
             f"Sensitivity/Finite Difference Step={args.step}"])
    sens = s["sensitivity"]
    c.check(sens["factorizations"] == 1, f"one factorization for both parameters ({sens['factorizations']})")
    c.check(sens["solves"] == 2, f"one back-substitution per parameter ({sens['solves']} for 2)")
    c.check(sens["finite_difference"]["runs"] == 4, f"two nonlinear solves per parameter ({sens['finite_difference']['runs']})")
    for field in ["velocity_field", "pressure_field"]:
        for p in ["Yield Stress", "Rate Exponent"]:
            e = s["fd_check"][field][p]
            c.check(not e["one_sided"] and e["rel_diff"] < TOL,
                    f"{field} d/d{p}: |DDM| {e['ddm']:.6g}, |FD| {e['fd']:.6g}, rel. difference {e['rel_diff']:.3e} < {TOL}")
    names = set(h5io.field_names(os.path.join(args.work, "channel")))
    want = {"du_dsigma0", "dp_dsigma0", "du_dn", "dp_dn"}
    c.check(want <= names, f"solution.h5 has {sorted(want)}")
    want = ["du_t_dsigma0", "du_n_dsigma0", "dp_dsigma0", "du_t_dn", "du_n_dn", "dp_dn"]
    for group in case_module.Case(case).groups():
        header = csvio.header(os.path.join(args.work, "channel"), group)
        c.check(all(w in header for w in want), f"boundary_{group}.csv columns {want}")


def extrusion(args, c):
    case, walls, force, pressure = extrusion_case(args)
    for nu in args.nu.split(","):
        sets = [f"Boundary Conditions/{w}/Friction Coefficient={nu}" for w in walls]
        sets += ["Sensitivity/Parameters={Friction Coefficient}", "Sensitivity/Finite Difference Check=true"]
        s = run(args.flowform, case, os.path.join(args.work, f"nu_{nu}"), sets)
        for response in [force, pressure]:
            e = s["fd_check"][response]["Friction Coefficient"]
            what = (f"ν = {nu}: d{response}/dν DDM {e['ddm']:.8g}, FD {e['fd']:.8g}, rel. difference "
                    f"{e['rel_diff']:.3e}")
            if e["one_sided"]:
                c.check(len(e["changed_nodes"]) > 0, what + f" — one-sided, {len(e['changed_nodes'])} node(s) switch (excluded)")
            else:
                c.check(e["rel_diff"] < TOL, what + f" < {TOL}")
        c.check(s["sensitivities"][force]["Friction Coefficient"] > 0, f"ν = {nu}: the ram force grows with ν")


def external(args, c):
    """DDM against a central difference of two independent full runs (each from scratch: predictor,
    continuation, the whole contact loop), not the built-in warm-started check.

    The runs at ν ± δ are separate processes and their contact loops may take different paths;
    the difference is only meaningful when both end in the same contact state, which is checked
    node by node from the boundary CSVs (status) and is then the truncation O(δ²) plus each
    run's solver error over δ (≤ 1e-10 / 2e-4 relative), so 1e-5 holds as for the built-in check.
    The walls' Penalty Viscosity is fixed (--penalty-viscosity, default 1): with the adaptive
    default each run takes its penalty scales from its own solution, so the two runs differ
    also through dα/dν, which the DDM (scales held) leaves out — measured 1.6e-5 (ν = 0.1) and
    1.6e-4 (ν = 0.3) relative, the size of the sticking penalty's effect (docs/sensitivity.md).
    """
    case, walls, force, _ = extrusion_case(args)
    delta = 2e-4
    for nu in args.nu.split(","):
        runs = {}
        for tag, value in (("base", float(nu)), ("minus", float(nu) - delta), ("plus", float(nu) + delta)):
            sets = [f"Boundary Conditions/{w}/Friction Coefficient={value!r}" for w in walls]
            if args.penalty_viscosity:
                sets += [f"Boundary Conditions/{w}/Penalty Viscosity={args.penalty_viscosity}" for w in walls]
            if tag == "base":
                sets += ["Sensitivity/Parameters={Friction Coefficient}"]
            out = os.path.join(args.work, f"nu_{nu}_{tag}")
            runs[tag] = (run(args.flowform, case, out, sets), out)
        def status(out):
            return [v for w in walls for v in csvio.status_column(out, w)]
        same = status(runs["minus"][1]) == status(runs["plus"][1]) == status(runs["base"][1])
        c.check(same, f"ν = {nu}: the two full runs at ν ± {delta} end in the base run's contact state")
        fm, fp = runs["minus"][0]["functionals"][force], runs["plus"][0]["functionals"][force]
        fd = (fp - fm) / (2 * delta)
        ddm = runs["base"][0]["sensitivities"][force]["Friction Coefficient"]
        rel = abs(ddm - fd) / abs(fd)
        # A wall node that changes between stick and slip inside [ν − δ, ν + δ] puts a kink of F
        # there (the contact statuses are compared above, the friction branches are not in the
        # CSVs): then the one-sided difference on the side without the kink is the derivative,
        # to its truncation O(δ) — |F''| δ / |F'| ≤ 1e-5 measured on the smooth side — so 5e-5.
        fb = runs["base"][0]["functionals"][force]
        one_sided = min(abs(ddm - (fp - fb) / delta), abs(ddm - (fb - fm) / delta)) / abs(ddm)
        c.check(rel < TOL or one_sided < 5 * TOL,
                f"ν = {nu}: dF/dν DDM {ddm:.8g} vs central difference of two full runs {fd:.8g}: "
                f"rel. difference {rel:.3e} < {TOL}" +
                ("" if rel < TOL else f", or one-sided (a kink within δ): {one_sided:.3e} < {5 * TOL:g}"))


def one_sided(args, c):
    case, walls, force, _ = extrusion_case(args)
    sets = [f"Boundary Conditions/{w}/Friction Coefficient=0.05" for w in walls]
    sets += ["Contact/Status Update=Certain Iterate"]  # the state (and its switching node) of the paper's loop
    sets += ["Sensitivity/Parameters={Friction Coefficient}", "Sensitivity/Finite Difference Check=true",
             "Sensitivity/Finite Difference Step=8e-4"]
    s = run(args.flowform, case, os.path.join(args.work, "one_sided"), sets)
    e = s["fd_check"][force]["Friction Coefficient"]
    c.check(e["one_sided"] and e["status"] == "one_sided", "the entry says one_sided")
    changed = e["changed_nodes"]
    c.check(any(n["wall"] == walls[0] and n["base"].startswith("slip") and n["plus"] == "stick" for n in changed),
            f"it lists the {walls[0]} node that sticks at ν + δ: {changed}")
    c.check(e.get("consistent_side") == "minus" and "rel_diff_one_sided" in e,
            f"and the side where nothing changed (minus), with the backward difference "
            f"{e['fd_backward']:.8g} vs DDM {e['ddm']:.8g}")
    v = s["fd_check"]["velocity_field"]["Friction Coefficient"]
    c.check(v["one_sided"], "the field entries are flagged too")


ST_PARAMETERS = {"Activation Energy": "Q", "Temperature": "T", "Stress Multiplier": "alpha", "Rate Factor": "A",
                 "Rate Exponent": "n"}


def sellars_tegart(args, c):
    case = os.path.join(args.source, "xml", "channel_sellars_tegart.xml")
    out = os.path.join(args.work, "sellars_tegart")
    s = run(args.flowform, case, out,
            ["Sensitivity/Parameters={" + ", ".join(ST_PARAMETERS) + "}", "Sensitivity/Finite Difference Check=true",
             f"Sensitivity/Finite Difference Step={args.step}"])
    c.check(s["parameters"]["Material"]["Law"] == "Sellars-Tegart", "the case runs the Sellars-Tegart law")
    sens = s["sensitivity"]
    c.check(sens["factorizations"] == 1 and sens["solves"] == 5,
            f"one factorization, one back-substitution per parameter ({sens['factorizations']}, {sens['solves']})")
    c.check(sens["finite_difference"]["runs"] == 10, f"two solves per parameter ({sens['finite_difference']['runs']})")
    for field in ["velocity_field", "pressure_field"]:
        for p in ST_PARAMETERS:
            e = s["fd_check"][field][p]
            c.check(not e["one_sided"] and e["rel_diff"] < TOL,
                    f"{field} d/d{p}: |DDM| {e['ddm']:.6g}, |FD| {e['fd']:.6g}, rel. difference {e['rel_diff']:.3e} < {TOL}")
        q, t = s["parameters"]["Material"]["Activation Energy"], s["parameters"]["Material"]["Temperature"]
        dq, dt = s["fd_check"][field]["Activation Energy"]["ddm"], s["fd_check"][field]["Temperature"]["ddm"]
        # Exact in exact arithmetic (∂R/∂T = −(Q/T) ∂R/∂Q, one factorization); the back-substitution's
        # round-off is relative to the whole vector, of which dp/dh is ~1e-3: measured 3.6e-10 (p),
        # 1e-12 (u). 1e-8; a wrong factor (R, T², the sign) is O(1).
        c.check(abs(t * dt - q * dq) <= 1e-8 * q * dq, f"{field}: T |d/dT| = {t * dt:.12g} = Q |d/dQ| = {q * dq:.12g}")
    names = set(h5io.field_names(out))
    want = {f"d{v}_d{sym}" for v in "up" for sym in ST_PARAMETERS.values()}
    c.check(want <= names, f"solution.h5 has {sorted(want)}")


HS_PARAMETERS = ["A", "m1", "m2", "m3", "m4", "m5", "m7", "m8", "m9", "Strain", "Temperature"]


def hensel_spittel(args, c):
    case = os.path.join(args.source, "xml", "channel_hensel_spittel.xml")
    out = os.path.join(args.work, "hensel_spittel")
    names = HS_PARAMETERS
    s = run(args.flowform, case, out,
            ["Sensitivity/Parameters={" + ", ".join(names) + "}", "Sensitivity/Finite Difference Check=true",
             f"Sensitivity/Finite Difference Step={args.step}"])
    c.check(s["parameters"]["Material"]["Law"] == "Hensel-Spittel", "the case runs the Hensel-Spittel law")
    sens = s["sensitivity"]
    c.check(sens["factorizations"] == 1 and sens["solves"] == len(names),
            f"one factorization, one back-substitution per parameter ({sens['factorizations']}, {sens['solves']})")
    for field in ["velocity_field", "pressure_field"]:
        for p in names:
            e = s["fd_check"][field][p]
            c.check(not e["one_sided"] and e["rel_diff"] < TOL,
                    f"{field} d/d{p}: |DDM| {e['ddm']:.6g}, |FD| {e['fd']:.6g}, rel. difference {e['rel_diff']:.3e} < {TOL}")
        # σ̄ ∝ A and ∝ e^(m7 ε): ∂R/∂m7 = ε A ∂R/∂A exactly, so ε A |d/dA| = |d/dm7| (one factorization:
        # round-off of the back-substitution, 1e-8 as for Sellars-Tegart's Q and T).
        a, m7 = s["fd_check"][field]["A"]["ddm"], s["fd_check"][field]["m7"]["ddm"]
        eps, big_a = s["parameters"]["Material"]["Strain"], s["parameters"]["Material"]["A"]
        c.check(abs(eps * big_a * a - m7) <= 1e-8 * abs(m7), f"{field}: eps A |d/dA| = {eps * big_a * a:.12g} = "
                                                             f"|d/dm7| = {m7:.12g}")


def no_work(args, c):
    case = os.path.join(args.source, "xml", "channel.xml")
    base = run(args.flowform, case, os.path.join(args.work, "none"), [])
    empty = run(args.flowform, case, os.path.join(args.work, "empty"), ["Sensitivity/Parameters={}"])
    ddm = run(args.flowform, case, os.path.join(args.work, "ddm"),
              ["Sensitivity/Parameters={Yield Stress, Rate Exponent, Rate Constant}"])
    for name, s in [("no Sensitivity list", base), ("empty Parameters", empty)]:
        sens = s["sensitivity"]
        c.check(sens["factorizations"] == 0 and sens["solves"] == 0 and sens["finite_difference"]["runs"] == 0,
                f"{name}: no sensitivity factorization, solve or FD run ({sens['factorizations']}, {sens['solves']}, "
                f"{sens['finite_difference']['runs']})")
        c.check(s["sensitivities"] == {} and s["fd_check"] == {} and s["timings"]["sensitivity"] == 0.0,
                f"{name}: no sensitivities, no fd_check, no sensitivity time")
        c.check(s["linear_solver"] == base["linear_solver"], f"{name}: the same linear-solver counts as without")
        out = os.path.join(args.work, "none" if s is base else "empty")
        extra = [n for n in h5io.field_names(out) if n.startswith(("du_", "dp_"))]
        columns = [h for group in case_module.Case(case).groups() for h in csvio.header(out, group)]
        c.check(not extra and not any(h.startswith(("du_", "dp_")) for h in columns),
                f"{name}: no sensitivity fields or columns")
    f = ddm["linear_solver"]["factorizations"] - base["linear_solver"]["factorizations"]
    n = ddm["linear_solver"]["solves"] - base["linear_solver"]["solves"]
    c.check(f == 1 and n == 3 and ddm["sensitivity"]["factorizations"] == 1 and ddm["sensitivity"]["solves"] == 3,
            f"3 parameters cost 1 factorization and 3 back-substitutions more ({f}, {n})")
    c.check(ddm["functionals"] == base["functionals"] and ddm["newton_iterations"] == base["newton_iterations"],
            "the flow solve is the same with and without sensitivities")


def shape(args, c):
    case, walls, force, _ = extrusion_case(args)
    s = run(args.flowform, case, os.path.join(args.work, "extrusion"),
            ["Mesh/Geo Parameters/exit=0.5", "Mesh/Geo Parameters/Le=1.5",
             "Sensitivity/Parameters={Geo Parameter:exit, Geo Parameter:Le}", "Sensitivity/Finite Difference Check=true"])
    F = s["functionals"][force]
    for p, value in (("Geo Parameter:exit", 0.5), ("Geo Parameter:Le", 1.5)):
        e = s["fd_check"][force][p]
        gap = abs(e["ddm"] - e["fd"]) * value / F
        c.check(gap < 2e-5, f"d{force}/d({p}): DDM {e['ddm']:.8g}, FD {e['fd']:.8g}, |difference| x {p[14:]} / F = "
                f"{gap:.2e} < 2e-5")
    d = s["sensitivities"][force]
    c.check(d["Geo Parameter:exit"] < 0 < d["Geo Parameter:Le"],
            f"the force falls as the opening grows ({d['Geo Parameter:exit']:.4f}) and rises with the land "
            f"({d['Geo Parameter:Le']:.4f})")
    swell = os.path.join(args.source, "xml", "die_swell.xml")
    s = run(args.flowform, swell, os.path.join(args.work, "die_swell"),
            ["Mesh/Geo Parameters/Ld=4", "Sensitivity/Parameters={Geo Parameter:Ld}",
             "Sensitivity/Finite Difference Check=true", "Error Estimation/Method=None"])
    for response in ("swell", "inflow", "outflow"):
        e = s["fd_check"][response]["Geo Parameter:Ld"]
        c.check(e["rel_diff_total_shape"] < 3e-4,
                f"d{response}/dLd through the free surface: DDM {e['ddm_total_shape']:.8g}, FD (re-converged) "
                f"{e['fd_moving_shape']:.8g}, rel. difference {e['rel_diff_total_shape']:.2e} < 3e-4")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("subcommand", choices=["channel", "extrusion", "external", "one-sided", "sellars-tegart",
                                                       "hensel-spittel",
                                                       "no-work", "shape"])
    parser.add_argument("flowform")
    parser.add_argument("source")
    parser.add_argument("work")
    parser.add_argument("--nu", default="0.05,0.1,0.3")
    parser.add_argument("--penalty-viscosity", default="1.0",
                        help="external: the walls' fixed Penalty Viscosity ('' = the adaptive default)")
    parser.add_argument("--step", default="2e-4", help="channel, sellars-tegart: the FD step (a coarse one must fail the check)")
    args = parser.parse_args()
    os.makedirs(args.work, exist_ok=True)
    c = Checker()
    {"channel": channel, "extrusion": extrusion, "external": external, "one-sided": one_sided,
     "sellars-tegart": sellars_tegart, "hensel-spittel": hensel_spittel, "no-work": no_work,
     "shape": shape}[args.subcommand](args, c)
    print("FAILED" if c.failed else "PASSED")
    return 1 if c.failed else 0


if __name__ == "__main__":
    sys.exit(main())
