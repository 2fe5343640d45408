"""flowform_tools.rolling_compare: the --set overrides of a pass, the P1 deviator recovery on a
field known by hand, the peak refinement and the slab's steady-rolling limit."""
import math
import unittest

import numpy as np

from flowform_tools import rolling_compare, rolling_theory


class PassSets(unittest.TestCase):
    def test_start_speed_follows_R_and_h1(self):
        sets = rolling_compare.pass_sets(R=20, h1=0.8, nu=0.3)
        self.assertIn("Mesh/Geo Parameters/R=20.0", sets)
        self.assertIn("Mesh/Geo Parameters/h1=0.8", sets)
        self.assertFalse(any("Rotation Centre" in x for x in sets))                 # the wall fits it
        self.assertIn("Boundary Conditions/inlet/Velocity X=16.0", sets)           # ωR h1/h0
        self.assertIn("Boundary Conditions/roll/Friction Coefficient=0.3", sets)

    def test_defaults_give_the_shipped_start(self):
        sets = rolling_compare.pass_sets()
        self.assertIn("Boundary Conditions/inlet/Velocity X=7.5", sets)

    def test_tresca(self):
        sets = rolling_compare.pass_sets(nu=1.0, law="Tresca")
        self.assertIn("Boundary Conditions/roll/Friction Law=Tresca", sets)
        self.assertIn("Boundary Conditions/roll/Shear Factor=1.0", sets)


class CellGradients(unittest.TestCase):
    def test_linear_field_is_exact(self):
        # u = (a x + b y, c x − a y): ∇u constant, recovered exactly on any triangle (and on a
        # quadrilateral split in two).
        xy = np.array([[0.0, 0.0], [1.0, 0.1], [0.9, 1.2], [-0.1, 0.8]])
        a, b, c = 0.3, -1.1, 0.7
        u = np.stack([a * xy[:, 0] + b * xy[:, 1], c * xy[:, 0] - a * xy[:, 1]], axis=1)
        for topo in (np.array([[0, 1, 2], [0, 2, 3]]), np.array([[0, 1, 2, 3]])):
            tris, cell, area, grads = rolling_compare._cell_geometry(xy, topo)
            L = np.einsum("cia,cib->cab", u[tris], grads)
            for Lc in L:
                np.testing.assert_allclose(Lc, [[a, b], [c, -a]], atol=1e-13)
            self.assertAlmostEqual(float(area.sum()), 0.5 * abs(np.cross(xy[2] - xy[0], xy[1] - xy[0]))
                                   + 0.5 * abs(np.cross(xy[3] - xy[0], xy[2] - xy[0])), places=13)


class Peak(unittest.TestCase):
    def test_parabola_vertex(self):
        x = np.linspace(0.0, 1.0, 11)
        self.assertAlmostEqual(rolling_compare.peak_angle(x, -(x - 0.43) ** 2), 0.43, places=12)

    def test_end_maximum_is_the_node(self):
        x = np.linspace(0.0, 1.0, 11)
        self.assertEqual(rolling_compare.peak_angle(x, x), 1.0)


class SteadyLimit(unittest.TestCase):
    def test_limit_brackets_the_no_neutral_point_transition(self):
        nu = rolling_compare.slab_min_nu(10.0, 1.0, 0.75)
        rolling_theory.solve(R=10.0, h0=1.0, h1=0.75, friction="coulomb", nu=nu + 1e-4, steps=200)
        with self.assertRaises(rolling_theory.NoNeutralPoint):
            rolling_theory.solve(R=10.0, h0=1.0, h1=0.75, friction="coulomb", nu=nu - 1e-4, steps=200)
        # near α/2 (docs/rolling_theory.md §5): 0.0792 against α/2 = 0.0791 for this pass
        self.assertLess(abs(nu - 0.5 * math.acos(1 - 0.25 / 20)), 2e-3)


if __name__ == "__main__":
    unittest.main()
