"""The line a benchmark script prints under a table of measured figures with --markdown: which
blockfrag measured it, on what machine, and the command that prints the table again.

    Measured with blockfrag 0.2.0 on 2 cores, load average 1.52 before and 1.80 after, by
    `/usr/bin/python3 tests/benchmarks/chunk_service.py --markdown`.

docs/performance.md, docs/accuracy.md and docs/validation.md put it under each such table as the
script prints it; tests/cli/docs_stamps_test.py checks that each carries the version of
CMakeLists.txt's project() (or says plainly which older version measured it). A timed figure is
only comparable with another taken on the same machine under the same load, so the stamp gives
both.
"""

import os
import re
import shlex
import subprocess
import sys
from pathlib import Path

SOURCE = Path(__file__).resolve().parents[2]


def blockfrag_version(executable):
    """The version `blockfrag --version` prints ("blockfrag 0.2.0 (commit ...)" -> "0.2.0")."""
    printed = subprocess.run([str(executable), "--version"], capture_output=True, text=True,
                             check=True, timeout=60).stdout
    found = re.match(r"blockfrag (\S+)", printed)
    if found is None:
        raise RuntimeError(f"{executable} --version printed {printed.strip()!r}, not 'blockfrag VERSION ...'")
    return found.group(1)


def command_line(argv=None):
    """The command that ran this script, as a reader in the source tree types it: the interpreter
    as /usr/bin/python3 and every path under the source tree relative to it."""
    argv = sys.argv if argv is None else argv

    def shown(argument):
        path = Path(argument)
        if path.is_absolute() and SOURCE in path.resolve().parents:
            return str(path.resolve().relative_to(SOURCE))
        return argument

    script = Path(argv[0]).resolve()
    words = [str(script.relative_to(SOURCE)) if SOURCE in script.parents else argv[0]]
    return "/usr/bin/python3 " + shlex.join(words + [shown(a) for a in argv[1:]])


class Stamp:
    """Created before the measurement (it reads the load average then); line() after it."""

    def __init__(self, executable, note=""):
        self.version = blockfrag_version(executable)
        self.load_before = os.getloadavg()[0]
        self.note = note

    def line(self, command=None):
        load_after = os.getloadavg()[0]
        note = f" ({self.note})" if self.note else ""
        return (f"Measured with blockfrag {self.version} on {os.cpu_count()} cores, load average "
                f"{self.load_before:.2f} before and {load_after:.2f} after{note}, by "
                f"`{command or command_line()}`.")
