"""Markdown tables for the benchmarks' reports (docs/BENCHMARKS.md takes them as printed)."""


def markdown(header, rows, align="---"):
    """A markdown table: the header's cells, then one line per row (cells already formatted as
    text). align is the separator of every column ("---:" right-aligns)."""
    out = "| " + " | ".join(header) + " |\n|" + "|".join(align for _ in header) + "|\n"
    for r in rows:
        out += "| " + " | ".join(r) + " |\n"
    return out


def fmt(v, form="{:.3g}"):
    """A table cell: "-" for None, a string as it is, a number by `form`."""
    if v is None:
        return "-"
    if isinstance(v, str):
        return v
    return form.format(v)
