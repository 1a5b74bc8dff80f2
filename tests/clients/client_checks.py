"""The failure bookkeeping shared by the client check scripts (check_meshio.py,
check_vtu_clients.py): each failed check is printed at once and counted."""

failures = []


def check(condition, message):
    """Records and prints message when condition is false; returns condition."""
    if not condition:
        failures.append(message)
        print("FAIL:", message)
    return condition


def exit_code(what):
    """The summary line of a script whose checks are called `what`, and its exit code."""
    if failures:
        print(f"{len(failures)} check(s) failed")
        return 1
    print(f"all {what} checks passed")
    return 0
