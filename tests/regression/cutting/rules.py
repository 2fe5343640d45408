"""The two classical rules that pick the shear angle φ of orthogonal cutting, at rake angle α = 0,
as functions of the Coulomb coefficient ν on the rake face (the friction angle λ = atan ν; the
resultant's lean θ = λ under full sliding). The chip ratio is t/t_c = tan φ.

Merchant (1945), minimum cutting power, φ = 45° − λ/2:

    t/t_c = sec λ − tan λ = √(1 + ν²) − ν,      d(t/t_c)/dν = ν / √(1 + ν²) − 1
    dφ/dν = −1 / (2 (1 + ν²))                   (dλ/dν = 1 / (1 + ν²))
    F_c / (k t) = 2 (√(1 + ν²) + ν)             (= 2 at ν = 0; dF_c/dν = 2 k t there)
    σ_n / k = tan(φ + λ) = tan(45° + λ/2)       (on his plane; shear_plane.normal_stress_ratio)

Lee & Shaffer (1951), the slip-line field with a uniform triangle, φ = 45° − λ:

    t/t_c = tan(45° − λ) = (1 − ν) / (1 + ν),   d(t/t_c)/dν = −2 / (1 + ν)²
    σ_n / k = tan 45° = 1

The model picks neither: its φ is its own chip ratio's (docs/cutting.md). bench/cutting_sweep.py
prints and plots these beside the runs; cutting_checks.py quotes Merchant's dφ/dν.
"""
import math


def merchant_chip_ratio(nu):
    """t/t_c = √(1 + ν²) − ν."""
    return math.sqrt(1.0 + nu * nu) - nu


def merchant_chip_ratio_derivative(nu):
    """d(t/t_c)/dν = ν / √(1 + ν²) − 1."""
    return nu / math.sqrt(1 + nu * nu) - 1


def merchant_shear_angle_derivative(nu):
    """dφ/dν in radians: −1 / (2 (1 + ν²))."""
    return -0.5 / (1.0 + nu * nu)


def merchant_force(nu):
    """F_c / (k t) of Merchant's minimum-power shear plane: 2 (√(1 + ν²) + ν)."""
    return 2.0 * (math.sqrt(1.0 + nu * nu) + nu)


def merchant_normal_stress_ratio(nu):
    """σ_n / k on Merchant's plane: tan(45° + λ/2)."""
    return math.tan(math.radians(45.0 + math.degrees(math.atan(nu)) / 2.0))


def friction_angle_derivative(nu):
    """dλ/dν = 1 / (1 + ν²): dθ/dν when the chip slides over the whole rake contact."""
    return 1.0 / (1.0 + nu * nu)


def lee_shaffer_chip_ratio(nu):
    """t/t_c = (1 − ν) / (1 + ν)."""
    return (1.0 - nu) / (1.0 + nu)


def lee_shaffer_chip_ratio_derivative(nu):
    """d(t/t_c)/dν = −2 / (1 + ν)²."""
    return -2.0 / (1.0 + nu) ** 2
