#!/usr/bin/python3
"""How many chunk requests rank 0 serves, and what the adaptive chunk size asks of it.

Not a test: prints a markdown table. The study's blocks never move (a 0.05 g pulse, far below
the rocking and sliding thresholds), so a sample costs microseconds and the run measures the
chunk service, not the engine. For each rank count (oversubscribed beyond the cores) it runs the
study with the adaptive chunk size and with --max-chunk 1 (every sample a request): wall time,
samples/s, chunks handed out and chunks per second, the rate rank 0 served.

    /usr/bin/python3 tests/benchmarks/chunk_service.py --blockfrag build/mpi_driver/blockfrag \\
        [--ranks 2,8,32] [--samples 400000] [--single-samples 100000] [--markdown]

--markdown prints under the table the line docs/performance.md shows under it: the version, the
cores and the load average that measured it, and this command (tests/benchmarks/markdown_stamp.py).

docs/performance.md turns the served rate into the rank count at which rank 0 saturates.
"""

import argparse
import json
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from markdown_stamp import Stamp

SOURCE = Path(__file__).resolve().parents[2]


def cheap_study(samples):
    study = json.loads((SOURCE / "configs" / "example_study.json").read_text())
    study["intensity_measure"] = {"type": "pga", "levels": [0.05]}
    study["samples_per_level"] = samples
    study["design"] = "monte_carlo"
    study["limit_states"] = [{"name": "overturn", "type": "overturning"}]
    study["bootstrap_resamples"] = 0
    study["checkpoint_interval_s"] = 600
    return study


def run(blockfrag, folder, ranks, samples, max_chunk):
    config = folder / "cheap.json"
    output = folder / "cheap.h5"
    config.write_text(json.dumps(cheap_study(samples)))
    command = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-n", str(ranks), blockfrag,
               "run", str(config), "--output", str(output)]
    if max_chunk:
        command += ["--max-chunk", str(max_chunk)]
    start = time.monotonic()
    result = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    wall = time.monotonic() - start
    if result.returncode != 0:
        sys.exit(f"{ranks} ranks: exit {result.returncode}:\n{result.stderr}")
    found = re.search(r"\((\d+) samples computed in this run, (\d+) chunks handed out", result.stderr)
    output.unlink()
    return wall, int(found.group(1)), int(found.group(2))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--blockfrag", default=str(SOURCE / "build" / "mpi_driver" / "blockfrag"))
    parser.add_argument("--ranks", default="2,8,32")
    parser.add_argument("--samples", type=int, default=400_000)
    parser.add_argument("--single-samples", type=int, default=100_000)
    parser.add_argument("--markdown", action="store_true", help="the stamp line under the table")
    args = parser.parse_args()
    stamp = Stamp(args.blockfrag, note="oversubscribed beyond the cores") if args.markdown else None
    print("| ranks | chunks | samples | wall s | samples/s | chunks handed out | chunks/s |")
    print("|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory(prefix="blockfrag_chunks_") as temporary:
        for ranks in (int(r) for r in args.ranks.split(",")):
            for label, samples, max_chunk in (("adaptive", args.samples, 0),
                                              ("--max-chunk 1", args.single_samples, 1)):
                wall, computed, chunks = run(args.blockfrag, Path(temporary), ranks, samples,
                                             max_chunk)
                print(f"| {ranks} | {label} | {computed:,} | {wall:.2f} | {computed / wall:,.0f} "
                      f"| {chunks:,} | {chunks / wall:,.0f} |", flush=True)
    if stamp:
        print()
        print(stamp.line())


if __name__ == "__main__":
    main()
