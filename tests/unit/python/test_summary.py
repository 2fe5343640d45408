"""flowform_tools.summary: loading summary.json (a directory or the file), dotted-path access,
and what happens when the file is absent or broken."""
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


if __name__ == "__main__":
    unittest.main()
