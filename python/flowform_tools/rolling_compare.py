"""A finished run of the rolling scene (xml/rolling.xml, docs/rolling.md) against the slab method
at the same pass (rolling_theory.py, docs/rolling_theory.md): what scripts/rolling_study.py,
bench/rolling_bench.py and tests/regression/rolling_slab_checks.py share.

    sets = rolling_compare.pass_sets(R=20, h1=0.8, nu=0.3)        # --set overrides of one pass
    c = rolling_compare.compare(run_dir)                           # FE, slab, relative differences
    c.fe["roll_force"], c.slab.force, c.rel["roll_force"]
    arc = rolling_compare.arc_profile(run_dir)                     # the FE along the arc

The pass (R, h0, h1, ν, ω, the roll centre) and the material are read from the run's
summary.json "parameters", so the slab solution is always the one of the run's own pass.

**The slab method's flow stress** (docs/rolling.md §7). The scene's material is rate dependent,
σ̄ = σ0 + (e_r/γ)^(1/n) (σ0 = γ = 1, n = 5), and the slab method takes one shear yield stress k.
The reference here is rolling_theory's choice: σ̄ at the time-averaged equivalent strain rate of a
material point under the arc, e_m = (2/√3) ln(h0/h1) / t_gap, iterated with the slab's own flux
(rolling_theory §9). With Coulomb friction and no tensions the slab equations are homogeneous
in k: force and torque scale with k, φ_n and the forward slip do not depend on it. So the
FE's own dissipation-weighted flow stress σ̄_D = plastic_power / ∫ e dA (from solution.h5) gives
the slab answer "at the FE's flow stress" by the factor σ̄_D/σ̄(e_m): `rate_factor`. It
separates the rate term (which mean flow stress) from the rest of the departure (shear,
inhomogeneity, the arc's ends).

**The FE's roll pressure along the arc.** boundary_roll.csv's p is the mean pressure −σ_m, not
the roll pressure. The roll pressure p_n = −n·σ·n = p − n·s·n and the friction shear
τ = t·s·n (n the strip's outward normal, towards the roll centre; t the rolling direction along
the arc) are recovered here from solution.h5: s = 2μD per cell (P1 velocity gradient,
"viscosity" cell field), averaged over the cells around each wall node (area weights). The
recovery is checked against the solver's own roll_force: R∫(p_n cos φ + τ sin φ)dφ over the arc
(`arc_force`) — 0.1–1.1 % apart on the meshes tried (the cells' D is first order).
Needs numpy (and h5py for arc_profile's p_n).
"""
import math
import os

import numpy as np

from . import csvio, launcher, rolling_theory, summary as summary_module

WALL, INLET, OUTLET = "roll", "inlet", "outlet"
COMPARED = ("roll_force", "roll_torque", "neutral_angle", "forward_slip", "contact_length")
SLAB_OF = {"roll_force": "force", "roll_torque": "torque", "neutral_angle": "neutral_angle",
           "forward_slip": "forward_slip", "contact_length": "contact_length"}


def pass_sets(R=None, h0=None, h1=None, nu=None, law=None, h=None, hc=None, omega=1.0,
              defaults=(10.0, 1.0, 0.75)):
    """The --set overrides of one pass of xml/rolling.xml: Geo Parameters R, h0, h1 (those given),
    the inlet's start speed ωR h1/h0 (the speed with the neutral
    point at the exit; the scene's 7.5 belongs to R = 10, h1 = 0.75), the friction coefficient
    (law "Coulomb") or shear factor (law "Tresca": nu is then m), mesh sizes h, hc."""
    R0, h00, h10 = defaults
    Rv, h0v, h1v = R if R is not None else R0, h0 if h0 is not None else h00, h1 if h1 is not None else h10
    sets = []
    for name, v in (("R", R), ("h0", h0), ("h1", h1), ("h", h), ("hc", hc)):
        if v is not None:
            sets.append(f"Mesh/Geo Parameters/{name}={launcher.lit(v)}")
    sets.append(f"Boundary Conditions/{INLET}/Velocity X={launcher.lit(omega * Rv * h1v / h0v)}")
    if law == "Tresca":
        sets += [f"Boundary Conditions/{WALL}/Friction Law=Tresca", f"Boundary Conditions/{WALL}/Shear Factor={launcher.lit(nu)}"]
    elif nu is not None:
        sets.append(f"Boundary Conditions/{WALL}/Friction Coefficient={launcher.lit(nu)}")
    return sets


BILATERAL = f"Boundary Conditions/{WALL}/Released Nodes=Never"


def run_pass(flowform, case, outdir, sets, timeout=None):
    """Runs one pass (launcher.run, quiet, output captured, outdir cleaned). When the contact
    statuses cycle (exit 3, "does not settle") it runs again with the roll bilateral
    (BILATERAL): the release criterion is the sign of the mean pressure p, which turns negative
    near the exit under a compressive roll pressure p_n (docs/rolling.md §7; R/h0 ≥ 20 with Coulomb
    on the contact force). Returns (Run, bilateral)."""
    r = launcher.run(flowform, case, outdir, list(sets), quiet=True, capture=True, timeout=timeout, clean=True)
    if r.status == 3 and "does not settle" in ((r.summary or {}).get("message") or ""):
        return launcher.run(flowform, case, outdir, list(sets) + [BILATERAL], quiet=True, capture=True,
                            timeout=timeout, clean=True), True
    return r, False


def is_bilateral(summary):
    return ((summary.get("parameters") or {}).get("Boundary Conditions") or {}).get(WALL, {}).get("Released Nodes") == "Never"


class Pass:
    """The pass of one run, read from its summary.json parameters."""

    def __init__(self, summary):
        params = summary.get("parameters") or {}
        geo = (params.get("Mesh") or {}).get("Geo Parameters") or {}
        wall = (params.get("Boundary Conditions") or {}).get(WALL) or {}
        mat = params.get("Material") or {}
        self.R = float(geo.get("R", 10.0))
        self.h0 = float(geo.get("h0", 1.0))
        self.h1 = float(geo.get("h1", 0.75))
        self.h = float(geo.get("h", 0.05))
        self.hc = float(geo.get("hc", self.h / 2.5))
        self.law = wall.get("Friction Law", "Coulomb")
        self.nu = float(wall.get("Friction Coefficient", 0.0))
        self.m = float(wall.get("Shear Factor", 0.0))
        self.omega = float(wall.get("Angular Velocity", 1.0))
        self.centre = (float(wall.get("Rotation Centre X", 0.0)), float(wall.get("Rotation Centre Y", self.h1 / 2 + self.R)))
        self.material = rolling_theory.PowerLaw(sigma0=float(mat.get("Yield Stress", 1.0)),
                                                gamma=float(mat.get("Rate Constant", 1.0)),
                                                n=float(mat.get("Rate Exponent", 1.0)),
                                                e0=float(mat.get("Strain Rate Cutoff", 1e-3)))
        self.sigma_b = -float((params.get("Boundary Conditions") or {}).get(INLET, {}).get("Traction X", 0.0))
        self.sigma_f = float((params.get("Boundary Conditions") or {}).get(OUTLET, {}).get("Traction X", 0.0))

    @property
    def reduction(self):
        return (self.h0 - self.h1) / self.h0

    def slab(self, friction=None, **kw):
        """rolling_theory.solve at this pass: the run's friction law (Coulomb ν; Tresca m) unless
        friction ("coulomb", "tresca", "orowan") is given, the flow stress at the mean rate."""
        friction = friction or ("tresca" if self.law == "Tresca" else "coulomb")
        args = dict(R=self.R, h0=self.h0, h1=self.h1, friction=friction, omega=self.omega,
                    sigma_b=self.sigma_b, sigma_f=self.sigma_f, flow_stress=self.material)
        if friction in ("coulomb", "orowan"):
            args["nu"] = kw.pop("nu", self.nu)
        if friction in ("tresca", "orowan"):
            args["m"] = kw.pop("m", self.m if friction == "tresca" else 1.0)
        args.update(kw)
        return rolling_theory.solve(**args)

    def slab_min_nu(self):
        return slab_min_nu(self.R, self.h0, self.h1, self.sigma_b, self.sigma_f)


def slab_min_nu(R, h0, h1, sigma_b=0.0, sigma_f=0.0, tol=1e-5):
    """The smallest Coulomb ν with a steady slab solution (a neutral point inside the arc), by
    bisection (200 intervals); without tensions it does not depend on k."""
    def steady(nu):
        try:
            rolling_theory.solve(R=R, h0=h0, h1=h1, friction="coulomb", nu=nu, steps=200,
                                 sigma_b=sigma_b, sigma_f=sigma_f)
            return True
        except rolling_theory.NoNeutralPoint:
            return False
    lo, hi = 1e-4, 2.0
    if not steady(hi):
        return math.inf
    while hi - lo > tol:
        mid = 0.5 * (lo + hi)
        lo, hi = (lo, mid) if steady(mid) else (mid, hi)
    return hi


# ---------------------------------------------------------------------------------- the FE side


def _cell_geometry(xy, topo):
    """Per triangle: area and the P1 shape-function gradients (cells × 3 × 2). Quadrilaterals
    are split along their 0-2 diagonal (plotting.triangulate's convention)."""
    if topo.shape[1] == 4:
        topo = np.vstack([topo[:, [0, 1, 2]], topo[:, [0, 2, 3]]])
        cell = np.concatenate([np.arange(len(topo) // 2)] * 2)
    else:
        cell = np.arange(len(topo))
    p = xy[topo]                                   # cells × 3 × 2
    d1, d2 = p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]
    det = d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]
    inv = np.empty((len(topo), 2, 2))
    inv[:, 0, 0], inv[:, 0, 1] = d2[:, 1] / det, -d2[:, 0] / det
    inv[:, 1, 0], inv[:, 1, 1] = -d1[:, 1] / det, d1[:, 0] / det
    ref = np.array([[-1.0, -1.0], [1.0, 0.0], [0.0, 1.0]])      # ∇ of the reference P1 functions
    grads = np.einsum("ij,cjk->cik", ref, inv)     # ∇N_i = J^{-T} ∇̂N_i: (ref @ inv)
    return topo, cell, 0.5 * np.abs(det), grads


def deviator_cells(run_dir):
    """(triangles, area, s) with s the deviatoric stress 2μD per triangle (cells × 2 × 2), from
    solution.h5's velocity and viscosity; also the strain rate and the mesh."""
    from . import h5io
    sol = h5io.read(run_dir, ["velocity", "viscosity", "strain_rate"])
    xy = sol.xy
    tris, cell, area, grads = _cell_geometry(xy, sol.topology)
    u = sol.fields["velocity"][:, :2][tris]        # cells × 3 × 2
    L = np.einsum("cia,cib->cab", u, grads)        # L_ab = ∂u_a/∂x_b
    D = 0.5 * (L + np.transpose(L, (0, 2, 1)))
    mu = np.asarray(sol.fields["viscosity"]).reshape(-1)[cell]
    return {"xy": xy, "tris": tris, "area": area, "s": 2.0 * mu[:, None, None] * D,
            "strain_rate": np.asarray(sol.fields["strain_rate"]).reshape(-1)[cell], "cell": cell}


def effective_flow_stress(run_dir, summary=None):
    """σ̄_D = plastic_power / ∫ e dA: the flow stress weighted by the strain rate (the
    dissipation-weighted mean), from solution.h5's cell strain rates and summary.json's
    Plastic Power (both over the half strip)."""
    s = summary or summary_module.load(run_dir)
    dev = deviator_cells(run_dir)
    # quads were split in two: their area halves carry the same rate, so the sum is right
    return s["functionals"]["plastic_power"] / float(np.sum(dev["area"] * dev["strain_rate"]))


def arc_profile(run_dir, summary=None, with_traction=True):
    """The FE along the roll arc, ordered from the exit (φ = 0) to the entry: φ (rad, about the
    roll centre from the exit plane), x, y, p (mean pressure, CSV), status (1 in contact),
    v (the strip surface's speed along the rolling direction, −u_t of the CSV), slip
    (v/(ωR) − 1: > 0 where the strip runs ahead of the roll); with_traction also p_n (roll
    pressure) and tau (friction shear on the strip along the rolling direction, > 0 where the
    roll drives it) from solution.h5 (module doc)."""
    s = summary or summary_module.load(run_dir)
    ps = Pass(s)
    d = csvio.columns(run_dir, WALL, numpy=True)
    cx, cy = ps.centre
    phi = np.arctan2(cx - d["x"], cy - d["y"])
    order = np.argsort(phi)
    out = {"phi": phi[order], "x": d["x"][order], "y": d["y"][order], "p": d["p"][order],
           "status": d.get("contact_status", np.ones_like(phi))[order], "v": -d["u_t"][order]}
    out["slip"] = out["v"] / (ps.omega * ps.R) - 1.0
    if with_traction:
        dev = deviator_cells(run_dir)
        xy, tris, area, sdev = dev["xy"], dev["tris"], dev["area"], dev["s"]
        # the mesh node of each CSV point, then the area-weighted mean deviator of its cells
        pts = np.stack([out["x"], out["y"]], axis=1)
        nodes = np.array([int(np.argmin(np.sum((xy - q) ** 2, axis=1))) for q in pts])
        pn, tau = np.zeros(len(nodes)), np.zeros(len(nodes))
        for k, (node, f) in enumerate(zip(nodes, out["phi"])):
            around = np.nonzero(np.any(tris == node, axis=1))[0]
            sm = np.einsum("c,cab->ab", area[around], sdev[around]) / np.sum(area[around])
            n = np.array([math.sin(f), math.cos(f)])        # outward, towards the roll centre
            t = np.array([math.cos(f), -math.sin(f)])       # rolling direction along the arc
            pn[k] = out["p"][k] - n @ sm @ n
            tau[k] = t @ sm @ n
        out["p_n"], out["tau"] = pn, tau
        # R∫(p_n cos φ + τ sin φ) dφ over the nodes in contact: the recovered roll force
        c = out["status"] > 0.5
        f_int = (pn * np.cos(out["phi"]) + tau * np.sin(out["phi"])) * ps.R
        out["arc_force"] = float(np.trapz(np.where(c, f_int, 0.0), out["phi"]))
    return out


def peak_angle(phi, values):
    """The angle of a profile's maximum refined by the parabola through it and its neighbours
    (the node itself at an end)."""
    k = int(np.argmax(values))
    if 0 < k < len(values) - 1:
        x0, x1, x2 = phi[k - 1:k + 2]
        y0, y1, y2 = values[k - 1:k + 2]
        den = (x0 - x1) * (x0 - x2) * (x1 - x2)
        a = (x2 * (y1 - y0) + x1 * (y0 - y2) + x0 * (y2 - y1)) / den
        b = (x2 * x2 * (y0 - y1) + x1 * x1 * (y2 - y0) + x0 * x0 * (y1 - y2)) / den
        if a < 0:
            return float(-b / (2 * a))
    return float(phi[k])


class Comparison:
    """fe: the run's responses (and inflow, fluxes); slab: rolling_theory.Solution at the mean
    rate; rel: (FE − slab)/slab per compared response; rate_factor: σ̄_D/σ̄(e_m) (module doc)."""

    def __init__(self, run_dir, summary=None, flow_stress=True):
        self.run_dir = run_dir
        self.summary = summary or summary_module.load(run_dir, missing_ok=False)
        self.ps = Pass(self.summary)
        f = self.summary["functionals"]
        self.fe = {k: f[k] for k in COMPARED if k in f}
        self.slab = self.ps.slab()
        self.rel = {k: (self.fe[k] - getattr(self.slab, SLAB_OF[k])) / getattr(self.slab, SLAB_OF[k])
                    for k in self.fe}
        self.flux_in = -f.get("inlet_flux", float("nan"))
        self.flux_out = f.get("outlet_flux", float("nan"))
        self.flux_entry_surface = f.get("entry_surface_flux", float("nan"))
        self.flux_exit_surface = f.get("exit_surface_flux", float("nan"))
        self.sigma_mean_rate = math.sqrt(3.0) * self.slab.k
        self.sigma_D = effective_flow_stress(run_dir, self.summary) if flow_stress else None
        self.rate_factor = self.sigma_D / self.sigma_mean_rate if flow_stress else None

    @property
    def flux_mismatch(self):
        """(Q_in − Q_out)/Q_out: what enters through the flat strip surfaces (docs/rolling.md §5)."""
        return (self.flux_in - self.flux_out) / self.flux_out


def compare(run_dir, summary=None, flow_stress=True):
    return Comparison(run_dir, summary, flow_stress)


def run_dir_ok(run_dir):
    s = summary_module.load(run_dir) if os.path.isdir(run_dir) else None
    return s is not None and s.converged
