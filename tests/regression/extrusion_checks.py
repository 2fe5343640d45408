"""Verification checks of the extrusion scene (docs/theory.md §2, §6.2; docs/extrusion_verification.md).

usage: extrusion_checks.py SUBCOMMAND FLOWFORM SOURCE_DIR OUTDIR [--meshes H,H,...] [--jobs N]

Every subcommand runs flowform on SOURCE_DIR/xml/extrusion.xml (or a variant of it written
into OUTDIR) with the mesh size h set through "Mesh/Geo Parameters" (hc = h/4 at the two die
corners), prints what it measured and one line per check ("ok" or "FAIL"), writes the
numbers to OUTDIR/<subcommand>.json and exits 1 when a check failed. Each run's full log
(Newton history, contact changes) is kept in OUTDIR/<run>.log.

  contact             after a converged run no active wall node is in tension beyond the
                      Pressure Tolerance and no free one penetrates beyond the Penetration
                      Tolerance (boundary_<wall>.csv); the loop ended (finite status changes);
                      negative control: a run stopped before the loop settled is caught
  power               ram power = plastic + friction + stabilization + penalty power (exact
                      discrete identity); the mismatch ram − plastic − friction shrinks with h
  convergence         ram force on a sequence of meshes: differences shrink; with 3 or more
                      meshes the observed order and the Richardson extrapolation
  penalty-normal      ram force vs Normal Penalty Factor over three decades
  penalty-tangential  ram force vs Tangential Penalty Factor over three decades
  sticking-penalty    F and dF/dν converge as κ_t grows to 1e8 (first order in 1/κ_t)
  frictionless        ν = 0 Coulomb ≡ Friction Law None; vs Symmetry walls (with and without
                      releasing nodes in tension)
  sticking            large ν vs no-slip (Velocity 0) container and die face
  monotone            ram force increases with ν ∈ {0, 0.05, 0.1, 0.2, 0.3, 0.5}
  theory              ν = 0, n = 20: ln R <= p/2k <= √2 (rigid-triangle upper bound), and with
                      2 or more meshes the two finest against each other and against Hill's
                      slip-line value 1/2 + π/4

The wall, response and boundary names come from the case file (flowform_tools.case). The
checks live in tests/regression/extrusion/, one module per group; this script only parses the
command line (the interface tests/regression/Extrusion.cmake uses).

Debian's /usr/bin/python3 (numpy, h5py). `gmsh` (the command) for `sticking` only.
"""
import argparse
import sys
import time

from extrusion import contact, convergence, limits, penalty, power, theory
from extrusion.common import Checks, Runner

COMMANDS = {}
for module in (contact, power, convergence, penalty, limits, theory):
    COMMANDS.update(module.COMMANDS)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("subcommand", choices=sorted(COMMANDS))
    parser.add_argument("flowform")
    parser.add_argument("source", help="the flowform source directory")
    parser.add_argument("outdir")
    parser.add_argument("--meshes", help="comma-separated bulk mesh sizes h (hc = h/4)")
    parser.add_argument("--nu", help="friction coefficient(s), where the subcommand takes them")
    parser.add_argument("--values", help="penalty factors to sweep (penalty-normal, penalty-tangential)")
    parser.add_argument("--jobs", type=int, default=1, help="flowform runs at a time")
    args = parser.parse_args()
    runner = Runner(args)
    checks = Checks(args.subcommand.replace("-", "_"), runner.out)
    start = time.time()
    try:
        COMMANDS[args.subcommand](runner, args, checks)
    except Exception as e:  # a broken output file is a failed check, not a crash
        checks.check(False, f"{type(e).__name__}: {e}")
    checks.record("seconds", round(time.time() - start, 1))
    print(f"{args.subcommand}: {time.time() - start:.1f} s")
    return checks.finish()


if __name__ == "__main__":
    sys.exit(main())
