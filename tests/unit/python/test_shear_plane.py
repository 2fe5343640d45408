"""The cutting scene's theory (tests/regression/cutting/shear_plane.py, imported as `cutting`):
the thin shear plane's relations at Merchant's and other angles worked by hand, and
force_derivative against a finite difference of the force relation it differentiates."""
import math
import unittest

from cutting import shear_plane


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


if __name__ == "__main__":
    unittest.main()
