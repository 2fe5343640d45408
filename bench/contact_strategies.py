"""Contact statuses: complementarity against the paper's loop (issue #26 part 1).

Runs every scene twice, with Contact/Status Update = Complementarity (the default) and = Certain
Iterate (the paper's pressure-sign loop, one change at a time read from certain Newton iterates),
and prints per scene the responses of both, their difference, their error estimates
(summary.json functionals_error_estimate, where the run estimates) and whether
|F_C − F_CI| ≤ |η_C| + |η_CI| (the strategies agree within the estimated discretization error);
the Newton iterations (all adaptive cycles added up), contact changes, flow solves, wall
seconds, exit status, whether the complementarity run fell back to the status loop (its
warning in the log) and u·n on the die face of the die-lip node (≈ 0: the face holds the lip;
about the exit speed: the lip slides along the land, the open corner); and where the final contact statuses differ (boundary_<wall>.csv
contact_status of both runs, each node's status held up to the midpoints to its neighbours,
compared along the wall's coordinate).

Scenes (--scenes, default all):
  plane-adaptive, plane-fixed, axisym-adaptive, axisym-fixed
      xml/extrusion.xml and xml/extrusion_axisym.xml at every ν of --nus (Friction Coefficient
      of all contact walls), with the shipped adaptivity (target 0.5 % on the ram force) and
      on the case's own mesh (Adaptivity/Enabled=false, the paper's mesh; no estimate);
  cycling-plane, cycling-axisym (not in the default list)
      the cases whose die-land nodes cycled under the status loop (exit 3 before): the
      extrusion at h = 0.2 with Rate Exponent = 1, Strain Rate Cutoff = 1e-2 or Yield Stress = 0,
      and ν = 1 and 2 on all walls, each with the shipped adaptivity;
  separation
      xml/extrusion_separation.xml as shipped (die land: Released Nodes = Free Surface, which
      keeps discrete statuses under both strategies; the container and die face differ);
  cutting
      xml/cutting.xml as shipped (slow: --skip-cutting).

usage:
  scripts/python bench/contact_strategies.py [FLOWFORM] [--nus 0,0.05,0.1,0.2,0.3,0.5]
        [--scenes plane-fixed,axisym-fixed,...] [--skip-cutting] [--out DIR] [--json OUT.json]
        [--timeout S]
        [--only LABEL-TEXT] [--strategies Complementarity]
  scripts/python bench/contact_strategies.py --report OUT.json [MORE.json ...]

Runs are kept in --out (default /tmp/contact_strategies), <scene>_nu<ν>_<strategy>/ with
flowform.log; everything in OUT/contact_strategies.json (rewritten after each pair). Needs
Debian's /usr/bin/python3. Exit status 0 when every run exited 0.
"""
import argparse
import json
import os
import sys

from flowform_tools import csvio, default_flowform, launcher, repo_path, tables
from flowform_tools.case import FIXED_MESH, Case
from flowform_tools.machine import binary_built, load, machine_info

STRATEGIES = ("Complementarity", "Certain Iterate")
SHORT = {"Complementarity": "C", "Certain Iterate": "CI"}
FALLBACK_TEXT = "Newton with the complementarity walls did not converge"
DEFAULT_NUS = "0,0.05,0.1,0.2,0.3,0.5"
SCENES = ("plane-adaptive", "plane-fixed", "axisym-adaptive", "axisym-fixed", "separation", "cutting",
          "cycling-plane", "cycling-axisym")
#: The cases whose die-land nodes cycled between active and free under the status loop (exit 3
#: before the complementarity, issue #26): with the shipped adaptivity, cycle 0 on h = 0.2.
CYCLING = (("n=1", ["Mesh/Geo Parameters/h=0.2", "Material/Rate Exponent=1"]),
           ("e0=1e-2", ["Mesh/Geo Parameters/h=0.2", "Material/Strain Rate Cutoff=1e-2"]),
           ("σ0=0", ["Mesh/Geo Parameters/h=0.2", "Material/Yield Stress=0"]),
           ("ν=1", "nu=1"), ("ν=2", "nu=2"))
EXTRUSION = {"plane": "xml/extrusion.xml", "axisym": "xml/extrusion_axisym.xml"}
#: F_inf of the ram force (the open-lip model's mesh limit, docs/BENCHMARKS.md §10), per (case, ν).
REFERENCES = {("plane", 0.0): 3.30663, ("plane", 0.1): 3.73325, ("plane", 0.3): 4.3595,
              ("axisym", 0.0): 18.2239, ("axisym", 0.1): 23.10283, ("axisym", 0.3): 26.646}


def friction_sets(case, nu):
    return [f"Boundary Conditions/{w}/Friction Coefficient={launcher.lit(nu)}" for w in case.contact_walls()]


def scene_runs(scenes, nus):
    """(scene, label, case file, --set overrides) of every pair to run, in order."""
    out = []
    for scene in scenes:
        if scene in ("separation", "cutting"):
            path = repo_path("xml", "extrusion_separation.xml" if scene == "separation" else "cutting.xml")
            out.append((scene, scene, path, []))
            continue
        if scene.startswith("cycling-"):
            kind = scene.split("-")[1]
            path = repo_path(EXTRUSION[kind])
            for label, sets in CYCLING:
                if isinstance(sets, str):
                    sets = friction_sets(Case(path), float(sets.split("=")[1]))
                out.append((scene, f"{kind} {label}", path, sets))
            continue
        kind, mode = scene.split("-")
        path = repo_path(EXTRUSION[kind])
        case = Case(path)
        for nu in nus:
            sets = friction_sets(case, nu) + (FIXED_MESH if mode == "fixed" else [])
            out.append((scene, f"{scene} ν={nu:g}", path, sets))
    return out


# ------------------------------------------------------------------------------------------
# One run and what it wrote


def wall_statuses(outdir, walls):
    """Per wall: the nodes along it (s, x, y, u_n, p, contact_status), sorted by s; None if the
    CSV is absent."""
    out = {}
    for w in walls:
        cols = csvio.columns(outdir, w, missing_ok=True)
        if cols is None or "contact_status" not in cols:
            continue
        order = sorted(range(len(cols["s"])), key=lambda i: cols["s"][i])
        out[w] = {k: [cols[k][i] for i in order] for k in ("s", "x", "y", "u_n", "p", "contact_status")}
    return out


def run_one(flowform, path, outdir, sets, strategy, timeout):
    os.makedirs(outdir, exist_ok=True)
    log_path = os.path.join(outdir, "flowform.log")
    load_before = load()
    r = launcher.run(flowform, path, outdir, sets + [f"Contact/Status Update={strategy}"], quiet=True,
                     log=log_path, timeout=timeout)
    s = r.summary or {}
    cycles = (s.get("adaptivity") or {}).get("cycles") or []
    newton = sum(c.get("newton_iterations", 0) for c in cycles) if cycles else s.get("newton_iterations")
    changes = sum(c.get("contact_changes", 0) for c in cycles) if cycles else s.get("contact_changes")
    with open(log_path, errors="replace") as f:
        log_text = f.read()
    walls = Case(path).contact_walls()
    return {
        "strategy": strategy, "status": "timeout" if r.timed_out else r.status, "wall": r.wall,
        "load": [load_before, load()], "dofs": s.get("dofs"), "cycles": len(cycles) or 1,
        "newton": newton, "newton_last": s.get("newton_iterations"), "contact_changes": changes,
        "solves_last": (s.get("solves") or {}).get("newton_iterations"),
        "free_surface_iterations": s.get("free_surface_iterations"),
        "functionals": s.get("functionals") or {}, "estimates": s.get("functionals_error_estimate") or {},
        "fallback": FALLBACK_TEXT in log_text, "message": s.get("message", ""),
        "statuses": wall_statuses(outdir, walls) if r.status == 0 else {},
    }


# ------------------------------------------------------------------------------------------
# Comparisons


def lip_un(statuses):
    """u·n on the die face of the die-lip node (the end shared by the last two walls in flow
    order, as bench/extrusion_bench.py reads it): ≈ 0 when the face holds the lip, about the exit
    speed when the lip node is free on the face (the open corner's leak); None without both walls."""
    walls = [w for w in statuses]
    if len(walls) < 2:
        return None
    a, b = statuses[walls[-2]], statuses[walls[-1]]
    ends_b = {(round(x, 9), round(y, 9)) for x, y in zip(b["x"], b["y"])}
    for x, y, un in zip(a["x"], a["y"], a["u_n"]):
        if (round(x, 9), round(y, 9)) in ends_b:
            return un
    return None


def coordinate(nodes):
    """The coordinate that varies along a wall: 'x' or 'y'."""
    span = lambda k: max(nodes[k]) - min(nodes[k])  # noqa: E731
    return "x" if span("x") >= span("y") else "y"


def held_intervals(nodes, c):
    """[(lo, hi, status)]: each node's status held from the midpoint to its previous neighbour to
    the midpoint to its next (along coordinate c; the wall's ends close the first and last)."""
    xs, st = nodes[c], nodes["contact_status"]
    order = sorted(range(len(xs)), key=lambda i: xs[i])
    xs = [xs[i] for i in order]
    st = [st[i] for i in order]
    mids = [0.5 * (a + b) for a, b in zip(xs, xs[1:])]
    lo = [xs[0]] + mids
    hi = mids + [xs[-1]]
    return [(lo[i], hi[i], st[i]) for i in range(len(xs))]


def status_at(intervals, x):
    for lo, hi, s in intervals:
        if lo <= x <= hi:
            return s
    return None


def status_differences(a, b):
    """Per wall: the ranges of the wall's coordinate where the statuses of runs a and b differ,
    [(lo, hi, status_a, status_b)], each range merged from consecutive differing pieces."""
    out = {}
    for w in sorted(set(a) & set(b)):
        c = coordinate(a[w])
        ia, ib = held_intervals(a[w], c), held_intervals(b[w], c)
        cuts = sorted({v for lo, hi, _ in ia + ib for v in (lo, hi)})
        ranges = []
        for lo, hi in zip(cuts, cuts[1:]):
            if hi - lo <= 1e-12:
                continue
            mid = 0.5 * (lo + hi)
            sa, sb = status_at(ia, mid), status_at(ib, mid)
            if sa == sb:
                continue
            if ranges and abs(ranges[-1][1] - lo) < 1e-12 and ranges[-1][2:] == (sa, sb):
                ranges[-1] = (ranges[-1][0], hi, sa, sb)
            else:
                ranges.append((lo, hi, sa, sb))
        out[w] = {"coordinate": c, "ranges": ranges}
    return out


def values_in(nodes, c, lo, hi, key):
    """(min, max) of column key over the nodes whose held interval meets [lo, hi]; None if none."""
    xs = sorted(nodes[c])
    v = [val for x, val in sorted(zip(nodes[c], nodes[key]))]
    mids = [0.5 * (a + b) for a, b in zip(xs, xs[1:])]
    own = [(([xs[0]] + mids)[i], (mids + [xs[-1]])[i]) for i in range(len(xs))]
    picked = [v[i] for i, (a, b) in enumerate(own) if b > lo + 1e-12 and a < hi - 1e-12]
    return (min(picked), max(picked)) if picked else None


def contact_zones(nodes):
    """The ranges (along the wall's coordinate) of consecutive active nodes, as 'lo–hi'."""
    c = coordinate(nodes)
    pts = sorted(zip(nodes[c], nodes["contact_status"]))
    zones, start, prev = [], None, None
    for x, s in pts:
        if s == 1 and start is None:
            start = x
        if s != 1 and start is not None:
            zones.append((start, prev))
            start = None
        prev = x
    if start is not None:
        zones.append((start, prev))
    return c, zones


def compare(pair):
    c, ci = pair["runs"]["Complementarity"], pair["runs"]["Certain Iterate"]
    rows = {}
    for name in sorted(set(c["functionals"]) & set(ci["functionals"])):
        fc, fci = c["functionals"][name], ci["functionals"][name]
        ec, eci = c["estimates"].get(name), ci["estimates"].get(name)
        diff = fc - fci
        bound = abs(ec) + abs(eci) if ec is not None and eci is not None else None
        rows[name] = {"C": fc, "CI": fci, "diff": diff, "rel": diff / max(abs(fci), 1e-300),
                      "eta_C": ec, "eta_CI": eci, "bound": bound,
                      "agree": (abs(diff) <= bound) if bound is not None else None}
    pair["comparison"] = rows
    pair["status_differences"] = status_differences(c["statuses"], ci["statuses"])
    return pair


# ------------------------------------------------------------------------------------------
# Tables


def g(v, spec=".5g"):
    return "-" if v is None else format(v, spec)


def ranges_text(diffs):
    parts = []
    for w, d in diffs.items():
        for lo, hi, sa, sb in d["ranges"]:
            parts.append(f"{w} {d['coordinate']} {lo:.4g}–{hi:.4g} (C {int(sa)}, CI {int(sb)})")
    return "; ".join(parts) if parts else "none"


def print_tables(data, out=sys.stdout):
    pairs = data["pairs"]
    m = data.get("machine", {})
    print(f"machine: {m.get('Model name', '?')}, {m.get('CPU(s)', '?')} CPUs, {m.get('memory', '?')}; "
          f"date {m.get('date', '?')}; commit {m.get('commit', '?')}; binary built {data.get('binary_built', '?')}",
          file=out)
    print("\n### Runs\n", file=out)
    rows = []
    for p in pairs:
        for strategy in STRATEGIES:
            r = p["runs"].get(strategy)
            if r is None:
                continue
            rows.append([p["label"], SHORT[strategy], str(r["status"]), g(r["dofs"], "d"), str(r["cycles"]),
                         g(r["newton"], "d"), g(r["contact_changes"], "d"), f"{r['wall']:.1f}",
                         f"{r['load'][0]:.1f}/{r['load'][1]:.1f}", "yes" if r["fallback"] else "",
                         g(lip_un(r["statuses"]), ".3g")])
    print(tables.markdown(["scene", "strategy", "exit", "dofs", "cycles", "Newton", "changes", "wall s", "load",
                           "fallback", "lip u_n (face)"], rows), file=out)
    print("\n### Responses\n", file=out)
    rows = []
    for p in pairs:
        for name, v in p.get("comparison", {}).items():
            agree = "-" if v["agree"] is None else ("yes" if v["agree"] else "**no**")
            rows.append([p["label"], name, g(v["C"], ".6g"), g(v["CI"], ".6g"), g(v["diff"], ".3e"),
                         g(v["rel"], ".2e"), g(v["eta_C"], ".2e"), g(v["eta_CI"], ".2e"), agree])
    print(tables.markdown(["scene", "response", "F (C)", "F (CI)", "F_C − F_CI", "rel.", "η_C", "η_CI",
                           "agree within η_C + η_CI"], rows), file=out)
    rows = []
    for p in pairs:
        if not p["scene"].endswith(("-fixed", "-adaptive")):
            continue
        ref = REFERENCES.get((p["scene"].split("-")[0], float(p["label"].split("=")[1])))
        if ref is None:
            continue
        cells = [p["label"], f"{ref:g}"]
        for strategy in STRATEGIES:
            r = p["runs"][strategy]
            f, e = r["functionals"].get("ram_force"), r["estimates"].get("ram_force")
            cells += [g(f, ".6g"), g((f - ref) / ref if f is not None else None, "+.1e"),
                      g(abs(e) / abs(f) if e is not None and f else None, ".1e")]
        rows.append(cells)
    if rows:
        print("\n### Ram force against the references of docs/BENCHMARKS.md §10 (F_inf)\n", file=out)
        print(tables.markdown(["scene", "F_ref", "F (C)", "rel. error C", "abs. η_C / F", "F (CI)", "rel. error CI",
                               "abs. η_CI / F"], rows), file=out)
    print("\n### Where the final statuses differ\n", file=out)
    rows = []
    for p in pairs:
        if "status_differences" in p:
            rows.append([p["label"], ranges_text(p["status_differences"])])
    print(tables.markdown(["scene", "ranges (wall, coordinate, status C/CI; 1 active, 0 free)"], rows), file=out)
    print("\n### p and u·n at the nodes whose statuses differ (min … max over each range)\n", file=out)
    rows = []
    span = lambda r: "-" if r is None else f"{r[0]:.3g} … {r[1]:.3g}"  # noqa: E731
    for p in pairs:
        runs = p["runs"]
        for w, d in (p.get("status_differences") or {}).items():
            for lo, hi, sa, sb in d["ranges"]:
                cells = []
                for strategy in STRATEGIES:
                    nodes = runs[strategy]["statuses"][w]
                    cells += [span(values_in(nodes, d["coordinate"], lo, hi, "p")),
                              span(values_in(nodes, d["coordinate"], lo, hi, "u_n"))]
                rows.append([p["label"], f"{w} {d['coordinate']} {lo:.4g}–{hi:.4g}", f"{int(sa)} / {int(sb)}"] + cells)
    print(tables.markdown(["scene", "range", "status C / CI", "p (C)", "u·n (C)", "p (CI)", "u·n (CI)"], rows), file=out)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("flowform", nargs="?", default=default_flowform())
    ap.add_argument("--nus", default=DEFAULT_NUS)
    ap.add_argument("--scenes", default=",".join(SCENES[:6]))
    ap.add_argument("--skip-cutting", action="store_true")
    ap.add_argument("--out", default="/tmp/contact_strategies")
    ap.add_argument("--json")
    ap.add_argument("--timeout", type=float, default=1800)
    ap.add_argument("--strategies", default=",".join(STRATEGIES),
                    help="run only these (a rerun of one run; --report merges it into the pair)")
    ap.add_argument("--only", help="run only the pairs whose label contains this text (e.g. 'ν=1')")
    ap.add_argument("--report", nargs="+", help="print the tables of earlier JSON files (merged; a later file's "
                    "pair replaces one of the same label), run nothing")
    a = ap.parse_args()
    if a.report:
        data = {"pairs": []}
        for path in a.report:
            with open(path) as f:
                d = json.load(f)
            for p in d["pairs"]:  # a later file's run replaces an earlier one of the same label and strategy
                same = [q for q in data["pairs"] if q["label"] == p["label"]]
                if same:
                    same[0]["runs"].update(p["runs"])
                else:
                    data["pairs"].append(p)
            data.setdefault("machine", d.get("machine"))
            data.setdefault("binary_built", d.get("binary_built"))
        data["pairs"] = [compare(p) if len(p["runs"]) == len(STRATEGIES) else p for p in data["pairs"]]
        print_tables(data)
        return 0
    flowform = launcher.require_executable(a.flowform, "contact_strategies.py")
    scenes = [s for s in a.scenes.split(",") if s]
    unknown = [s for s in scenes if s not in SCENES]
    if unknown:
        raise SystemExit(f"contact_strategies.py: unknown scene(s) {unknown}; known: {', '.join(SCENES)}")
    if a.skip_cutting:
        scenes = [s for s in scenes if s != "cutting"]
    nus = [float(v) for v in a.nus.split(",")]
    os.makedirs(a.out, exist_ok=True)
    json_path = a.json or os.path.join(a.out, "contact_strategies.json")
    data = {"machine": machine_info(), "binary_built": binary_built(flowform), "flowform": flowform, "pairs": []}
    ok = True
    for scene, label, path, sets in scene_runs(scenes, nus):
        if a.only and a.only not in label:
            continue
        pair = {"scene": scene, "label": label, "case": os.path.relpath(path, repo_path()), "sets": sets, "runs": {}}
        for strategy in [t for t in STRATEGIES if t in a.strategies.split(",")]:
            outdir = os.path.join(a.out, label.replace(" ", "_").replace("ν=", "nu") + "_" + SHORT[strategy])
            r = run_one(flowform, path, outdir, sets, strategy, a.timeout)
            pair["runs"][strategy] = r
            ok = ok and r["status"] == 0
            print(f"{label:24} {SHORT[strategy]:3} exit {r['status']} {r['wall']:7.1f} s Newton {r['newton']} "
                  f"changes {r['contact_changes']} F {r['functionals']}", flush=True)
        data["pairs"].append(compare(pair) if len(pair["runs"]) == len(STRATEGIES) else pair)
        with open(json_path + ".tmp", "w") as f:
            json.dump(data, f, indent=1)
        os.replace(json_path + ".tmp", json_path)
    print_tables(data)
    print(f"\nJSON: {json_path}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
