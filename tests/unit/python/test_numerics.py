"""flowform_tools.numerics: observed orders, Richardson extrapolation, relative difference and
median, on sequences whose answers are known by hand."""
import math
import unittest

from flowform_tools import numerics


class ObservedOrder(unittest.TestCase):
    def test_second_order_sequence(self):
        # F(h) = 1 + h² on h = 1, 1/2, 1/4, 1/8: differences −3/4, −3/16, −3/64, each 1/4 of the last.
        values = [1.0 + h * h for h in (1.0, 0.5, 0.25, 0.125)]
        self.assertEqual(numerics.observed_order(values), [2.0, 2.0])

    def test_first_order_with_ratio_three(self):
        # F(h) = 2 + h on h = 1, 1/3, 1/9: differences −2/3, −2/9, ratio 3 -> order 1.
        q = numerics.observed_order([3.0, 2.0 + 1.0 / 3.0, 2.0 + 1.0 / 9.0], ratio=3.0)
        self.assertEqual(len(q), 1)
        self.assertAlmostEqual(q[0], 1.0, places=12)

    def test_oscillating_sign_uses_the_magnitude(self):
        # differences +1, −1/2: |d0/d1| = 2 -> order 1 (the sign is not an order).
        self.assertAlmostEqual(numerics.observed_order([0.0, 1.0, 0.5])[0], 1.0, places=14)

    def test_vanishing_last_difference_is_infinite(self):
        self.assertEqual(numerics.observed_order([1.0, 2.0, 2.0]), [float("inf")])

    def test_too_short_gives_no_order(self):
        self.assertEqual(numerics.observed_order([1.0, 2.0]), [])


class Richardson(unittest.TestCase):
    def test_exact_for_the_assumed_order(self):
        # F(h) = 1 + h²: from h = 1/2 and 1/4, F + (F − F_prev)/3 = 1 exactly.
        self.assertEqual(numerics.richardson([1.25, 1.0625], 2), 1.0)

    def test_uses_the_last_two_values_and_the_ratio(self):
        # F(h) = 2 + h on h = 1/3, 1/9 with ratio 3, order 1: 2 + 1/9 + (1/9 − 1/3)/2 = 2.
        self.assertAlmostEqual(numerics.richardson([100.0, 2.0 + 1.0 / 3.0, 2.0 + 1.0 / 9.0], 1, ratio=3.0),
                               2.0, places=14)


class RelativeDifference(unittest.TestCase):
    def test_scaled_by_the_larger_magnitude(self):
        self.assertAlmostEqual(numerics.relative_difference(1.0, 1.1), 0.1 / 1.1, places=15)
        self.assertEqual(numerics.relative_difference(-2.0, 2.0), 2.0)
        self.assertEqual(numerics.relative_difference(3.0, 3.0), 0.0)

    def test_both_zero_is_zero(self):
        self.assertEqual(numerics.relative_difference(0.0, 0.0), 0.0)

    def test_symmetric(self):
        self.assertEqual(numerics.relative_difference(2.0, 5.0), numerics.relative_difference(5.0, 2.0))


class Median(unittest.TestCase):
    def test_ignores_none(self):
        self.assertEqual(numerics.median([3.0, None, 1.0, 2.0]), 2.0)
        self.assertEqual(numerics.median([4.0, 1.0, None, 2.0, 3.0]), 2.5)

    def test_nothing_left_is_none(self):
        self.assertIsNone(numerics.median([None, None]))
        self.assertIsNone(numerics.median([]))


if __name__ == "__main__":
    unittest.main()


class ExtrapolateThree(unittest.TestCase):
    def test_second_order_sequence_on_uneven_meshes(self):
        # F(h) = 1 + h² on h = 0.1, 0.07, 0.05: the order 2 is recovered and the limit is 1.
        hs = [0.1, 0.07, 0.05]
        limit, order, monotone = numerics.extrapolate_three(hs, [1.0 + h * h for h in hs])
        self.assertTrue(monotone)
        self.assertAlmostEqual(order, 2.0, places=8)
        self.assertAlmostEqual(limit, 1.0, places=10)

    def test_order_clamped(self):
        # F(h) = 1 + h^3: the order 3 is clamped to 2; the lower order takes a larger correction,
        # which overshoots the limit 1 by less than the last difference.
        hs = [0.1, 0.07, 0.05]
        limit, order, monotone = numerics.extrapolate_three(hs, [1.0 + h ** 3 for h in hs])
        self.assertEqual(order, 2.0)
        self.assertTrue(1.0 - (0.07 ** 3 - 0.05 ** 3) < limit < 1.0)

    def test_oscillating_is_flagged_with_order_one(self):
        limit, order, monotone = numerics.extrapolate_three([0.1, 0.07, 0.05], [1.0, 1.1, 1.05])
        self.assertFalse(monotone)
        self.assertEqual(order, 1.0)
        self.assertAlmostEqual(limit, 1.05 + (-0.05) / (0.07 / 0.05 - 1.0), places=12)
