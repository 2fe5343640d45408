"""summary.json, the stable machine-readable result of a flowform run (docs/theory.md §5).

    s = summary.load(outdir)            # None when the run wrote none (bad input)
    s["converged"], s.at("linear_solver.factorizations"), s.at("timings.solve", 0.0)
    s.functional("ram_force")

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
