"""Checks of the host-comparison tests (tests/debian13, tests/pymeshlab): each check prints PASS or
FAIL with what it compared; verdict() prints the count and gives the exit status."""
failures = []


def check(cond, what):
    print(("PASS " if cond else "FAIL ") + what, flush=True)
    if not cond:
        failures.append(what)
    return cond


def max_diff(a, b):
    return max((abs(x - y) for x, y in zip(a, b)), default=0.0)


def verdict():
    print("%d check(s) failed" % len(failures))
    return 1 if failures else 0
