"""tests/benchmarks/minimum_overturning_table.py end to end (its four spectra, seconds), so that it
cannot rot and docs/validation.md's table cannot drift from what it prints.

Against $BLOCKFRAG with --markdown: exit 0; a row per pulse and omega_p / p = 1, 2, 3; every minimum
found to its tolerance (no state in a cell) and the refined one at or below the map's lowest onset
(within that tolerance, 1e-3); the same numbers as the table under "Published results" in
docs/validation.md, to the refinement's tolerance; the stamp line (tests/benchmarks/markdown_stamp.py)
last; nothing left in its temporary folder. Prints "N passed, M failed" last; exits non-zero on any
failure.
"""

import os
import subprocess
import sys
import tempfile
from pathlib import Path

SOURCE = Path(os.environ.get("BLOCKFRAG_SOURCE_DIR", Path(__file__).resolve().parents[2]))
sys.path.insert(0, str(SOURCE / "tests" / "support"))
from script_checks import check, summary  # noqa: E402  (tests/support is not a package)
SCRIPT = SOURCE / "tests" / "benchmarks" / "minimum_overturning_table.py"
BLOCKFRAG = os.environ["BLOCKFRAG"]
TOLERANCE = 1e-3  # the refinement's default, relative


def table_rows(lines):
    """The first markdown table in lines as a list of lists of cells, the header first."""
    table = []
    for line in lines:
        if line.startswith("|"):
            table.append([cell.strip() for cell in line.strip().strip("|").split("|")])
        elif table:
            break
    assert len(table) >= 2 and set(table[1]) == {"---"}, lines
    return [table[0]] + table[2:]


def documented_table(header):
    """The table of docs/validation.md whose header is header."""
    lines = (SOURCE / "docs" / "validation.md").read_text().split("\n")
    start = next(i for i, line in enumerate(lines)
                 if line.startswith("|") and [c.strip() for c in line.strip().strip("|").split("|")] == header)
    return table_rows(lines[start:])


def main():
    with tempfile.TemporaryDirectory() as scratch:
        environment = dict(os.environ, TMPDIR=scratch)
        run = subprocess.run([sys.executable, str(SCRIPT), "--blockfrag", BLOCKFRAG, "--markdown"],
                             capture_output=True, text=True, timeout=600, env=environment)
        left = list(Path(scratch).iterdir())

    def exits_0():
        assert run.returncode == 0, run.stderr[-2000:]

    def a_row_per_pulse_and_frequency():
        rows = table_rows(run.stdout.splitlines())[1:]
        assert [(row[0], row[1]) for row in rows] == [(pulse, w) for pulse in ("one-sine", "one-cosine")
                                                      for w in ("1", "2", "3")], run.stdout

    def refined_at_or_below_the_maps_onset():
        for row in table_rows(run.stdout.splitlines())[1:]:
            values = [float(cell) for cell in row[2:]]  # a cell with a state is not a number
            for onset, refined in (values[0:2], values[2:4]):
                assert 0.9 < refined <= onset * (1 + TOLERANCE), row

    def the_documented_numbers():
        printed = table_rows(run.stdout.splitlines())
        documented = documented_table(printed[0])
        assert len(documented) == len(printed), documented
        for mine, theirs in zip(printed[1:], documented[1:]):
            assert mine[:2] == theirs[:2], (mine, theirs)
            for a, b in zip(mine[2:], theirs[2:]):
                assert abs(float(a) - float(b)) <= TOLERANCE * float(b), (mine, theirs)

    def stamped():
        version = subprocess.run([BLOCKFRAG, "--version"], capture_output=True, text=True).stdout.split()[1]
        last = run.stdout.strip().splitlines()[-1]
        assert last.startswith(f"Measured with blockfrag {version} on {os.cpu_count()} cores, "), last
        assert "by `/usr/bin/python3 tests/benchmarks/minimum_overturning_table.py --blockfrag " in last, last
        assert last.endswith(" --markdown`."), last

    def temporary_folder_removed():
        assert left == [], left

    check("exits 0", exits_0)
    check("a row per pulse and frequency", a_row_per_pulse_and_frequency)
    check("every minimum found, the refined one at or below the map's onset", refined_at_or_below_the_maps_onset)
    check("docs/validation.md's numbers", the_documented_numbers)
    check("the stamp line last", stamped)
    check("the temporary folder is removed", temporary_folder_removed)
    return summary()


if __name__ == "__main__":
    sys.exit(main())
