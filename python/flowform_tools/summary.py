"""summary.json, the stable machine-readable result of a flowform run (docs/theory.md §5).

    s = summary.load(outdir)            # None when the run wrote none (bad input)
    s["converged"], s.at("linear_solver.factorizations"), s.at("timings.solve", 0.0)
    s.functional("ram_force")
    summary.adaptive_totals(s)          # cycles, Newton iterations and seconds over the adaptive loop

Summary is a dict (the parsed JSON) with dotted-path access on top. A dotted path splits at
every "."; no key flowform writes contains one (parameter names such as "Rate Exponent" have
spaces, not dots).
"""
import json
import os

_MISSING = object()


def lookup(node, path, default=_MISSING):
    """node[k1][k2]... for path "k1.k2..." (or a list/tuple of keys). Without a default a
    missing key raises KeyError naming the whole path."""
    keys = path.split(".") if isinstance(path, str) else list(path)
    for key in keys:
        if isinstance(node, dict) and key in node:
            node = node[key]
        elif default is _MISSING:
            raise KeyError(f"summary.json has no '{path if isinstance(path, str) else '.'.join(keys)}'")
        else:
            return default
    return node


class Summary(dict):
    """The parsed summary.json of one run."""

    path = None

    def at(self, path, default=_MISSING):
        """The value at a dotted path; default (if given) when any key is missing."""
        return lookup(self, path, default)

    def number(self, *paths):
        """The first of several dotted paths that holds a number (not a bool), else None."""
        for path in paths:
            value = lookup(self, path, None)
            if isinstance(value, (int, float)) and not isinstance(value, bool):
                return value
        return None

    @property
    def converged(self):
        return self.get("converged") is True

    def functional(self, name):
        """functionals[name], the value of one response."""
        return self["functionals"][name]

    def timing(self, key, default=None):
        """timings[key] in seconds (default when absent)."""
        return (self.get("timings") or {}).get(key, default)

    @property
    def parameters(self):
        """The full validated parameter list the run used."""
        return self.get("parameters") or {}


def path_of(outdir_or_file):
    if os.path.isdir(outdir_or_file) or not outdir_or_file.endswith(".json"):
        return os.path.join(outdir_or_file, "summary.json")
    return outdir_or_file


def load(outdir_or_file, missing_ok=True):
    """The Summary in an output directory (or a summary.json path). None when the file is
    absent or not valid JSON and missing_ok; otherwise the error propagates."""
    path = path_of(outdir_or_file)
    try:
        with open(path) as f:
            s = Summary(json.load(f))
    except (OSError, ValueError):
        if missing_ok:
            return None
        raise
    s.path = path
    return s


def _estimate_seconds_of_cycle(cycle):
    """The seconds one adaptive cycle spent in its error estimate, when the cycle entry says
    (a "timings" block or an "estimate_seconds"/"error_estimation_seconds" key); else None."""
    for value in ((cycle.get("timings") or {}).get("error_estimation"), cycle.get("estimate_seconds"),
                  cycle.get("error_estimation_seconds")):
        if isinstance(value, (int, float)) and not isinstance(value, bool):
            return float(value)
    return None


def adaptive_totals(s):
    """What a whole run cost, adaptive or not, from its summary.json (a dict):

      cycles             adaptive cycles done (1 without the adaptive loop)
      newton_iterations  over every cycle (the top-level count is the last cycle's)
      contact_changes    over every cycle
      seconds            the adaptive loop's seconds (adaptivity.seconds), else timings.total
      estimate_seconds   seconds in the error estimate: the sum over the cycles when every
                         cycle entry gives its own, else the last (or only) solve's
                         timings.error_estimation; None when the run did not estimate
      estimate_complete  True when estimate_seconds covers every cycle
      target_met         adaptivity.target_met (None without the adaptive loop)

    The top-level newton_iterations, contact_changes and timings of an adaptive run are its
    last cycle's; the cycles' entries (adaptivity.cycles) carry the rest."""
    s = s or {}
    timings = s.get("timings") or {}
    adaptivity = s.get("adaptivity") or {}
    cycles = adaptivity.get("cycles") or []
    last_estimate = timings.get("error_estimation")
    if last_estimate is None:
        last_estimate = (s.get("error_estimation") or {}).get("seconds")
    if not s.get("functionals_error_estimate"):
        last_estimate = None
    if cycles:
        per_cycle = [_estimate_seconds_of_cycle(c) for c in cycles]
        complete = all(v is not None for v in per_cycle)
        return {"cycles": len(cycles),
                "newton_iterations": sum(c.get("newton_iterations") or 0 for c in cycles),
                "contact_changes": sum(c.get("contact_changes") or 0 for c in cycles),
                "seconds": adaptivity.get("seconds", timings.get("total")),
                "estimate_seconds": sum(per_cycle) if complete else last_estimate,
                "estimate_complete": complete or len(cycles) == 1,
                "target_met": adaptivity.get("target_met")}
    return {"cycles": 1 if s else 0, "newton_iterations": s.get("newton_iterations"),
            "contact_changes": s.get("contact_changes"), "seconds": timings.get("total"),
            "estimate_seconds": last_estimate, "estimate_complete": True, "target_met": None}
