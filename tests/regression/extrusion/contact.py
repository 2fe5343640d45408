"""Contact criteria after the paper's status loop (docs/extrusion_verification.md §1): the runs
select it (Contact/Status Update = Certain Iterate), whose criteria (p, u·n) these are."""
from .common import contact_state, mesh_list


def cmd_contact(runner, args, checks):
    """Contact criteria after converged runs (ν = 0 and 0.1), and a run stopped early."""
    h = mesh_list(args.meshes, "0.1")[0]
    loop = ["Contact/Status Update=Certain Iterate"]
    runs = runner.run_all([(f"h = {h}, nu = {nu}", dict(name=f"contact_nu{nu}", h=h, nu=nu, sets=loop))
                           for nu in (0.0, 0.1)]
                          + [("h = 0.2, nu = 0.1, Max Status Changes = 0",
                              dict(name="contact_stopped", h=0.2, nu=0.1, sets=loop + ["Contact/Max Status Changes=0"],
                                   expect_failure=True))],
                          checks)
    for run in runs[:2]:
        if not checks.check(run.converged, f"{run.label}: converged (exit 0)"):
            continue
        contact = run.params["Contact"]
        ptol, utol, cap = contact["Pressure Tolerance"], contact["Penetration Tolerance"], contact["Max Status Changes"]
        changes = run.summary["contact_changes"]
        checks.check(isinstance(changes, int) and 0 <= changes < cap,
                     f"{run.label}: the status loop ended after {changes} change(s) (< Max Status Changes = {cap})")
        violations, ambiguous, counts = contact_state(run, ptol, utol, runner.walls)
        for v in violations:
            print("        " + v)
        checks.check(not violations, f"{run.label}: active p >= -{ptol:g} and free u_n <= {utol:g} on all "
                                     f"{sum(c['active'] + c['free'] for c in counts.values())} wall nodes "
                                     f"({len(violations)} violations)")
        checks.record(f"status_{run.name}", counts)
        for a in ambiguous:
            checks.note(f"{run.label}: {a}")
        container = run.wall(runner.walls[0])
        checks.check(all(r["contact_status"] == 1.0 and r["p"] > 0 for r in container),
                     f"{run.label}: the billet is pressed against the whole {runner.walls[0]} (all active, p > 0)")
    stopped = runs[2]
    checks.check(stopped.status == 3 and stopped.summary is not None and stopped.summary["converged"] is False,
                 f"{stopped.label}: exit 3, converged false")
    if stopped.summary is not None:
        contact = stopped.params["Contact"]
        violations, _, _ = contact_state(stopped, contact["Pressure Tolerance"], contact["Penetration Tolerance"],
                                         runner.walls)
        checks.check(len(violations) > 0,
                     f"negative control: the criterion check finds the unsettled nodes of the stopped run "
                     f"({len(violations)}; first: {violations[0] if violations else '-'})")


COMMANDS = {"contact": cmd_contact}
