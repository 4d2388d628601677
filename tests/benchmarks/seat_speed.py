#!/usr/bin/python3
"""The seat's cost against the flat ground's: the paper's type B dam block (on its polygonal seat)
and type A block (on flat ground), for a build and optionally an older one side by side.

Not a test: prints a markdown table. Rows: `blockfrag bench` of configs/dam_block_type_b.json and
configs/dam_block_type_a.json (median time of --repeat runs, steps), their ratio B / A, and with
--studies the wall time of the type B and type A record-suite studies
(configs/dam_type_b_record_suite.json, configs/record_suite_study.json: the same records, inputs
and levels) on two ranks, and their ratio. With --wet, also each block under its reservoir
(configs/dam_block_type_{a,b}_reservoir.json, water at the crest) and its ratio wet / dry: what
the water costs; and each under a pool 1 cm deep (its reservoir with the level 1 cm above the
block's lowest point): the dry motion with every load of the water computed at every right-hand
side, which parts the water's own cost from what the water does to the motion. With --flat-seat,
also the type A block on the flat ground given as a seat of one segment (1 km either side of its
base's middle) and its ratio to the flat ground's: what the seat's engine costs where the two
engines run the same physics; with --studies too, the same for two whole studies on one rank, each
on the flat ground and on a one-segment seat under the rectangle's base: the paper's grid (a = 0.5
m, b = 1 m, mu 0.6, e 0.6, a one-cycle cosine pulse of 2 s for 4 s, 4,000 amplitudes from 0.3 to
1.5 g, no bootstrap) and configs/example_study.json at 1,000 samples a level (medians of 5 runs,
the flat ground's and the seat's alternating). The builds' runs
alternate, so that a change of the machine's load falls on both.

    /usr/bin/python3 tests/benchmarks/seat_speed.py --blockfrag build/mpi_driver/blockfrag \\
        [--baseline OLD/mpi_driver/blockfrag] [--repeat 10] [--studies] [--wet] [--flat-seat]
        [--markdown]

--markdown prints under the table the line docs/performance.md shows under it: the version, the
cores and the load average that measured it, and this command (tests/benchmarks/markdown_stamp.py).
"""

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from markdown_stamp import Stamp

ROOT = Path(__file__).resolve().parents[2]
SCENES = {"B": "configs/dam_block_type_b.json", "A": "configs/dam_block_type_a.json"}
STUDIES = {"B": "configs/dam_type_b_record_suite.json", "A": "configs/record_suite_study.json"}
WET = {"B": "configs/dam_block_type_b_reservoir.json", "A": "configs/dam_block_type_a_reservoir.json"}
SHALLOW_POOL_M = 0.01  # the shallow pool's depth over the block's lowest point
FLAT_SEAT_HALF_M = 1000.0  # how far the flat seat reaches either side of the block's base's middle
PAPER_GRID = {
    "scene": {"block": {"half_width": 0.5, "half_height": 1.0},
              "contact": {"friction": 0.6, "restitution": 0.6},
              "ground_motion": {"type": "cosine_pulse", "amplitude_g": 1.0, "period": 2.0,
                                "cycles": 1},
              "duration": 4.0},
    "intensity_measure": {"from": 0.3, "to": 1.5, "count": 4000}, "samples_per_level": 1,
    "limit_states": [{"name": "overturn", "type": "overturning"}], "seed": 1,
    "output": "out.h5", "checkpoint_interval_s": 600, "bootstrap_resamples": 0}
EXAMPLE_SAMPLES_PER_LEVEL = 1000
FLAT_SEAT_STUDY_RUNS = 5  # each study's wall time is the median of this many runs


def shallow_pool(wet_scene, folder):
    """A copy of the wet scene with its reservoir SHALLOW_POOL_M deep, written in folder."""
    scene = json.loads((ROOT / wet_scene).read_text())
    lowest = min(y for _, y in scene["block"]["polygon"])
    scene["reservoir"]["level"] = lowest + SHALLOW_POOL_M
    path = Path(folder) / ("shallow_" + Path(wet_scene).name)
    path.write_text(json.dumps(scene))
    return str(path)


def flat_seat(scene_file, folder):
    """A copy of the dry scene on a seat of one level segment under its base, written in folder."""
    scene = json.loads((ROOT / scene_file).read_text())
    lowest = min(y for _, y in scene["block"]["polygon"])
    base = [x for x, y in scene["block"]["polygon"] if y == lowest]
    middle = 0.5 * (min(base) + max(base))
    scene["seat"] = [[middle - FLAT_SEAT_HALF_M, lowest], [middle + FLAT_SEAT_HALF_M, lowest]]
    path = Path(folder) / ("flat_seat_" + Path(scene_file).name)
    path.write_text(json.dumps(scene))
    return str(path)


def flat_seat_studies(folder):
    """The paper's grid and the example study, each as is and on a one-segment seat under its
    rectangle's base, written in folder: {label: path}."""
    example = json.loads((ROOT / "configs/example_study.json").read_text())
    example["samples_per_level"] = EXAMPLE_SAMPLES_PER_LEVEL
    example["checkpoint_interval_s"] = 600
    studies = {}
    for name, study in (("grid", PAPER_GRID), ("example", example)):
        seated = json.loads(json.dumps(study))
        base = -seated["scene"]["block"]["half_height"]
        seated["scene"]["seat"] = [[-FLAT_SEAT_HALF_M, base], [FLAT_SEAT_HALF_M, base]]
        for label, content in ((name + " flat", study), (name + " seat", seated)):
            path = Path(folder) / (label.replace(" ", "_") + ".json")
            path.write_text(json.dumps(content))
            studies[label] = str(path)
    return studies


def one_rank_wall(blockfrag, study):
    with tempfile.TemporaryDirectory() as folder:
        start = time.monotonic()
        subprocess.run([blockfrag, "run", study, "--output", os.path.join(folder, "out.h5")],
                       cwd=folder, check=True, capture_output=True)
        return time.monotonic() - start


def bench(blockfrag, scene, repeat):
    out = subprocess.run([blockfrag, "bench", scene, "--repeat", str(repeat)], cwd=ROOT,
                         check=True, capture_output=True, text=True).stdout
    result = json.loads(out)
    return result["median_us"] / 1e3, result["steps"]


def study_wall(blockfrag, study):
    with tempfile.TemporaryDirectory() as folder:
        command = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-n", "2",
                   blockfrag, "run", study, "--output",
                   os.path.join(folder, "out.h5")]
        start = time.monotonic()
        subprocess.run(command, cwd=ROOT, check=True, capture_output=True)
        return time.monotonic() - start


def measure(builds, repeat, studies, wet, on_flat_seat):
    rows = {name: {} for name in builds}
    scenes = [("bench " + key, scene) for key, scene in SCENES.items()]
    with tempfile.TemporaryDirectory() as folder:
        if on_flat_seat:
            scenes.append(("flat seat A", flat_seat(SCENES["A"], folder)))
        if wet:
            scenes += [("wet " + key, scene) for key, scene in WET.items()]
            scenes += [("shallow " + key, shallow_pool(scene, folder)) for key, scene in WET.items()]
        for label, scene in scenes:
            for name, binary in builds.items():
                rows[name][label] = bench(binary, scene, repeat)
        if studies and on_flat_seat:
            paths = flat_seat_studies(folder)
            walls = {(name, label): [] for name in builds for label in paths}
            for run in range(FLAT_SEAT_STUDY_RUNS):
                order = list(paths) if run % 2 == 0 else list(reversed(list(paths)))
                for label in order:
                    for name, binary in builds.items():
                        walls[name, label].append(one_rank_wall(binary, paths[label]))
            for (name, label), wall in walls.items():
                rows[name][label] = statistics.median(wall)
    if studies:
        for key, study in STUDIES.items():
            for name, binary in reversed(list(builds.items())):
                rows[name]["study " + key] = study_wall(binary, study)
    return rows


def table(rows, studies, wet, on_flat_seat):
    names = list(rows)
    lines = ["| measure | " + " | ".join(names) + " |", "|---" * (len(names) + 1) + "|"]

    def row(label, cell):
        lines.append(f"| {label} | " + " | ".join(cell(rows[n]) for n in names) + " |")

    for key in SCENES:
        row(f"bench type {key}: median ms (steps)",
            lambda r, k=key: f"{r['bench ' + k][0]:.2f} ({r['bench ' + k][1]:,})")
    row("**bench ratio B / A**", lambda r: f"**{r['bench B'][0] / r['bench A'][0]:.2f}**")
    if on_flat_seat:
        row("bench type A on a one-segment seat: median ms (steps)",
            lambda r: f"{r['flat seat A'][0]:.2f} ({r['flat seat A'][1]:,})")
        row("**one-segment seat / flat ground, type A**",
            lambda r: f"**{r['flat seat A'][0] / r['bench A'][0]:.2f}**")
    if studies:
        for key in STUDIES:
            row(f"record-suite study type {key}: wall s", lambda r, k=key: f"{r['study ' + k]:.2f}")
        row("**study ratio B / A**", lambda r: f"**{r['study B'] / r['study A']:.2f}**")
    if studies and on_flat_seat:
        for key, what in (("grid", "paper grid, 4,000 amplitudes"),
                          ("example", "example study, 1,000 samples a level")):
            row(f"{what}, one rank: wall s flat / seat",
                lambda r, k=key: f"{r[k + ' flat']:.2f} / {r[k + ' seat']:.2f}")
            row(f"**{what}: seat / flat**",
                lambda r, k=key: f"**{r[k + ' seat'] / r[k + ' flat']:.2f}**")
    if wet:
        for key in SCENES:
            row(f"bench type {key} under its reservoir: median ms (steps)",
                lambda r, k=key: f"{r['wet ' + k][0]:.2f} ({r['wet ' + k][1]:,})")
            row(f"**wet / dry, type {key}**",
                lambda r, k=key: f"**{r['wet ' + k][0] / r['bench ' + k][0]:.2f}**")
            row(f"bench type {key} under a pool 1 cm deep: median ms (steps)",
                lambda r, k=key: f"{r['shallow ' + k][0]:.2f} ({r['shallow ' + k][1]:,})")
            row(f"**1 cm pool / dry, type {key}**",
                lambda r, k=key: f"**{r['shallow ' + k][0] / r['bench ' + k][0]:.2f}**")
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--blockfrag", default="build/mpi_driver/blockfrag")
    parser.add_argument("--baseline", help="an older build, measured side by side")
    parser.add_argument("--repeat", type=int, default=10, help="bench runs per scene")
    parser.add_argument("--studies", action="store_true",
                        help="also time the two record-suite studies on two ranks")
    parser.add_argument("--wet", action="store_true",
                        help="also bench each block under its reservoir, and wet / dry")
    parser.add_argument("--flat-seat", action="store_true",
                        help="also bench the type A block on a one-segment seat, and its ratio")
    parser.add_argument("--markdown", action="store_true", help="the stamp line under the table")
    args = parser.parse_args()
    builds = {"build": args.blockfrag}
    if args.baseline:
        builds["baseline"] = args.baseline
    for name, binary in builds.items():
        if not Path(binary).is_file():
            sys.exit(f"seat_speed.py: no such program: {binary}")
        builds[name] = os.path.abspath(binary)
    stamp = Stamp(builds["build"], note=f"bench medians of {args.repeat} runs") if args.markdown else None
    rows = measure(builds, args.repeat, args.studies, args.wet, args.flat_seat)
    print(table(rows, args.studies, args.wet, args.flat_seat))
    if stamp:
        print()
        print(stamp.line())


if __name__ == "__main__":
    main()
