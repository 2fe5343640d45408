"""The thin shear plane's mechanics (Ernst & Merchant 1941), and the same quantities read off a
converged cutting run (xml/cutting.xml, docs/cutting.md §5.6).

A shear plane from the tool tip at the angle φ to the cutting direction carries the shear flow
stress k over its length t / sin φ, and the resultant R of the forces the chip passes through it
leans from the cutting direction by θ (tan θ = F_t / F_c; θ = λ − α with λ the friction angle
on the rake face, α the rake angle). Resolving R along and across the plane:

    F_s = R cos(φ + θ) = k t / sin φ                  (the shear force)
    F_n = R sin(φ + θ)                                (the normal force)
    σ_n / k = F_n / F_s = tan(φ + θ)                  (the plane's normal stress, compressive)
    R cos θ / (k t) = cos θ / (sin φ cos(φ + θ))      (the force along the cutting direction)

Differentiated with respect to a parameter h (the friction coefficient), with k held, the last
one says how the force moves with φ and θ (force_derivative): Merchant's dF_c/dν = 2 k t at
ν = 0 is its θ term alone, and his d(t/t_c)/dν = −1 is sec²45° times his rule's dφ/dν = −1/2.

These hold at **any** φ: they are the plane's equilibrium, before any rule that picks φ
(Merchant's minimum power, Lee & Shaffer's stress field). The run's φ is its chip ratio's, its θ
the force the shear zone carries (the drive force and the thrust), and σ_n and k are read in the
band itself: on a maximum-shear plane of a yielding plane-strain material the normal stress is
the mean stress −p, and k = σ̄ / √3.

Needs numpy and h5py (h5io) for band_state; the relations themselves only math.
"""
import math


def normal_stress_ratio(phi_deg, theta_deg):
    """σ_n / k = tan(φ + θ) of a shear plane at φ whose resultant leans by θ (degrees)."""
    return math.tan(math.radians(phi_deg + theta_deg))


def cutting_force_ratio(phi_deg, theta_deg):
    """The force along the cutting direction over k t: cos θ / (sin φ cos(φ + θ))."""
    p, th = math.radians(phi_deg), math.radians(theta_deg)
    return math.cos(th) / (math.sin(p) * math.cos(p + th))


def resultant_angle(f):
    """θ in degrees: the lean of the force the shear zone carries, tan θ = F_t / drive force, from a
    run's functionals (at α = 0; the straight chip's outlet pushes on the chip, not through the
    plane, so the drive force, not F_c)."""
    return math.degrees(math.atan2(f["thrust_force"], f["drive_force"]))


def plane_state(outdir, f, t=1.0):
    """The run's band (band_state) beside the plane's relations at the run's own φ (its
    shear_angle) and θ (resultant_angle): angle, p_over_k and k of the band; theta;
    p_over_k_plane = tan(φ + θ); drive_over_kt = drive force / (k t) with the band's k;
    drive_over_kt_plane = cos θ / (sin φ cos(φ + θ))."""
    band = band_state(outdir, t)
    phi, theta = f["shear_angle"], resultant_angle(f)
    return {"angle": band["angle"], "p_over_k": band["p_over_k"], "k": band["k"], "theta": theta,
            "p_over_k_plane": normal_stress_ratio(phi, theta),
            "drive_over_kt": f["drive_force"] / (band["k"] * t),
            "drive_over_kt_plane": cutting_force_ratio(phi, theta)}


def force_derivative(phi_deg, theta_deg, dphi, dtheta, force):
    """dF/dh of the force along the cutting direction that a plane at φ passes on, from the
    derivatives of φ and θ (radians per unit h), with k held: F = k t G(φ, θ), G = cos θ / (sin φ
    cos(φ + θ)), so dF/dh = F (∂_φ G dφ/dh + ∂_θ G dθ/dh) / G, where

        ∂_θ G / G = tan(φ + θ) − tan θ,    ∂_φ G / G = tan(φ + θ) − cot φ.

    k t is taken from the force itself (k t = F / G), so the work done off the plane, which the
    relation leaves out, scales the derivative as it scales the value. At Merchant's φ = 45°,
    θ = 0, dθ/dν = 1: dF/dν = 2 k t (its ∂_φ G vanishes there)."""
    p, th = math.radians(phi_deg), math.radians(theta_deg)
    return force * ((math.tan(p + th) - 1.0 / math.tan(p)) * dphi + (math.tan(p + th) - math.tan(th)) * dtheta)


def run_derivatives(f, d):
    """(dφ/dν, dθ/dν, the plane's d(drive)/dν) of a run at α = 0 from its functionals f (chip_ratio,
    shear_angle, drive_force, thrust_force) and their derivatives d (the same names): φ = atan(t/t_c)
    gives dφ = d(t/t_c) / (1 + (t/t_c)²), θ = atan(F_t / D) gives dθ = (dF_t D − F_t dD) / (D² + F_t²),
    and force_derivative the plane's dD from them."""
    ratio, drive, thrust = f["chip_ratio"], f["drive_force"], f["thrust_force"]
    dphi = d["chip_ratio"] / (1.0 + ratio * ratio)
    dtheta = (d["thrust_force"] * drive - thrust * d["drive_force"]) / (drive * drive + thrust * thrust)
    return dphi, dtheta, force_derivative(f["shear_angle"], resultant_angle(f), dphi, dtheta, drive)


def band_state(outdir, t=1.0, alpha_deg=0.0, levels=(0.3, 0.4, 0.5, 0.6, 0.7), half_width=0.03):
    """The primary shear band of a converged cutting run, read from its solution.h5.

    At each level y = f t (f in `levels`: the middle of the uncut layer, away from the tip's
    and the free-surface corner's own fields) the band is the cell of largest equivalent strain
    rate among the cells whose centroid lies within half_width·t of the level and upstream of
    the rake face by more than 0.1 t (so that the secondary zone along the rake is not taken
    for it). Returns a dict with, per level, the cell's centroid, p (the mean of its nodes'
    pressures), k = σ̄ / √3, p / k and e; and the medians p_over_k, k, and the band's angle to
    the cutting direction, from the tip (0, 0) to the levels' cells (least squares through the
    tip).
    """
    import numpy as np

    from flowform_tools import h5io

    s = h5io.read(outdir, ["pressure", "strain_rate", "equivalent_stress"])
    xy, cells = s.xy, s.topology
    e = np.asarray(s.fields["strain_rate"]).ravel()
    seq = np.asarray(s.fields["equivalent_stress"]).ravel()
    p = np.asarray(s.fields["pressure"]).ravel()
    if len(e) != len(cells):
        raise ValueError(f"{h5io.path(outdir)}: strain_rate is not a cell field")
    centroid = xy[cells].mean(axis=1)
    p_cell = p[cells].mean(axis=1)
    rake_x = centroid[:, 1] * math.tan(math.radians(alpha_deg))

    rows = []
    for f in levels:
        y = f * t
        near = (np.abs(centroid[:, 1] - y) < half_width * t) & (centroid[:, 0] < rake_x - 0.1 * t)
        if not near.any():
            raise ValueError(f"{h5io.path(outdir)}: no cell at the level y = {y:g} upstream of the rake")
        c = np.flatnonzero(near)[np.argmax(e[near])]
        k = seq[c] / math.sqrt(3.0)
        rows.append({"x": float(centroid[c, 0]), "y": float(centroid[c, 1]), "p": float(p_cell[c]),
                     "k": float(k), "p_over_k": float(p_cell[c] / k), "e": float(e[c])})
    xs = np.array([-r["x"] for r in rows])
    ys = np.array([r["y"] for r in rows])
    angle = math.degrees(math.atan2(float(np.dot(xs, ys)), float(np.dot(xs, xs))))
    return {"levels": rows,
            "p_over_k": float(np.median([r["p_over_k"] for r in rows])),
            "k": float(np.median([r["k"] for r in rows])),
            "angle": angle}
