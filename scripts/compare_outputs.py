"""Compares every summary.json below two output trees (e.g. two builds' build/tests after
the same ctest run): the responses, sensitivities and FD-check values to a relative
tolerance, and the counts (Newton iterations, contact changes, factorizations) exactly.
A refactoring that claims "no change of behaviour" is checked with it:

    scripts/python scripts/compare_outputs.py OLD/build/tests NEW/build/tests --rtol 1e-12

Prints one row per run (worst relative difference, counts equal or not) and a closing
'N passed, N failed' line; exit status 1 when any run differs or is missing on one side.
"""
import argparse
import math
import os
import sys

from flowform_tools import summary as summaries

COUNTS = ["converged", "exit_status", "newton_iterations", "contact_changes", "continuation_stages",
          "linear_solver.factorizations", "linear_solver.solves", "dofs"]
VALUES = ["functionals", "sensitivities", "fd_check"]


def numbers(node, prefix=""):
    """Every number below node, by dotted path."""
    if isinstance(node, dict):
        for k, v in node.items():
            yield from numbers(v, f"{prefix}.{k}" if prefix else k)
    elif isinstance(node, (int, float)) and not isinstance(node, bool):
        yield prefix, float(node)


def relative(a, b):
    if a == b or (math.isnan(a) and math.isnan(b)):
        return 0.0
    return abs(a - b) / max(abs(a), abs(b), 1e-300)


def compare(old, new, rtol):
    """(worst relative difference, its path, list of count mismatches, missing paths)."""
    worst, where, counts, missing = 0.0, "", [], []
    for path in COUNTS:
        a, b = old.at(path, None), new.at(path, None)
        if a != b:
            counts.append(f"{path}: {a} -> {b}")
    for key in VALUES:
        a = dict(numbers(old.get(key, {}), key))
        b = dict(numbers(new.get(key, {}), key))
        for path in sorted(set(a) | set(b)):
            if path not in a or path not in b:
                missing.append(path)
                continue
            r = relative(a[path], b[path])
            if r > worst:
                worst, where = r, path
    return worst, where, counts, missing


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("old")
    ap.add_argument("new")
    ap.add_argument("--rtol", type=float, default=1e-12)
    args = ap.parse_args()
    runs = set()
    for root in (args.old, args.new):
        for dirpath, _, files in os.walk(root):
            if "summary.json" in files:
                runs.add(os.path.relpath(dirpath, root))
    passed = failed = 0
    print(f"{'run':70s} {'worst rel. diff':>16s}  counts")
    for run in sorted(runs):
        old = summaries.load(os.path.join(args.old, run))
        new = summaries.load(os.path.join(args.new, run))
        if old is None or new is None:
            print(f"{run:70s} {'missing on one side':>16s}")
            failed += 1
            continue
        worst, where, counts, missing = compare(old, new, args.rtol)
        ok = worst <= args.rtol and not counts and not missing
        passed += ok
        failed += not ok
        note = "equal" if not counts else "; ".join(counts)
        if missing:
            note += f"; only on one side: {', '.join(missing[:3])}"
        if worst > args.rtol:
            note += f"; worst at {where}"
        print(f"{run:70s} {worst:16.2e}  {note}")
    print(f"{passed} passed, {failed} failed")
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
