#!/usr/bin/python3
"""The tables of the Google Benchmarks models_bench and engine_bench, as docs/performance.md shows
them.

Not a test: runs the benchmark executable given (built with BLOCKFRAG_BUILD_BENCHMARKS=ON) with
--benchmark_repetitions=N and JSON output, and prints the medians over the repetitions as a
markdown table:

- models_bench (tests/benchmarks/models_bench.cpp): each model on the grid of 36 scenes, its CPU
  time, steps and right-hand-side evaluations per scene, and how many times cheaper than `full`;
- engine_bench (tests/benchmarks/engine_bench.cpp): a few scenes of the accuracy suite with each
  setting, the CPU time per scene, steps and right-hand-side evaluations, and how many times
  cheaper than RK4 at dt = 0.00025 s on the same scene.

    /usr/bin/python3 tests/benchmarks/bench_tables.py build/tests/models_bench [--repetitions 5] [--markdown]
    /usr/bin/python3 tests/benchmarks/bench_tables.py build/tests/engine_bench [--repetitions 5] [--markdown]

--markdown prints under the table the line docs/performance.md shows under it: the version of the
build the benchmark belongs to (the blockfrag executable beside it, BUILD/mpi_driver/blockfrag),
the cores and the load average that measured it, and this command (tests/benchmarks/markdown_stamp.py).
"""

import argparse
import json
import subprocess
import sys
from pathlib import Path

from markdown_stamp import Stamp

MODEL_SCENES = 36  # the grid of models_bench.cpp: 3 aspect ratios x 2 frictions x 3 amplitudes x 2 periods
ENGINE_REFERENCE = "rk4 dt=0.00025"


def medians(executable, repetitions):
    """Each benchmark's median row, by name (without the _median suffix)."""
    printed = subprocess.run([str(executable), f"--benchmark_repetitions={repetitions}",
                              "--benchmark_report_aggregates_only=true", "--benchmark_format=json"],
                             capture_output=True, text=True, check=True).stdout
    rows = {}
    for row in json.loads(printed)["benchmarks"]:
        if row.get("aggregate_name") == "median" or repetitions == 1:
            rows[row["run_name"]] = row
    return rows


def microseconds(row):
    scale = {"ns": 1e-3, "us": 1.0, "ms": 1e3, "s": 1e6}[row["time_unit"]]
    return row["cpu_time"] * scale


def models_table(rows):
    full = microseconds(rows["models/full"]) / MODEL_SCENES
    lines = ["| model | CPU time per scene (us) | steps per scene | RHS evaluations per scene | times cheaper than `full` |",
             "|---|---|---|---|---|"]
    for name, row in rows.items():
        per_scene = microseconds(row) / MODEL_SCENES
        lines.append(f"| `{name.split('/', 1)[1]}` | {per_scene:.3g} | {row['steps_per_scene']:.1f} "
                     f"| {row['rhs_per_scene']:.1f} | {full / per_scene:.2g} |")
    return lines


def engine_table(rows):
    lines = ["| scene | setting | CPU time per scene (us) | steps | RHS evaluations | times cheaper than RK4 at 0.00025 s |",
             "|---|---|---|---|---|---|"]
    for name, row in rows.items():
        scene, setting = name.split("/", 1)
        reference = rows.get(f"{scene}/{ENGINE_REFERENCE}")
        ratio = f"{microseconds(reference) / microseconds(row):.3g}" if reference else "-"
        lines.append(f"| `{scene}` | {setting} | {microseconds(row):.3g} | {row['steps']:.0f} "
                     f"| {row['rhs_evaluations']:.0f} | {ratio} |")
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("benchmark", type=Path, help="build/tests/models_bench or build/tests/engine_bench")
    parser.add_argument("--repetitions", type=int, default=5, help="runs of each benchmark; the table gives medians")
    parser.add_argument("--markdown", action="store_true", help="the stamp line under the table")
    args = parser.parse_args()
    if args.repetitions < 1:
        parser.error("--repetitions must be at least 1")
    blockfrag = args.benchmark.resolve().parents[1] / "mpi_driver" / "blockfrag"
    note = f"medians of {args.repetitions} repetitions" if args.repetitions > 1 else "one repetition"
    stamp = Stamp(blockfrag, note=note) if args.markdown else None
    rows = medians(args.benchmark, args.repetitions)
    lines = models_table(rows) if "models/full" in rows else engine_table(rows)
    print("\n".join(lines))
    if stamp:
        print()
        print(stamp.line())
    return 0


if __name__ == "__main__":
    sys.exit(main())
