"""What the whole-run checks under tests/regression/ share: one line per check, the verdict, and
the test for plots that were drawn.

    failed += checks.check(value < bound, f"what was measured: {value}")
    ...
    return checks.verdict(failed)        # prints PASSED or FAILED; the exit status
"""
import os


def check(ok, text):
    """Prints 'ok' or 'FAIL' before the text; 0 or 1 to add to the count of failures."""
    print(f"{'ok  ' if ok else 'FAIL'} {text}")
    return 0 if ok else 1


def verdict(failed):
    """Prints PASSED or FAILED; the script's exit status (1 when anything failed)."""
    print("FAILED" if failed else "PASSED")
    return 1 if failed else 0


def pictures_drawn(paths, min_bytes=10000):
    """Whether every PNG exists and is larger than min_bytes (an empty figure is a few kB)."""
    return all(os.path.isfile(p) and os.path.getsize(p) > min_bytes for p in paths)
