"""Accuracy per second (issue #26): what the ram force's true error costs on fixed meshes and
through the adaptive loop, what the estimate costs, and the cutting default with its estimate.
Prints markdown tables (docs/BENCHMARKS.md takes them as printed); a benchmark, not a test.

  (a) fixed  every fixed extrusion mesh (h, hc) from scratch (Adaptivity/Enabled = false, no
             estimate): Newton iterations, contact changes, flow solves, dofs, wall seconds,
             the ram force and its true relative error (F − F_ref)/F_ref. Issue target: ≤ 20
             Newton iterations, not growing with the mesh.
  (b) adaptive  the adaptive loop asked for each target (Adaptivity/Target Relative Error) on
             xml/extrusion.xml and xml/extrusion_axisym.xml: cycles, dofs of the last cycle,
             Newton iterations over the cycles, wall seconds, the loop's seconds, seconds in
             the estimate and their share, the estimated relative error η/F (signed; η ≈ F_ref − F,
             so its sign is the opposite of the true error's when it points the right way), the
             true one, the effectivity η/(F_ref − F), whether the true error is within the target, and
             whether the true error falls as the target does. Issue targets: ≤ 5·10⁻⁴ in ≤ 3 s
             and ≤ 1·10⁻⁴ in ≤ 20 s asking for exactly that target; the estimate ≤ 30 % of the
             run; a target met in truth.
  (c) cutting  xml/cutting.xml as shipped (its two-level estimate included): wall seconds,
             the estimate's seconds, every response and derivative with its estimate. Issue
             target: ≤ 15 s.

usage: scripts/python bench/accuracy_per_second.py [--flowform build/flowform] [--repeat N] [--quick]
           [--parts fixed,adaptive,cutting] [--cases plane,axisym] [--nu 0.1] [--large]
           [--meshes H:HC,...] [--targets 0.01,0.005,...] [--reference CASE:NU=F[:PM] ...]
           [--workdir DIR] [--timeout S] [--json FILE] [--set P=V ...]

  --repeat N   runs per row; the seconds are medians, the counts the first run's (a note is
               printed when the repeats differ in the ram force)
  --quick      one repeat, meshes (0.1, 0.025) and (0.1, 0.01), targets 1 % and 0.5 %
  --large      add the fine fixed meshes (0.05, 0.002) and (0.025, 0.001) (minutes each today)
  --nu         friction coefficient(s) of all contact walls, each with a reference (default 0.1;
               0 and 0.3 have references too)
  --reference  replace or add a reference ram force, e.g. plane:0.1=3.73325:0.00046 (the value
               after the second colon is its uncertainty)
  --set P=V    a case parameter added to every run (repeatable), e.g. 'Error Estimation/Nested
               Start=false' for the loop with its levels solved after each cycle's run

The references (F_inf, ±) are docs/BENCHMARKS.md §10 (bench/extrusion_references.py: a least-
squares fit of two mesh families, ± its largest residual, the contact pattern's mesh-to-mesh
noise). A true error below the reference's ± is marked "(noise)": it says only that the error
is below the reference's own uncertainty. Seconds: "wall" is the whole process (mesh
generation and output included), as a user waits; "loop" is summary.json adaptivity.seconds.
The estimate's seconds are summed over the cycles when summary.json gives each cycle's; it
gives only the last cycle's today (timings.error_estimation), and such entries are marked †
with the share taken of the last cycle's seconds. Every number comes from summary.json and the
process's wall clock (python/flowform_tools: launcher, summary.adaptive_totals).
"""
import argparse
import json
import os
import sys

from flowform_tools import default_flowform, launcher, repo_path, summary as summary_module
from flowform_tools.case import FIXED_MESH, Case
from flowform_tools.launcher import lit
from flowform_tools.machine import binary_built, load, machine_info
from flowform_tools.numerics import median
from flowform_tools.tables import fmt, markdown

CASES = {"plane": "xml/extrusion.xml", "axisym": "xml/extrusion_axisym.xml"}
#: (case, ν): (F_inf, ±), docs/BENCHMARKS.md §10
REFERENCES = {("plane", 0.0): (3.30663, 0.0008), ("plane", 0.1): (3.73325, 0.00046), ("plane", 0.3): (4.3595, 0.014),
              ("axisym", 0.0): (18.2239, 0.0077), ("axisym", 0.1): (23.10283, 0.0031), ("axisym", 0.3): (26.646, 0.20)}
MESHES = [(0.1, 0.025), (0.1, 0.01), (0.05, 0.005)]
LARGE_MESHES = [(0.05, 0.002), (0.025, 0.001)]
TARGETS = [0.01, 0.005, 0.002, 0.001, 0.0005]
NO_FILES = ["Output/Write Solution=false", "Output/Boundary CSV=false"]
NEWTON_TARGET = 20
ESTIMATE_SHARE_TARGET = 0.30
CUTTING_SECONDS_TARGET = 15.0
# (true relative error, seconds) the adaptive loop must reach asking for exactly that target
SPEED_TARGETS = [(5e-4, 3.0), (1e-4, 20.0)]


def parse_mesh(text):
    h, hc = text.split(":")
    return float(h), float(hc)


def parse_reference(text):
    """"plane:0.1=3.73469[:0.0022]" -> (("plane", 0.1), (3.73469, 0.0022 or 0))."""
    try:
        key, value = text.split("=")
        case, nu = key.split(":")
        parts = value.split(":")
        return (case, float(nu)), (float(parts[0]), float(parts[1]) if len(parts) > 1 else 0.0)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected CASE:NU=F[:PM], got '{text}'")


class Bench:
    def __init__(self, args):
        self.args = args
        self.walls = {case: Case(repo_path(path)).contact_walls() for case, path in CASES.items()}

    def friction(self, case, nu):
        return [f"Boundary Conditions/{w}/Friction Coefficient={lit(nu)}" for w in self.walls[case]]

    def run(self, case_file, name, sets):
        """--repeat runs of one case; the first run's summary, the exit statuses, the median wall
        seconds and whether the repeats gave the same functionals."""
        runs = []
        for k in range(self.args.repeat):
            out = os.path.join(self.args.workdir, f"{name}_r{k}")
            r = launcher.run(self.args.flowform, repo_path(case_file), out, NO_FILES + sets + self.args.set, quiet=True,
                             clean=True,
                             log=os.path.join(self.args.workdir, f"{name}_r{k}.log"), timeout=self.args.timeout)
            runs.append(r)
            s = r.summary or {}
            print(f"  {name} run {k}: exit {'timeout' if r.timed_out else r.status}, {s.get('dofs')} dofs, "
                  f"{r.wall:.1f} s wall, load {load():.2f}", flush=True)
            if r.status not in (0, 3):
                break
        s = runs[0].summary or {}
        same = all((r.summary or {}).get("functionals") == s.get("functionals") for r in runs)
        return {"summary": s, "status": ["timeout" if r.timed_out else r.status for r in runs],
                "wall": median([r.wall for r in runs]), "walls": [r.wall for r in runs], "same": same}

    def reference(self, case, nu):
        return self.args.references.get((case, nu))


def true_error(F, ref):
    """(F − F_ref)/F_ref and whether |F − F_ref| is below the reference's ±."""
    if F is None or ref is None:
        return None, False
    value, pm = ref
    return (F - value) / value, abs(F - value) <= pm


def error_cell(rel, noise):
    return "-" if rel is None else f"{rel:+.1e}" + (" (noise)" if noise else "")


# ------------------------------------------------------------------------------------------
# (a) fixed meshes


def part_fixed(bench, results):
    a = bench.args
    print("\n## (a) Fixed meshes from scratch (Adaptivity/Enabled = false, no estimate)\n", flush=True)
    for case in a.cases:
        for nu in a.nu:
            rows = []
            for h, hc in a.meshes:
                name = f"fixed_{case}_nu{nu:g}_h{h:g}_hc{hc:g}"
                r = bench.run(CASES[case], name, FIXED_MESH + [f"Mesh/Geo Parameters/h={lit(h)}",
                                                               f"Mesh/Geo Parameters/hc={lit(hc)}"] +
                              bench.friction(case, nu))
                s = r["summary"]
                F = (s.get("functionals") or {}).get("ram_force")
                rel, noise = true_error(F, bench.reference(case, nu))
                rows.append({"case": case, "nu": nu, "h": h, "hc": hc, "status": r["status"], "dofs": s.get("dofs"),
                             "newton": s.get("newton_iterations"), "changes": s.get("contact_changes"),
                             "solves": len((s.get("solves") or {}).get("newton_iterations") or []),
                             "wall": r["wall"], "walls": r["walls"], "F": F, "true": rel, "noise": noise,
                             "same": r["same"]})
            ref = bench.reference(case, nu)
            print(f"\n{case}, ν = {nu:g} (F_ref = {fmt(ref and ref[0], '{:g}')} ± {fmt(ref and ref[1], '{:g}')}):\n")
            print(markdown(["h", "hc", "exit", "dofs", "Newton", "contact changes", "flow solves", "wall s",
                            "F", "true rel. error"],
                           [[f"{r['h']:g}", f"{r['hc']:g}", ",".join(map(str, r["status"])), fmt(r["dofs"], "{}"),
                             fmt(r["newton"], "{}"), fmt(r["changes"], "{}"), fmt(r["solves"], "{}"),
                             fmt(r["wall"], "{:.2f}"), fmt(r["F"], "{:.5f}"), error_cell(r["true"], r["noise"])]
                            for r in rows], align="---:"))
            newton = [r["newton"] for r in rows if r["newton"] is not None]
            if newton:
                growing = any(b > a_ for a_, b in zip(newton, newton[1:]))
                ok = max(newton) <= NEWTON_TARGET and not growing
                print(f"target ≤ {NEWTON_TARGET} Newton iterations, not growing with the mesh: "
                      f"{'met' if ok else 'missed'} (max {max(newton)}, {'growing' if growing else 'not growing'}: "
                      f"{' → '.join(map(str, newton))})")
            for r in rows:
                if not r["same"]:
                    print(f"note: h = {r['h']:g}, hc = {r['hc']:g}: the repeats differ in the functionals")
            results["fixed"] += rows


# ------------------------------------------------------------------------------------------
# (b) the adaptive loop


def part_adaptive(bench, results):
    a = bench.args
    print("\n## (b) The adaptive loop asked for each target (the case's Adaptivity section)\n", flush=True)
    for case in a.cases:
        for nu in a.nu:
            rows = []
            for target in a.targets:
                name = f"adaptive_{case}_nu{nu:g}_t{target:g}"
                r = bench.run(CASES[case], name, [f"Adaptivity/Target Relative Error={lit(target)}"] +
                              bench.friction(case, nu))
                s = r["summary"]
                totals = summary_module.adaptive_totals(s)
                F = (s.get("functionals") or {}).get("ram_force")
                eta = (s.get("functionals_error_estimate") or {}).get("ram_force")
                rel, noise = true_error(F, bench.reference(case, nu))
                ref = bench.reference(case, nu)
                cycles = (s.get("adaptivity") or {}).get("cycles") or []
                est = totals["estimate_seconds"]
                if est is not None and totals["estimate_complete"]:
                    share = est / totals["seconds"] if totals["seconds"] else None
                else:  # the last cycle's estimate against the last cycle's seconds
                    last = cycles[-1].get("seconds") if cycles else None
                    share = est / last if est is not None and last else None
                rows.append({"case": case, "nu": nu, "target": target, "status": r["status"],
                             "cycles": totals["cycles"], "dofs": s.get("dofs"), "newton": totals["newton_iterations"],
                             "changes": totals["contact_changes"], "wall": r["wall"], "walls": r["walls"],
                             "loop": totals["seconds"], "estimate": est, "estimate_complete": totals["estimate_complete"],
                             "share": share, "F": F, "eta": eta,
                             "eta_rel": eta / abs(F) if eta is not None and F else None,
                             "true": rel, "noise": noise,
                             "effectivity": eta / (ref[0] - F) if eta is not None and F is not None and ref and
                             ref[0] != F else None,
                             "target_met_flowform": totals["target_met"],
                             "within": None if rel is None else abs(rel) <= target, "same": r["same"]})
            ref = bench.reference(case, nu)
            print(f"\n{case}, ν = {nu:g} (F_ref = {fmt(ref and ref[0], '{:g}')} ± {fmt(ref and ref[1], '{:g}')}, "
                  f"relative ± {fmt(ref and ref[1] / ref[0], '{:.1e}')}):\n")
            body = []
            for r in rows:
                mark = "" if r["estimate_complete"] else " †"
                body.append([f"{r['target']:g}", ",".join(map(str, r["status"])), fmt(r["cycles"], "{}"),
                             fmt(r["dofs"], "{}"), fmt(r["newton"], "{}"), fmt(r["wall"], "{:.2f}"),
                             fmt(r["loop"], "{:.2f}"), fmt(r["estimate"], "{:.2f}") + mark,
                             fmt(r["share"] and 100 * r["share"], "{:.0f} %") + mark, fmt(r["F"], "{:.5f}"),
                             fmt(r["eta_rel"], "{:+.1e}"), error_cell(r["true"], r["noise"]),
                             fmt(r["effectivity"], "{:.2f}") + (" (noise)" if r["noise"] and r["effectivity"] is not None
                                                                else ""),
                             "-" if r["within"] is None else ("yes" if r["within"] else "no")])
            print(markdown(["target", "exit", "cycles", "dofs (last)", "Newton (all cycles)", "wall s", "loop s",
                            "estimate s", "estimate share", "F", "η/F", "true rel. error", "effectivity",
                            "true ≤ target"], body, align="---:"))
            errors = [abs(r["true"]) for r in rows if r["true"] is not None]
            if len(errors) > 1:
                monotone = all(b <= a_ for a_, b in zip(errors, errors[1:]))
                targets = ", ".join("%g" % r["target"] for r in rows if r["true"] is not None)
                print(f"true error over the targets {targets}: "
                      f"{' → '.join(f'{e:.1e}' for e in errors)}: {'monotone' if monotone else 'NOT monotone'}")
            for r in rows:
                for bound, seconds in SPEED_TARGETS:
                    if abs(r["target"] - bound) <= 1e-12:
                        ok = r["within"] and r["wall"] <= seconds
                        print(f"target true error ≤ {bound:g} in ≤ {seconds:g} s asking for {bound:g}: "
                              f"{'met' if ok else 'missed'} (true {error_cell(r['true'], r['noise'])}, "
                              f"{r['wall']:.2f} s)")
            shares = [r["share"] for r in rows if r["share"] is not None]
            if shares:
                print(f"target estimate ≤ {ESTIMATE_SHARE_TARGET:.0%} of the run: "
                      f"{'met' if max(shares) <= ESTIMATE_SHARE_TARGET else 'missed'} (largest share {max(shares):.0%}"
                      + (", of the last cycle †" if not all(r["estimate_complete"] for r in rows) else "") + ")")
            for r in rows:
                if not r["same"]:
                    print(f"note: target {r['target']:g}: the repeats differ in the functionals")
            results["adaptive"] += rows
    if any(not r["estimate_complete"] for r in results["adaptive"]):
        print("\n† summary.json gives the estimate's seconds of the last cycle only (timings.error_estimation); "
              "the share is of the last cycle's seconds (adaptivity.cycles[-1].seconds).")


# ------------------------------------------------------------------------------------------
# (c) the cutting default


def part_cutting(bench, results):
    print("\n## (c) The cutting default (xml/cutting.xml as shipped, with its estimate)\n", flush=True)
    r = bench.run("xml/cutting.xml", "cutting_default", [])
    s = r["summary"]
    t = s.get("timings") or {}
    est = t.get("error_estimation")
    print(markdown(["exit", "dofs", "surface updates", "Newton", "wall s", "total s", "estimate s", "estimate share"],
                   [[",".join(map(str, r["status"])), fmt(s.get("dofs"), "{}"), fmt(s.get("free_surface_iterations"), "{}"),
                     fmt(s.get("newton_iterations"), "{}"), fmt(r["wall"], "{:.2f}"), fmt(t.get("total"), "{:.2f}"),
                     fmt(est, "{:.2f}"), fmt(est / t["total"] * 100 if est is not None and t.get("total") else None,
                                            "{:.0f} %")]], align="---:"))
    values, etas = s.get("functionals") or {}, s.get("functionals_error_estimate") or {}
    refined = (s.get("error_estimation") or {}).get("refined_functionals") or {}
    body = [[name, fmt(v, "{:.6g}"), fmt(etas.get(name), "{:+.3e}"),
             fmt(etas.get(name) / abs(v) * 100 if etas.get(name) is not None and v else None, "{:+.2f} %"),
             fmt(refined.get(name), "{:.6g}")] for name, v in values.items()]
    for key in ("sensitivities", "sensitivities_total_shape"):
        for name, per in (s.get(key) or {}).items():
            for p, v in per.items():
                e = ((s.get(key + "_error_estimate") or {}).get(name) or {}).get(p)
                label = f"d{name}/d{p}" + (" (total)" if key.endswith("total_shape") else "")
                body.append([label, fmt(v, "{:.6g}"), fmt(e, "{:+.3e}"),
                             fmt(e / abs(v) * 100 if e is not None and v else None, "{:+.2f} %"), "-"])
    print(markdown(["response", "value", "η", "relative η", "refined mesh"], body, align="---:"))
    ok = r["status"][0] == 0 and r["wall"] <= CUTTING_SECONDS_TARGET
    print(f"target cutting default with its estimate ≤ {CUTTING_SECONDS_TARGET:g} s: {'met' if ok else 'missed'} "
          f"({r['wall']:.1f} s wall)")
    results["cutting"] = {"status": r["status"], "wall": r["wall"], "walls": r["walls"], "summary_timings": t,
                          "functionals": values, "estimates": etas}


# ------------------------------------------------------------------------------------------


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0], formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog=__doc__.split("\n", 1)[1])
    ap.add_argument("--flowform", default=default_flowform())
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--parts", default="fixed,adaptive,cutting")
    ap.add_argument("--cases", default="plane,axisym")
    ap.add_argument("--nu", default="0.1")
    ap.add_argument("--large", action="store_true")
    ap.add_argument("--meshes", help="H:HC,... instead of the issue's list")
    ap.add_argument("--targets", help="comma-separated relative targets (default 0.01,0.005,0.002,0.001,0.0005)")
    ap.add_argument("--reference", action="append", type=parse_reference, default=[])
    ap.add_argument("--workdir", default="/tmp/flowform_accuracy_per_second")
    ap.add_argument("--timeout", type=float, default=3600)
    ap.add_argument("--json", help="every row as JSON (default WORKDIR/accuracy_per_second.json)")
    ap.add_argument("--set", action="append", default=[], metavar="P=V",
                    help="a case parameter for every run (e.g. 'Error Estimation/Nested Start=false')")
    a = ap.parse_args()

    a.flowform = launcher.require_executable(a.flowform, "accuracy_per_second.py")
    a.parts = [p for p in a.parts.split(",") if p]
    a.cases = [c for c in a.cases.split(",") if c]
    for p in a.parts:
        if p not in ("fixed", "adaptive", "cutting"):
            ap.error(f"unknown part '{p}' (fixed, adaptive, cutting)")
    for c in a.cases:
        if c not in CASES:
            ap.error(f"unknown case '{c}' ({', '.join(CASES)})")
    if a.repeat < 1:
        ap.error("--repeat must be >= 1")
    try:
        a.nu = [float(v) for v in a.nu.split(",") if v]
        a.meshes = ([parse_mesh(m) for m in a.meshes.split(",") if m] if a.meshes else
                    MESHES[:2] if a.quick else MESHES + (LARGE_MESHES if a.large else []))
        a.targets = ([float(t) for t in a.targets.split(",") if t] if a.targets else
                     TARGETS[:2] if a.quick else TARGETS)
    except ValueError as e:
        ap.error(str(e))
    if a.quick:
        a.repeat = 1
    a.references = dict(REFERENCES)
    a.references.update(dict(a.reference))
    for c in a.cases:
        for nu in a.nu:
            if (c, nu) not in a.references:
                print(f"note: no reference for {c} at ν = {nu:g}: no true errors (give --reference)")
    os.makedirs(a.workdir, exist_ok=True)

    info = machine_info()
    info["binary_built"] = binary_built(a.flowform)
    print("# flowform accuracy per second (issue #26)")
    print(f"binary {a.flowform} (built {info['binary_built']}; commit of the work tree {info.get('commit')}); "
          f"{info.get('date')}; {info.get('Model name')} × {info.get('CPU(s)')}, {info.get('memory')}; "
          f"load {load():.2f}; {a.repeat} repeat(s), seconds are medians")
    bench = Bench(a)
    results = {"machine": info, "fixed": [], "adaptive": [], "cutting": None}
    if "fixed" in a.parts:
        part_fixed(bench, results)
    if "adaptive" in a.parts:
        part_adaptive(bench, results)
    if "cutting" in a.parts:
        part_cutting(bench, results)
    path = a.json or os.path.join(a.workdir, "accuracy_per_second.json")
    with open(path, "w") as f:
        json.dump(results, f, indent=1, default=str)
    print(f"\nrows: {path}")
    statuses = [s for r in results["fixed"] + results["adaptive"] for s in r["status"]]
    statuses += (results["cutting"] or {}).get("status", [])
    return 0 if all(s == 0 for s in statuses) else 1


if __name__ == "__main__":
    sys.exit(main())
