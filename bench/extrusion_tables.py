"""The tables of bench/extrusion_bench.py (markdown): counts, seconds, work–precision and mass
leak of one case, from the rows extrusion_bench.py builds (or reads back with --report).
Imported by extrusion_bench.py, which has put python/ on the path."""
import math
import sys

from flowform_tools.tables import fmt, markdown


def count_table(rows):
    header = ["h", "dofs", "exit", "F (ram_force)", "Newton", "Newton 1st solve", "Newton in re-solves",
              "flow solves", "Newton/re-solve mean, median (max)", "factorizations", "contact changes"]
    body = []
    for r in rows:
        body.append([fmt(r["h"], "{:g}"), fmt(r["dofs"], "{}"), ",".join(str(s) for s in r["status"]),
                     fmt(r["ram_force"], "{:.5f}"), fmt(r["newton"], "{}"), fmt(r["first_solve_newton"], "{}"),
                     fmt(r["resolve_newton_total"], "{}"),
                     fmt(r["solves"], "{}") + (f" ({r['restarts']} restarted)" if r["restarts"] else ""),
                     (fmt(r["resolve_newton_mean"], "{:.1f}") + ", " + fmt(r["resolve_newton_median"], "{:g}") +
                      " (" + fmt(r["resolve_newton_max"], "{}") + ")"),
                     fmt(r["factorizations"], "{}"), fmt(r["contact_changes"], "{}")])
    return markdown(header, body)


def time_table(rows):
    header = ["h", "setup", "asm_res", "asm_jac", "fact", "fact/call ms", "linsolve", "other", "total",
              "fact/total", "peak RSS MiB", "total, each repeat"]
    body = []
    for r in rows:
        other = per_call = None
        if r["solve"] is not None:
            other = r["solve"] - (r["assembly_residual"] + r["assembly_jacobian"] + r["factorization"] +
                                  r["linear_solve"])
        if r["factorization"] is not None and r["factorizations"]:
            per_call = 1e3 * r["factorization"] / r["factorizations"]
        body.append([fmt(r["h"], "{:g}"), fmt(r["setup"], "{:.3g}"), fmt(r["assembly_residual"], "{:.3g}"),
                     fmt(r["assembly_jacobian"], "{:.3g}"), fmt(r["factorization"], "{:.4g}"),
                     fmt(per_call, "{:.3g}"), fmt(r["linear_solve"], "{:.3g}"), fmt(other, "{:.3g}"),
                     fmt(r["total"], "{:.4g}"), fmt(r["fact_share"], "{:.0%}"),
                     fmt(r["rss"] / 2**20 if r["rss"] else None, "{:.0f}"),
                     ", ".join(fmt(t, "{:.3g}") for t in r["total_all"])])
    return markdown(header, body)


def wp_table(rows):
    header = ["h", "dofs", "F", "error vs F_R", "total s (median)", "repeats", "load before/after"]
    body = [[fmt(r["h"], "{:g}"), fmt(r["dofs"], "{}"), fmt(r["ram_force"], "{:.5f}"),
             fmt(r.get("error_richardson"), "{:.2e}"), fmt(r["total"], "{:.4g}"), str(r["repeats"]),
             ", ".join(f"{a:.1f}/{b:.1f}" for a, b in zip(r["load_before"], r["load_after"]))] for r in rows]
    return markdown(header, body)


def leak_table(rows):
    ref = next((r for r in rows if "leak" in r), None)
    lip = ref.get("lip_wall", "die_face") if ref else "die_face"  # JSON files from before lip_wall: die_face
    others = [w for w in ref["wall_flux"] if w != lip] if ref else []
    header = (["h", "hc", "Q_in", "Q_out", "leak 1 − Q_out/Q_in", "leak / hc", "u_n at die lip",
               f"{lip} flux / Q_in", f"{lip} flux / (hc Q_in)"] + others)
    body = []
    for r in rows:
        if "leak" not in r:
            body.append([fmt(r["h"], "{:g}"), fmt(r["hc"], "{:g}")] + ["-"] * (len(header) - 2))
            continue
        w = r["wall_flux"]
        body.append([fmt(r["h"], "{:g}"), fmt(r["hc"], "{:g}"), fmt(r["q_in"], "{:.5f}"),
                     fmt(r["q_out"], "{:.5f}"), fmt(r["leak"], "{:.4f}"), fmt(r["leak_over_hc"], "{:.3f}"),
                     fmt(r["lip_u_n"], "{:.3f}"), fmt(w[lip], "{:.4f}"), fmt(w[lip] / r["hc"], "{:.3f}")]
                    + [fmt(w[o], "{:.1e}") for o in others])
    return markdown(header, body)


def print_case(case, entry, axisymmetric=False):
    """Every table of one case (axisymmetric: the default when the entry does not say)."""
    rows, wp, title = entry["rows"], entry["richardson"], f"{case} ({entry['case']})"
    print(f"\n### cost, {title}: counts\n\n" + count_table(rows))
    print(f"\n### cost, {title}: seconds (medians over the repeats)\n\n" + time_table(rows))
    print(f"\n### work–precision of the ram force, {title}\n")
    if "F_R" in wp:
        print(f"three finest meshes h = {', '.join(f'{h:g}' for h in wp['h'])}: differences "
              f"{wp['differences'][0]:+.5f}, {wp['differences'][1]:+.5f}; observed order p = {wp['order']:.3f}; "
              f"F_R = {wp['F_R']:.5f}")
        for t in wp.get("triples", []):
            print(f"  triple h = {', '.join(f'{h:g}' for h in t['h'])}: p = {t['order']:.3f}, F_R = {t['F_R']:.5f}")
        print()
    else:
        print(f"no extrapolation: {wp.get('error')}\n")
    print(wp_table(rows))
    print(f"\n### mass leak, {title} (Q over ram / outlet / walls, trapezoid in s"
          f"{', × 2πr (r = x)' if entry.get('axisymmetric', axisymmetric) else ''})\n\n" + leak_table(rows))
    leaks = [(r["h"], r["leak"]) for r in rows if r.get("leak", 0) > 0]
    orders = [math.log(a[1] / b[1]) / math.log(a[0] / b[0]) for a, b in zip(leaks, leaks[1:])]
    if orders:
        print("observed order of the leak between successive meshes: " + ", ".join(f"{q:.2f}" for q in orders))
    built = sorted({b for r in rows for b in r.get("binary_built", [])})
    if len(built) > 1:
        print(f"note: the binary changed during the runs (time stamps {', '.join(built)})")
    sys.stdout.flush()
