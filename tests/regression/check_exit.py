"""Runs one flowform command and checks how it ended (tests/regression/BadInput.cmake).

usage: check_exit.py --outdir DIR [--status N] [--stderr-contains TEXT ...]
                     [--no-output | --converged | --not-converged | --flagged | --outdir-is-a-file |
                      --summary-is-a-directory] [--message-contains TEXT ...] [--written FILE ...]
                     -- COMMAND ...

  COMMAND                an argument @EMPTY@ is passed as the empty string (CMake drops those)
  --outdir DIR           the output directory the command was given (-o DIR); removed first,
                         so a result from an earlier run cannot pass the check
  --status N             expected exit status (default 2, bad input)
  --stderr-contains T    stderr must contain T (repeatable; case-sensitive)
  --no-output            DIR must not exist afterwards (bad input writes nothing)
  --converged            DIR/summary.json must exist and say "converged": true
  --not-converged        DIR/summary.json must exist and say "converged": false (exit 3: the
                         results are written, flagged)
  --flagged              DIR/summary.json must exist with "exit_status" N (whatever "converged",
                         the solve's own, says: an adaptive run whose target was not met)
  --message-contains T   summary.json "message" must contain T (repeatable; with --converged,
                         --not-converged or --flagged)
  --written FILE         DIR/FILE must exist (repeatable)
  --outdir-is-a-file     DIR is made a regular file first and must be left as it was
  --summary-is-a-directory  DIR/summary.json is made a directory first (the run cannot write its
                         summary) and must be left as it was, empty

Prints the command, its status and its output, then each failed check; exits 0 when every
check passes, 1 otherwise.
"""
import argparse
import os
import shutil
import sys

from flowform_tools import launcher, summary as summary_module


def main():
    if "--" not in sys.argv:
        sys.exit("check_exit.py: expected '-- COMMAND ...'")
    split = sys.argv.index("--")
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--outdir", required=True)
    parser.add_argument("--status", type=int, default=2)
    parser.add_argument("--stderr-contains", action="append", default=[])
    mode = parser.add_mutually_exclusive_group()
    mode.add_argument("--no-output", action="store_true")
    mode.add_argument("--converged", action="store_true")
    mode.add_argument("--not-converged", action="store_true")
    mode.add_argument("--flagged", action="store_true")
    mode.add_argument("--outdir-is-a-file", action="store_true",
                      help="make DIR a regular file first; it must be left as it was")
    mode.add_argument("--summary-is-a-directory", action="store_true",
                      help="make DIR/summary.json a directory first; it must be left as it was")
    parser.add_argument("--message-contains", action="append", default=[])
    parser.add_argument("--written", action="append", default=[])
    parser.add_argument("--timeout", type=float, default=600)
    args = parser.parse_args(sys.argv[1:split])
    # CMake drops empty arguments from a command: @EMPTY@ stands for one.
    command = ["" if a == "@EMPTY@" else a for a in sys.argv[split + 1:]]
    if not command:
        sys.exit("check_exit.py: no command after '--'")

    shutil.rmtree(args.outdir, ignore_errors=True)
    marker = "flowform must leave this file alone\n"
    if args.outdir_is_a_file:
        if os.path.isfile(args.outdir):
            os.remove(args.outdir)
        os.makedirs(os.path.dirname(os.path.abspath(args.outdir)), exist_ok=True)
        with open(args.outdir, "w") as f:
            f.write(marker)
    blocked_summary = os.path.join(args.outdir, "summary.json")
    if args.summary_is_a_directory:
        os.makedirs(blocked_summary)
    print("command:", launcher.command_line(command))
    run = launcher.run_command(command, capture=True, timeout=args.timeout)
    if run.timed_out:
        print(f"FAIL: no exit within {args.timeout:g} s (a rank waiting on a failed one?)")
        return 1
    stdout, stderr = run.stdout, run.stderr
    print(f"exit status: {run.status}")
    print("--- stdout ---\n" + stdout.rstrip())
    print("--- stderr ---\n" + stderr.rstrip())
    print("--------------")

    failures = []
    if run.status != args.status:
        failures.append(f"exit status {run.status}, expected {args.status}")
    for text in args.stderr_contains:
        if text not in stderr:
            failures.append(f"stderr does not contain {text!r}")
    if args.no_output and os.path.exists(args.outdir):
        written = sorted(os.listdir(args.outdir)) if os.path.isdir(args.outdir) else []
        failures.append(f"output directory {args.outdir} was created (contents: {written})")
    if args.outdir_is_a_file:
        try:
            with open(args.outdir) as f:
                if f.read() != marker:
                    failures.append(f"{args.outdir} was changed")
        except OSError as e:
            failures.append(f"{args.outdir} is no longer a readable file: {e}")
    if args.summary_is_a_directory and not (os.path.isdir(blocked_summary) and not os.listdir(blocked_summary)):
        failures.append(f"{blocked_summary} is no longer an empty directory")
    if args.converged or args.not_converged or args.flagged:
        path = os.path.join(args.outdir, "summary.json")
        try:
            summary = summary_module.load(path, missing_ok=False)
            if not args.flagged and summary.get("converged") is not bool(args.converged):
                failures.append(f"{path}: converged is {summary.get('converged')!r}, expected "
                                f"{str(bool(args.converged)).lower()}")
            message = summary.get("message") or ""
            print(f"summary.json message: {message}")
            for text in args.message_contains:
                if text not in message:
                    failures.append(f"{path}: message does not contain {text!r}")
            if summary.get("exit_status") != args.status:
                failures.append(f"{path}: exit_status is {summary.get('exit_status')!r}, "
                                f"expected {args.status}")
        except (OSError, ValueError) as e:
            failures.append(f"cannot read {path}: {e}")

    for name in args.written:
        if not os.path.exists(os.path.join(args.outdir, name)):
            failures.append(f"{os.path.join(args.outdir, name)} was not written")

    for f in failures:
        print("FAIL:", f)
    if not failures:
        print("PASS")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
