"""The cutting scene's theory (tests/regression/cutting/, imported as `cutting`): the thin shear
plane's relations at Merchant's and other angles worked by hand, force_derivative against a
finite difference of the force relation it differentiates, and Merchant's and Lee & Shaffer's
rules at hand values, against their angles and against the plane's relations."""
import math
import unittest

from cutting import rules, shear_plane


class PlaneRelations(unittest.TestCase):
    def test_merchant_point(self):
        # φ = 45°, θ = 0: σ_n/k = tan 45° = 1, F/(k t) = 1 / (sin 45° cos 45°) = 2
        self.assertAlmostEqual(shear_plane.normal_stress_ratio(45.0, 0.0), 1.0, places=14)
        self.assertAlmostEqual(shear_plane.cutting_force_ratio(45.0, 0.0), 2.0, places=14)

    def test_other_angles(self):
        # φ = 30°, θ = 15°: cos 15° / (sin 30° cos 45°) = (√6 + √2)/4 · 4/√2 = √3 + 1
        self.assertAlmostEqual(shear_plane.cutting_force_ratio(30.0, 15.0), math.sqrt(3.0) + 1.0, places=13)
        # φ + θ = 60°: σ_n/k = √3
        self.assertAlmostEqual(shear_plane.normal_stress_ratio(40.0, 20.0), math.sqrt(3.0), places=13)

    def test_resultant_angle(self):
        self.assertAlmostEqual(shear_plane.resultant_angle({"thrust_force": 1.0, "drive_force": 1.0}), 45.0,
                               places=13)
        self.assertEqual(shear_plane.resultant_angle({"thrust_force": 0.0, "drive_force": 3.0}), 0.0)
        self.assertAlmostEqual(shear_plane.resultant_angle({"thrust_force": -1.0, "drive_force": math.sqrt(3.0)}),
                               -30.0, places=13)


class Derivatives(unittest.TestCase):
    def test_merchant_slope(self):
        # at φ = 45°, θ = 0 the φ term vanishes (tan 45° − cot 45° = 0) and dF/dν = F (tan 45° − tan 0) dθ:
        # with F = 2 k t, k t = 1 and dθ/dν = 1, dF/dν = 2 k t = 2
        self.assertAlmostEqual(shear_plane.force_derivative(45.0, 0.0, 0.0, 1.0, 2.0), 2.0, places=14)
        self.assertAlmostEqual(shear_plane.force_derivative(45.0, 0.0, 1.0, 0.0, 2.0), 0.0, places=14)

    def test_against_a_finite_difference_of_the_force(self):
        # F = k t G(φ, θ); the relation's dF/dh for φ(h) = φ0 + a h, θ(h) = θ0 + b h (radians)
        phi0, theta0, a, b, kt = 30.0, 10.0, 0.3, -0.2, 1.7

        def force(h):
            return kt * shear_plane.cutting_force_ratio(phi0 + math.degrees(a * h), theta0 + math.degrees(b * h))

        step = 1e-5
        fd = (force(step) - force(-step)) / (2 * step)
        exact = shear_plane.force_derivative(phi0, theta0, a, b, force(0.0))
        # central difference: error O(step²) relative to the curvature of F, far below 1e-8
        self.assertAlmostEqual(exact, fd, delta=1e-8 * abs(fd))
        self.assertGreater(abs(exact), 0.1)  # not a vanishing derivative that anything would match

    def test_run_derivatives(self):
        # t/t_c = 1 (φ = 45°), no thrust, drive 2, d(t/t_c) = −1, d thrust = 2, d drive = 0:
        # dφ = −1/(1 + 1) = −1/2; dθ = (2·2 − 0)/(4 + 0) = 1; the plane's dD = 2 (0·(−1/2) + 1·1) = 2
        f = {"chip_ratio": 1.0, "shear_angle": 45.0, "drive_force": 2.0, "thrust_force": 0.0}
        d = {"chip_ratio": -1.0, "drive_force": 0.0, "thrust_force": 2.0}
        dphi, dtheta, plane = shear_plane.run_derivatives(f, d)
        self.assertEqual(dphi, -0.5)
        self.assertEqual(dtheta, 1.0)
        self.assertAlmostEqual(plane, 2.0, places=14)


def central_difference(f, x, step=1e-5):
    return (f(x + step) - f(x - step)) / (2 * step)


class Rules(unittest.TestCase):
    def test_no_friction(self):
        self.assertEqual(rules.merchant_chip_ratio(0.0), 1.0)
        self.assertEqual(rules.lee_shaffer_chip_ratio(0.0), 1.0)
        self.assertEqual(rules.merchant_force(0.0), 2.0)
        self.assertAlmostEqual(rules.merchant_normal_stress_ratio(0.0), 1.0, places=14)
        self.assertEqual(rules.merchant_chip_ratio_derivative(0.0), -1.0)
        self.assertEqual(rules.lee_shaffer_chip_ratio_derivative(0.0), -2.0)
        self.assertEqual(rules.merchant_shear_angle_derivative(0.0), -0.5)
        self.assertEqual(rules.friction_angle_derivative(0.0), 1.0)

    def test_hand_values(self):
        # ν = 3/4: √(1 + 9/16) = 5/4, so t/t_c = 1/2 and F_c/(k t) = 2 (5/4 + 3/4) = 4
        self.assertEqual(rules.merchant_chip_ratio(0.75), 0.5)
        self.assertEqual(rules.merchant_force(0.75), 4.0)
        self.assertAlmostEqual(rules.merchant_chip_ratio_derivative(0.75), 0.75 / 1.25 - 1.0, places=15)
        # ν = 1/2: Lee-Shaffer (1/2)/(3/2) = 1/3, slope −2/(9/4) = −8/9; Merchant (√5 − 1)/2, dφ/dν = −2/5
        self.assertAlmostEqual(rules.lee_shaffer_chip_ratio(0.5), 1.0 / 3.0, places=15)
        self.assertAlmostEqual(rules.lee_shaffer_chip_ratio_derivative(0.5), -8.0 / 9.0, places=15)
        self.assertAlmostEqual(rules.merchant_chip_ratio(0.5), (math.sqrt(5.0) - 1.0) / 2.0, places=15)
        self.assertAlmostEqual(rules.merchant_shear_angle_derivative(0.5), -0.4, places=15)
        self.assertAlmostEqual(rules.friction_angle_derivative(0.5), 0.8, places=15)

    def test_chip_ratios_are_the_rules_angles(self):
        for nu in (0.1, 0.3, 0.6):
            lam = math.atan(nu)
            self.assertAlmostEqual(rules.merchant_chip_ratio(nu), math.tan(math.pi / 4 - lam / 2), places=14)
            self.assertAlmostEqual(rules.lee_shaffer_chip_ratio(nu), math.tan(math.pi / 4 - lam), places=14)

    def test_derivatives_against_central_differences(self):
        # step 1e-5: truncation ~1e-10, round-off ~1e-11; 1e-8 is far above both, far below any slip
        for nu in (0.1, 0.3, 0.6):
            with self.subTest(nu=nu):
                self.assertAlmostEqual(rules.merchant_chip_ratio_derivative(nu),
                                       central_difference(rules.merchant_chip_ratio, nu), delta=1e-8)
                self.assertAlmostEqual(rules.lee_shaffer_chip_ratio_derivative(nu),
                                       central_difference(rules.lee_shaffer_chip_ratio, nu), delta=1e-8)
                phi = lambda n: math.pi / 4 - math.atan(n) / 2  # noqa: E731 (Merchant's φ in radians)
                self.assertAlmostEqual(rules.merchant_shear_angle_derivative(nu), central_difference(phi, nu),
                                       delta=1e-8)
                self.assertAlmostEqual(rules.friction_angle_derivative(nu), central_difference(math.atan, nu),
                                       delta=1e-8)

    def test_merchant_is_the_plane_at_his_angle(self):
        # the plane's relations (shear_plane) at φ = 45° − λ/2, θ = λ give his force and stress
        for nu in (0.0, 0.2, 0.5):
            lam = math.degrees(math.atan(nu))
            phi = 45.0 - lam / 2.0
            self.assertAlmostEqual(shear_plane.cutting_force_ratio(phi, lam), rules.merchant_force(nu), places=13)
            self.assertAlmostEqual(shear_plane.normal_stress_ratio(phi, lam), rules.merchant_normal_stress_ratio(nu),
                                   places=13)


if __name__ == "__main__":
    unittest.main()
