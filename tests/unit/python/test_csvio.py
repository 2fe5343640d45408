"""flowform_tools.csvio: boundary_<group>.csv read back, and the trapezoid integrals along the
curve, on a three-point curve whose integrals are known by hand."""
import math
import os
import tempfile
import unittest

from flowform_tools import csvio

# The curve y = 0, x = s in [0, 2], written out of order in s; u_n = 1 + 2 s (linear, so the
# trapezoid rule is exact: ∫ u_n ds = 6).
WALL = """s,x,y,u_t,u_n,p,contact_status
1,1,0,0.5,3,-1,2
0,0,0,0,1,-2,1
2,2,0,1,5,0,0
"""
OTHER = """s,x,y,u_t,u_n,p
0,2,0,0,0,0
1,2,1,0,0,0
"""


class BoundaryCsv(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name
        for group, text in (("wall", WALL), ("other", OTHER)):
            with open(csvio.path(self.dir, group), "w") as f:
                f.write(text)

    def tearDown(self):
        self.tmp.cleanup()

    def test_path_and_header(self):
        self.assertEqual(csvio.path("out", "die"), os.path.join("out", "boundary_die.csv"))
        names = ["s", "x", "y", "u_t", "u_n", "p", "contact_status"]
        self.assertEqual(csvio.header(self.dir, "wall"), names)
        self.assertEqual(csvio.header(csvio.path(self.dir, "wall")), names)

    def test_rows_in_file_order_or_sorted(self):
        self.assertEqual([r["s"] for r in csvio.rows(self.dir, "wall")], [1.0, 0.0, 2.0])
        rows = csvio.rows(self.dir, "wall", sort=True)
        self.assertEqual([r["s"] for r in rows], [0.0, 1.0, 2.0])
        self.assertEqual(rows[2], {"s": 2.0, "x": 2.0, "y": 0.0, "u_t": 1.0, "u_n": 5.0, "p": 0.0,
                                   "contact_status": 0.0})

    def test_columns(self):
        c = csvio.columns(self.dir, "wall")
        self.assertEqual(c["u_n"], [3.0, 1.0, 5.0])
        n = csvio.columns(self.dir, "wall", numpy=True)
        self.assertEqual(n["p"].tolist(), [-1.0, -2.0, 0.0])
        self.assertIsNone(csvio.columns(self.dir, "absent", missing_ok=True))
        with self.assertRaises(OSError):
            csvio.columns(self.dir, "absent")

    def test_empty_file(self):
        with open(csvio.path(self.dir, "empty"), "w") as f:
            f.write("s,x,y\n")
        self.assertIsNone(csvio.columns(self.dir, "empty", missing_ok=True))
        with self.assertRaises(ValueError):
            csvio.columns(self.dir, "empty")

    def test_integral_of_a_linear_function_is_exact(self):
        self.assertEqual(csvio.integral(self.dir, "wall", "u_n"), 6.0)
        self.assertEqual(csvio.flux(self.dir, "wall"), 6.0)
        # p: −2, −1, 0 at s = 0, 1, 2 -> −3/2 − 1/2 = −2
        self.assertEqual(csvio.integral(self.dir, "wall", "p"), -2.0)

    def test_integral_weighted(self):
        self.assertEqual(csvio.integral(self.dir, "wall", "u_n", weight=lambda r: 2.0), 12.0)
        # weight x: trapezoid of 0, 3, 10 over unit steps: 3/2 + 13/2 = 8
        self.assertEqual(csvio.integral(self.dir, "wall", "u_n", weight=lambda r: r["x"]), 8.0)

    def test_integral_axisymmetric(self):
        # 2π x u_n = 0, 6π, 20π at s = 0, 1, 2: trapezoid 3π + 13π = 16π
        self.assertAlmostEqual(csvio.integral(self.dir, "wall", "u_n", axisymmetric=True), 16 * math.pi,
                               places=12)
        self.assertAlmostEqual(csvio.flux(self.dir, "wall", axisymmetric=True), 16 * math.pi, places=12)

    def test_shared_points(self):
        self.assertEqual(csvio.shared_points(self.dir, "wall", "other"), [(2.0, 0.0)])

    def test_status_column_as_written(self):
        self.assertEqual(csvio.status_column(self.dir, "wall"), ["2", "1", "0"])


if __name__ == "__main__":
    unittest.main()
