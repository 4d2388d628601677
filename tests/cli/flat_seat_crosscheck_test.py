"""tests/benchmarks/flat_seat_crosscheck.py small: a flat seat through the seat's engine against the flat ground.

Three runs of the script (a few seconds each):

- the accuracy suite as given and 20 random scenes: exit 0, a row per compared field and the table
  of what the values over 1e-9 are made of; the suite's scenes released tilted run on both seats;
  every run ends, on the flat ground and on the seat; the flat ground's reference runs ran (g
  changed in its 15th digit for every scene, tolerance 1e-12 for the adaptive ones); the verdicts
  (overturned, fell, settled) are equal wherever both ended, and on the suite every onset time too
  (present on both or on neither); on the random scenes that RK4 runs, the fields agree within the
  tolerances below; the script's temporary folders are gone;
- the suite with every adaptive scene at tolerance 1e-12: no verdict difference at all (every
  onset time present on both or on neither) and the fields within the tolerances below;
- the same through a blockfrag that adds 1e-7 rad to a seat run's max |theta|: those checks fail.

The tolerances are what the full run (the suite and 1,000 random scenes, docs/validation.md, "A flat
seat against the flat ground") measured, with a margin, so they hold for any random scenes:

- RK4: angles 9.0e-10 rad (random-0875; a settled block's final theta 4e-16; one still bouncing at
  the end, e > 0.9, is chaotic: not compared); rock onsets 3.6e-13 s, overturn, first impact and
  end times 1.1e-11 s; max |slide| 1.5e-8 R, a settled block's final slide 8.3e-6 R (random-0713,
  after 525 impacts at e = 0.96: chaotic, as the flat ground's own run with g changed in its 15th
  digit shows). Slide onsets and settle times are not compared: where a chaotic chain of bounces
  ends, and a slip at its end, moves as far on the flat ground under that change of g (slide
  onsets by up to 9.3e-4 s, random-0736; settle times 0.019 s, random-0713).
- The suite at 1e-12: max |theta| 8.8e-12 rad, final theta and slide 6.3e-8 (bounce_cosine_e09, e =
  0.9), max |slide| 8.9e-12 R, slide onset, first impact, overturn and end times 2.0e-10 s, rock
  onsets 1.4e-13 s; settle times not compared (4.2e-4 s, bounce_small_block_e08).

At the default tolerance (1e-8) the two engines are two discretizations each about that far from
the converged motion (the seat's engine integrates x, y and theta and projects the block back onto
its contacts at each event); the suite's fields differ by up to 9e-4 rad and 2.5e-3 s (a settle
time), so only the verdicts are checked there.

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
# Largest |seat - flat ground| allowed, per field (rad, s, or over R): see the docstring.
RK4_TOLERANCES = {"max_abs_theta": 1e-9, "overturn_time": 1e-9, "first_impact_time": 1e-9, "end_time": 1e-9,
                  "rock_start_time": 1e-9, "max_abs_slide": 1e-6}
RK4_SETTLED_TOLERANCES = {"final_theta": 1e-9, "final_slide": 3e-5}
TIGHT_SUITE_TOLERANCES = {"max_abs_theta": 1e-9, "final_theta": 1e-7, "final_slide": 1e-7, "max_abs_slide": 1e-9,
                          "slide_start_time": 1e-9, "first_impact_time": 1e-9, "overturn_time": 1e-9,
                          "end_time": 1e-9, "rock_start_time": 1e-9}
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


def beyond(records, tolerances):
    """Every compared value over its tolerance, as 'scene (seat): field d'."""
    return [f"{r['scene']} ({r['seat']}): {field} {r['differences'][field]:.3g} > {limit:g}"
            for r in records for field, limit in tolerances.items()
            if r["differences"][field] is not None and r["differences"][field] > limit]


def settled_on_flat_ground(data):
    return {s["name"] for s in data["scenes"] if s["runs"]["flat"].get("settled")}


def tight_suite_problems(data):
    """What the suite at tolerance 1e-12 must not show: a verdict difference or a field past its tolerance."""
    problems = [f"{r['scene']} ({r['seat']}): {'; '.join(r['verdicts'])}" for r in data["compared"] if r["verdicts"]]
    return problems + beyond(data["compared"], TIGHT_SUITE_TOLERANCES)


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
            for scene in data["scenes"]:
                runs = scene["runs"]
                assert runs["flat_perturbed"].get("status") == "ok", scene["name"]
                adaptive = scene["scene"].get("solver", {}).get("method", "adaptive") == "adaptive"
                assert ("flat_tight" in runs) == adaptive, scene["name"]
                if adaptive:
                    assert runs["flat_tight"].get("status") == "ok", scene["name"]
            assert all(r["flat_sensitivity"]["max_abs_theta"] is not None for r in data["compared"])

        def verdicts_equal():
            differing = [(r["scene"], r["seat"], v) for r in data["compared"] for v in r["verdicts"]
                         if v.split(":")[0] in ("overturned", "fell", "settled")]
            assert differing == [], differing

        def suite_onsets_equal():
            differing = [(r["scene"], r["seat"], v) for r in data["compared"] if r["group"] == "suite"
                         for v in r["verdicts"]]
            assert differing == [], differing

        def rk4_within_tolerances():
            rk4 = [r for r in data["compared"] if r["group"] == "random, rk4"]
            assert len(rk4) >= 10, len(rk4)
            settled = [r for r in rk4 if r["scene"] in settled_on_flat_ground(data)]
            onsets = [(r["scene"], v) for r in rk4 for v in r["verdicts"] if not v.startswith("slide_start_time")]
            problems = beyond(rk4, RK4_TOLERANCES) + beyond(settled, RK4_SETTLED_TOLERANCES)
            assert onsets == [] and problems == [], (onsets, problems)

        def temporary_folders_removed():
            assert list(scratch.iterdir()) == [], list(scratch.iterdir())

        check("exits 0 with a row per field", exits_0_with_the_table)
        check("the scenes released tilted run on both seats", runs_the_scenes_released_tilted)
        check("every run ends", every_run_ends)
        check("the flat ground's reference runs ran", reference_runs_ran)
        check("overturned, fell and settled equal", verdicts_equal)
        check("the suite's onset times present alike", suite_onsets_equal)
        check("RK4 scenes within their tolerances", rk4_within_tolerances)
        check("the temporary folders are removed", temporary_folders_removed)

        tight_result, tight = run(BLOCKFRAG, scratch, work / "tight.json", "--random", "0",
                                  "--adaptive-tolerance", "1e-12")

        def tight_suite_agrees():
            assert tight_result.returncode == 0, tight_result.stderr[-2000:]
            assert len(tight["compared"]) >= 60, len(tight["compared"])
            problems = tight_suite_problems(tight)
            assert problems == [], problems

        check("the suite at tolerance 1e-12 agrees", tight_suite_agrees)

        perturbing = work / "perturbing_blockfrag"
        perturbing.write_text(PERTURBING)
        perturbing.chmod(0o755)
        _, perturbed = run(perturbing, scratch, work / "perturbed.json", "--random", "0", "--adaptive-tolerance",
                           "1e-12")

        def a_perturbed_seat_fails_the_checks():
            problems = tight_suite_problems(perturbed)
            assert len(problems) == len(perturbed["compared"]), problems
            assert all(": max_abs_theta 1e-07 > 1e-09" in p for p in problems), problems

        check("a seat off by 1e-7 rad fails the checks", a_perturbed_seat_fails_the_checks)

    return summary()


if __name__ == "__main__":
    sys.exit(main())
