"""Power balance: the discrete identity and the discretization's share (docs/extrusion_verification.md §2)."""
import math

from .common import mesh_list, stabilization_power


def cmd_power(runner, args, checks):
    """Ram power vs plastic + friction dissipation: the mismatch is what the discretization adds.

    Exactly (the discrete identity, docs/extrusion_verification.md §2):
        ram power = plastic + friction + stabilization + penalty power.
    The stabilization and penalty terms are discretization artefacts (τ_K ∝ h_K², α_n ∝ 1/u_n
    penetration), so (ram − plastic − friction)/ram must shrink under refinement.
    """
    meshes = mesh_list(args.meshes, "0.2,0.1,0.05")
    nus = (0.0, 0.1)
    extra = ["Responses/stabilization_power/Type=Stabilization Power", "Responses/penalty_power/Type=Penalty Power"]
    specs = [(f"h = {h}, nu = {nu}", dict(name=f"power_nu{nu}_h{h}", h=h, nu=nu, sets=extra))
             for nu in nus for h in meshes]
    runs = dict(zip([(nu, h) for nu in nus for h in meshes], runner.run_all(specs, checks)))
    table = []
    for nu in nus:
        mismatch = []
        for h in meshes:
            run = runs[(nu, h)]
            if not checks.check(run.converged, f"{run.label}: converged"):
                mismatch.append(None)
                continue
            F, BP = run.force, run.f(runner.power_name)
            PP, FP = run.f("plastic_power"), run.f("friction_power")
            S, Pi = run.f("stabilization_power"), run.f("penalty_power")
            S_h5 = stabilization_power(run)
            m = (BP - PP - FP) / BP
            mismatch.append(m)
            table.append(dict(nu=nu, h=h, ram_force=F, ram_power=BP, plastic=PP, friction=FP, stabilization=S,
                              stabilization_from_h5=S_h5, penalty=Pi, mismatch=m))
            print(f"    nu = {nu} h = {h}: ram power {BP:.6f} = plastic {PP:.6f} + friction {FP:.6f} + "
                  f"stabilization {S:.6f} (from solution.h5 {S_h5:.6f}) + penalty {Pi:.3e}; "
                  f"(ram - plastic - friction)/ram = {m:.4%}")
            checks.check(abs(F * 1.0 - BP) <= 1e-12 * abs(BP) and abs(run.f(runner.pressure_name) - F / 1.0) <= 1e-12 * abs(F),
                         f"{run.label}: ram force x ram speed 1 = ram power = ram pressure x ram length 1 "
                         f"({F:.12g}, {BP:.12g})")
            # |F| <= 1e-10 at convergence bounds the identity's error by ~1e-9 of the ram power.
            identity = (BP - PP - FP - S - Pi) / BP
            checks.check(abs(identity) <= 1e-8, f"{run.label}: ram - plastic - friction - stabilization - penalty "
                                                f"power = {identity:.1e} of the ram power (|.| <= 1e-8)")
            # An independent recomputation of Σ τ_K |∇p|² |K| from the written fields (P1: ∇p constant
            # per cell; τ_K from the written centroid viscosity): it must agree to round-off.
            checks.check(abs(S_h5 - S) <= 1e-6 * abs(S), f"{run.label}: stabilization power from solution.h5 "
                                                         f"{S_h5:.8f} = the response {S:.8f} (rel. 1e-6)")
            checks.check(Pi > 0 and S > 0, f"{run.label}: penalty {Pi:.2e} > 0 and stabilization {S:.2e} > 0 dissipate")
        done = [(h, m) for h, m in zip(meshes, mismatch) if m is not None]
        for (h1, m1), (h2, m2) in zip(done, done[1:]):
            rate = math.log(m1 / m2) / math.log(h1 / h2)
            checks.check(m1 / m2 >= 1.4, f"nu = {nu}: mismatch {m1:.4%} (h = {h1}) -> {m2:.4%} (h = {h2}), "
                                         f"ratio {m1 / m2:.2f} >= 1.4 (observed order {rate:.2f} >= 0.5)")
        if any(h == 0.1 for h, _ in done):
            m01 = dict(done)[0.1]
            checks.check(0 < m01 < 0.03, f"nu = {nu}: mismatch at h = 0.1 is {m01:.4%}, in (0, 3%)")
    checks.record("table", table)


COMMANDS = {"power": cmd_power}
