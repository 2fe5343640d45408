#!/usr/bin/python3
"""The dual-weighted-residual estimate (experimental, docs/theory.md §7) on a case whose
response has no discretization error: the wall force of the channel.

usage: error_estimate_checks.py FLOWFORM SOURCE_DIR WORKDIR

The channel (xml/channel.xml, triangles) is driven by the inlet traction 4 with u_y = 0 at both
ends, so the discrete momentum balance gives the top wall's x-reaction −4 exactly on every mesh
(half the applied force, by the symmetry of the mesh). Its error is zero, and so must be the
estimate, up to round-off: |η| ≤ 1e-10 (measured ≤ 1.2e-13; before the estimate reconstructed
the adjoint with the response's Dirichlet data, ζ = c − z, it gave O(h): 0.015, 0.0075, 0.0037).
Newtonian and n = 5, σ0 = 0.5, on N = 4 and 8.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "python"))
from flowform_tools import launcher, summary  # noqa: E402

TOL = 1e-10


def main():
    flowform, source, work = sys.argv[1:4]
    failed = 0
    for n_cells in ("4", "8"):
        for n, sigma0 in (("1.0", "0.0"), ("5.0", "0.5")):
            out = os.path.join(work, f"N{n_cells}_n{n}")
            sets = ["Mesh/Element Type=Triangle", f"Mesh/Geo Parameters/N={n_cells}", f"Material/Rate Exponent={n}",
                    f"Material/Yield Stress={sigma0}", "Responses/top_force/Type=Boundary Force",
                    "Responses/top_force/Boundary=top", "Error Estimation/Method=Dual Weighted Residual"]
            run = launcher.run(flowform, os.path.join(source, "xml/channel.xml"), out, sets, quiet=True, clean=True)
            s = summary.load(out) or {}
            force = (s.get("functionals") or {}).get("top_force")
            eta = (s.get("functionals_error_estimate") or {}).get("top_force")
            ok = run.status == 0 and force is not None and abs(force + 4.0) <= 1e-12 * 4 and eta is not None \
                and abs(eta) <= TOL
            failed += not ok
            print(f"{'ok  ' if ok else 'FAIL'} N = {n_cells}, n = {n}: exit {run.status}, F = {force}, estimate {eta}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
