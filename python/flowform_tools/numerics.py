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


def extrapolate_three(hs, vs):
    """(v_inf, p, monotone) from the last three (h, v) of a mesh sequence (any ratios): the
    Richardson extrapolation v_3 + (v_3 − v_2)/((h_2/h_3)^p − 1) with the observed order p solved
    from the three values and clamped to [0.5, 2]; p = 1 and monotone = False when the
    differences change sign or do not shrink (bench/cutting_bench.py, bench/rolling_bench.py)."""
    (h1, h2, h3), (v1, v2, v3) = hs[-3:], vs[-3:]
    d1, d2 = v2 - v1, v3 - v2
    monotone = d1 * d2 > 0 and abs(d2) < abs(d1)
    r1, r2 = h1 / h2, h2 / h3
    p = 1.0
    if monotone:
        # |d1|/|d2| = (h1^p - h2^p)/(h2^p - h3^p): solved by bisection on p in [0.5, 2].
        target = abs(d1) / abs(d2)
        lo, hi = 0.5, 2.0
        ratio = lambda q: (h1 ** q - h2 ** q) / (h2 ** q - h3 ** q)  # noqa: E731
        if ratio(lo) >= target:
            p = lo
        elif ratio(hi) <= target:
            p = hi
        else:
            for _ in range(60):
                mid = 0.5 * (lo + hi)
                lo, hi = (mid, hi) if ratio(mid) < target else (lo, mid)
            p = 0.5 * (lo + hi)
    return v3 + d2 / (r2 ** p - 1.0), p, monotone
