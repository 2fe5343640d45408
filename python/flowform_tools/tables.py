"""Markdown tables for the benchmarks' reports (docs/BENCHMARKS.md takes them as printed)."""


def markdown(header, rows, align="---"):
    """A markdown table: the header's cells, then one line per row (cells already formatted as
    text). align is the separator of every column ("---:" right-aligns)."""
    out = "| " + " | ".join(header) + " |\n|" + "|".join(align for _ in header) + "|\n"
    for r in rows:
        out += "| " + " | ".join(r) + " |\n"
    return out
