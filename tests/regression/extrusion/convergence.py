"""Mesh convergence of the ram force and the die-lip leak (docs/extrusion_verification.md §3)."""
import math

import numpy as np

from .common import mesh_list, observed_order, outlet_flux, richardson


def cmd_convergence(runner, args, checks):
    """Ram force on meshes h_0 > h_1 > ... with a constant ratio r = h_j/h_{j+1}.

    The observed order from three consecutive meshes, q = ln(d_j/d_{j+1})/ln r (d the
    differences of F), and the Richardson estimate F_R = F_fine + d_last/(r^q − 1).
    Also the mass that leaves through the die face next to the die lip: the lip is a re-entrant
    corner of the material where the exit speed meets the die face, so the first die-face
    segment (length hc) carries a flux ~ hc × exit speed/2: 1 − outlet flux must be O(h).
    """
    meshes = mesh_list(args.meshes, "0.2,0.1,0.05")
    ratios = [a / b for a, b in zip(meshes, meshes[1:])]
    ratio = ratios[0]
    if len(meshes) < 3 or any(abs(q / ratio - 1) > 0.01 for q in ratios) or ratio < 1.2:
        raise ValueError(f"convergence needs >= 3 meshes with one ratio >= 1.2 (got {meshes})")
    nus = [float(v) for v in (args.nu or "0.0,0.1").split(",")]
    specs = [(f"h = {h}, nu = {nu}", dict(name=f"conv_nu{nu}_h{h}", h=h, nu=nu)) for nu in nus for h in meshes]
    allruns = runner.run_all(specs, checks)
    table = {}
    for i, nu in enumerate(nus):
        runs = allruns[i * len(meshes):(i + 1) * len(meshes)]
        if not all(checks.check(r.converged, f"{r.label}: converged") for r in runs):
            continue
        F = [r.force for r in runs]
        d = np.diff(F)
        leak = [1.0 - outlet_flux(r) for r in runs]
        orders = observed_order(F, ratio)
        extrapolated = [richardson(F[: j + 3], orders[j], ratio) for j in range(len(orders))]
        entry = {"h": meshes, "ratio": ratio, "ram_force": F, "differences": d.tolist(), "orders": orders,
                 "richardson": extrapolated, "leak": leak,
                 "dofs": [r.summary["dofs"] for r in runs], "seconds": [r.seconds for r in runs],
                 "newton": [r.summary["newton_iterations"] for r in runs],
                 "contact_changes": [r.summary["contact_changes"] for r in runs]}
        print(f"    nu = {nu}: F = " + ", ".join(f"{f:.6f}" for f in F) + "; differences " +
              ", ".join(f"{x:+.6f}" for x in d))
        print(f"    nu = {nu}: observed orders " + ", ".join(f"{q:.3f}" for q in orders) +
              "; Richardson " + ", ".join(f"{x:.5f}" for x in extrapolated))
        print(f"    nu = {nu}: 1 - outlet flux = " + ", ".join(f"{x:.5f}" for x in leak))
        checks.check(all(x > 0 for x in d) or all(x < 0 for x in d),
                     f"nu = {nu}: the ram force changes monotonically under refinement")
        for j in range(len(d) - 1):
            checks.check(abs(d[j + 1]) < abs(d[j]), f"nu = {nu}: |F(h={meshes[j + 1]}) - F(h={meshes[j + 2]})| = "
                                                    f"{abs(d[j + 1]):.5f} < {abs(d[j]):.5f} (the previous difference)")
        q = orders[-1]
        checks.check(0.5 <= q <= 2.5, f"nu = {nu}: observed order on the finest three meshes {q:.3f} in [0.5, 2.5] "
                                      f"(P1 velocity: <= 2; the re-entrant die lip: about 1)")
        error = abs(F[-1] - extrapolated[-1]) / abs(extrapolated[-1])
        entry["finest_error_estimate"] = error
        if len(extrapolated) >= 2:  # four meshes or more: is the extrapolation itself settled?
            spread = abs(extrapolated[-1] - extrapolated[-2]) / abs(extrapolated[-1])
            entry["richardson_spread"] = spread
            checks.check(spread < 0.5 * error, f"nu = {nu}: the last two Richardson estimates differ by {spread:.3%}, "
                                               f"less than half the finest mesh's estimated error {error:.3%}")
        leak_orders = [math.log(a / b) / math.log(ratio) for a, b in zip(leak, leak[1:])]
        entry["leak_orders"] = leak_orders
        checks.check(all(x > 0 for x in leak) and all(0.7 <= o <= 1.3 for o in leak_orders),
                     f"nu = {nu}: the die-lip leak 1 - outlet flux > 0 is O(h): orders " +
                     ", ".join(f"{o:.2f}" for o in leak_orders) + " in [0.7, 1.3]")
        table[str(nu)] = entry
    checks.record("table", table)


COMMANDS = {"convergence": cmd_convergence}
