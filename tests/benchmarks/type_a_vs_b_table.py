#!/usr/bin/python3
"""The paper's two dam blocks over the record suite: each limit state's fitted median, type A
against type B, as docs/validation.md shows it.

Not a test: runs configs/record_suite_study.json (type A on flat ground) and
configs/dam_type_b_record_suite.json (type B on its seat: the same records, inputs, levels and
seed) on --ranks ranks, and prints a markdown table, one row per limit state of both studies: the
fitted median with its 95 % bootstrap interval (in the studies' intensity measure), and how many
samples exceeded the limit state, of how many, for each block. For the overturning limit state
(lost: overturned or fell off the seat) it gives the levels of the samples lost and how many of
them fell. With --figure, draws both studies' curves there (postproc/plots/plot_fragility_pair.py).

    /usr/bin/python3 tests/benchmarks/type_a_vs_b_table.py --blockfrag build/mpi_driver/blockfrag \\
        [--ranks 2] [--figure docs/dam_type_a_vs_b_fragility.png] [--markdown]

--markdown prints under the table the line docs/validation.md shows under it: the version that
computed it, the cores and the load average, and this command (tests/benchmarks/markdown_stamp.py).
Both studies write into a temporary folder, removed at the end.
"""

import argparse
import json
import math
import subprocess
import sys
import tempfile
from collections import Counter
from pathlib import Path

import h5py
import numpy as np

from markdown_stamp import Stamp

SOURCE = Path(__file__).resolve().parents[2]
STUDIES = (("type A", SOURCE / "configs" / "record_suite_study.json"),
           ("type B", SOURCE / "configs" / "dam_type_b_record_suite.json"))
PLOT = SOURCE / "postproc" / "plots" / "plot_fragility_pair.py"


def run_study(blockfrag, study, output, ranks):
    command = [str(Path(blockfrag).resolve()), "run", str(study), "--output", str(output)]
    if ranks > 1:
        command = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-n", str(ranks)] + command
    result = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if result.returncode != 0:
        sys.exit(f"{study.name}: blockfrag exited with {result.returncode}:\n{result.stderr[-2000:]}")


def text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


def describe(path):
    """Per limit state: the fit's cell and the exceedances' cell."""
    cells = {}
    with h5py.File(path, "r") as f:
        fell = np.asarray(f["/results/fell"][()]) == 1
        overturned = np.asarray(f["/results/overturned"][()]) == 1
        for name, group in f["fragility"].items():
            attrs = group.attrs
            exceedances = np.asarray(group["exceedances"][()], dtype=int)
            trials = int(np.sum(group["trials"][()]))
            median = float(attrs["median"])
            if text(attrs["fit_status"]) == "ok" and math.isfinite(median):
                fit = f"{median:.3g}"
                if "median_ci" in attrs:
                    low, high = (float(v) for v in attrs["median_ci"])
                    fit += f" [{low:.3g}, {high:.3g}]"
            else:
                fit = f"no fit ({text(attrs['fit_status'])})"
            count = f"{int(exceedances.sum())} of {trials}"
            if text(attrs["type"]) == "overturning" and exceedances.sum() > 0:
                levels = Counter()
                for level, n in zip(group["im"][()], exceedances):
                    if n:
                        levels[f"{level:g}"] += int(n)
                at = ", ".join(f"{n} at {level}" for level, n in levels.items())
                count += f" ({at}; {int(fell.sum())} fell, {int(overturned.sum())} overturned)"
            cells[name] = (fit, count)
        measure = f["fragility"].attrs
        units = f"{text(measure['im_label'])}, {text(measure['im_units'])}" if "im_label" in measure else ""
    return cells, units


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--blockfrag", required=True, help="the blockfrag executable")
    parser.add_argument("--ranks", type=int, default=2)
    parser.add_argument("--figure", type=Path, help="PNG of both studies' curves")
    parser.add_argument("--markdown", action="store_true", help="the stamp line under the table")
    args = parser.parse_args()
    stamp = Stamp(args.blockfrag, note=f"{args.ranks} ranks") if args.markdown else None
    with tempfile.TemporaryDirectory(prefix="blockfrag_type_a_vs_b_") as temporary:
        outputs = []
        for label, study in STUDIES:
            output = Path(temporary) / f"{study.stem}.h5"
            run_study(args.blockfrag, study, output, args.ranks)
            outputs.append(output)
        described = [describe(output) for output in outputs]
        if args.figure:
            subprocess.run(["/usr/bin/python3", str(PLOT), str(outputs[0]), str(outputs[1]), "-o",
                            str(args.figure), "--labels", STUDIES[0][0], STUDIES[1][0]], check=True)
    (a, units), (b, _) = described
    header = ["limit state"]
    for label, _ in STUDIES:
        header += [f"{label}: median{f' ({units})' if units else ''} [95 % bootstrap]", f"{label}: exceeded"]
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    order = [state["name"] for state in json.loads(STUDIES[0][1].read_text())["limit_states"]]
    for name in [n for n in order if n in a and n in b]:
        lines.append(f"| {name} | {a[name][0]} | {a[name][1]} | {b[name][0]} | {b[name][1]} |")
    print("\n".join(lines))
    if stamp:
        print()
        print(stamp.line())
    return 0


if __name__ == "__main__":
    sys.exit(main())
