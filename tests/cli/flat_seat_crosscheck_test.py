"""tests/benchmarks/flat_seat_crosscheck.py small: a flat seat through the seat's engine against the flat ground.

Two runs of the script (a few seconds each):

- the accuracy suite as given and 20 random scenes: exit 0, a row per compared field and the table
  of what the values over 1e-9 are made of; the suite's scenes released tilted run on both seats;
  every run ends, on the flat ground and on the seat; the flat ground's reference runs ran (g
  changed in its 15th digit for every scene, tolerance 1e-12 for the adaptive ones, a hundredth of
  the step for an RK4 one with a seat value over 1e-9); the verdicts (overturned, fell, settled)
  and the onset times' presence are equal wherever both ended; every field of every seat run is
  within 1e-9 of the flat ground's (rad, s, R) unless the script finds it chaotic (the flat
  ground's own value moves by more than 1e-12 when g changes in its 15th digit, and by at least a
  thousandth of the difference: the suite's bounce_small_block_e08, e = 0.8, where its chain of
  bounces ends, its settle time, moves 1.5e-3 s on the seat and 1.7e-3 s on the flat ground under
  that change of g) or the seat as near the reference as the flat ground; the script's temporary
  folders are gone;
- the suite through a blockfrag that adds 1e-7 rad to a seat run's max |theta|: that check fails
  on every seat run.

The full run (the suite and 1,000 random scenes, docs/validation.md, "A flat seat against the flat
ground") finds values over 1e-9 that are neither, most from a rule the engines do not share (the
flat ground's lay_flat keeps a landing block's slip where that adds kinetic energy, the seat does
not); these 20 scenes and the suite have none.

Prints "N passed, M failed" last; exits non-zero on any failure.
"""

import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

SOURCE = Path(os.environ.get("BLOCKFRAG_SOURCE_DIR", Path(__file__).resolve().parents[2]))
sys.path.insert(0, str(SOURCE / "tests" / "support"))
from script_checks import check, summary  # noqa: E402  (tests/support is not a package)
SCRIPT = SOURCE / "tests" / "benchmarks" / "flat_seat_crosscheck.py"
SUITE = SOURCE / "configs" / "accuracy_suite.json"
BLOCKFRAG = os.environ["BLOCKFRAG"]
RANDOM_SCENES = 20
SEED = 20261127
FIELDS = ("max_abs_theta", "final_theta", "final_slide", "max_abs_slide", "rock_start_time", "slide_start_time",
          "first_impact_time", "overturn_time", "settle_time", "end_time")
TOLERANCE = 1e-9  # rad, s, or over R
PERTURBATION = 1e-7  # rad added to a seat run's max |theta| by the perturbing blockfrag

# A blockfrag that runs the real one and adds PERTURBATION to max_abs_theta when the scene has a seat.
PERTURBING = f"""#!/usr/bin/python3
import json, subprocess, sys
result = subprocess.run([{BLOCKFRAG!r}] + sys.argv[1:], capture_output=True, text=True)
if result.returncode != 0 or "--summary-json" not in sys.argv:
    sys.stdout.write(result.stdout)
    sys.stderr.write(result.stderr)
    sys.exit(result.returncode)
summary = json.loads(result.stdout)
if "seat" in json.loads(open(sys.argv[2]).read()):
    summary["max_abs_theta"] += {PERTURBATION!r}
print(json.dumps(summary))
"""


def run(blockfrag, scratch, output, *args):
    """The script's run, its JSON output read back (None if it wrote none)."""
    # Every run that should end does within a second or two of CPU time; the script's CPU-time limit
    # is set far above that so that the sanitizers cannot turn a slow run into "no result".
    timeout = ["--timeout", "120"]
    result = subprocess.run([sys.executable, str(SCRIPT), "--blockfrag", str(blockfrag), "--json", str(output),
                             *timeout, *args], capture_output=True, text=True, timeout=600,
                            env=dict(os.environ, TMPDIR=str(scratch)))
    data = json.loads(output.read_text()) if output.exists() else None
    return result, data


def unexplained(records):
    """Every value over 1e-9 that the script finds neither chaotic nor as near the reference as the flat
    ground's, as 'scene (seat): field d'."""
    return [f"{r['scene']} ({r['seat']}): {field} {r['differences'][field]:.3g}"
            for r in records for field, label in r["explanations"].items() if label not in ("chaotic", "as accurate")]


def released_tilted():
    suite = json.loads(SUITE.read_text())
    return {e["name"] for e in suite["scenes"] if e["scene"].get("initial", {}).get("theta", 0) != 0}


def main():
    with tempfile.TemporaryDirectory() as work:
        work = Path(work)
        scratch = work / "tmp"
        scratch.mkdir()
        result, data = run(BLOCKFRAG, scratch, work / "default.json", "--random", str(RANDOM_SCENES),
                           "--seed", str(SEED))

        def exits_0_with_the_table():
            assert result.returncode == 0, result.stderr[-2000:]
            for field in FIELDS:
                assert f"| `{field}` |" in result.stdout, field
            assert "What the values over 1e-09 are made of" in result.stdout, result.stdout[-3000:]
            assert len([s for s in data["scenes"] if s["group"] != "suite"]) == RANDOM_SCENES

        def runs_the_scenes_released_tilted():
            assert len(released_tilted()) == 5, released_tilted()
            compared = {(r["scene"], r["seat"]) for r in data["compared"]}
            assert {(name, seat) for name in released_tilted() for seat in ("one_segment", "two_segments")} <= compared

        def every_run_ends():
            flat = [s["name"] for s in data["scenes"] if s["runs"]["flat"].get("status") != "ok"]
            assert flat == [], flat
            assert data["unfinished"] == [], data["unfinished"]

        def reference_runs_ran():
            over = {r["scene"] for r in data["compared"]
                    if any(d is not None and d > TOLERANCE for d in r["differences"].values())}
            for scene in data["scenes"]:
                runs = scene["runs"]
                assert runs["flat_perturbed"].get("status") == "ok", scene["name"]
                adaptive = scene["scene"].get("solver", {}).get("method", "adaptive") == "adaptive"
                assert ("flat_tight" in runs) == (adaptive or scene["name"] in over), scene["name"]
                if "flat_tight" in runs:
                    assert runs["flat_tight"].get("status") == "ok", scene["name"]
            assert all(r["flat_sensitivity"]["max_abs_theta"] is not None for r in data["compared"])

        def verdicts_and_onsets_equal():
            differing = [(r["scene"], r["seat"], v) for r in data["compared"] for v in r["verdicts"]]
            assert differing == [], differing

        def within_tolerance_unless_chaotic():
            assert len(data["compared"]) >= 2 * (41 + RANDOM_SCENES), len(data["compared"])
            problems = unexplained(data["compared"])
            assert problems == [], problems

        def temporary_folders_removed():
            assert list(scratch.iterdir()) == [], list(scratch.iterdir())

        check("exits 0 with a row per field", exits_0_with_the_table)
        check("the scenes released tilted run on both seats", runs_the_scenes_released_tilted)
        check("every run ends", every_run_ends)
        check("the flat ground's reference runs ran", reference_runs_ran)
        check("verdicts and onset times' presence equal", verdicts_and_onsets_equal)
        check("every field within 1e-9 unless chaotic", within_tolerance_unless_chaotic)
        check("the temporary folders are removed", temporary_folders_removed)

        perturbing = work / "perturbing_blockfrag"
        perturbing.write_text(PERTURBING)
        perturbing.chmod(0o755)
        _, perturbed = run(perturbing, scratch, work / "perturbed.json", "--random", "0")

        def a_perturbed_seat_fails_the_check():
            flagged = [p for p in unexplained(perturbed["compared"]) if ": max_abs_theta 1e-07" in p]
            assert len(perturbed["compared"]) >= 80, len(perturbed["compared"])
            assert len(flagged) == len(perturbed["compared"]), (len(flagged), len(perturbed["compared"]))

        check("a seat off by 1e-7 rad fails the check", a_perturbed_seat_fails_the_check)

    return summary()


if __name__ == "__main__":
    sys.exit(main())
