"""Small numerical helpers of the verification checks and benchmarks."""
import math


def observed_order(values, ratio=2.0):
    """Orders of convergence from consecutive triples of a sequence computed on meshes
    refined by `ratio` each time: q_j = ln(d_j / d_{j+1}) / ln(ratio), d the differences."""
    d = [b - a for a, b in zip(values, values[1:])]
    return [math.log(abs(d[i] / d[i + 1])) / math.log(ratio) if d[i + 1] != 0 else float("inf")
            for i in range(len(d) - 1)]


def richardson(values, order, ratio=2.0):
    """Richardson extrapolation from the last two values: F + (F − F_prev) / (ratio^order − 1)."""
    return values[-1] + (values[-1] - values[-2]) / (ratio**order - 1.0)


def relative_difference(a, b):
    """|a − b| / max(|a|, |b|) (0 when both vanish)."""
    return abs(a - b) / max(abs(a), abs(b), 1e-300)


def median(values):
    """The median of the values that are not None; None if there are none."""
    import statistics
    values = [v for v in values if v is not None]
    return statistics.median(values) if values else None
