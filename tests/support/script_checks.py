"""The Python script tests' tally: each check runs, a failure is reported with its traceback and
counted, and the next check runs; summary() prints the "N passed, M failed" line CTest's output is
read for and gives the exit code."""

import sys
import traceback

_passed = 0
_failed = 0


def check(name, function):
    global _passed, _failed
    try:
        function()
        _passed += 1
    except Exception:  # noqa: BLE001  (every failure is reported and counted, then the next check runs)
        _failed += 1
        print(f"FAIL: {name}", file=sys.stderr)
        traceback.print_exc()


def summary():
    """Prints the tally; the exit code: 0 when every check passed."""
    print(f"{_passed} passed, {_failed} failed")
    return 0 if _failed == 0 else 1
