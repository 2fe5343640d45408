"""Smoothness of the ram force in the mesh and in ν: complementarity against the paper's loop
(issue #26 part 2).

Two series, each run with Contact/Status Update = Complementarity and = Certain Iterate, on the
case's fixed mesh family (Adaptivity/Enabled=false):

  mesh   h fixed (--h, default 0.1), the die-corner size hc geometric from --hc-max to --hc-min in
         --hc-steps values (default 0.02 … 0.004, 12 values). Fits F = F0 + a hc and
         F = F0 + a hc + b hc² by least squares and prints each fit's RMS residual: the ram
         force's mesh-to-mesh scatter about a smooth limit (the contact pattern's noise).
  nu     ν (Friction Coefficient of all walls) from --nu-min to --nu-max in --nu-steps values
         (default 0.08 … 0.12, 9) on one mesh (--nu-mesh H:HC, default 0.1:0.01), each run with
         dF/dν by the DDM and its built-in finite-difference check (Sensitivity/Finite Difference
         Check: two more solves at ν ± δ, δ = 2e-4; summary.json fd_check). Prints F, the DDM,
         the check's FD and their relative difference, the central difference of the sweep itself
         (F(ν+Δ) − F(ν−Δ)) / 2Δ against the DDM, the second differences
         Δ²F = F(ν+Δ) − 2F(ν) + F(ν−Δ) (a smooth F has Δ²F ≈ F''Δ², nearly constant), and the RMS
         residual of a quadratic and a cubic fit of F(ν).

usage:
  scripts/python bench/contact_smoothness.py [FLOWFORM] [--case xml/extrusion.xml] [--series mesh,nu]
        [--h 0.1] [--hc-max 0.02] [--hc-min 0.004] [--hc-steps 12] [--nu 0.1]
        [--nu-min 0.08] [--nu-max 0.12] [--nu-steps 9] [--nu-mesh 0.1:0.01] [--out DIR]
  scripts/python bench/contact_smoothness.py --report OUT/contact_smoothness.json

Runs are kept in --out (default /tmp/contact_smoothness) with flowform.log each; everything in
OUT/contact_smoothness.json. Needs Debian's /usr/bin/python3 (numpy). Exit status 0 when every
run exited 0.
"""
import argparse
import json
import os
import sys

import numpy as np

from flowform_tools import csvio, default_flowform, launcher, repo_path, tables
from flowform_tools.case import FIXED_MESH, Case
from flowform_tools.machine import binary_built, load, machine_info

STRATEGIES = ("Complementarity", "Certain Iterate")
SHORT = {"Complementarity": "C", "Certain Iterate": "CI"}
SENSITIVITY = ["Sensitivity/Parameters={Friction Coefficient}", "Sensitivity/Finite Difference Check=true"]


def run_dir(out, series, value, strategy):
    return os.path.join(out, (f"mesh_hc{value:.5f}" if series == "mesh" else f"nu{value:.4f}") + "_" + SHORT[strategy])


def lip_un(outdir, walls):
    """u·n on the die face of the die-lip node, the end shared by the last two walls in flow order
    (≈ 0: the face holds the lip; about the exit speed: the lip slides along the land, the open
    corner); None when the CSVs are absent."""
    try:
        shared = csvio.shared_points(outdir, walls[-2], walls[-1])
        rows = csvio.rows(outdir, walls[-2])
    except (OSError, IndexError):
        return None
    for r in rows:
        if (round(r["x"], 9), round(r["y"], 9)) in shared:
            return r["u_n"]
    return None


def run_one(flowform, case, outdir, sets, strategy, timeout):
    os.makedirs(outdir, exist_ok=True)
    before = load()
    r = launcher.run(flowform, case, outdir, FIXED_MESH + sets + [f"Contact/Status Update={strategy}"],
                     quiet=True, log=os.path.join(outdir, "flowform.log"), timeout=timeout)
    s = r.summary or {}
    force = Case(case).tool_force()
    check = ((s.get("fd_check") or {}).get(force) or {}).get("Friction Coefficient") or {}
    return {"status": "timeout" if r.timed_out else r.status, "wall": r.wall, "load": [before, load()],
            "dofs": s.get("dofs"), "newton": s.get("newton_iterations"), "changes": s.get("contact_changes"),
            "F": (s.get("functionals") or {}).get(force),
            "ddm": ((s.get("sensitivities") or {}).get(force) or {}).get("Friction Coefficient"),
            "fd": check.get("fd"), "fd_forward": check.get("fd_forward"), "fd_backward": check.get("fd_backward"),
            "fd_status": check.get("status"), "fd_rel_diff": check.get("rel_diff"),
            "lip_un": lip_un(outdir, Case(case).contact_walls())}


def fit(x, y, degree):
    """Least-squares polynomial of the degree; (coefficients from the constant up, RMS residual)."""
    x, y = np.asarray(x, float), np.asarray(y, float)
    A = np.vander(x, degree + 1, increasing=True)
    c, *_ = np.linalg.lstsq(A, y, rcond=None)
    return c.tolist(), float(np.sqrt(np.mean((A @ c - y) ** 2)))


def g(v, spec=".6g"):
    return "-" if v is None else format(v, spec)


def mesh_tables(series, out):
    rows = []
    for pt in series["points"]:
        c, ci = pt["runs"]["Complementarity"], pt["runs"]["Certain Iterate"]
        rows.append([g(pt["hc"], ".4g"), g(c["dofs"], "d"), g(c["F"]), g(ci["F"]),
                     g(c["F"] - ci["F"] if c["F"] is not None and ci["F"] is not None else None, ".2e"),
                     f"{g(c['newton'], 'd')} / {g(ci['newton'], 'd')}", f"{g(c['changes'], 'd')} / {g(ci['changes'], 'd')}",
                     f"{c['wall']:.1f} / {ci['wall']:.1f}", f"{c['status']} / {ci['status']}",
                     f"{g(c.get('lip_un'), '.3g')} / {g(ci.get('lip_un'), '.3g')}"])
    print(f"\n### Ram force against hc (h = {series['h']}, ν = {series['nu']})\n", file=out)
    print(tables.markdown(["hc", "dofs", "F (C)", "F (CI)", "C − CI", "Newton C / CI", "changes C / CI",
                           "wall s C / CI", "exit C / CI", "lip u_n C / CI"], rows), file=out)
    rows = []
    for key, what in (("fits", "all meshes"), ("fits_lip_open", f"meshes where both let the lip slide (lip u_n > {LIP_SLIDES})")):
        for strategy in STRATEGIES:
            f = (series.get(key) or {}).get(strategy)
            if not f:
                continue
            (l0, l1), lr = f["linear"]
            (q0, q1, q2), qr = f["quadratic"]
            rows.append([what, SHORT[strategy], str(f.get("points", "")), g(l0), g(l1, ".4g"), g(lr, ".2e"),
                         g(lr / abs(l0), ".1e"), g(q0), g(q1, ".4g"), g(q2, ".4g"), g(qr, ".2e"), g(qr / abs(q0), ".1e"),
                         g(f["max_abs_dev_quadratic"], ".2e")])
    print("\nFits F = F0 + a hc (+ b hc²); RMS = the scatter about the fit\n", file=out)
    print(tables.markdown(["meshes", "strategy", "n", "F0 (lin.)", "a", "RMS", "RMS/F0", "F0 (quad.)", "a", "b", "RMS",
                           "RMS/F0", "max abs dev. (quad.)"], rows), file=out)


def nu_tables(series, out):
    print(f"\n### Ram force against ν (h = {series['h']}, hc = {series['hc']}); dF/dν by DDM and FD\n", file=out)
    for strategy in STRATEGIES:
        pts = series["points"]
        rows = []
        F = [pt["runs"][strategy]["F"] for pt in pts]
        nus = [pt["nu"] for pt in pts]
        for i, pt in enumerate(pts):
            r = pt["runs"][strategy]
            central = d2 = None
            if 0 < i < len(pts) - 1 and None not in (F[i - 1], F[i], F[i + 1]):
                central = (F[i + 1] - F[i - 1]) / (nus[i + 1] - nus[i - 1])
                d2 = F[i + 1] - 2 * F[i] + F[i - 1]
            rel = lambda a, b: None if a is None or b is None else abs(a - b) / max(abs(b), 1e-300)  # noqa: E731
            rows.append([g(pt["nu"], ".4g"), g(r["F"]), g(r["ddm"], ".5g"), g(r["fd"], ".5g"),
                         g(r["fd_rel_diff"], ".1e"), str(r["fd_status"]), g(central, ".5g"),
                         g(rel(central, r["ddm"]), ".1e"), g(d2, ".2e"), g(r["newton"], "d"), g(r["changes"], "d"),
                         str(r["status"]), g(r.get("lip_un"), ".3g")])
        print(f"\n{strategy}:\n", file=out)
        print(tables.markdown(["ν", "F", "dF/dν DDM", "FD (check, ±2e-4)", "DDM–FD rel.", "check", "sweep central diff.",
                               "vs DDM rel.", "Δ²F", "Newton", "changes", "exit", "lip u_n"], rows), file=out)
    rows = []
    for strategy in STRATEGIES:
        s = series["summary"].get(strategy)
        if not s:
            continue
        rows.append([SHORT[strategy], g(s["quadratic_rms"], ".2e"), g(s.get("cubic_rms"), ".2e"), g(s["d2_mean"], ".2e"), g(s["d2_std"], ".2e"),
                     g(s["d2_max_abs"], ".2e"), g(s["ddm_fd_max_rel"], ".1e"), g(s["ddm_central_max_rel"], ".1e")])
    print("\nSmoothness of F(ν): RMS residual of a quadratic and a cubic fit; second differences (a smooth F has them nearly"
          " constant); the largest DDM–FD and DDM–sweep differences\n", file=out)
    print(tables.markdown(["strategy", "quad. fit RMS", "cubic fit RMS", "Δ²F mean", "Δ²F std", "max abs Δ²F", "max DDM–FD rel.",
                           "max DDM–sweep rel."], rows), file=out)


def print_tables(data, out=sys.stdout):
    m = data.get("machine", {})
    print(f"machine: {m.get('Model name', '?')}, {m.get('CPU(s)', '?')} CPUs, {m.get('memory', '?')}; "
          f"date {m.get('date', '?')}; commit {m.get('commit', '?')}; binary built {data.get('binary_built', '?')}; "
          f"case {data.get('case')}", file=out)
    if "mesh" in data:
        mesh_tables(data["mesh"], out)
    if "nu" in data:
        nu_tables(data["nu"], out)


#: lip u·n above this: the die-lip node slides along the land (the open corner, u·n ≈ the exit speed)
LIP_SLIDES = 0.5


def summarize_mesh(series):
    """Fits over every mesh ("fits") and over the meshes where both strategies let the die-lip
    node slide ("fits_lip_open": the same corner model, so that only the walls' contact zones
    differ)."""
    for key, keep in (("fits", lambda pt: True),
                      ("fits_lip_open", lambda pt: all((r.get("lip_un") or 0.0) > LIP_SLIDES for r in pt["runs"].values()))):
        series[key] = {}
        for strategy in STRATEGIES:
            pts = [(pt["hc"], pt["runs"][strategy]["F"]) for pt in series["points"] if keep(pt)
                   and pt["runs"][strategy]["F"] is not None and pt["runs"][strategy]["status"] == 0]
            if len(pts) < 4:
                continue
            x, y = zip(*pts)
            lin, quad = fit(x, y, 1), fit(x, y, 2)
            dev = np.asarray(y) - np.vander(np.asarray(x), 3, increasing=True) @ np.asarray(quad[0])
            series[key][strategy] = {"linear": lin, "quadratic": quad, "points": len(pts),
                                     "max_abs_dev_quadratic": float(np.max(np.abs(dev)))}


def summarize_nu(series):
    series["summary"] = {}
    for strategy in STRATEGIES:
        runs = [pt["runs"][strategy] for pt in series["points"]]
        if len(runs) < 3 or any(r["F"] is None or r["status"] != 0 for r in runs):
            continue
        nus = [pt["nu"] for pt in series["points"]]
        F = [r["F"] for r in runs]
        d2 = [F[i + 1] - 2 * F[i] + F[i - 1] for i in range(1, len(F) - 1)]
        central = [(F[i + 1] - F[i - 1]) / (nus[i + 1] - nus[i - 1]) for i in range(1, len(F) - 1)]
        ddm = [r["ddm"] for r in runs]
        fd_rel = [abs(r["ddm"] - r["fd"]) / abs(r["fd"]) for r in runs if r["ddm"] is not None and r["fd"]]
        series["summary"][strategy] = {
            "quadratic_rms": fit(nus, F, 2)[1], "cubic_rms": fit(nus, F, 3)[1], "d2": d2, "d2_mean": float(np.mean(d2)), "d2_std": float(np.std(d2)),
            "d2_max_abs": float(np.max(np.abs(d2))),
            "ddm_fd_max_rel": max(fd_rel) if fd_rel else None,
            "ddm_central_max_rel": max(abs(c - d) / abs(d) for c, d in zip(central, ddm[1:-1]) if d)}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("flowform", nargs="?", default=default_flowform())
    ap.add_argument("--case", default=repo_path("xml", "extrusion.xml"))
    ap.add_argument("--series", default="mesh,nu")
    ap.add_argument("--h", type=float, default=0.1)
    ap.add_argument("--hc-max", type=float, default=0.02)
    ap.add_argument("--hc-min", type=float, default=0.004)
    ap.add_argument("--hc-steps", type=int, default=12)
    ap.add_argument("--nu", type=float, default=0.1, help="ν of the mesh series (all walls)")
    ap.add_argument("--nu-min", type=float, default=0.08)
    ap.add_argument("--nu-max", type=float, default=0.12)
    ap.add_argument("--nu-steps", type=int, default=9)
    ap.add_argument("--nu-mesh", default="0.1:0.01")
    ap.add_argument("--out", default="/tmp/contact_smoothness")
    ap.add_argument("--timeout", type=float, default=900)
    ap.add_argument("--report", help="print the tables of an earlier JSON, run nothing")
    a = ap.parse_args()
    if a.report:
        with open(a.report) as f:
            data = json.load(f)
        walls = Case(repo_path(data["case"])).contact_walls()
        for series, key in (("mesh", "hc"), ("nu", "nu")):
            for pt in (data.get(series) or {}).get("points", []):
                for strategy, r in pt["runs"].items():
                    if r.get("lip_un") is None:
                        r["lip_un"] = lip_un(run_dir(os.path.dirname(os.path.abspath(a.report)), series, pt[key], strategy),
                                             walls)
        if "mesh" in data:
            summarize_mesh(data["mesh"])
        if "nu" in data:
            summarize_nu(data["nu"])
        print_tables(data)
        return 0
    flowform = launcher.require_executable(a.flowform, "contact_smoothness.py")
    case = os.path.abspath(a.case)
    walls = Case(case).contact_walls()
    friction = lambda nu: [f"Boundary Conditions/{w}/Friction Coefficient={launcher.lit(nu)}" for w in walls]  # noqa: E731
    os.makedirs(a.out, exist_ok=True)
    json_path = os.path.join(a.out, "contact_smoothness.json")
    data = {"machine": machine_info(), "binary_built": binary_built(flowform), "case": os.path.relpath(case, repo_path())}
    ok = True

    def save():
        with open(json_path + ".tmp", "w") as f:
            json.dump(data, f, indent=1)
        os.replace(json_path + ".tmp", json_path)

    series = a.series.split(",")
    if "mesh" in series:
        hcs = np.geomspace(a.hc_max, a.hc_min, a.hc_steps).tolist()
        data["mesh"] = {"h": a.h, "nu": a.nu, "points": []}
        for hc in hcs:
            sets = [f"Mesh/Geo Parameters/h={launcher.lit(a.h)}", f"Mesh/Geo Parameters/hc={launcher.lit(hc)}"] + friction(a.nu)
            pt = {"hc": hc, "runs": {}}
            for strategy in STRATEGIES:
                r = run_one(flowform, case, run_dir(a.out, "mesh", hc, strategy), sets, strategy, a.timeout)
                pt["runs"][strategy] = r
                ok = ok and r["status"] == 0
                print(f"hc={hc:.5f} {SHORT[strategy]:3} exit {r['status']} {r['wall']:6.1f} s F {r['F']} "
                      f"Newton {r['newton']}", flush=True)
            data["mesh"]["points"].append(pt)
            summarize_mesh(data["mesh"])
            save()
    if "nu" in series:
        h, hc = (float(v) for v in a.nu_mesh.split(":"))
        data["nu"] = {"h": h, "hc": hc, "points": []}
        for nu in np.linspace(a.nu_min, a.nu_max, a.nu_steps).tolist():
            nu = round(nu, 12)
            sets = [f"Mesh/Geo Parameters/h={launcher.lit(h)}", f"Mesh/Geo Parameters/hc={launcher.lit(hc)}"] + \
                friction(nu) + SENSITIVITY
            pt = {"nu": nu, "runs": {}}
            for strategy in STRATEGIES:
                r = run_one(flowform, case, run_dir(a.out, "nu", nu, strategy), sets, strategy, a.timeout)
                pt["runs"][strategy] = r
                ok = ok and r["status"] == 0
                print(f"nu={nu:.4f} {SHORT[strategy]:3} exit {r['status']} {r['wall']:6.1f} s F {r['F']} "
                      f"DDM {r['ddm']} FD {r['fd']}", flush=True)
            data["nu"]["points"].append(pt)
            summarize_nu(data["nu"])
            save()
    print_tables(data)
    print(f"\nJSON: {json_path}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
