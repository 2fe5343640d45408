"""The friction sweep and its plot as a user runs them (scripts/sweep_friction.py,
scripts/plot_extrusion.py; docs/extrusion.md "Friction sweep").

usage: sweep_script_checks.py FLOWFORM SOURCE_DIR OUTDIR

Runs the sweep at ν = 0 and 0.2 with the case's accuracy (its adaptive loop and, by default,
dF/dν by DDM), with a coarse target (5 %: the loop stops after its first cycle, so the test
takes seconds), then ν = 0.1 with --fixed-mesh, and plots the first sweep. Checks:

  - both sweeps exit 0 and sweep.csv has, per response, <r>_error_estimate, <r>_dnu and
    <r>_dnu_error_estimate, and cycles, target_met, newton_iterations_total,
    contact_changes_total, time_error_estimation;
  - adaptive sweep: the ram force's estimate, dF/dν and its estimate are finite in every row,
    the estimate is non-zero and below 10 % of F (the 5 % target was met on it: target_met = 1,
    and the relative estimate ≤ 5 %), dF/dν > 0 (F grows with ν, docs/extrusion.md) and the
    secant (F(0.2) − F(0))/0.2 lies between the two tangents (F is concave in ν: dF/dν falls
    from ≈ 4.4 to ≈ 3.3, the paper's fig. 4; the two runs share the first cycle's mesh);
  - fixed-mesh sweep: one cycle, no estimate (the case's Error Estimation/Method is None), but
    dF/dν (DDM does not need the loop);
  - plot_extrusion.py draws force_vs_nu.png with 2 points, 2 error bars and 2 DDM tangents on
    the ram force (what it prints, read from the artists it drew), and the PNG is not empty.
"""
import math
import os
import sys

from flowform_tools import checks, launcher
from flowform_tools.sweep import RUN_COLUMNS, estimate_column_names, num, read

RESPONSES = ["ram_force", "ram_pressure", "dead_zone"]


def run_script(source, name, args, outdir):
    """Runs scripts/<name> with Debian's python3 (PYTHONPATH as ctest sets it); the exit
    status and the captured output (also echoed)."""
    r = launcher.run_command([sys.executable, os.path.join(source, "scripts", name)] + args, capture=True,
                             cwd=outdir)
    print(r.stdout, end="")
    print(r.stderr, end="", file=sys.stderr)
    return r.status, r.stdout or ""


def main():
    flowform, source, outdir = sys.argv[1:4]
    os.makedirs(outdir, exist_ok=True)
    adaptive, fixed = os.path.join(outdir, "adaptive"), os.path.join(outdir, "fixed")
    failed = 0
    status, _ = run_script(source, "sweep_friction.py", ["--flowform", flowform, "--case",
                                                         os.path.join(source, "xml", "extrusion.xml"),
                                                         "--nu", "0,0.2", "--target", "0.05", "--out", adaptive],
                           outdir)
    failed += checks.check(status == 0, f"adaptive sweep (target 5 %): exit {status}")
    status_fixed, _ = run_script(source, "sweep_friction.py", ["--flowform", flowform, "--case",
                                                               os.path.join(source, "xml", "extrusion.xml"),
                                                               "--nu", "0.1", "--fixed-mesh", "--out", fixed], outdir)
    failed += checks.check(status_fixed == 0, f"fixed-mesh sweep: exit {status_fixed}")
    rows, rows_fixed = read(adaptive) or [], read(fixed) or []
    failed += checks.check(len(rows) == 2 and len(rows_fixed) == 1,
                           f"sweep.csv rows: {len(rows)} adaptive, {len(rows_fixed)} fixed")
    if failed:
        return checks.verdict(failed)

    wanted = estimate_column_names(RESPONSES) + RUN_COLUMNS
    for label, table in (("adaptive", rows), ("fixed", rows_fixed)):
        missing = [c for c in wanted if c not in table[0]]
        failed += checks.check(not missing, f"{label} sweep.csv has the estimate and derivative columns"
                               + (f"; missing {missing}" if missing else ""))

    F = [num(r["ram_force"]) for r in rows]
    eta = [num(r.get("ram_force_error_estimate")) for r in rows]
    d = [num(r.get("ram_force_dnu")) for r in rows]
    d_eta = [num(r.get("ram_force_dnu_error_estimate")) for r in rows]
    for r, f, e, s, se in zip(rows, F, eta, d, d_eta):
        nu = num(r["nu"])
        failed += checks.check(all(math.isfinite(v) for v in (f, e, s, se)),
                               f"ν = {nu:g}: F = {f:.6f}, η = {e:.3e}, dF/dν = {s:.5f}, η(dF/dν) = {se:.3e}: finite")
        failed += checks.check(0 < abs(e) < 0.1 * f and abs(e) / f <= 0.05 and r.get("target_met") == "1",
                               f"ν = {nu:g}: 0 < |η|/F = {abs(e) / f:.2%} <= 5 % (the target), target_met = "
                               f"{r.get('target_met')}")
        failed += checks.check(math.isfinite(num(r.get("time_error_estimation"))) and num(r["cycles"]) >= 1,
                               f"ν = {nu:g}: {r['cycles']} cycle(s), {r.get('time_error_estimation')} s in the estimate")
    secant = (F[1] - F[0]) / (num(rows[1]["nu"]) - num(rows[0]["nu"]))
    failed += checks.check(d[0] > secant > d[1] > 0,
                           f"dF/dν(0) = {d[0]:.4f} > secant {secant:.4f} > dF/dν(0.2) = {d[1]:.4f} > 0 (F grows, concave)")

    r = rows_fixed[0]
    failed += checks.check(r["cycles"] == "1" and r["ram_force_error_estimate"] == "" and r["target_met"] == "" and
                           math.isfinite(num(r["ram_force_dnu"])),
                           f"--fixed-mesh: {r['cycles']} cycle, {r['dofs']} dofs, no estimate "
                           f"('{r['ram_force_error_estimate']}'), dF/dν = {r['ram_force_dnu']}")

    status, out = run_script(source, "plot_extrusion.py", ["--sweep", adaptive], outdir)
    png = os.path.join(adaptive, "force_vs_nu.png")
    failed += checks.check(status == 0 and "force_vs_nu.png: ram_force: 2 points, 2 error bars, 2 DDM tangents" in out,
                           f"plot_extrusion.py: exit {status}; the ram force drawn with 2 error bars and 2 DDM tangents")
    failed += checks.check(checks.pictures_drawn([png]), f"{png} drawn")
    status, out = run_script(source, "plot_extrusion.py", ["--sweep", fixed], outdir)
    failed += checks.check(status == 0 and "force_vs_nu.png: ram_force: 1 points, 0 error bars, 1 DDM tangents" in out,
                           f"plot_extrusion.py on the fixed-mesh sweep: exit {status}; no error bar, 1 DDM tangent")
    return checks.verdict(failed)


if __name__ == "__main__":
    sys.exit(main())
