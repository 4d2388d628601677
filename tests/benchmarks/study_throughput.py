#!/usr/bin/python3
"""Whole-study throughput and memory of `blockfrag run`, and of an older build side by side.

Not a test: prints a markdown table, one row per case, of the wall time (median of the repeats),
the scenes per second per core (scenes / wall / ranks) and the peak resident memory of rank 0 and
of the largest rank, for the build and, with --baseline, for another build with the ratios
new/old. The runs of the two builds alternate (new, old, then old, new, ...), so that a change of
the machine's load falls on both.

    /usr/bin/python3 tests/benchmarks/study_throughput.py --blockfrag build/mpi_driver/blockfrag \\
        [--baseline OLD/mpi_driver/blockfrag] [--ranks 2] [--repeats 3] [--quick] [--cases grid,...] \\
        [--markdown]

Below the table: each build's version, the machine's load and every run's wall time. With
--markdown, below the table only the line docs/performance.md shows under it: the version, the
cores and the load average that measured it, and this command (tests/benchmarks/markdown_stamp.py).

Cases (--quick shrinks each to a smoke test of a second or so):
  grid          the paper's grid: one block (a = 0.5 m, b = 1 m, mu 0.6, e 0.6) under a one-cycle
                cosine pulse of 2 s for 4 s, at 20,000 amplitudes from 0.3 to 1.5 g, one sample
                each, one limit state (overturning), on one rank without mpirun
  grid_engine   the same grid without the fit's bootstrap ("bootstrap_resamples": 0): what is
                left is the engine, the sampling, the fit and writing the output
  example1e5    configs/example_study.json at 10,000 samples per level (100,000 scenes) on --ranks
  example1e6    the same at 100,000 samples per level (1,000,000 scenes)
  record_suite  configs/record_suite_study.json as it is (360 scenes) on --ranks

Each run writes its output, checkpoint and lock into a fresh temporary folder, removed after the
run. Peak memory comes from /usr/bin/time (Debian's `time`) around each rank. A build that refuses
a case's study (exit code 2: an older build that does not know a key) shows "refused" in its cells
and the reason below the table; another exit code shows "failed". Exit code 1 when the build under
test (not the baseline) refused or failed a case.
"""

import argparse
import json
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from markdown_stamp import Stamp

TIME = "/usr/bin/time"
# Peak resident set size (KiB), wall, user and system seconds of one rank, as /usr/bin/time gives them.
TIME_FORMAT = "%M %e %U %S"

# The paper's grid: every key is one that builds since the first study format know.
GRID_STUDY = {
    "scene": {
        "block": {"half_width": 0.5, "half_height": 1.0},
        "contact": {"friction": 0.6, "restitution": 0.6},
        "ground_motion": {"type": "cosine_pulse", "amplitude_g": 1.0, "period": 2.0, "cycles": 1},
        "duration": 4.0,
    },
    "intensity_measure": {"from": 0.3, "to": 1.5, "count": 20000},
    "samples_per_level": 1,
    "limit_states": [{"name": "overturn", "type": "overturning"}],
    "seed": 1,
    "output": "grid.h5",
    "checkpoint_interval_s": 600,
}

CASE_NAMES = ("grid", "grid_engine", "example1e5", "example1e6", "record_suite")


class Case:
    """One study to time: its file, the --samples-per-level to pass (None: the file's own), its ranks."""

    def __init__(self, name, study, samples_per_level, ranks):
        self.name = name
        self.study = study
        self.samples_per_level = samples_per_level
        self.ranks = ranks
        config = json.loads(Path(study).read_text())
        measure = config["intensity_measure"]
        levels = measure.get("count", len(measure.get("levels", [None])))
        self.scenes = levels * (samples_per_level or config["samples_per_level"])


class Cell:
    """The runs of one case with one build."""

    def __init__(self):
        self.walls = []
        self.rss_rank0 = []
        self.rss_max = []
        self.problem = None  # "refused" or "failed", with the first line of its message in reason
        self.reason = ""
        self.exit3 = False
        self.checkpoints = []  # as each run reports them: "N in S s"


def make_cases(args, scratch):
    source = Path(args.source_dir)
    grid = dict(GRID_STUDY)
    grid["intensity_measure"] = dict(GRID_STUDY["intensity_measure"], count=200 if args.quick else 20000)
    grid_path = scratch / "grid.json"
    grid_path.write_text(json.dumps(grid, indent=1))
    grid_engine_path = scratch / "grid_engine.json"
    grid_engine_path.write_text(json.dumps(dict(grid, bootstrap_resamples=0), indent=1))
    example = source / "configs" / "example_study.json"
    records = source / "configs" / "record_suite_study.json"
    cases = {
        "grid": Case("grid", grid_path, None, 1),
        "grid_engine": Case("grid_engine", grid_engine_path, None, 1),
        "example1e5": Case("example1e5", example, 10 if args.quick else 10000, args.ranks),
        "example1e6": Case("example1e6", example, 100 if args.quick else 100000, args.ranks),
        "record_suite": Case("record_suite", records, 2 if args.quick else None, args.ranks),
    }
    return [cases[name] for name in args.cases]


def launcher(ranks, times):
    """The command prefix that starts `ranks` ranks, each under /usr/bin/time writing times.RANK."""
    if ranks == 1:
        return [TIME, "-f", TIME_FORMAT, "-o", f"{times}.0"]
    command = ["mpirun", "-np", str(ranks)]
    if ranks > (os.cpu_count() or 1):
        command.append("--oversubscribe")
    # Open MPI gives each rank its number in OMPI_COMM_WORLD_RANK.
    wrapper = 'f=$1; o=$2; shift 2; exec "$0" -f "$f" -o "$o.$OMPI_COMM_WORLD_RANK" "$@"'
    return command + ["sh", "-c", wrapper, TIME, TIME_FORMAT, str(times)]


def read_rss(times, ranks):
    """Peak RSS (MiB) of each rank; /usr/bin/time puts a 'Command exited' line first on failure."""
    rss = []
    for rank in range(ranks):
        lines = Path(f"{times}.{rank}").read_text().split("\n")
        last = [line for line in lines if line.strip()][-1]
        rss.append(int(last.split()[0]) / 1024.0)
    return rss


def run_once(executable, case, scratch):
    """One run of case with executable: (exit code, wall seconds, per-rank RSS, what went wrong,
    the checkpoints the run reports and the seconds it took to write them)."""
    folder = Path(tempfile.mkdtemp(prefix="run-", dir=scratch))
    try:
        times = folder / "time"
        command = launcher(case.ranks, times) + [
            str(executable), "run", str(case.study), "--output", str(folder / "out.h5")]
        if case.samples_per_level is not None:
            command += ["--samples-per-level", str(case.samples_per_level)]
        start = time.perf_counter()
        finished = subprocess.run(command, cwd=folder, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                                  text=True, errors="replace")
        wall = time.perf_counter() - start
        if finished.returncode not in (0, 3):
            return finished.returncode, wall, [], first_error_line(finished.stderr), ""
        # A run that computed fewer samples than the study has (say, one that found an output to
        # resume) would look fast: it counts as failed. An older build may word its summary otherwise.
        computed = re.search(r"\((\d+) samples computed in this run", finished.stderr)
        if computed is not None and int(computed.group(1)) != case.scenes:
            return None, wall, [], f"computed {computed.group(1)} of {case.scenes} samples", ""
        checkpoints = re.search(r"(\d+) checkpoints taking ([0-9.e+-]+) s", finished.stderr)
        checkpoints = f"{checkpoints.group(1)} in {float(checkpoints.group(2)):.2f} s" if checkpoints else "?"
        return finished.returncode, wall, read_rss(times, case.ranks), "", checkpoints
    finally:
        shutil.rmtree(folder, ignore_errors=True)


def first_error_line(stderr):
    for line in stderr.splitlines():
        if line.strip() and not line.startswith(("study ", "progress:")):
            return line.strip()
    return stderr.strip()[:200]


def measure(builds, cases, repeats, scratch):
    cells = {(case.name, label): Cell() for case in cases for label, _ in builds}
    for repeat in range(repeats):
        order = builds if repeat % 2 == 0 else builds[::-1]
        for case in cases:
            for label, executable in order:
                cell = cells[(case.name, label)]
                if cell.problem:
                    continue
                code, wall, rss, error, checkpoints = run_once(executable, case, scratch)
                if code in (0, 3):
                    cell.walls.append(wall)
                    cell.rss_rank0.append(rss[0])
                    cell.rss_max.append(max(rss))
                    cell.exit3 = cell.exit3 or code == 3
                    cell.checkpoints.append(checkpoints)
                    note = f"{wall:.2f} s, peak RSS of each rank " + ", ".join(f"{r:.1f}" for r in rss) + " MiB"
                else:
                    cell.problem = "refused" if code == 2 else "failed"
                    cell.reason = error if code is None else f"exit code {code}: {error}"
                    note = cell.problem
                print(f"[{repeat + 1}/{repeats}] {case.name} {label}: {note}", file=sys.stderr, flush=True)
    return cells


def table(builds, cases, cells, label_columns=True):
    """label_columns False (one build only): the columns without the build's label."""
    labels = [label for label, _ in builds]
    header = ["case", "ranks", "scenes"]
    for label in labels:
        prefix = f"{label} " if label_columns else ""
        header += [f"{prefix}wall s", f"{prefix}scenes/s/core", f"{prefix}RSS rank 0 MiB", f"{prefix}RSS max MiB"]
    if len(labels) == 2:
        header += ["scenes/s new/old", "RSS rank 0 new/old", "RSS max new/old"]
    rows = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    for case in cases:
        row = [case.name, str(case.ranks), str(case.scenes)]
        values = []
        for label in labels:
            cell = cells[(case.name, label)]
            if cell.problem:
                row += [cell.problem] * 4
                values.append(None)
                continue
            wall = statistics.median(cell.walls)
            rate = case.scenes / wall / case.ranks
            rss0, rss_max = statistics.median(cell.rss_rank0), statistics.median(cell.rss_max)
            row += [f"{wall:.2f}", f"{rate:.0f}", f"{rss0:.1f}", f"{rss_max:.1f}"]
            values.append((rate, rss0, rss_max))
        if len(labels) == 2:
            if None in values:
                row += ["-"] * 3
            else:
                row += [f"{new / old:.2f}" for new, old in zip(values[0], values[1])]
        rows.append("| " + " | ".join(row) + " |")
    return "\n".join(rows)


def version(executable):
    try:
        return subprocess.run([str(executable), "--version"], capture_output=True, text=True,
                              timeout=30).stdout.strip()
    except (OSError, subprocess.SubprocessError) as error:
        return f"(no version: {error})"


def parse_args():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--blockfrag", default=os.environ.get("BLOCKFRAG"),
                        help="the blockfrag executable to measure (default: $BLOCKFRAG)")
    parser.add_argument("--baseline", help="another blockfrag executable, measured side by side")
    parser.add_argument("--ranks", type=int, default=2, help="ranks of every case but grid (default 2)")
    parser.add_argument("--repeats", type=int, help="runs of each case and build (default 3, 1 with --quick)")
    parser.add_argument("--quick", action="store_true", help="tiny studies: a smoke test, not a measurement")
    parser.add_argument("--markdown", action="store_true",
                        help="the table as the docs show it: only the stamp line below it")
    parser.add_argument("--cases", default=",".join(CASE_NAMES),
                        help=f"comma-separated, from {','.join(CASE_NAMES)} (default all)")
    parser.add_argument("--source-dir", default=os.environ.get("BLOCKFRAG_SOURCE_DIR",
                                                               Path(__file__).resolve().parents[2]),
                        help="the source tree whose configs/ to run (default: this script's)")
    args = parser.parse_args()
    if not args.blockfrag:
        parser.error("--blockfrag (or $BLOCKFRAG) is required")
    args.cases = [name.strip() for name in args.cases.split(",") if name.strip()]
    unknown = [name for name in args.cases if name not in CASE_NAMES]
    if unknown or not args.cases:
        parser.error(f"--cases: unknown {', '.join(unknown) or '(none given)'}; choose from {','.join(CASE_NAMES)}")
    if args.ranks < 1:
        parser.error("--ranks must be at least 1")
    if args.repeats is None:
        args.repeats = 1 if args.quick else 3
    if args.repeats < 1:
        parser.error("--repeats must be at least 1")
    for path in [args.blockfrag] + ([args.baseline] if args.baseline else []):
        if not os.access(path, os.X_OK):
            parser.error(f"{path}: not an executable file")
    if not os.access(TIME, os.X_OK):
        parser.error(f"{TIME} is missing (Debian package 'time'): it measures each rank's peak memory")
    return args


def main():
    args = parse_args()
    if os.geteuid() == 0:
        os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
        os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    builds = [("new", Path(args.blockfrag).resolve())]
    if args.baseline:
        builds.append(("old", Path(args.baseline).resolve()))
    with tempfile.TemporaryDirectory(prefix="study_throughput-") as scratch:
        scratch = Path(scratch)
        cases = make_cases(args, scratch)
        if args.markdown:
            runs = f"medians of {args.repeats} runs of each case" if args.repeats > 1 else "one run of each case"
            stamp = Stamp(builds[0][1], note=runs
                          + (", --quick: sizes for a smoke test, not a measurement" if args.quick else ""))
        load_before = os.getloadavg()
        cells = measure(builds, cases, args.repeats, scratch)
        load_after = os.getloadavg()
    failed = any(cells[(case.name, "new")].problem for case in cases)
    print(table(builds, cases, cells, label_columns=len(builds) == 2 or not args.markdown))
    print()
    if args.markdown:
        print(stamp.line())
        for case in cases:
            for label, _ in builds:
                cell = cells[(case.name, label)]
                if cell.problem:
                    print(f"- {case.name}, {label}: {cell.problem} ({cell.reason})", file=sys.stderr)
        return 1 if failed else 0
    for label, executable in builds:
        print(f"- {label}: {executable} ({version(executable)})")
    print(f"- {args.repeats} run(s) of each case and build, medians; {os.cpu_count()} cores; "
          f"load average {load_before[0]:.2f} before, {load_after[0]:.2f} after"
          + ("; --quick: sizes for a smoke test, not a measurement" if args.quick else ""))
    for case in cases:
        for label, _ in builds:
            cell = cells[(case.name, label)]
            if cell.problem:
                print(f"- {case.name}, {label}: {cell.problem} ({cell.reason})")
            else:
                walls = ", ".join(f"{wall:.2f}" for wall in cell.walls)
                print(f"- {case.name}, {label}: wall s of each run {walls}; checkpoints "
                      + ", ".join(cell.checkpoints)
                      + ("; exit code 3 (more failed samples than allowed)" if cell.exit3 else ""))
    # The build under test must run every case; a baseline may refuse what it does not know.
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
