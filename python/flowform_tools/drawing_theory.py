"""Classical drawing stress of a round wire through a conical die (docs/drawing.md §2), for a
rigid-perfectly plastic wire of flow stress Y, drawn from radius R0 to R1 through a cone of
semi-angle alpha (radians), no back tension:

- homogeneous (ideal) work: sigma_d / Y = 2 ln(R0/R1), a lower bound without friction;
- Sachs's slab method with Coulomb friction mu on the cone (no redundant work, the cone's
  pressure p = Y - sigma_z): sigma_d / Y = (1 + B)/B [1 - (R1/R0)^(2B)], B = mu cot(alpha);
- Avitzur's upper bound (spherical velocity field, friction factor m on cone and land of length
  L): sigma_d / Y = 2 f(alpha) ln(R0/R1) + (2/sqrt 3)(alpha/sin^2 alpha - cot alpha)
  + 2 m (cot alpha ln(R0/R1) + L/R1), with
  f(alpha) = [1 - cos(alpha) sqrt(1 - (11/12) sin^2 alpha)
              + ln((1 + sqrt(11/12)) / (sqrt(11/12) cos(alpha) + sqrt(1 - (11/12) sin^2 alpha))) / sqrt(132)]
             / sin^2 alpha;
- the angle that minimizes the upper bound (numerically; for small angles, where f = 1 and
  alpha/sin^2 - cot = 2 alpha/3, d/dalpha = 0 gives alpha* = sqrt(3 sqrt(3) m ln(R0/R1) / 2)).
"""
import math


def ideal_stress(r0, r1):
    return 2.0 * math.log(r0 / r1)


def sachs_stress(mu, alpha, r0, r1):
    if mu == 0.0:
        return ideal_stress(r0, r1)
    b = mu / math.tan(alpha)
    return (1.0 + b) / b * (1.0 - (r1 / r0) ** (2.0 * b))


def avitzur_f(alpha):
    s2 = math.sin(alpha) ** 2
    if s2 < 1e-12:
        return 1.0
    root = math.sqrt(1.0 - 11.0 / 12.0 * s2)
    c = math.sqrt(11.0 / 12.0)
    return (1.0 - math.cos(alpha) * root
            + math.log((1.0 + c) / (c * math.cos(alpha) + root)) / math.sqrt(132.0)) / s2


def upper_bound_stress(alpha, r0, r1, m, land=0.0):
    strain = math.log(r0 / r1)
    shear = 2.0 / math.sqrt(3.0) * (alpha / math.sin(alpha) ** 2 - 1.0 / math.tan(alpha))
    friction = 2.0 * m * (strain / math.tan(alpha) + land / r1)
    return 2.0 * avitzur_f(alpha) * strain + shear + friction


def optimal_angle_small(m, r0, r1):
    return math.sqrt(3.0 * math.sqrt(3.0) * m * math.log(r0 / r1) / 2.0)


def optimal_angle_upper_bound(m, r0, r1, land=0.0, lo=math.radians(0.5), hi=math.radians(60.0)):
    """The alpha in [lo, hi] minimizing upper_bound_stress (golden-section search: the bound is
    convex in alpha here, friction falling as cot alpha and the shear rising as alpha)."""
    g = (math.sqrt(5.0) - 1.0) / 2.0
    a, b = lo, hi
    for _ in range(200):
        c, d = b - g * (b - a), a + g * (b - a)
        if upper_bound_stress(c, r0, r1, m, land) < upper_bound_stress(d, r0, r1, m, land):
            b = d
        else:
            a = c
        if b - a < 1e-12:
            break
    return 0.5 * (a + b)
