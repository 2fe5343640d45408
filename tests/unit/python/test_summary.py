"""flowform_tools.summary: loading summary.json (a directory or the file), dotted-path access,
what happens when the file is absent or broken, and the totals over an adaptive loop."""
import json
import os
import tempfile
import unittest

from flowform_tools import summary

DOC = {
    "converged": True,
    "newton_iterations": 7,
    "functionals": {"ram_force": 3.5, "ram_pressure": -1.25},
    "linear_solver": {"factorizations": 4, "solver": "Klu2"},
    "timings": {"solve": 1.5},
    "parameters": {"Material": {"Rate Exponent": 5.0}},
    "flags": {"fd": True},
}


class Loading(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name
        with open(os.path.join(self.dir, "summary.json"), "w") as f:
            json.dump(DOC, f)

    def tearDown(self):
        self.tmp.cleanup()

    def test_directory_and_file_give_the_same_summary(self):
        a = summary.load(self.dir)
        b = summary.load(os.path.join(self.dir, "summary.json"))
        self.assertEqual(a, DOC)
        self.assertEqual(b, DOC)
        self.assertEqual(a.path, os.path.join(self.dir, "summary.json"))

    def test_absent_file(self):
        empty = os.path.join(self.dir, "empty")
        os.mkdir(empty)
        self.assertIsNone(summary.load(empty))
        with self.assertRaises(OSError):
            summary.load(empty, missing_ok=False)

    def test_broken_json(self):
        broken = os.path.join(self.dir, "broken")
        os.mkdir(broken)
        with open(os.path.join(broken, "summary.json"), "w") as f:
            f.write('{"converged": tru')  # a run killed while writing would leave this (it does not: AtomicFile)
        self.assertIsNone(summary.load(broken))
        with self.assertRaises(ValueError):
            summary.load(broken, missing_ok=False)


class Access(unittest.TestCase):
    def setUp(self):
        self.s = summary.Summary(json.loads(json.dumps(DOC)))

    def test_dotted_paths(self):
        self.assertEqual(self.s.at("linear_solver.factorizations"), 4)
        self.assertEqual(self.s.at("parameters.Material.Rate Exponent"), 5.0)
        self.assertEqual(self.s.at(["parameters", "Material", "Rate Exponent"]), 5.0)

    def test_missing_key_names_the_whole_path(self):
        with self.assertRaises(KeyError) as e:
            self.s.at("linear_solver.nonexistent")
        self.assertIn("linear_solver.nonexistent", str(e.exception))
        self.assertEqual(self.s.at("linear_solver.nonexistent", 0.0), 0.0)
        # a path through a leaf is missing too, not an error of the leaf's type
        self.assertIsNone(self.s.at("newton_iterations.x", None))

    def test_number_skips_bools_and_text(self):
        self.assertEqual(self.s.number("flags.fd", "linear_solver.solver", "newton_iterations"), 7)
        self.assertIsNone(self.s.number("flags.fd", "nope"))

    def test_converged_only_when_true(self):
        self.assertTrue(self.s.converged)
        self.assertFalse(summary.Summary({"converged": 1}).converged)
        self.assertFalse(summary.Summary({}).converged)

    def test_functional_timing_parameters(self):
        self.assertEqual(self.s.functional("ram_pressure"), -1.25)
        with self.assertRaises(KeyError):
            self.s.functional("drive_force")
        self.assertEqual(self.s.timing("solve"), 1.5)
        self.assertIsNone(self.s.timing("assemble"))
        self.assertEqual(self.s.timing("assemble", 0.0), 0.0)
        self.assertEqual(summary.Summary({"timings": None}).timing("solve", 2.0), 2.0)
        self.assertEqual(self.s.parameters, {"Material": {"Rate Exponent": 5.0}})
        self.assertEqual(summary.Summary({}).parameters, {})


# An adaptive run as flowform writes it: the top-level counts and timings are the last cycle's.
ADAPTIVE = {
    "newton_iterations": 9, "contact_changes": 0,
    "timings": {"total": 2.4, "error_estimation": 2.1},
    "functionals_error_estimate": {"ram_force": 0.0165},
    "adaptivity": {"seconds": 5.4, "target_met": True, "cycles": [
        {"cycle": 0, "newton_iterations": 54, "contact_changes": 19, "seconds": 3.0},
        {"cycle": 1, "newton_iterations": 9, "contact_changes": 0, "seconds": 2.4}]},
}


class AdaptiveTotals(unittest.TestCase):
    def test_adaptive_run_sums_the_cycles(self):
        t = summary.adaptive_totals(ADAPTIVE)
        self.assertEqual((t["cycles"], t["newton_iterations"], t["contact_changes"]), (2, 63, 19))
        self.assertEqual(t["seconds"], 5.4)
        self.assertIs(t["target_met"], True)
        # the cycles do not say what their estimates cost: the last one's, flagged incomplete
        self.assertEqual(t["estimate_seconds"], 2.1)
        self.assertFalse(t["estimate_complete"])

    def test_estimate_seconds_of_every_cycle_are_summed(self):
        doc = json.loads(json.dumps(ADAPTIVE))
        doc["adaptivity"]["cycles"][0]["estimate_seconds"] = 0.5
        doc["adaptivity"]["cycles"][1]["timings"] = {"error_estimation": 2.1}
        t = summary.adaptive_totals(doc)
        self.assertAlmostEqual(t["estimate_seconds"], 2.6)
        self.assertTrue(t["estimate_complete"])

    def test_run_without_the_loop(self):
        t = summary.adaptive_totals({"newton_iterations": 54, "contact_changes": 19,
                                     "timings": {"total": 3.0, "error_estimation": 0.0}})
        self.assertEqual((t["cycles"], t["newton_iterations"], t["contact_changes"], t["seconds"]),
                         (1, 54, 19, 3.0))
        self.assertIsNone(t["estimate_seconds"])  # no functionals_error_estimate: it did not estimate
        self.assertIsNone(t["target_met"])
        self.assertEqual(summary.adaptive_totals(None)["cycles"], 0)


if __name__ == "__main__":
    unittest.main()
