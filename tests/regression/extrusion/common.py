"""Shared parts of the extrusion checks: reporting, running flowform, derived quantities.

The scene's names come from the case file (flowform_tools.case): the Contact Wall groups
(container, die_face, die_land in xml/extrusion.xml, in flow order), the tool force response
and its boundary (ram_force on the ram), the mean tool pressure and dead-zone responses, and
the Traction group (the outlet).
"""
import concurrent.futures
import json
import math
import os

import numpy as np

from flowform_tools import case as case_module, csvio, h5io, launcher
from flowform_tools.launcher import lit  # noqa: F401 (the checks' double literals)
from flowform_tools.numerics import observed_order, richardson  # noqa: F401

SLIP_LINE_R2 = 0.5 + math.pi / 4  # Hill's frictionless square-die value of p/2k for R = 2
RIGID_TRIANGLE_R2 = math.sqrt(2.0)  # the best single-triangle upper bound (derived in the doc)


# ---------------------------------------------------------------------------------------------
# Reporting


class Checks:
    def __init__(self, name, outdir):
        self.name, self.outdir = name, outdir
        self.failed = 0
        self.results = {"subcommand": name, "checks": [], "runs": {}}

    def check(self, ok, what):
        print(f"  {'ok  ' if ok else 'FAIL'}  {what}")
        self.results["checks"].append({"ok": bool(ok), "what": what})
        self.failed += 0 if ok else 1
        return ok

    def note(self, text):
        print(f"  note  {text}")
        self.results.setdefault("notes", []).append(text)

    def record(self, key, value):
        self.results[key] = value

    def finish(self):
        with open(os.path.join(self.outdir, f"{self.name}.json"), "w") as f:
            json.dump(self.results, f, indent=1, sort_keys=True)
        print(f"{self.name}: {'FAILED (' + str(self.failed) + ')' if self.failed else 'passed'}")
        return 1 if self.failed else 0


# ---------------------------------------------------------------------------------------------
# Running flowform


class ExtrusionRun:
    """One finished flowform run of the scene: status, summary.json, boundary CSVs, solution.h5."""

    def __init__(self, name, result, label, runner):
        self.name, self.dir, self.label = name, result.outdir, label
        self.status, self.seconds, self.summary = result.status, result.wall, result.summary
        self.result, self.runner = result, runner

    @property
    def converged(self):
        return self.result.converged

    def f(self, name):
        return self.summary["functionals"][name]

    @property
    def force(self):
        return self.f(self.runner.force_name)

    @property
    def params(self):
        return self.summary["parameters"]

    def wall(self, group):
        return csvio.rows(self.dir, group)

    def log_tail(self, lines=12):
        return self.result.log_tail(lines)

    def row(self):
        if self.summary is None:
            return f"{self.label:44s} exit {self.status}, no summary.json"
        s = self.summary
        if not s["converged"]:
            return f"{self.label:44s} exit {self.status}, NOT CONVERGED: {s['message']}"
        return (f"{self.label:44s} F = {self.force:.8f}  Newton {s['newton_iterations']:5d}  "
                f"changes {s['contact_changes']:3d}  {self.seconds:6.1f} s")

    def brief(self):
        out = {"status": self.status, "seconds": round(self.seconds, 2)}
        if self.summary:
            s = self.summary
            out.update(converged=s["converged"], message=s["message"], newton=s["newton_iterations"],
                       contact_changes=s["contact_changes"], dofs=s["dofs"], functionals=s["functionals"])
        return out


class Runner:
    """Runs flowform on SOURCE/xml/extrusion.xml (or a variant) into OUTDIR/<name>, log in OUTDIR/<name>.log."""

    def __init__(self, args):
        self.flowform = os.path.abspath(args.flowform)
        self.source = os.path.abspath(args.source)
        self.out = os.path.abspath(args.outdir)
        self.jobs = args.jobs
        self.case = os.path.join(self.source, "xml", "extrusion.xml")
        self.scene = case_module.Case(self.case)
        self.walls = self.scene.contact_walls()
        self.tool = self.scene.tool_boundary()
        self.force_name = self.scene.tool_force()
        self.pressure_name = self.scene.response("Mean Pressure", boundary=self.tool)
        self.dead_zone_name = self.scene.response("Dead Zone")
        self.power_name = f"{self.tool}_power"
        self.outlet = self.scene.groups("Traction")[0]
        os.makedirs(self.out, exist_ok=True)

    def command(self, name, h=None, nu=None, sets=(), case=None, powers=True):
        """(name, outdir, case, --set list) of one run: the scene without its adaptive loop, mesh size
        h (hc = h/4), ν on every wall,
        the plastic, friction and tool power responses, then the given sets."""
        outdir = os.path.join(self.out, name)
        overrides = ["Adaptivity/Enabled=false"]  # the mesh asked for, solved once
        if h is not None:
            overrides += [f"Mesh/Geo Parameters/h={lit(h)}", f"Mesh/Geo Parameters/hc={lit(h / 4)}"]
        if nu is not None:
            overrides += [f"Boundary Conditions/{w}/Friction Coefficient={lit(nu)}" for w in self.walls]
        if powers:
            overrides += ["Responses/plastic_power/Type=Plastic Power",
                          "Responses/friction_power/Type=Friction Power",
                          f"Responses/{self.power_name}/Type=Boundary Power",
                          f"Responses/{self.power_name}/Boundary={self.tool}"]
        return name, outdir, case or self.case, overrides + list(sets)

    def _execute(self, item, label):
        name, outdir, case, sets = item
        result = launcher.run(self.flowform, case, outdir, sets, log=outdir + ".log", clean=True)
        return ExtrusionRun(name, result, label, self)

    def run_all(self, specs, checks=None):
        """specs: list of (label, kwargs of command()). Returns the ExtrusionRuns in order."""
        quiet = [kw.pop("expect_failure", False) for _, kw in specs]
        items = [(self.command(**kw), label) for label, kw in specs]
        with concurrent.futures.ThreadPoolExecutor(max_workers=self.jobs) as pool:
            runs = list(pool.map(lambda it: self._execute(*it), items))
        for r, expected in zip(runs, quiet):
            print(r.row())
            if not r.converged and not expected:
                tail = r.log_tail()
                print("    log tail:\n    " + tail.replace("\n", "\n    "))
            if checks is not None:
                checks.results["runs"][r.name] = r.brief()
        return runs

    def variant(self, name, edit):
        """Writes OUTDIR/name.xml: xml/extrusion.xml edited by edit(root); Mesh/File made absolute."""
        return self.scene.variant(os.path.join(self.out, name + ".xml"), edit)


def symmetry_walls(walls):
    """An edit for Runner.variant: every wall becomes a Symmetry group."""
    def edit(root):
        for w in walls:
            case_module.set_group(root, w, [("Type", "string", "Symmetry")])
    return edit


def mesh_list(text, default):
    return [float(h) for h in (text or default).split(",")]


# ---------------------------------------------------------------------------------------------
# Quantities computed from the output files


def contact_state(run, ptol, utol, walls):
    """Checks the contact criteria on the walls' CSVs.

    Returns (violations, ambiguous, counts): violations as text; `ambiguous` the nodes shared by
    two walls (the die corners), where the CSV's contact_status is one nodal field for two wall
    statuses (the last wall's): there the node must satisfy the criterion of at least one status.
    """
    rows = {w: run.wall(w) for w in walls}
    seen = {}
    for w in walls:
        for r in rows[w]:
            seen.setdefault((round(r["x"], 9), round(r["y"], 9)), []).append(w)
    violations, ambiguous, counts = [], [], {}
    for w in walls:
        active = free = 0
        for r in rows[w]:
            key = (round(r["x"], 9), round(r["y"], 9))
            status, p, un = r["contact_status"], r["p"], r["u_n"]
            where = f"{w} node at ({r['x']:.4g}, {r['y']:.4g}): status {status:g}, p = {p:.4g}, u_n = {un:.3g}"
            if status not in (0.0, 1.0):
                violations.append(where + " (status neither 0 nor 1)")
                continue
            active += status == 1.0
            free += status == 0.0
            if len(seen[key]) > 1:
                ambiguous.append(where + f" (shared by {', '.join(seen[key])})")
                if not (p >= -ptol or un <= utol):
                    violations.append(where + " (satisfies neither criterion)")
            elif status == 1.0 and p < -ptol:
                violations.append(where + f" (active in tension beyond {ptol:g})")
            elif status == 0.0 and un > utol:
                violations.append(where + f" (free and penetrating beyond {utol:g})")
        counts[w] = {"active": active, "free": free}
    return violations, sorted(set(ambiguous)), counts


def p1_mesh(run):
    s = h5io.read(run.dir, ["velocity", "pressure", "viscosity", "strain_rate"])
    X, T = s.xy, s.topology
    u, p, mu, e = s.fields["velocity"][:, :2], s.fields["pressure"], s.fields["viscosity"], s.fields["strain_rate"]
    if T.shape[1] != 3:
        raise RuntimeError(f"{run.name}: the power terms are computed for P1 triangles only")
    return X, T, u, p, mu, e


def cell_geometry(X, T):
    xa, xb, xc = X[T[:, 0]], X[T[:, 1]], X[T[:, 2]]
    det = (xb[:, 0] - xa[:, 0]) * (xc[:, 1] - xa[:, 1]) - (xc[:, 0] - xa[:, 0]) * (xb[:, 1] - xa[:, 1])
    dNdx = np.stack([xb[:, 1] - xc[:, 1], xc[:, 1] - xa[:, 1], xa[:, 1] - xb[:, 1]], 1) / det[:, None]
    dNdy = np.stack([xc[:, 0] - xb[:, 0], xa[:, 0] - xc[:, 0], xb[:, 0] - xa[:, 0]], 1) / det[:, None]
    edges = np.stack([np.hypot(*(xa - xb).T), np.hypot(*(xb - xc).T), np.hypot(*(xc - xa).T)])
    return 0.5 * np.abs(det), dNdx, dNdy, edges.max(0)


def stabilization_power(run):
    """Σ_K τ_K |∇p|² |K|, τ_K = β h_K²/(2 μ_K): what the HFB term takes out of the ram power.

    From the continuity rows (all free at convergence): Σ_a p_a R_p,a = −∫ p div u − Σ τ|∇p|² = 0.
    P1: ∇p constant per cell, μ_K the cell's centroid viscosity (solution.h5), h_K its longest
    edge (the cell diameter of docs/verification.md §4).
    """
    X, T, u, p, mu, _ = p1_mesh(run)
    area, dNdx, dNdy, hK = cell_geometry(X, T)
    px, py = (dNdx * p[T]).sum(1), (dNdy * p[T]).sum(1)
    beta = run.params["Stabilization"]["Beta"]
    return float((area * beta * hK**2 / (2 * mu) * (px**2 + py**2)).sum())


def effective_flow_stress(run):
    """σ̄_eff = ∫ σ̄(e_r) e dΩ / ∫ e dΩ (the law at the cell strain rates), and the σ̄ range over 99 % of it."""
    X, T, _, _, _, e = p1_mesh(run)
    area = cell_geometry(X, T)[0]
    m = run.params["Material"]
    er = np.sqrt(e**2 + m["Strain Rate Cutoff"] ** 2)
    sigma = m["Yield Stress"] + (er / m["Rate Constant"]) ** (1.0 / m["Rate Exponent"])
    dissipation = area * sigma * e
    order = np.argsort(sigma)
    cum = np.cumsum(dissipation[order]) / dissipation.sum()
    lo, hi = sigma[order][np.searchsorted(cum, 0.005)], sigma[order][np.searchsorted(cum, 0.995)]
    return float(dissipation.sum() / (area * e).sum()), float(lo), float(hi)


def tool_corner(run, group):
    """The point where the tool boundary (the ram) meets a wall, from the two CSVs."""
    points = csvio.shared_points(run.dir, run.runner.tool, group)
    if len(points) != 1:
        raise RuntimeError(f"{run.runner.tool} and {group} share {len(points)} points, expected 1")
    return points[0]


def ram_corner_friction(run, group=None):
    """f̂ at the ram corner node: ν L (p⁺_c/3 + p⁺_o/6) on the first wall's (the container's)
    first segment. That node has the ram's velocity (1, 0) and slides along the container at
    speed 1 whatever ν."""
    group = group or run.runner.walls[0]
    corner = tool_corner(run, group)
    rows = sorted(run.wall(group), key=lambda r: math.hypot(r["x"] - corner[0], r["y"] - corner[1]))
    c, o = rows[0], rows[1]
    if math.hypot(c["x"] - corner[0], c["y"] - corner[1]) > 1e-9:
        raise RuntimeError(f"the {group} has no node at the ram corner")
    nu = run.params["Boundary Conditions"][group]["Friction Coefficient"]
    L = math.hypot(o["x"] - c["x"], o["y"] - c["y"])
    return nu * L * (max(c["p"], 0.0) / 3 + max(o["p"], 0.0) / 6)


def outlet_flux(run):
    """∫ u·n ds over the outlet (P1: the trapezoid rule is exact); the ram feeds 1."""
    return csvio.flux(run.dir, run.runner.outlet)
