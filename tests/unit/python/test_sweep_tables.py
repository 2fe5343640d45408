"""flowform_tools.sweep (value lists, sweep.csv), tables (markdown), checks (the verdict) and
benchmark (the channel's size)."""
import argparse
import contextlib
import io
import math
import os
import tempfile
import unittest

from flowform_tools import benchmark, checks, sweep, tables


class SweepValues(unittest.TestCase):
    def test_list(self):
        self.assertEqual(sweep.parse_values("0, 0.05,0.1,"), [0.0, 0.05, 0.1])

    def test_range_includes_stop_and_rounds(self):
        # 3 × 0.1 is 0.30000000000000004 in floating point; the range gives 0.3
        self.assertEqual(sweep.parse_values("0:0.5:0.1"), [0.0, 0.1, 0.2, 0.3, 0.4, 0.5])
        self.assertEqual(sweep.parse_values("1:2:0.4"), [1.0, 1.4, 1.8])
        self.assertEqual(sweep.parse_values("0.2:0.2:1"), [0.2])

    def test_refused(self):
        for text in ("", " , ", "a,b", "1:0:0.1", "0:1:0", "0:1", "0:1:-0.1"):
            with self.subTest(text=text), self.assertRaises(argparse.ArgumentTypeError):
                sweep.parse_values(text)

    def test_label(self):
        self.assertEqual(sweep.label(0.1), "nu_0.1")
        self.assertEqual(sweep.label(0.0), "nu_0")
        self.assertEqual(sweep.label(0.5), "nu_0.5")

    def test_num(self):
        self.assertEqual(sweep.num("2.5"), 2.5)
        for text in ("", None, "n/a"):
            self.assertTrue(math.isnan(sweep.num(text)))


class SweepCsv(unittest.TestCase):
    def test_write_then_read(self):
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "sweep.csv")
            sweep.write(path, ["dir", "nu", "force"],
                        [{"dir": "nu_0", "nu": 0.1, "force": None, "extra": 1},
                         {"dir": "nu_0.2", "nu": 0.2, "force": 1 / 3}])
            self.assertEqual(os.listdir(d), ["sweep.csv"])  # no PATH.tmp left behind
            with open(path) as f:
                self.assertEqual(f.read().splitlines(),
                                 ["dir,nu,force", "nu_0,0.1,", "nu_0.2,0.2,0.3333333333333333"])
            rows = sweep.read(d)
            self.assertEqual(rows[0], {"dir": os.path.join(d, "nu_0"), "nu": "0.1", "force": ""})
            self.assertEqual(sweep.num(rows[1]["force"]), 1 / 3)  # repr: the float comes back exactly
            self.assertIsNone(sweep.read(os.path.join(d, "absent")))


class Markdown(unittest.TestCase):
    def test_table(self):
        self.assertEqual(tables.markdown(["N", "time"], [["8", "1.5"], ["16", "6.0"]], align="---:"),
                         "| N | time |\n|---:|---:|\n| 8 | 1.5 |\n| 16 | 6.0 |\n")
        self.assertEqual(tables.markdown(["a"], []), "| a |\n|---|\n")


class Checks(unittest.TestCase):
    def test_count_and_verdict(self):
        out = io.StringIO()
        with contextlib.redirect_stdout(out):
            failed = checks.check(True, "first") + checks.check(False, "second")
            status = checks.verdict(failed)
        self.assertEqual((failed, status), (1, 1))
        self.assertEqual(out.getvalue(), "ok   first\nFAIL second\nFAILED\n")
        with contextlib.redirect_stdout(io.StringIO()):
            self.assertEqual(checks.verdict(0), 0)

    def test_pictures_drawn(self):
        with tempfile.TemporaryDirectory() as d:
            big, small = os.path.join(d, "big.png"), os.path.join(d, "small.png")
            with open(big, "wb") as f:
                f.write(b"\0" * 20000)
            with open(small, "wb") as f:
                f.write(b"\0" * 100)
            self.assertTrue(checks.pictures_drawn([big]))
            self.assertFalse(checks.pictures_drawn([big, small]))
            self.assertFalse(checks.pictures_drawn([big, os.path.join(d, "absent.png")]))
            self.assertTrue(checks.pictures_drawn([small], min_bytes=50))


class Channel(unittest.TestCase):
    def test_dofs_and_overrides(self):
        # N = 8: 9 × 17 nodes, 3 fields
        self.assertEqual(benchmark.channel_dofs(8), 459)
        self.assertEqual(benchmark.channel_size(8, "quad"),
                         ["Mesh/Geo Parameters/N=8.0", "Mesh/Element Type=Quadrilateral"])
        with self.assertRaises(KeyError):
            benchmark.channel_size(8, "hex")


if __name__ == "__main__":
    unittest.main()
