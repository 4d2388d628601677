"""tests/benchmarks/study_throughput.py end to end at its --quick sizes, so that it cannot rot.

Against $BLOCKFRAG as its own baseline on 2 ranks: exit 0, a table with a row per case, the quick
sizes in its scenes column, a number in every cell (medians, rates, memory, ratios), nothing left in
its temporary folder. Against a baseline that refuses every study: "refused" in the old build's
cells with the reason below, and still exit 0; as the build under test, exit 1. An unknown case is
refused up front. With --markdown: the table's columns without the build's label, and under it
only the stamp line (tests/benchmarks/markdown_stamp.py) with the executable's version, the cores
and the command. Prints "N passed, M failed" last; exits non-zero on any failure.
"""

import os
import subprocess
import sys
import tempfile
from pathlib import Path

SOURCE = Path(os.environ.get("BLOCKFRAG_SOURCE_DIR", Path(__file__).resolve().parents[2]))
sys.path.insert(0, str(SOURCE / "tests" / "support"))
from script_checks import check, summary  # noqa: E402  (tests/support is not a package)
SCRIPT = SOURCE / "tests" / "benchmarks" / "study_throughput.py"
BLOCKFRAG = os.environ["BLOCKFRAG"]
QUICK_SCENES = {"grid": 200, "grid_engine": 200, "example1e5": 100, "example1e6": 1000, "record_suite": 20}


def run(scratch, *args):
    environment = dict(os.environ, TMPDIR=str(scratch))
    return subprocess.run([sys.executable, str(SCRIPT), "--blockfrag", BLOCKFRAG, *args], capture_output=True,
                          text=True, timeout=300, env=environment)


def table_rows(stdout):
    """The markdown table as a list of dicts, header names to cells."""
    lines = [line for line in stdout.splitlines() if line.startswith("|")]
    split = [[cell.strip() for cell in line.strip("|").split("|")] for line in lines]
    assert len(split) >= 2 and set(split[1]) == {"---"}, stdout
    return [dict(zip(split[0], row)) for row in split[2:]]


def main():
    with tempfile.TemporaryDirectory() as work:
        work = Path(work)

        scratch = work / "tmp-self"
        scratch.mkdir()
        self_run = run(scratch, "--baseline", BLOCKFRAG, "--quick", "--ranks", "2")

        def exits_0():
            assert self_run.returncode == 0, self_run.stderr[-2000:]

        def a_row_per_case():
            rows = table_rows(self_run.stdout)
            assert [row["case"] for row in rows] == list(QUICK_SCENES), self_run.stdout
            for row in rows:
                assert int(row["scenes"]) == QUICK_SCENES[row["case"]], row
                assert int(row["ranks"]) == (1 if row["case"].startswith("grid") else 2), row

        def every_cell_a_number():
            rows = table_rows(self_run.stdout)
            assert len(rows[0]) == 3 + 2 * 4 + 3, rows[0]
            for row in rows:
                for column, cell in row.items():
                    if column == "case":
                        continue
                    value = float(cell)
                    assert value > 0, (column, row)
                    if column.startswith(("RSS", "scenes/s new/old")):
                        # The same executable: ratios near 1 (memory), within the machine's noise (rate).
                        assert 0.05 < value < 20, (column, row)

        def every_run_listed():
            for case in QUICK_SCENES:
                for label in ("new", "old"):
                    assert f"- {case}, {label}: wall s of each run " in self_run.stdout, (case, label)

        def temporary_folder_removed():
            assert list(scratch.iterdir()) == [], list(scratch.iterdir())

        check("exits 0", exits_0)
        check("a row per case with the quick sizes", a_row_per_case)
        check("every cell a number", every_cell_a_number)
        check("every run listed", every_run_listed)
        check("the temporary folder is removed", temporary_folder_removed)

        refuser = work / "refuser.sh"
        refuser.write_text("#!/bin/sh\necho 'study.json: /scene/duration: is required' >&2\nexit 2\n")
        refuser.chmod(0o755)
        scratch = work / "tmp-refused"
        scratch.mkdir()
        refused = run(scratch, "--baseline", str(refuser), "--quick", "--cases", "grid")

        def refused_cells():
            assert refused.returncode == 0, refused.stderr[-2000:]
            (row,) = table_rows(refused.stdout)
            assert row["case"] == "grid" and float(row["new scenes/s/core"]) > 0, row
            assert row["old wall s"] == "refused" and row["old RSS max MiB"] == "refused", row
            assert row["scenes/s new/old"] == "-", row
            assert "- grid, old: refused (exit code 2: study.json: /scene/duration: is required)" in refused.stdout

        check("a refusing baseline shows refused", refused_cells)

        refused_new = subprocess.run([sys.executable, str(SCRIPT), "--blockfrag", str(refuser), "--quick", "--cases",
                                      "grid"], capture_output=True, text=True, timeout=60)

        def refusing_build_under_test():
            assert refused_new.returncode == 1, (refused_new.returncode, refused_new.stderr[-2000:])
            (row,) = table_rows(refused_new.stdout)
            assert row["new wall s"] == "refused", row

        check("a refusing build under test exits 1", refusing_build_under_test)

        scratch = work / "tmp-markdown"
        scratch.mkdir()
        markdown = run(scratch, "--quick", "--cases", "grid,record_suite", "--markdown")

        def markdown_stamped():
            assert markdown.returncode == 0, markdown.stderr[-2000:]
            rows = table_rows(markdown.stdout)
            assert [row["case"] for row in rows] == ["grid", "record_suite"], markdown.stdout
            assert float(rows[0]["scenes/s/core"]) > 0 and "new wall s" not in rows[0], rows[0]
            version = subprocess.run([BLOCKFRAG, "--version"], capture_output=True, text=True).stdout.split()[1]
            last = markdown.stdout.strip().splitlines()[-1]
            assert last.startswith(f"Measured with blockfrag {version} on {os.cpu_count()} cores, load average "), last
            assert "--quick: sizes for a smoke test" in last, last
            assert "by `/usr/bin/python3 tests/benchmarks/study_throughput.py --blockfrag " in last, last
            assert last.endswith(" --quick --cases grid,record_suite --markdown`."), last
            assert "- grid, new: wall s of each run" not in markdown.stdout, markdown.stdout

        check("--markdown: the table without labels and the stamp under it", markdown_stamped)

        unknown = run(work, "--cases", "grid,nonsense")

        def unknown_case():
            assert unknown.returncode == 2 and "--cases: unknown nonsense" in unknown.stderr, unknown.stderr

        check("an unknown case is refused", unknown_case)

    return summary()


if __name__ == "__main__":
    sys.exit(main())
