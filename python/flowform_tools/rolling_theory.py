"""Flat rolling in plane strain by the slab method (von Kármán 1925, Orowan 1943), on the exact
arc, with Coulomb, Tresca and Orowan (capped Coulomb) friction; Hill's and Sims's roll-force
formulas for comparison. The derivation, the assumptions and what the slab method leaves out:
docs/rolling_theory.md (section numbers below refer to it).

Conventions (those of the rolling scene, xml/rolling.xml): the upper half of the strip, one
roll of radius R turning at ω, strip moving in +x; φ is the roll angle measured from the exit
plane (the line of centres), the entry at φ = α. Per unit width and for the one roll:

    force          the roll's reaction normal to the strip (vertical), R ∫ (p cos φ + g τ sin φ) dφ
    torque         about the roll centre, R² ∫ g τ dφ (g = +1 between entry and neutral point,
                   −1 between neutral point and exit: the sign of the roll's slip on the strip)
    neutral_angle  φ_n in degrees from the exit plane
    forward_slip   v_exit/(ωR) − 1 = h_n cos φ_n / h1 − 1        (mass conservation, §5)
    contact_length R sin α, projected on the rolling direction

Stresses: σ_x the horizontal stress (tension positive), s the vertical compressive stress on a
slab, p the roll pressure (normal to the arc, compressive positive), τ ≥ 0 the friction shear's
magnitude, k the shear yield stress (k = σ̄/√3, so 2k = 2σ̄/√3 the plane-strain yield stress).
Homogeneous compression: s + σ_x = 2k w (w = 1; Orowan's inhomogeneity factor w < 1 only to
reproduce Sims's w = π/4, §8). Tensions σ_b (entry), σ_f (exit) are stresses on the strip.

Models of the slab's vertical stress (§3):
    "orowan"      s = p + g τ tan φ, the vertical stress the arc's traction actually puts on a
                  slab (default; with it the slab solution's power balance closes exactly, §6)
    "karman"      s = p (von Kármán's equation, the usual textbook form)
    "bland_ford"  s = p and Bland & Ford's d(h σ_x) ≈ −h ds (their closed form, §7)
Arcs: "exact" h = h1 + 2R(1 − cos φ); "parabolic" the small-angle theory: h = h1 + Rφ²,
sin φ → φ, cos φ → 1, and the force R∫p dφ (the friction's vertical part, O(α) smaller, left
out as in Bland & Ford and Sims).

numpy only; one solve integrates two ODEs by RK4 on `steps` intervals (a few ms).
"""
import math
from dataclasses import dataclass, field

import numpy as np

ARCS = ("exact", "parabolic")
MODELS = ("orowan", "karman", "bland_ford")
FRICTIONS = ("coulomb", "tresca", "orowan")


class NoNeutralPoint(ValueError):
    """The entry and exit branches of the friction hill do not meet inside the arc: no steady
    rolling. `kind` is "skids" (the roll slides forward over the whole arc: friction too low
    for the reduction, or too much back tension) or "pulled" (the strip runs faster than the
    roll everywhere: too much front tension)."""

    def __init__(self, kind, text):
        super().__init__(text)
        self.kind = kind


# ---------------------------------------------------------------------------------- geometry (§2)

def bite_angle(R, h0, h1, arc="exact"):
    """α in radians: cos α = 1 − (h0 − h1)/(2R) on the exact arc, √((h0 − h1)/R) on the parabola."""
    _check_geometry(R, h0, h1)
    if arc == "parabolic":
        return math.sqrt((h0 - h1) / R)
    return math.acos(1.0 - (h0 - h1) / (2.0 * R))


def thickness(phi, R, h1, arc="exact"):
    """Whole-strip thickness under the arc at roll angle φ: h1 + 2R(1 − cos φ) (or h1 + Rφ²)."""
    phi = np.asarray(phi, dtype=float)
    return h1 + R * phi * phi if arc == "parabolic" else h1 + 2.0 * R * (1.0 - np.cos(phi))


def contact_length(R, h0, h1, arc="exact"):
    """The arc's length projected on the rolling direction, R sin α (parabolic: √(R Δh))."""
    a = bite_angle(R, h0, h1, arc)
    return R * a if arc == "parabolic" else R * math.sin(a)


def bites(nu, R, h0, h1):
    """Coulomb bite condition ν ≥ tan α: the friction on the roll's first contact line can pull
    the strip in against the pressure's backward component (p sin α ≤ ν p cos α). Steady rolling,
    once bitten, needs less (roughly ν ≳ α/2, see solve's NoNeutralPoint)."""
    return nu >= math.tan(bite_angle(R, h0, h1))


def _check_geometry(R, h0, h1):
    if not (R > 0 and h1 > 0 and h0 > h1):
        raise ValueError(f"rolling geometry: need R > 0 and h0 > h1 > 0, got R = {R}, h0 = {h0}, h1 = {h1}")
    if h0 - h1 >= 2.0 * R:
        raise ValueError(f"rolling geometry: the draught h0 − h1 = {h0 - h1} must be below the roll diameter 2R = {2 * R}")


# ---------------------------------------------------------------------------------- flow stress (§9)

@dataclass
class PowerLaw:
    """flowform's "Power Law" (docs/theory.md §1): σ̄(e) = σ0 + (e_r/γ)^(1/n), e_r = √(e² + e0²)."""
    sigma0: float = 1.0
    gamma: float = 1.0
    n: float = 1.0
    e0: float = 1e-3

    def __call__(self, e):
        return self.sigma0 + (math.sqrt(e * e + self.e0 * self.e0) / self.gamma) ** (1.0 / self.n)


def transit_time(R, h0, h1, flux):
    """Time a material point spends under the arc (exact arc): ∫ dx / v = (R/Q) ∫_0^α h cos φ dφ,
    ∫_0^α h cos φ dφ = (h1 + 2R) sin α − R (α + sin α cos α)."""
    a = bite_angle(R, h0, h1)
    return R / flux * ((h1 + 2.0 * R) * math.sin(a) - R * (a + math.sin(a) * math.cos(a)))


def mean_strain_rate(R, h0, h1, flux):
    """The time-averaged equivalent strain rate of a material point in the gap: the equivalent
    strain of homogeneous plane-strain compression, (2/√3) ln(h0/h1), over the transit time."""
    return 2.0 / math.sqrt(3.0) * math.log(h0 / h1) / transit_time(R, h0, h1, flux)


# ---------------------------------------------------------------------------------- the slab solution

@dataclass
class Solution:
    """One slab solution (per unit width, one roll). Arrays along the arc, ordered from the exit
    (φ = 0) to the entry (φ = α), the neutral point included twice (both sides)."""
    force: float                 # vertical reaction on the roll, R ∫ (p cos φ + g τ sin φ) dφ
    force_pressure: float        # its pressure part R ∫ p cos φ dφ (what Hill and Sims give)
    torque: float                # about the roll centre, R² ∫ g τ dφ
    neutral_angle: float         # degrees from the exit plane
    forward_slip: float          # v_exit/(ωR) − 1
    backward_slip: float         # 1 − v_entry/(ωR)
    contact_length: float        # R sin α
    bite_angle: float            # degrees
    k: float                     # the shear yield stress used (mean, when rate dependent)
    flux: float                  # Q = h v, whole strip, = ωR h_n cos φ_n
    roll_power: float            # torque·ω, one roll
    friction_power: float        # one roll: ∫ τ |ωR − v_t| R dφ
    plastic_power: float         # whole strip: Q · 2kw ln(h0/h1) (homogeneous compression)
    tension_power: float         # whole strip: Q (σ_f − σ_b), the power the tensions put in
                                 # (balance: 2·roll_power + tension_power = 2·friction_power + plastic_power)
    mean_pressure: float         # force / contact_length
    phi: np.ndarray = field(repr=False)        # radians
    pressure: np.ndarray = field(repr=False)   # p
    shear: np.ndarray = field(repr=False)      # g τ (signed: + where the roll drives the strip)
    sigma_x: np.ndarray = field(repr=False)
    slip: np.ndarray = field(repr=False)       # ωR − v_t: the roll's slip over the strip surface

    def as_dict(self):
        return {k: v for k, v in self.__dict__.items() if not isinstance(v, np.ndarray)}


class _Pass:
    """The data of one solve and the slab equations (§3–4)."""

    def __init__(self, R, h0, h1, k, friction, nu, m, sigma_b, sigma_f, model, arc, w):
        _check_geometry(R, h0, h1)
        if arc not in ARCS:
            raise ValueError(f"arc = {arc!r}: allowed {ARCS}")
        if model not in MODELS:
            raise ValueError(f"model = {model!r}: allowed {MODELS}")
        if friction not in FRICTIONS:
            raise ValueError(f"friction = {friction!r}: allowed {FRICTIONS}")
        if friction in ("coulomb", "orowan") and not (nu is not None and nu >= 0):
            raise ValueError(f"friction {friction!r} needs nu >= 0, got nu = {nu}")
        if friction in ("tresca", "orowan") and not (m is not None and 0 <= m <= 1):
            raise ValueError(f"friction {friction!r} needs 0 <= m <= 1, got m = {m}")
        if not k > 0:
            raise ValueError(f"the shear yield stress k must be > 0, got {k}")
        self.R, self.h0, self.h1, self.k, self.w = R, h0, h1, k, w
        self.friction, self.nu, self.m = friction, nu, m
        self.sigma_b, self.sigma_f, self.model, self.arc = sigma_b, sigma_f, model, arc
        self.alpha = bite_angle(R, h0, h1, arc)

    def trig(self, phi):
        if self.arc == "parabolic":
            return phi, 1.0, phi                        # sin, cos, tan
        c = math.cos(phi)
        return math.sin(phi), c, math.tan(phi)

    def h(self, phi):
        return float(thickness(phi, self.R, self.h1, self.arc))

    def traction(self, s, g, tan_phi):
        """(p, τ) from the slab's vertical stress s on the side g of the neutral point (§3):
        s = p + g τ tan φ ("orowan") or s = p, with τ = ν p, m k or min(ν p, m k)."""
        mk = (self.m or 0.0) * self.k
        t = g * tan_phi if self.model == "orowan" else 0.0
        if self.friction == "tresca":
            return s - mk * t, mk
        p = s / (1.0 + self.nu * t)                     # Coulomb
        if self.friction == "orowan" and self.nu * p > mk:
            return s - mk * t, mk                       # capped at the shear yield: sticking
        return p, self.nu * p

    def rhs(self, phi, y, g):
        """d/dφ of the state y = (σ_x, P, T, J) on side g (§4):
            d(h σ_x)/dφ = 2R (−p sin φ + g τ cos φ)   ("bland_ford": h dσ_x/dφ = the same)
            dP/dφ = R (p cos φ + g τ sin φ),  dT/dφ = R² g τ,  dJ/dφ = R g τ / (h cos φ)."""
        sx = y[0]
        sn, cs, tn = self.trig(phi)
        h = self.h(phi)
        s = 2.0 * self.k * self.w - sx
        p, tau = self.traction(s, g, tn)
        dF = 2.0 * self.R * (-p * sn + g * tau * cs)
        dsx = dF / h if self.model == "bland_ford" else (dF - sx * 2.0 * self.R * sn) / h
        dP = self.R * p if self.arc == "parabolic" else self.R * (p * cs + g * tau * sn)
        return np.array([dsx, dP, self.R * self.R * g * tau, self.R * g * tau / (h * cs)]), p, tau


def _branch(ps, grid, g, start):
    """RK4 along the grid (either direction) from σ_x = start; node states, their derivatives,
    and p, τ at the nodes."""
    n = len(grid)
    Y, dY = np.zeros((n, 4)), np.zeros((n, 4))
    p, tau = np.zeros(n), np.zeros(n)
    y = np.array([start, 0.0, 0.0, 0.0])
    for i in range(n):
        Y[i] = y
        dY[i], p[i], tau[i] = ps.rhs(grid[i], y, g)
        if i + 1 < n:
            d = grid[i + 1] - grid[i]
            k1 = dY[i]
            k2 = ps.rhs(grid[i] + d / 2, y + d / 2 * k1, g)[0]
            k3 = ps.rhs(grid[i] + d / 2, y + d / 2 * k2, g)[0]
            k4 = ps.rhs(grid[i + 1], y + d * k3, g)[0]
            y = y + d / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
    return Y, dY, p, tau


def _hermite(x0, x1, y0, y1, d0, d1, x):
    """Cubic Hermite interpolation on [x0, x1] (fourth-order like RK4's node values)."""
    hh = x1 - x0
    t = (x - x0) / hh
    h00, h10 = 2 * t**3 - 3 * t**2 + 1, t**3 - 2 * t**2 + t
    h01, h11 = -2 * t**3 + 3 * t**2, t**3 - t**2
    return h00 * y0 + h10 * hh * d0 + h01 * y1 + h11 * hh * d1


def solve(R, h0, h1, sigma0=1.0, friction="coulomb", nu=None, m=None, sigma_b=0.0, sigma_f=0.0,
          omega=1.0, model="orowan", arc="exact", inhomogeneity=1.0, steps=400, flow_stress=None):
    """The slab solution of one pass (§3–6). sigma0: the rigid-plastic yield stress (k = σ0/√3);
    flow_stress: instead a callable e ↦ σ̄(e) (e.g. PowerLaw), taken at the mean strain rate of
    mean_strain_rate (iterated with the flux to 1e-10, §9). friction "coulomb" (nu), "tresca" (m)
    or "orowan" (τ = min(ν p, m k); m = 1 is Orowan's sticking limit). Raises NoNeutralPoint
    when no steady rolling exists, ValueError on bad input (naming the parameter)."""
    if flow_stress is None:
        return _solve(R, h0, h1, sigma0 / math.sqrt(3.0), friction, nu, m, sigma_b, sigma_f, omega,
                      model, arc, inhomogeneity, steps)
    k = flow_stress(0.0) / math.sqrt(3.0)
    for _ in range(30):
        sol = _solve(R, h0, h1, k, friction, nu, m, sigma_b, sigma_f, omega, model, arc, inhomogeneity, steps)
        k_new = flow_stress(mean_strain_rate(R, h0, h1, sol.flux)) / math.sqrt(3.0)
        if abs(k_new - k) <= 1e-10 * k_new:
            return sol if k_new == k else _solve(R, h0, h1, k_new, friction, nu, m, sigma_b, sigma_f, omega,
                                                  model, arc, inhomogeneity, steps)
        k = k_new
    raise ArithmeticError("rate-dependent mean flow stress: the fixed point k ↔ flux did not converge in 30 steps")


def _solve(R, h0, h1, k, friction, nu, m, sigma_b, sigma_f, omega, model, arc, w, steps):
    if not omega > 0:
        raise ValueError(f"omega must be > 0, got {omega}")
    ps = _Pass(R, h0, h1, k, friction, nu, m, sigma_b, sigma_f, model, arc, w)
    a = ps.alpha
    grid = np.linspace(0.0, a, steps + 1)
    Yo, dYo, po, to = _branch(ps, grid, -1.0, sigma_f)                 # exit branch, 0 → α
    Yi, dYi, pi_, ti = _branch(ps, grid[::-1], +1.0, sigma_b)          # entry branch, α → 0
    Yi, dYi, pi_, ti = Yi[::-1], dYi[::-1], pi_[::-1], ti[::-1]        # both on the grid 0 → α
    f = Yi[:, 0] - Yo[:, 0]          # σ_x(entry branch) − σ_x(exit branch): > 0 at α, < 0 at 0 (§5)
    if np.all(f > 0):
        raise NoNeutralPoint("skids", f"no neutral point: the roll slides over the whole arc (friction too low "
                             f"for this reduction or too much back tension; σ_x jumps by {f.min():.4g} at best)")
    if np.all(f < 0):
        raise NoNeutralPoint("pulled", "no neutral point: the strip runs faster than the roll over the whole arc "
                             "(too much front tension)")
    # the crossing nearest the entry where f changes from − (exit side) to + (entry side)
    j = int(np.nonzero((f[:-1] <= 0) & (f[1:] > 0))[0][-1])

    def state(Y, dY, x):
        return _hermite(grid[j], grid[j + 1], Y[j], Y[j + 1], dY[j], dY[j + 1], x)

    lo, hi = grid[j], grid[j + 1]
    for _ in range(60):                                                # bisection on the cubic
        mid = 0.5 * (lo + hi)
        if state(Yi, dYi, mid)[0] - state(Yo, dYo, mid)[0] > 0:
            hi = mid
        else:
            lo = mid
    phin = 0.5 * (lo + hi)
    yo, yi = state(Yo, dYo, phin), state(Yi, dYi, phin)
    force = yo[1] - yi[1]            # exit side accumulated 0 → φ_n, entry side α → φ_n (negative)
    torque = yo[2] - yi[2]
    J = yo[3] - yi[3]
    hn = ps.h(phin)
    cn = ps.trig(phin)[1]
    flux = omega * R * cn * hn       # no slip at the neutral point: Q/(h_n cos φ_n) = ωR (§5)
    # the pressure part alone, by the trapezoid rule on the hill (diagnostic; the force is exact)
    side = grid < phin
    phi = np.concatenate([grid[side], [phin, phin], grid[~side]])
    sx = np.concatenate([Yo[side, 0], [yo[0], yi[0]], Yi[~side, 0]])
    g = np.concatenate([-np.ones(side.sum() + 1), np.ones((~side).sum() + 1)])
    pt = [ps.traction(2 * k * w - s, gg, ps.trig(x)[2]) for x, s, gg in zip(phi, sx, g)]
    p = np.array([q[0] for q in pt])
    tau = np.array([q[1] for q in pt])
    cos = np.ones_like(phi) if arc == "parabolic" else np.cos(phi)
    force_p = R * float(np.sum(0.5 * (p[1:] * cos[1:] + p[:-1] * cos[:-1]) * np.diff(phi)))
    slip = omega * R - flux / (thickness(phi, R, h1, arc) * cos)
    plastic = flux * 2.0 * k * w * math.log(h0 / h1)
    return Solution(force=force, force_pressure=force_p, torque=torque, neutral_angle=math.degrees(phin),
                    forward_slip=flux / (h1 * omega * R) - 1.0, backward_slip=1.0 - flux / (h0 * omega * R),
                    contact_length=contact_length(R, h0, h1, arc), bite_angle=math.degrees(a), k=k, flux=flux,
                    roll_power=torque * omega, friction_power=torque * omega - flux * J, plastic_power=plastic,
                    tension_power=flux * (sigma_f - sigma_b), mean_pressure=force / contact_length(R, h0, h1, arc),
                    phi=phi, pressure=p, shear=g * tau, sigma_x=sx, slip=slip)


# ---------------------------------------------------------------------------------- sensitivities (§10)

RESPONSES = ("force", "torque", "forward_slip", "neutral_angle")


def derivative(parameter, step=None, **kwargs):
    """Central finite differences of the slab solution's responses with respect to one keyword of
    solve (nu, m, R, h0, h1, sigma_b, sigma_f, sigma0): {response: d response / d parameter}.
    The step defaults to 1e-4 × max(|value|, 0.01); the truncation error is O(step²) and the
    integration error, smooth in the parameter at fixed steps, cancels to O(steps⁻⁴). At m = 1
    (Tresca's upper bound) the difference is one-sided (3f(m) − 4f(m − δ) + f(m − 2δ))/2δ."""
    x = kwargs[parameter]
    dx = step if step is not None else 1e-4 * max(abs(x), 0.01)
    at = lambda v: solve(**{**kwargs, parameter: v})
    if parameter == "m" and x + dx > 1.0:       # m ≤ 1: one-sided, second order, from below
        f0, f1, f2 = at(x), at(x - dx), at(x - 2 * dx)
        return {r: (3 * getattr(f0, r) - 4 * getattr(f1, r) + getattr(f2, r)) / (2.0 * dx) for r in RESPONSES}
    plus, minus = at(x + dx), at(x - dx)
    return {r: (getattr(plus, r) - getattr(minus, r)) / (2.0 * dx) for r in RESPONSES}


def dforce_dnu(**kwargs):
    return derivative("nu", **kwargs)["force"]


def dtorque_dnu(**kwargs):
    return derivative("nu", **kwargs)["torque"]


def dforward_slip_dnu(**kwargs):
    return derivative("nu", **kwargs)["forward_slip"]


# ---------------------------------------------------------------------------------- closed forms (§7–8)

def ford_H(phi, R, h1):
    """Bland & Ford's H(φ) = 2√(R/h1) arctan(√(R/h1) φ) = ∫_0^φ 2R dψ / (h1 + Rψ²)."""
    c = math.sqrt(R / h1)
    return 2.0 * c * np.arctan(c * np.asarray(phi, dtype=float))


def bland_ford_hill(phi, R, h0, h1, k, nu, sigma_b=0.0, sigma_f=0.0):
    """Bland & Ford's (1948) small-angle Coulomb friction hill, the vertical stress s(φ) = p:
        exit side   s⁺ = 2k (h/h1) (1 − σ_f/2k) exp(ν H)
        entry side  s⁻ = 2k (h/h0) (1 − σ_b/2k) exp(ν (H0 − H)),  h = h1 + Rφ², the smaller of the two."""
    phi = np.asarray(phi, dtype=float)
    h = h1 + R * phi * phi
    H, H0 = ford_H(phi, R, h1), ford_H(math.sqrt((h0 - h1) / R), R, h1)
    out = 2 * k * h / h1 * (1 - sigma_f / (2 * k)) * np.exp(nu * H)
    inn = 2 * k * h / h0 * (1 - sigma_b / (2 * k)) * np.exp(nu * (H0 - H))
    return np.minimum(out, inn)


def bland_ford_neutral_angle(R, h0, h1, k, nu, sigma_b=0.0, sigma_f=0.0):
    """φ_n in radians where Bland & Ford's two branches meet:
        H_n = H0/2 − (1/2ν) ln[(h0/h1)(1 − σ_f/2k)/(1 − σ_b/2k)],  φ_n = √(h1/R) tan(√(h1/R) H_n/2)."""
    H0 = float(ford_H(math.sqrt((h0 - h1) / R), R, h1))
    Hn = H0 / 2 - math.log(h0 / h1 * (1 - sigma_f / (2 * k)) / (1 - sigma_b / (2 * k))) / (2 * nu)
    c = math.sqrt(h1 / R)
    return c * math.tan(c * Hn / 2)


def simple_neutral_angle(R, h0, h1, nu):
    """The first-order small-angle neutral point, φ_n ≈ α/2 − α²/(4ν) (α = √(Δh/R)): Bland &
    Ford's H_n expanded for small √(R/h1)·φ and Δh/h1, no tensions."""
    a = math.sqrt((h0 - h1) / R)
    return a / 2 - a * a / (4 * nu)


def ford_forward_slip(phi_n, R, h1):
    """The classical small-angle forward slip R φ_n² / h1 (exact on the parabolic arc)."""
    return R * phi_n * phi_n / h1


def hill_force(R, h0, h1, k, nu):
    """Hill's (1950) fit to Bland & Ford's loads, no tensions, rigid roll:
        P = 2k √(R Δh) (1.08 + 1.79 r ν √(1 − r) √(R/h1) − 1.02 r),   r = Δh / h0."""
    r = (h0 - h1) / h0
    return 2 * k * math.sqrt(R * (h0 - h1)) * (1.08 + 1.79 * r * nu * math.sqrt(1 - r) * math.sqrt(R / h1) - 1.02 * r)


def sims_neutral_angle(R, h0, h1):
    """Sims's (1954) neutral point (sticking friction, small angles, w = π/4):
        φ_n = √(h1/R) tan( ½ arctan√(r/(1 − r)) − (π/8) √(h1/R) ln(h0/h1) )."""
    r = (h0 - h1) / h0
    c = math.sqrt(h1 / R)
    return c * math.tan(0.5 * math.atan(math.sqrt(r / (1 - r))) - math.pi / 8 * c * math.log(h0 / h1))


def sims_force(R, h0, h1, k):
    """Sims's (1954) roll force per unit width, P = 2k √(R Δh) Q_p,
        Q_p = (π/2)√((1−r)/r) arctan√(r/(1−r)) − π/4 − √((1−r)/r) √(R/h1) ln(h_n/h1)
              + ½ √((1−r)/r) √(R/h1) ln(1/(1−r)),   h_n = h1 + R φ_n² (Sims's φ_n)."""
    r = (h0 - h1) / h0
    a, c = math.sqrt((1 - r) / r), math.sqrt(R / h1)
    hn = h1 + R * sims_neutral_angle(R, h0, h1) ** 2
    qp = math.pi / 2 * a * math.atan(1 / a) - math.pi / 4 - a * c * math.log(hn / h1) + 0.5 * a * c * math.log(1 / (1 - r))
    return 2 * k * math.sqrt(R * (h0 - h1)) * qp


def sims_torque(R, h0, h1, k):
    """Sims's torque per roll and unit width, 2R²k (α/2 − φ_n), α = √(Δh/R): R² ∫ g k dφ."""
    return 2 * R * R * k * (math.sqrt((h0 - h1) / R) / 2 - sims_neutral_angle(R, h0, h1))
