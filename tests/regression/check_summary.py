"""Runs flowform and checks entries of summary.json.

usage: check_summary.py [--expect-exit N] FLOWFORM CASE.xml OUTDIR [--set P=V ...] -- KEY=VALUE ...
KEY is a dotted path into summary.json (e.g. linear_solver.factorizations); VALUE is
compared exactly (JSON literal: true, 1, "text"). The run must exit N (default 0), and
summary.json must exist whatever the status.
"""
import json
import sys

from flowform_tools import launcher, summary


def main():
    args = sys.argv[1:]
    expected_status = 0
    if args[0] == "--expect-exit":
        expected_status = int(args[1])
        args = args[2:]
    sep = args.index("--")
    flowform, case, outdir = args[0:3]
    extra, checks = args[3:sep], args[sep + 1:]
    run = launcher.run(flowform, case, outdir, args=extra, quiet=True)
    if run.status != expected_status:
        print(f"flowform exited {run.status}, expected {expected_status}")
        return 1
    result = summary.load(outdir, missing_ok=False)
    failed = False
    for check in checks:
        key, expected = check.split("=", 1)
        value = result.at(key)
        ok = value == json.loads(expected)
        print(f"{key} = {value!r} (expected {expected}) {'ok' if ok else 'MISMATCH'}")
        failed |= not ok
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
