"""What the benchmarks in bench/ share: the channel's size and material settings, and one
timed run whose result is a plain dict (it goes into the benchmarks' JSON files).

Every number a benchmark reports comes from summary.json ("timings", "newton_iterations",
"linear_solver", ...) or from /usr/bin/time -v (peak memory), never from flowform's log.
"""
import os

from . import case as case_module, launcher, machine

ELEMENTS = {"tri": "Triangle", "quad": "Quadrilateral"}
CHANNEL_MATERIALS = {
    # the channel case's own material (σ0 = 0.5, n = 5)
    "nonlinear": [],
    "newtonian": ["Material/Rate Exponent=1", "Material/Yield Stress=0"],
}
#: No solution.h5 and no CSVs: a benchmark that reads only summary.json writes less.
NO_OUTPUT = ["Output/Write Solution=false", "Output/Boundary CSV=false"]


def channel_dofs(n):
    """Dofs of xml/channel.xml with N cells across the height and 2N along: 3 (N+1)(2N+1)."""
    return 3 * (n + 1) * (2 * n + 1)


def channel_size(n, element):
    """The --set overrides of one channel size and element ("tri" or "quad")."""
    return [f"Mesh/Geo Parameters/N={float(n)}", f"Mesh/Element Type={ELEMENTS[element]}"]


def require_tools(flowform, script):
    """The absolute path of the flowform binary; exits with a message when it or GNU time
    (Debian package `time`) is missing."""
    flowform = launcher.require_executable(flowform, script)
    launcher.require_time(script)
    return flowform


def run_case(flowform, case, outdir, overrides, np=1, timeout=None, log=None, quiet=True):
    """Runs flowform once under /usr/bin/time -v, on the case's own mesh (case.FIXED_MESH);
    returns a dict: status (exit status, or
    "timeout"), wall (s), rss (peak resident bytes; under mpirun the largest process), stderr
    (captured unless log is given: then stdout and stderr go to the log file), summary (the
    parsed summary.json or None), load ([1-minute load average before, after]), log."""
    before = machine.load()
    r = launcher.run(flowform, case, outdir, case_module.FIXED_MESH + list(overrides), quiet=quiet, np=np, timeout=timeout, log=log,
                     capture=log is None, peak_memory=True)
    return {"status": "timeout" if r.timed_out else r.status, "wall": r.wall, "rss": r.peak_rss,
            "stderr": r.stderr or "", "summary": r.summary, "load": [before, machine.load()], "log": log}


def binary_info(flowform):
    """The binary's path and time stamp, for the heading of a benchmark's output."""
    return {"flowform": os.path.abspath(flowform), "binary_built": machine.binary_built(flowform)}
