"""flowform_tools.sweep (value lists, sweep.csv and its estimate and derivative columns),
tables (markdown), checks (the verdict) and benchmark (the channel's size)."""
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


WALLS = ["container", "die_face", "die_land"]
FRICTION = ["Boundary Conditions/%s/Friction Coefficient" % w for w in WALLS]


class SensitivityNames(unittest.TestCase):
    def test_every_wall_is_the_one_parameter(self):
        self.assertEqual(sweep.sensitivity_names(FRICTION, WALLS), ["Friction Coefficient"])
        self.assertEqual(sweep.sensitivity_names(FRICTION[::-1], WALLS), ["Friction Coefficient"])

    def test_some_walls_one_name_each(self):
        self.assertEqual(sweep.sensitivity_names(FRICTION[:2], WALLS),
                         ["Friction Coefficient:container", "Friction Coefficient:die_face"])
        self.assertEqual(sweep.sensitivity_names(["Boundary Conditions/die_land/Shear Factor"], WALLS),
                         ["Shear Factor:die_land"])

    def test_material_and_other_paths(self):
        self.assertEqual(sweep.sensitivity_names(["Material/Rate Exponent"], WALLS), ["Rate Exponent"])
        self.assertIsNone(sweep.sensitivity_names(["Mesh/Geo Parameters/h"], WALLS))
        self.assertIsNone(sweep.sensitivity_names(["Material/Rate Exponent", "Mesh/Geo Parameters/h"], WALLS))


SUMMARY = {
    "newton_iterations": 9, "contact_changes": 0, "timings": {"total": 2.4, "error_estimation": 2.1},
    "functionals": {"ram_force": 3.7, "dead_zone": 0.07},
    "functionals_error_estimate": {"ram_force": 0.0165, "dead_zone": -0.0098},
    "sensitivities": {"ram_force": {"Friction Coefficient:container": 3.0, "Friction Coefficient:die_face": 1.25}},
    "sensitivities_error_estimate": {"ram_force": {"Friction Coefficient:container": -0.5}},
    "adaptivity": {"seconds": 5.4, "target_met": False, "cycles": [
        {"newton_iterations": 54, "contact_changes": 19}, {"newton_iterations": 9, "contact_changes": 0}]},
}


class EstimateColumns(unittest.TestCase):
    def test_names(self):
        self.assertEqual(sweep.estimate_column_names(["ram_force"]),
                         ["ram_force_error_estimate", "ram_force_dnu", "ram_force_dnu_error_estimate"])

    def test_columns_of_a_run(self):
        walls = ["Friction Coefficient:container", "Friction Coefficient:die_face"]
        row = sweep.estimate_columns(SUMMARY, ["ram_force", "dead_zone"], walls)
        self.assertEqual(row["ram_force_error_estimate"], 0.0165)
        self.assertEqual(row["dead_zone_error_estimate"], -0.0098)  # signed, as flowform writes it
        self.assertEqual(row["ram_force_dnu"], 4.25)  # the two walls' derivatives add up
        self.assertIsNone(row["ram_force_dnu_error_estimate"])  # die_face's has no estimate
        self.assertIsNone(row["dead_zone_dnu"])
        self.assertEqual((row["cycles"], row["target_met"], row["newton_iterations_total"],
                          row["contact_changes_total"], row["time_error_estimation"]), (2, 0, 63, 19, 2.1))
        self.assertEqual(set(row), set(sweep.estimate_column_names(["ram_force", "dead_zone"]) + sweep.RUN_COLUMNS))

    def test_a_derivative_needs_every_parameter(self):
        row = sweep.estimate_columns(SUMMARY, ["ram_force"], ["Friction Coefficient:container", "Rate Exponent"])
        self.assertIsNone(row["ram_force_dnu"])
        row = sweep.estimate_columns(SUMMARY, ["ram_force"], None)  # no sensitivity asked for
        self.assertIsNone(row["ram_force_dnu"])
        self.assertIsNone(row["ram_force_dnu_error_estimate"])

    def test_run_without_estimate(self):
        row = sweep.estimate_columns({"functionals": {"ram_force": 3.6}, "newton_iterations": 54},
                                     ["ram_force"], ["Friction Coefficient"])
        self.assertIsNone(row["ram_force_error_estimate"])
        self.assertIsNone(row["target_met"])
        self.assertEqual(row["newton_iterations_total"], 54)


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
