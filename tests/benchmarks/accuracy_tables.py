#!/usr/bin/python3
"""The tables of docs/accuracy.md from one run of `blockfrag accuracy`, and its diagram.

Not a test: runs

    blockfrag accuracy configs/accuracy_suite.json --output ACCURACY.h5 --table TABLE.md \\
        --fragility-study STUDY.json

with STUDY.json configs/example_study.json at --samples-per-level a level (default 40: 400
samples per setting), and prints what the command writes into TABLE.md: the reference's check,
the work-precision table, the fragility curves per setting and Monte Carlo against Latin
hypercube sampling. With --figure, draws the work-precision diagram of ACCURACY.h5 there
(postproc/plots/plot_work_precision.py).

    /usr/bin/python3 tests/benchmarks/accuracy_tables.py --blockfrag build/mpi_driver/blockfrag \\
        [--samples-per-level 40] [--figure docs/work_precision.png] [--markdown]

--markdown prints under each table the line docs/accuracy.md shows under it: the version, the
cores and the load average that measured it, and this command (tests/benchmarks/markdown_stamp.py).
Everything is written into a temporary folder, removed at the end.
"""

import argparse
import json
import subprocess
import sys
import tempfile
from pathlib import Path

from markdown_stamp import Stamp

SOURCE = Path(__file__).resolve().parents[2]
PLOT = SOURCE / "postproc" / "plots" / "plot_work_precision.py"


def stamped(table_text, stamp_line):
    """table_text with stamp_line after every table (a run of lines starting with '|')."""
    lines = table_text.rstrip("\n").split("\n")
    out = []
    for k, line in enumerate(lines):
        out.append(line)
        ends_table = line.startswith("|") and (k + 1 == len(lines) or not lines[k + 1].startswith("|"))
        if ends_table:
            out += ["", stamp_line]
    return "\n".join(out)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--blockfrag", required=True, help="the blockfrag executable")
    parser.add_argument("--samples-per-level", type=int, default=40,
                        help="samples per level of the fragility study compared per setting")
    parser.add_argument("--figure", type=Path, help="PNG of the work-precision diagram")
    parser.add_argument("--markdown", action="store_true", help="the stamp line under each table")
    args = parser.parse_args()
    stamp = Stamp(args.blockfrag) if args.markdown else None
    with tempfile.TemporaryDirectory(prefix="blockfrag_accuracy_") as temporary:
        folder = Path(temporary)
        study = json.loads((SOURCE / "configs" / "example_study.json").read_text())
        study["samples_per_level"] = args.samples_per_level
        study["output"] = str(folder / "study.h5")
        (folder / "study.json").write_text(json.dumps(study))
        command = [str(Path(args.blockfrag).resolve()), "accuracy", str(SOURCE / "configs" / "accuracy_suite.json"),
                   "--output", str(folder / "accuracy.h5"), "--table", str(folder / "table.md"),
                   "--fragility-study", str(folder / "study.json")]
        result = subprocess.run(command, cwd=folder, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                                text=True)
        if result.returncode != 0:
            sys.exit(f"blockfrag accuracy exited with {result.returncode}:\n{result.stderr[-2000:]}")
        table = (folder / "table.md").read_text()
        print(stamped(table, stamp.line()) if stamp else table.rstrip("\n"))
        if args.figure:
            subprocess.run(["/usr/bin/python3", str(PLOT), str(folder / "accuracy.h5"), str(args.figure)],
                           check=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
