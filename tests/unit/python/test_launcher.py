"""flowform_tools.launcher: double literals for --set, the command line of a run, GNU time's
report, and run_command/run on small shell commands (a stand-in flowform writes summary.json)."""
import os
import stat
import tempfile
import unittest

from flowform_tools import launcher

FAKE_FLOWFORM = """#!/bin/sh
# Stand-in for flowform: writes its arguments and a summary.json into the -o directory.
out=""
prev=""
for a in "$@"; do
  if [ "$prev" = "-o" ]; then out="$a"; fi
  prev="$a"
done
mkdir -p "$out"
echo "$@" > "$out/args.txt"
printf '{"converged": %s, "functionals": {"ram_force": 2.5}}' "$CONVERGED" > "$out/summary.json"
echo "solving" 
exit "$STATUS"
"""


class Literals(unittest.TestCase):
    def test_lit_is_always_a_double(self):
        self.assertEqual(launcher.lit(1), "1.0")
        self.assertEqual(launcher.lit(0.25), "0.25")
        self.assertEqual(launcher.lit(1e-05), "1.0e-05")
        self.assertEqual(launcher.lit(1e20), "1.0e+20")
        self.assertEqual(launcher.lit(2.5e-7), "2.5e-07")
        self.assertEqual(launcher.lit(float("inf")), "inf")

    def test_set_args(self):
        self.assertEqual(launcher.set_args(["A/B=1", "C=x y"]), ["--set", "A/B=1", "--set", "C=x y"])
        self.assertEqual(launcher.set_args([]), [])

    def test_command_line_quotes(self):
        self.assertEqual(launcher.command_line(["flowform", "a b.xml", 3]), "flowform 'a b.xml' 3")


class CommandOfARun(unittest.TestCase):
    def test_serial(self):
        self.assertEqual(launcher.flowform_command("ff", "c.xml", "out", ["A=1"], args=["--check"], quiet=True),
                         ["ff", "c.xml", "-o", "out", "--quiet", "--set", "A=1", "--check"])

    def test_no_outdir(self):
        self.assertEqual(launcher.flowform_command("ff", "c.xml", None), ["ff", "c.xml"])

    def test_mpi(self):
        self.assertEqual(launcher.flowform_command("ff", "c.xml", "out", np=2, mpi_args=["--bind-to", "none"]),
                         ["mpirun", "-np", "2", "--bind-to", "none", "ff", "c.xml", "-o", "out"])


class TimeReport(unittest.TestCase):
    def test_peak_memory_and_wall(self):
        text = ("\tCommand being timed: \"flowform\"\n"
                "\tElapsed (wall clock) time (h:mm:ss or m:ss): 1:02.50\n"
                "\tMaximum resident set size (kbytes): 2048\n")
        self.assertEqual(launcher.parse_time_v(text), (2048 * 1024, 62.5))
        hours = "Elapsed (wall clock) time (h:mm:ss or m:ss): 1:00:01\n"
        self.assertEqual(launcher.parse_time_v(hours), (None, 3601.0))
        self.assertEqual(launcher.parse_time_v(""), (None, None))


class RunCommand(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.tmp.cleanup()

    def test_capture_and_status(self):
        r = launcher.run_command(["/bin/sh", "-c", "echo out; echo err >&2; exit 3"], capture=True)
        self.assertEqual((r.status, r.timed_out, r.stdout, r.stderr), (3, False, "out\n", "err\n"))
        self.assertEqual(r.log_tail(), "err")

    def test_log_file_starts_with_the_command(self):
        log = os.path.join(self.tmp.name, "run.log")
        r = launcher.run_command(["/bin/sh", "-c", "echo hello; echo oops >&2"], log=log)
        self.assertEqual(r.status, 0)
        with open(log) as f:
            self.assertEqual(f.read(), "$ /bin/sh -c 'echo hello; echo oops >&2'\nhello\noops\n")
        self.assertEqual(r.log_tail(lines=1), "oops\n")

    def test_timeout_kills_the_group(self):
        # the child shell's own child (sleep) must die too: the call returns long before 30 s
        r = launcher.run_command(["/bin/sh", "-c", "sleep 30 & wait"], timeout=0.5, capture=True)
        self.assertTrue(r.timed_out)
        self.assertIsNone(r.status)
        self.assertLess(r.wall, 10.0)


class RunFlowform(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.ff = os.path.join(self.tmp.name, "flowform")
        with open(self.ff, "w") as f:
            f.write(FAKE_FLOWFORM)
        os.chmod(self.ff, os.stat(self.ff).st_mode | stat.S_IXUSR)
        self.out = os.path.join(self.tmp.name, "out")

    def tearDown(self):
        self.tmp.cleanup()

    def run_fake(self, status, converged, **kw):
        env = dict(os.environ, STATUS=str(status), CONVERGED=converged)
        return launcher.run(self.ff, "case.xml", self.out, ["Material/Rate Exponent=5.0"], quiet=True,
                            env=env, capture=True, **kw)

    def test_converged_run(self):
        r = self.run_fake(0, "true")
        self.assertEqual(r.status, 0)
        self.assertTrue(r.converged)
        self.assertEqual(r.functional("ram_force"), 2.5)
        self.assertEqual(r.stdout, "solving\n")
        with open(os.path.join(self.out, "args.txt")) as f:
            self.assertEqual(f.read(), f"case.xml -o {self.out} --quiet --set Material/Rate Exponent=5.0\n")

    def test_not_converged_is_the_exit_status_and_the_summary(self):
        self.assertFalse(self.run_fake(3, "false").converged)
        self.assertFalse(self.run_fake(0, "false").converged)  # exit 0 but the summary says no
        self.assertFalse(self.run_fake(3, "true").converged)   # the summary says yes, exit 3

    def test_clean_removes_an_earlier_run(self):
        os.makedirs(self.out)
        stale = os.path.join(self.out, "stale.txt")
        open(stale, "w").close()
        self.run_fake(0, "true", clean=True)
        self.assertFalse(os.path.exists(stale))


if __name__ == "__main__":
    unittest.main()
