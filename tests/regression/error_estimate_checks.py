#!/usr/bin/python3
"""The two-level error estimate and the adaptive loop (docs/theory.md §7).

usage: error_estimate_checks.py FLOWFORM SOURCE_DIR WORKDIR

1. Exact response, zero estimate. The channel (xml/channel.xml, triangles) is driven by the
   inlet traction 4 with u_y = 0 at both ends, so the discrete momentum balance gives the top
   wall's x-reaction -4 exactly on every mesh. The refined mesh gives the same value, so the
   estimate must vanish up to the solver tolerance: |eta| <= 1e-8 (Newton stops at |F| ~ 1e-10;
   the factor 2 of the Order-1 extrapolation and the summed reactions allow 100x that).
   Newtonian and n = 5, sigma0 = 0.5, N = 4.
2. Effectivity on the extrusion (xml/extrusion.xml, default mesh, plane strain): eta / (F_ref - F)
   with F_ref the Richardson values of docs/extrusion_verification.md §3 (hc = h/4 sequence
   h = 0.2, 0.1, 0.05): 3.316 (nu = 0) and 3.735 (nu = 0.1). The references are uncertain by about
   0.005 (the finest mesh (0.025, 0.001) gives 3.7305 for nu = 0.1), 4 % of the default mesh's
   error of 0.12; the band is the issue's goal [0.5, 2] (measured 0.93-0.95).
3. Adaptivity: the default extrusion with a 0.5 % target on the ram force meets it (exit 0),
   lists every cycle, and its final F + eta lies within 0.3 % of the reference 3.735 (the target
   plus the reference's own uncertainty, 0.13 %; measured 0.12 %).
4. Bad input: an Adaptivity response that has no indicator (Dead Zone) exits 2.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "python"))
from flowform_tools import launcher, summary  # noqa: E402

REFERENCE = {"0.0": 3.316, "0.1": 3.735}
WALLS = ("container", "die_face", "die_land")


def friction(nu):
    return [f"Boundary Conditions/{w}/Friction Coefficient={nu}" for w in WALLS]


def check(ok, text):
    print(f"{'ok  ' if ok else 'FAIL'} {text}")
    return 0 if ok else 1


def main():
    flowform, source, work = sys.argv[1:4]
    failed = 0
    channel = os.path.join(source, "xml/channel.xml")
    extrusion = os.path.join(source, "xml/extrusion.xml")
    for n, sigma0 in (("1.0", "0.0"), ("5.0", "0.5")):
        out = os.path.join(work, f"channel_n{n}")
        sets = ["Mesh/Element Type=Triangle", "Mesh/Geo Parameters/N=4", f"Material/Rate Exponent={n}",
                f"Material/Yield Stress={sigma0}", "Responses/top_force/Type=Boundary Force",
                "Responses/top_force/Boundary=top", "Error Estimation/Method=Two-Level"]
        run = launcher.run(flowform, channel, out, sets, quiet=True, clean=True)
        s = summary.load(out) or {}
        force = (s.get("functionals") or {}).get("top_force")
        eta = (s.get("functionals_error_estimate") or {}).get("top_force")
        failed += check(run.status == 0 and force is not None and abs(force + 4.0) <= 1e-10 and eta is not None
                        and abs(eta) <= 1e-8, f"channel n = {n}: exit {run.status}, F = {force}, estimate {eta}")

    for nu, ref in REFERENCE.items():
        out = os.path.join(work, f"extrusion_nu{nu}")
        run = launcher.run(flowform, extrusion, out, ["Error Estimation/Method=Two-Level"] + friction(nu),
                           quiet=True, clean=True)
        s = summary.load(out) or {}
        force = (s.get("functionals") or {}).get("ram_force")
        eta = (s.get("functionals_error_estimate") or {}).get("ram_force")
        eff = eta / (ref - force) if force is not None and eta is not None else None
        failed += check(run.status == 0 and eff is not None and 0.5 <= eff <= 2.0,
                        f"extrusion nu = {nu}: F = {force}, estimate {eta}, true {ref - (force or 0):.4g}, "
                        f"effectivity {eff}")

    out = os.path.join(work, "adaptive")
    run = launcher.run(flowform, extrusion, out, ["Adaptivity/Responses={ram_force}",
                                                 "Adaptivity/Target Relative Error=0.005"], quiet=True, clean=True)
    s = summary.load(out) or {}
    cycles = (s.get("adaptivity") or {}).get("cycles") or []
    force = (s.get("functionals") or {}).get("ram_force")
    eta = (s.get("functionals_error_estimate") or {}).get("ram_force")
    ok = run.status == 0 and len(cycles) >= 2 and s["adaptivity"]["target_met"] and force is not None and \
        eta is not None and abs(eta) <= 0.005 * abs(force) and abs(force + eta - 3.735) <= 0.003 * 3.735
    failed += check(ok, f"adaptive: exit {run.status}, {len(cycles)} cycles, dofs "
                        f"{[c.get('dofs') for c in cycles]}, F = {force}, estimate {eta}")

    out = os.path.join(work, "adaptive_bad")
    run = launcher.run(flowform, extrusion, out, ["Adaptivity/Responses={dead_zone}"], quiet=True, clean=True)
    failed += check(run.status == 2 and not os.path.exists(os.path.join(out, "summary.json")),
                    f"adaptive on Dead Zone: exit {run.status} (2 expected), nothing written")
    print(f"error estimate checks: {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
