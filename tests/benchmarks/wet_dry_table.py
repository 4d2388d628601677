#!/usr/bin/python3
"""The paper's dam blocks dry and under a full reservoir: a markdown table.

Not a test: runs configs/dam_block_type_a.json and configs/dam_block_type_b.json and their
reservoir versions (configs/dam_block_type_*_reservoir.json: the water at the crest, H = 100 m,
Westergaard's added mass, the uplift unchanged during the shaking) under the paper's pulse
lambda = A cos(pi t) for 2 s at A = 1.0 g and 1.5 g, both ways (A and -A: the ground first
accelerating upstream or downstream), on rigid ground and on the crest of the dam of
configs/record_suite_study.json (H = 100 m, E = 25 GPa, 5 % damping), each run until it settles
(no duration; max_duration 30 s). For each it prints the verdict (stays, overturns, falls, or still
moving at 30 s), the largest rotation, the final slide of the centre of mass (m, + downstream) and,
wet, the post-earthquake sliding and overturning safety factors of the settled block (full uplift;
inf: nothing drives that way, as the type B block, which can slide downstream only up its incline;
-: the block does not stand at the end).

    /usr/bin/python3 tests/benchmarks/wet_dry_table.py --blockfrag build/mpi_driver/blockfrag [--markdown]

Each run writes into a fresh temporary folder, removed at the end.
"""

import argparse
import concurrent.futures
import json
import subprocess
import sys
import tempfile
from pathlib import Path

from markdown_stamp import Stamp

SOURCE = Path(__file__).resolve().parents[2]
DAM = {"height": 100.0, "elastic_modulus": 25e9, "damping": 0.05}


def scene(block, wet, amplitude, on_dam):
    name = f"dam_block_type_{block}{'_reservoir' if wet else ''}.json"
    s = json.loads((SOURCE / "configs" / name).read_text())
    s["ground_motion"] = {"type": "cosine_pulse", "amplitude_g": amplitude, "period": 2.0, "cycles": 1}
    s.pop("duration", None)
    s["max_duration"] = 30.0
    if on_dam:
        s["dam"] = DAM
    return s


def run(blockfrag, s):
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "scene.json"
        path.write_text(json.dumps(s))
        out = subprocess.run([blockfrag, "simulate", str(path), "--summary-json"], capture_output=True,
                             text=True, timeout=600)
        if out.returncode != 0:
            raise RuntimeError(out.stderr)
        return json.loads(out.stdout)


def verdict(summary):
    if summary["status"] != "ok":
        return "failed"
    if summary["overturned"]:
        return f"overturns at {summary['overturn_time']:.2f} s"
    if summary.get("fell"):
        return f"falls at {summary['fell_time']:.2f} s"
    return "stays" if summary["settled"] else "moving at 30 s"


def cells(summary):
    return [verdict(summary), f"{summary['max_abs_theta']:.4f}", f"{summary['final_slide']:.3f}"]


def factors(summary):
    values = [summary.get("post_earthquake_sliding_safety_factor"),
              summary.get("post_earthquake_overturning_safety_factor")]
    if summary.get("post_earthquake_sliding_safety_factor", 0) is None and values[1] is None:
        return "-"  # not standing at rest at the end
    return " / ".join("inf" if v is None else f"{v:.2f}" for v in values)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--blockfrag", default=str(SOURCE / "build" / "mpi_driver" / "blockfrag"))
    parser.add_argument("--markdown", action="store_true", help="print the stamp line under the table")
    args = parser.parse_args()
    stamp = Stamp(args.blockfrag) if args.markdown else None
    cases = [(block, on_dam, amplitude) for block in "ab" for on_dam in (False, True)
             for amplitude in (1.0, -1.0, 1.5, -1.5)]
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        dry = list(pool.map(lambda c: run(args.blockfrag, scene(c[0], False, c[2], c[1])), cases))
        wet = list(pool.map(lambda c: run(args.blockfrag, scene(c[0], True, c[2], c[1])), cases))
    print("| block | ground | A (g) | dry | dry max abs theta (rad) | dry final slide (m) | wet | "
          "wet max abs theta (rad) | wet final slide (m) | wet after: sliding / overturning FS |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for (block, on_dam, amplitude), d, w in zip(cases, dry, wet):
        row = [f"type {block.upper()}", "dam crest" if on_dam else "rigid", f"{amplitude:+.1f}"]
        row += cells(d) + cells(w) + [factors(w)]
        print("| " + " | ".join(row) + " |")
    if stamp:
        print()
        print(stamp.line())
    return 0


if __name__ == "__main__":
    sys.exit(main())
