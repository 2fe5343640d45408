"""Moving tools (docs/theory.md §2 "Moving tools", docs/verification.md "Moving tools").

usage: moving_tool_checks.py SUBCOMMAND FLOWFORM SOURCE_DIR OUTDIR

  couette    drag flow under a translating tool with Norton friction (q = 1), Newtonian material
             (tests/regression/moving_tool/couette.xml): u = U (y + 1)/H with U = V β/(β + μ/H),
             for β = μ/H (U = V/2) and β = 1000 μ/H (nearly sticking, U = 1000 V/1001); the tool's
             force and power against the exact ones, and the power balance
             Tool Power = Plastic + Friction + Penalty + Stabilization Power.
  container  xml/extrusion.xml with the container translating at the ram speed (1, 0): the same
             ram force as the fixed frictionless container when the moving container is
             frictionless too (the motion alone changes nothing); with ν = 0.1 the container
             moves with the billet where the billet is rigid (relative slip ~ 0, sticking) and
             drags the slower metal at the die corner forward, so the ram force falls below the
             frictionless container's; the container's Tool Power = −(its Wall Force X) · 1.

Prints what it measured and one line per check; exits 0 when every check passes.
"""
import os
import sys

from flowform_tools import csvio, launcher

MU, H, V, LENGTH = 1.0 / 3.0, 2.0, 1.0, 4.0  # couette.xml: μ = 1/(3γ), channel height, tool speed, length
SOLVER_TOL = 1e-8  # Newton stops at |F| <= 1e-10 (relative to O(1) loads); velocities to ~1e-10


class Checks:
    def __init__(self):
        self.failed = 0

    def __call__(self, ok, text):
        print(("PASS " if ok else "FAIL ") + text)
        self.failed += not ok


def run(flowform, case, outdir, sets):
    r = launcher.run(flowform, case, outdir, sets, quiet=True, clean=True)
    if r.status != 0:
        print(f"flowform exited {r.status} on {outdir}:\n{r.log_tail() if hasattr(r, 'log_tail') else ''}")
        sys.exit(1)
    return r.summary["functionals"]


def couette(flowform, source, outdir, check):
    case = os.path.join(source, "tests/regression/moving_tool/couette.xml")
    powers = {"plastic": "Plastic Power", "friction": "Friction Power", "penalty": "Penalty Power",
              "stabilization": "Stabilization Power"}
    for factor in (1.0, 1000.0):
        beta = factor * MU / H
        U = V * beta / (beta + MU / H)
        tau = MU * U / H
        out = os.path.join(outdir, f"beta{factor:g}")
        sets = [f"Boundary Conditions/top/Norton Coefficient={beta!r}"] + [
            f"Responses/{name}/Type={kind}" for name, kind in powers.items()]
        f = run(flowform, case, out, sets)
        top = csvio.rows(out, "top")
        inlet = csvio.rows(out, "inlet") + csvio.rows(out, "outlet")
        # top: t = (−1, 0), so u_x = −u_t; inlet normal (−1, 0): u_x = −u_n, outlet (1, 0): u_x = u_n
        top_err = max(abs(-r["u_t"] - U) for r in top)
        profile_err = max(abs((-r["u_n"] if r["x"] < 2.0 else r["u_n"]) - U * (r["y"] + 1.0) / H) for r in inlet)
        print(f"beta = {beta:.6g}: U exact {U:.12f}, tool node speeds max |u_x - U| = {top_err:.2e}, "
              f"end profiles max |u_x - U (y+1)/H| = {profile_err:.2e}")
        print(f"  tool force X {f['tool_force']:.12f} (exact -tau L = {-tau * LENGTH:.12f}), "
              f"tool power {f['tool_power']:.12f} (exact tau L V = {tau * LENGTH * V:.12f})")
        dissipated = sum(f[n] for n in powers)
        print("  " + ", ".join(f"{n} {f[n]:.6e}" for n in powers))
        check(top_err <= SOLVER_TOL, f"beta={beta:.4g}: the tool's nodes move at U = V beta/(beta + mu/H) "
              f"({top_err:.1e} <= {SOLVER_TOL:g})")
        check(profile_err <= SOLVER_TOL, f"beta={beta:.4g}: the Couette profile u = U (y+1)/H at both ends "
              f"({profile_err:.1e} <= {SOLVER_TOL:g})")
        force_err = abs(f["tool_force"] + tau * LENGTH) / (tau * LENGTH)
        power_err = abs(f["tool_power"] - tau * LENGTH * V) / (tau * LENGTH * V)
        check(force_err <= SOLVER_TOL and power_err <= SOLVER_TOL,
              f"beta={beta:.4g}: Wall Force X = -tau L and Tool Power = tau L V (relative {force_err:.1e}, "
              f"{power_err:.1e} <= {SOLVER_TOL:g})")
        balance = abs(f["tool_power"] - dissipated) / abs(f["tool_power"])
        check(balance <= SOLVER_TOL, f"beta={beta:.4g}: Tool Power = Plastic + Friction + Penalty + "
              f"Stabilization Power (relative {balance:.1e} <= {SOLVER_TOL:g})")


def container(flowform, source, outdir, check):
    case = os.path.join(source, "xml/extrusion.xml")
    base = ["Adaptivity/Enabled=false"]
    moving = ["Boundary Conditions/container/Tool Motion=Translation",
              "Boundary Conditions/container/Tool Velocity X=1.0"]
    frictionless = ["Boundary Conditions/container/Friction Coefficient=0.0"]
    wall = ["Responses/tool_power/Type=Tool Power", "Responses/tool_power/Boundary=container",
            "Responses/container_x/Type=Wall Force", "Responses/container_x/Boundary=container",
            "Responses/container_x/Component=X"]
    runs = {
        "fixed": base,
        "fixed_frictionless": base + frictionless,
        "moving": base + moving + wall,
        "moving_frictionless": base + moving + frictionless,
    }
    f = {name: run(flowform, case, os.path.join(outdir, name), sets) for name, sets in runs.items()}
    F = {name: v["ram_force"] for name, v in f.items()}
    for name in runs:
        print(f"{name:20s} ram force {F[name]:.12f}  dead zone {f[name]['dead_zone']:.5f}")
    m = f["moving"]
    print(f"moving container: Wall Force X {m['container_x']:.12f}, Tool Power {m['tool_power']:.12f}")
    same = abs(F["moving_frictionless"] - F["fixed_frictionless"]) / F["fixed_frictionless"]
    check(same <= 1e-12, f"a frictionless container: moving it changes nothing (relative {same:.1e} <= 1e-12)")
    below = (F["fixed_frictionless"] - F["moving"]) / F["fixed_frictionless"]
    check(below >= 0.05, f"ν = 0.1, moving container: the ram force is {below:.2%} below the frictionless "
          f"container's (>= 5 %: the container drags the die-corner metal forward)")
    fixed_gap = (F["fixed"] - F["moving"]) / F["fixed"]
    check(fixed_gap >= 0.10, f"... and {fixed_gap:.2%} below the fixed container's (>= 10 %)")
    check(m["container_x"] < 0.0 and abs(m["tool_power"] + m["container_x"]) <= 1e-12 * abs(m["tool_power"]),
          "the container pulls the billet toward the die (Wall Force X < 0) and Tool Power = -Wall Force X * 1")
    # Relative slip on the container where the billet is rigid (x <= -1, the upstream third): the
    # container's t = (-1, 0), so the relative slip is u_t + 1.
    slip = max(abs(r["u_t"] + 1.0) for r in csvio.rows(os.path.join(outdir, "moving"), "container") if r["x"] <= -1.0)
    check(slip <= 1e-3, f"the billet moves with the container for x <= -1 (max relative slip {slip:.1e} <= 1e-3)")


def main():
    sub, flowform, source, outdir = sys.argv[1:5]
    check = Checks()
    {"couette": couette, "container": container}[sub](flowform, source, outdir, check)
    return 1 if check.failed else 0


if __name__ == "__main__":
    sys.exit(main())
