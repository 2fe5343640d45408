"""Running flowform (and other commands) from Python.

    from flowform_tools import launcher
    r = launcher.run(flowform, "xml/channel.xml", "out/ch", ["Mesh/Geo Parameters/N=8"], quiet=True)
    r.status, r.converged, r.summary.at("newton_iterations"), r.wall

run() builds the command line

    [/usr/bin/time -o T -v] [mpirun -np N MPI_ARGS] flowform CASE -o OUTDIR [--quiet]
        [--set P=V ...] [ARGS ...]

and returns a Run: exit status, wall seconds, the parsed summary.json (None when none was
written), the log path or the captured output, and the peak resident memory when asked.
Where the output goes:
  log=PATH      stdout and stderr into PATH, after a first line "$ <command>";
  capture=True  stdout and stderr kept as text (Run.stdout, Run.stderr);
  neither       inherited from the caller (the terminal, or ctest's log).
A timeout kills the whole process group (flowform under mpirun or time included) and sets
Run.timed_out; status is then None.

run_command() is the same for any command line (check_exit.py runs the commands of
tests/regression/BadInput.cmake with it).
"""
import os
import re
import shlex
import signal
import subprocess
import tempfile
import time

from . import summary as summary_module

TIME = "/usr/bin/time"
#: mpirun refuses to run as root without these (docs/toolchain.md, run time).
MPI_ROOT_ENV = {"OMPI_ALLOW_RUN_AS_ROOT": "1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1"}


def lit(x):
    """A double literal that --set reads as a double inside free-form sublists
    (1 -> "1.0", 1e-05 -> "1.0e-05"): an integer literal would become an int parameter."""
    s = repr(float(x))
    if "." not in s and "inf" not in s and "nan" not in s:
        s = s.replace("e", ".0e") if "e" in s else s + ".0"
    return s


def set_args(sets):
    """["P=V", ...] -> ["--set", "P=V", ...]."""
    out = []
    for s in sets:
        out += ["--set", s]
    return out


def command_line(command):
    """A command as one shell-quoted line (for logs and messages)."""
    return shlex.join(str(c) for c in command)


def require_executable(path, script):
    """The absolute path of an executable; exits with a message naming the script if absent."""
    path = os.path.abspath(path)
    if not os.access(path, os.X_OK):
        raise SystemExit(f"{script}: no executable flowform at {path} (give its path)")
    return path


def require_time(script):
    """Exits with a message when GNU time (Debian package `time`) is missing."""
    if not os.access(TIME, os.X_OK):
        raise SystemExit(f"{script}: {TIME} not found: apt-get install time")


def parse_time_v(text):
    """Peak RSS in bytes and wall seconds from GNU `time -v` output (None when absent)."""
    rss = re.search(r"Maximum resident set size \(kbytes\):\s*(\d+)", text)
    wall = re.search(r"Elapsed \(wall clock\) time \(h:mm:ss or m:ss\):\s*([\d:.]+)", text)
    seconds = None
    if wall:
        seconds = 0.0
        for part in wall.group(1).split(":"):
            seconds = 60 * seconds + float(part)
    return (int(rss.group(1)) * 1024 if rss else None), seconds


class CommandResult:
    """How one command ended."""

    def __init__(self, command, status, timed_out, wall, log=None, stdout=None, stderr=None, peak_rss=None):
        self.command = command
        self.status = status          # exit status; None when killed after the timeout
        self.timed_out = timed_out
        self.wall = wall              # seconds
        self.log = log                # path of the log file, if any
        self.stdout = stdout          # text, when captured
        self.stderr = stderr
        self.peak_rss = peak_rss      # bytes (time -v "Maximum resident set size"), if measured

    def log_tail(self, lines=12):
        """The last lines of the log file (or of the captured stderr); "" if there is none."""
        if self.log:
            try:
                with open(self.log, errors="replace") as f:
                    return "".join(f.readlines()[-lines:])
            except OSError:
                return ""
        return "\n".join((self.stderr or "").splitlines()[-lines:])


def _kill_group(proc):
    try:
        os.killpg(proc.pid, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        pass


def run_command(command, *, log=None, log_header=True, capture=False, timeout=None, env=None,
                peak_memory=False, cwd=None):
    """Runs a command; returns a CommandResult. See the module doc for log/capture.

    peak_memory runs it under `/usr/bin/time -o FILE -v` and reads the peak RSS from FILE
    (under mpirun: the largest single process). With a timeout the command runs in its own
    process group, which is killed as a whole when the time is up (or on KeyboardInterrupt).
    """
    command = [str(c) for c in command]
    timing_file = None
    full = command
    if peak_memory:
        fd, timing_file = tempfile.mkstemp(prefix="flowform_time_", suffix=".txt")
        os.close(fd)
        full = [TIME, "-o", timing_file, "-v"] + command
    log_file = None
    if log:
        log_file = open(log, "w")
        if log_header:
            log_file.write("$ " + command_line(command) + "\n")
            log_file.flush()
        stdout, stderr = log_file, subprocess.STDOUT
    elif capture:
        stdout = stderr = subprocess.PIPE
    else:
        stdout = stderr = None
    own_group = timeout is not None
    start = time.monotonic()
    timed_out, out, err = False, None, None
    try:
        proc = subprocess.Popen(full, stdout=stdout, stderr=stderr, env=env, cwd=cwd,
                                text=True if capture and not log else None,
                                errors="replace" if capture and not log else None,
                                start_new_session=own_group)
        try:
            out, err = proc.communicate(timeout=timeout)
        except subprocess.TimeoutExpired:
            timed_out = True
            _kill_group(proc)
            out, err = proc.communicate()
        except BaseException:
            if own_group:
                _kill_group(proc)
            else:
                proc.kill()
            proc.wait()
            raise
    finally:
        if log_file:
            log_file.close()
    wall = time.monotonic() - start
    rss = None
    if timing_file:
        try:
            with open(timing_file) as f:
                rss = parse_time_v(f.read())[0]
        except OSError:
            pass
        os.unlink(timing_file)
    return CommandResult(command, None if timed_out else proc.returncode, timed_out, wall,
                         log=log, stdout=out, stderr=err, peak_rss=rss)


class Run(CommandResult):
    """One finished flowform run: a CommandResult with its output directory and summary."""

    def __init__(self, result, outdir):
        super().__init__(**{k: getattr(result, k) for k in
                            ("command", "status", "timed_out", "wall", "log", "stdout", "stderr", "peak_rss")})
        self.outdir = outdir
        self.summary = summary_module.load(outdir) if outdir else None

    @property
    def converged(self):
        """Exit 0 and summary.json says converged."""
        return self.status == 0 and self.summary is not None and self.summary.converged

    def functional(self, name):
        return self.summary.functional(name)


def flowform_command(flowform, case, outdir, sets=(), *, args=(), quiet=False, np=1, mpiexec="mpirun",
                     mpi_args=()):
    """The command line of one flowform run (see the module doc)."""
    command = [flowform, case]
    if outdir is not None:
        command += ["-o", outdir]
    if quiet:
        command.append("--quiet")
    command += set_args(sets) + list(args)
    if np and int(np) > 1:
        command = [mpiexec, "-np", str(np)] + list(mpi_args) + command
    return command


def run(flowform, case, outdir, sets=(), *, args=(), quiet=False, np=1, mpiexec="mpirun", mpi_args=(),
        log=None, capture=False, timeout=None, peak_memory=False, env=None, mpi_env=None, clean=False):
    """Runs flowform once and returns a Run.

    sets      "Path/To/Param=value" overrides (each becomes --set P=V)
    args      further raw arguments, appended after the --set pairs
    np        > 1: under `mpiexec -np np mpi_args...`
    mpi_env   add OMPI_ALLOW_RUN_AS_ROOT(_CONFIRM) to the environment (default: when np > 1)
    clean     remove outdir first, so that nothing of an earlier run can be read as this one's
    """
    if clean and outdir:
        import shutil
        shutil.rmtree(outdir, ignore_errors=True)
    command = flowform_command(flowform, case, outdir, sets, args=args, quiet=quiet, np=np, mpiexec=mpiexec,
                               mpi_args=mpi_args)
    if mpi_env is None:
        mpi_env = bool(np and int(np) > 1)
    if mpi_env:
        env = dict(env if env is not None else os.environ, **MPI_ROOT_ENV)
    result = run_command(command, log=log, capture=capture, timeout=timeout, env=env, peak_memory=peak_memory)
    return Run(result, outdir)
