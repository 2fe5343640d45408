"""flowform_tools.plotting.values_with_estimates: every point with its error bar ± |η| and its
DDM tangent (a segment of slope dy/dx through the point), read back from the drawn artists."""
import math
import unittest

import numpy as np

from flowform_tools import plotting

plt = plotting.pyplot()


class ValuesWithEstimates(unittest.TestCase):
    def setUp(self):
        self.fig, self.ax = plt.subplots()

    def tearDown(self):
        plt.close(self.fig)

    def test_bars_and_tangents_where_given(self):
        x = [0.0, 0.1, 0.3]
        y = [3.2, 3.6, 4.3]
        eta = [0.1, -0.02, float("nan")]  # signed, as flowform writes it; the last run has none
        slope = [4.4, None, 1.8]
        d = plotting.values_with_estimates(self.ax, x, y, eta, slope, label="ram_force", half_width=0.02)
        self.assertEqual((d["points"], d["bars"], d["segments"]), (3, 2, 2))
        # the error bars: vertical segments from y - |η| to y + |η| at the first two points
        bars = d["error_bars"].lines[2][0].get_segments()
        self.assertEqual(len(bars), 2)
        for seg, xi, yi, e in zip(bars, x, y, eta):
            np.testing.assert_allclose(seg, [[xi, yi - abs(e)], [xi, yi + abs(e)]], rtol=0, atol=1e-12)
        # the tangents: through (x, y), slope dy/dx, x ± half_width
        tangents = d["tangents"].get_segments()
        for seg, xi, yi, s in zip(tangents, [0.0, 0.3], [3.2, 4.3], [4.4, 1.8]):
            (x0, y0), (x1, y1) = seg
            self.assertAlmostEqual(x1 - x0, 0.04)
            self.assertAlmostEqual((y1 - y0) / (x1 - x0), s)
            self.assertAlmostEqual(0.5 * (x0 + x1), xi)
            self.assertAlmostEqual(0.5 * (y0 + y1), yi)
        self.assertIn(d["tangents"], self.ax.collections)

    def test_nothing_to_bar(self):
        d = plotting.values_with_estimates(self.ax, [0.0, 0.2], [3.2, 4.0])
        self.assertEqual((d["points"], d["bars"], d["segments"]), (2, 0, 0))
        self.assertIsNone(d["error_bars"])
        self.assertIsNone(d["tangents"])
        self.assertEqual(self.ax.containers, [])

    def test_missing_value_is_not_drawn(self):
        d = plotting.values_with_estimates(self.ax, [0.0, 0.2], [math.nan, 4.0], [0.1, 0.1], [1.0, 1.0])
        self.assertEqual((d["points"], d["bars"], d["segments"]), (1, 1, 1))


class TangentWidth(unittest.TestCase):
    def test_fraction_of_the_smallest_spacing(self):
        self.assertAlmostEqual(plotting.tangent_half_width([0.0, 0.05, 0.1, 0.3]), 0.015)
        self.assertAlmostEqual(plotting.tangent_half_width([0.2, 0.2]), 0.05)
        self.assertAlmostEqual(plotting.tangent_half_width([4.0]), 0.2)
        self.assertAlmostEqual(plotting.tangent_half_width([]), 0.05)


if __name__ == "__main__":
    unittest.main()
