#!/usr/bin/python3
"""The paper's type B dam block (section 4) against blockfrag's: a markdown table.

Not a test: runs configs/dam_block_type_b.json (lambda = A cos(pi t) for 2 s, mu = 1.05, e = 0.2,
RK4 at dt = 0.00025 s) at A = 1.0 g and 1.5 g, both ways (A and -A), on rigid ground and on the
crest of the dam of configs/record_suite_study.json (H = 100 m, E = 25 GPa: T1 = 0.241 s, 5 %
damping), and prints for each run next to the paper's numbers:

- the largest upstream rotation (theta > 0: the block turns counter-clockwise, about its heel or
  the seat's upstream end, its top towards the reservoir) and when, and the largest downstream one
  (theta < 0, about its toe on the incline), both up to 2.5 s (the pulse and just after: where the
  paper gives its peaks);
- theta and its rate at 2.0 s and theta at 3.0 s (the paper's numbers for the forward pulse);
- the upstream dislocation at 3.0 s: how far upstream the heel (the block's vertex at the crack's
  upstream end) has moved horizontally from its place at rest, and the centre of mass's (the
  history's x, which includes the shift from rocking);
- the verdict of a run that settles (no duration; max_duration 30 s from t = 0, well past the
  pulse and the crest's ringing): stays (and where it comes to rest), falls into the reservoir
  (past the seat's upstream end, with its time), overturns (with its time), or still moving at 30 s.

    /usr/bin/python3 tests/benchmarks/type_b_paper_table.py --blockfrag build/mpi_driver/blockfrag [--markdown]

Each run writes into a fresh temporary folder, removed at the end. --markdown prints under the
table the line docs/validation.md shows under it: the version that computed it and this command
(tests/benchmarks/markdown_stamp.py).
"""

import argparse
import csv
import json
import math
import subprocess
import sys
import tempfile
from pathlib import Path

from markdown_stamp import Stamp
from shoelace import centroid as centroid_of

SOURCE = Path(__file__).resolve().parents[2]
SCENE = SOURCE / "configs" / "dam_block_type_b.json"
# The dam of the record-suite and type A studies: Fenves & Chopra's period of a 100 m dam of 25 GPa.
DAM = {"height": 100.0, "elastic_modulus": 25e9, "damping": 0.05}
AMPLITUDES = (1.0, -1.0, 1.5, -1.5)
HISTORY_INTERVAL = 0.001
PEAK_WINDOW = 2.5  # s: the rotation peaks are sought up to here

# The paper's FEM numbers (an elastic dam, mu = 1.05) in the table's columns; for 1.0 g it says
# only that neither block overturns.
PAPER = {
    1.0: ["-", "-", "-", "-", "-", "does not overturn"],
    -1.0: ["-", "-", "-", "-", "-", "does not overturn"],
    1.5: ["-", "-", "24.5, > 0", "36.77", "-", "falls into the reservoir"],
    -1.5: ["6.205 at 0.847", "10.13 at 2.147", "-", "-", "1.64", "stays on the dam"],
}


def run(blockfrag, scene, folder, name):
    """The summary (JSON) and the history rows of one scene."""
    scene_path = folder / f"{name}.json"
    history_path = folder / f"{name}.csv"
    scene_path.write_text(json.dumps(scene))
    result = subprocess.run([blockfrag, "simulate", str(scene_path), "--summary-json", "--history",
                             str(history_path), "--history-interval", str(HISTORY_INTERVAL)],
                            capture_output=True, text=True, check=False)
    if result.returncode != 0:
        sys.exit(f"{blockfrag} simulate {name}: exit {result.returncode}: {result.stderr.strip()}")
    with open(history_path) as stream:
        rows = [{k: (v if k == "mode" else float(v)) for k, v in row.items()} for row in csv.DictReader(stream)]
    return json.loads(result.stdout), rows


def at(rows, t):
    """The row nearest time t (None past the history's end)."""
    if rows[-1]["t"] < t - 0.5 * HISTORY_INTERVAL:
        return None
    return min(rows, key=lambda row: abs(row["t"] - t))


def heel_shift(row, centroid):
    """The heel's horizontal displacement from rest: the heel is the vertex (0, 0), centroid the
    centre of mass at rest in the same frame; the history's x is the centre's displacement."""
    c, s = math.cos(row["theta"]), math.sin(row["theta"])
    rx, ry = -centroid[0], -centroid[1]
    return row["x"] + (c * rx - s * ry) - rx


def degrees(theta):
    """In degrees, a value that prints as 0.00 without its sign."""
    value = math.degrees(theta)
    return 0.0 if abs(value) < 0.005 else value


def verdict(summary):
    if summary.get("fell"):
        return f"falls into the reservoir at {summary['fell_time']:.2f} s"
    if summary.get("overturned"):
        return f"overturns at {summary['overturn_time']:.2f} s"
    if summary.get("settled"):
        return (f"stays (at rest at {summary['settle_time']:.1f} s, theta {degrees(summary['final_theta']):.2f} deg, "
                f"moved {summary['final_slide']:+.2f} m)")
    return f"still moving at {summary['end_time']:.0f} s (theta {degrees(summary['final_theta']):.2f} deg)"


def describe(summary, rows, centroid):
    early = [row for row in rows if row["t"] <= PEAK_WINDOW + 0.5 * HISTORY_INTERVAL]
    up = max(early, key=lambda row: row["theta"])
    down = min(early, key=lambda row: row["theta"])
    def peak(row, sign):
        if sign * row["theta"] <= 0:
            return "none"
        if row is early[-1]:
            return f"{degrees(sign * row['theta']):.2f} at {row['t']:.1f}, still growing"
        return f"{degrees(sign * row['theta']):.2f} at {row['t']:.3f}"

    cells = [peak(up, 1), peak(down, -1)]
    two, three = at(rows, 2.0), at(rows, 3.0)
    cells.append(f"{degrees(two['theta']):.2f}, {two['omega']:+.3f}" if two else "ended")
    cells.append(f"{degrees(three['theta']):.2f}" if three else "ended")
    cells.append(f"{-heel_shift(three, centroid):.2f} ({-three['x']:.2f})" if three else "ended")
    cells.append(verdict(summary))
    return cells


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--blockfrag", required=True, help="the blockfrag executable")
    parser.add_argument("--markdown", action="store_true", help="the stamp line under the table")
    args = parser.parse_args()
    stamp = Stamp(args.blockfrag) if args.markdown else None
    base = json.loads(SCENE.read_text())
    base.pop("duration", None)
    base["max_duration"] = 30.0
    centroid = centroid_of(base["block"]["polygon"])

    header = ["A", "model", "max upstream theta to 2.5 s [deg] at [s]", "max downstream theta to 2.5 s [deg] at [s]",
              "theta [deg], omega [rad/s] at 2.0 s", "theta at 3.0 s [deg]",
              "upstream dislocation at 3.0 s [m]: heel (centre)", "verdict"]
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    with tempfile.TemporaryDirectory() as directory:
        folder = Path(directory)
        for amplitude in AMPLITUDES:
            lines.append(f"| {amplitude:+.1f} g | the paper (FEM) | " + " | ".join(PAPER[amplitude]) + " |")
            for dam in (False, True):
                scene = json.loads(json.dumps(base))
                scene["ground_motion"]["amplitude_g"] = amplitude
                if dam:
                    scene["dam"] = DAM
                name = f"b_{amplitude:+.1f}_{'dam' if dam else 'rigid'}"
                summary, rows = run(args.blockfrag, scene, folder, name)
                cells = describe(summary, rows, centroid)
                lines.append(f"| {amplitude:+.1f} g | {'dam, T1 = 0.241 s' if dam else 'rigid'} | "
                             + " | ".join(cells) + " |")
    print("\n".join(lines))
    if stamp:
        print()
        print(stamp.line())
    return 0


if __name__ == "__main__":
    sys.exit(main())
