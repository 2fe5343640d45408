#!/usr/bin/env python3
"""Two flowform runs writing the same output directory at once (tests/regression/BadInput.cmake).

usage: concurrent_output.py FLOWFORM CASE.xml WORKDIR

Runs the case twice alone with different yield stresses (sets A and B, each in its own
directory), then, several times, both at once with the same -o. Afterwards the shared directory
must hold exactly one of the two sets, whole: every result file byte-equal to A's or every one
to B's (summary.json compared without its timings, solution.h5 by its datasets), no staging directory or .tmp file left, and
the other files put there first (a script's log) untouched. Exits 0 when every round passes.
"""
import json
import os
import shutil
import subprocess
import sys

ROUNDS = 4


def result_files(directory):
    return sorted(f for f in os.listdir(directory) if not f.startswith("."))


def content(directory, name):
    path = os.path.join(directory, name)
    if name == "summary.json":
        with open(path) as f:
            s = json.load(f)
        s.pop("timings", None)
        return json.dumps(s, sort_keys=True)
    if name.endswith(".h5"):  # HDF5 files differ run to run in their metadata: compare the data
        import h5py
        import numpy
        parts = []
        with h5py.File(path, "r") as f:
            f.visititems(lambda key, obj: parts.append(key.encode() + numpy.asarray(obj).tobytes())
                         if isinstance(obj, h5py.Dataset) else None)
        return b"".join(parts)
    with open(path, "rb") as f:
        return f.read()


def run(flowform, case, outdir, yield_stress, wait=True):
    cmd = [flowform, case, "-o", outdir, "--quiet", "--set", f"Material/Yield Stress={yield_stress}"]
    p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if wait:
        out, err = p.communicate(timeout=300)
        if p.returncode != 0:
            sys.exit(f"FAIL: {' '.join(cmd)} exited {p.returncode}: {err}")
    return p


def main():
    flowform, case, work = sys.argv[1:4]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    sets = {}
    for label, sigma in (("A", 0.5), ("B", 0.7)):
        d = os.path.join(work, label)
        run(flowform, case, d, sigma)
        sets[label] = {f: content(d, f) for f in result_files(d)}
    if sets["A"]["summary.json"] == sets["B"]["summary.json"]:
        sys.exit("FAIL: the two reference runs gave the same summary; the test could not tell them apart")
    shared = os.path.join(work, "shared")
    os.makedirs(shared)
    log = os.path.join(shared, "script.log")
    with open(log, "w") as f:
        f.write("a file that is not flowform's\n")
    failures = []
    for r in range(ROUNDS):
        procs = [run(flowform, case, shared, s, wait=False) for s in (0.5, 0.7)]
        for p in procs:
            _, err = p.communicate(timeout=300)
            if p.returncode != 0:
                failures.append(f"round {r}: a run exited {p.returncode}: {err.strip()}")
        leftovers = [f for f in os.listdir(shared) if f.startswith(".") or f.endswith(".tmp")]
        if leftovers:
            failures.append(f"round {r}: left behind {leftovers}")
        names = [f for f in result_files(shared) if f != "script.log"]
        matches = [label for label, ref in sets.items()
                   if sorted(ref) == names and all(content(shared, f) == ref[f] for f in names)]
        print(f"round {r}: the directory holds set {matches or 'none'} ({len(names)} files)")
        if len(matches) != 1:
            mixed = {f: [label for label, ref in sets.items() if f in ref and content(shared, f) == ref[f]]
                     for f in names}
            failures.append(f"round {r}: a mixed or partial set: {mixed}")
        with open(log) as f:
            if f.read() != "a file that is not flowform's\n":
                failures.append(f"round {r}: script.log was changed")
    for f in failures:
        print("FAIL:", f)
    print("PASS" if not failures else "")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
