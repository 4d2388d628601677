#!/usr/bin/python3
"""A flat seat through the seat's engine against the flat ground's engine: a markdown table.

Not a test (tests/cli/flat_seat_crosscheck_test.py runs it small). A scene with a `seat` runs the
general planar contact (engine/seat/), one without it the flat ground's engine; a seat that is one
flat line under the block is the flat ground, so the two should give the same summary. Each scene
runs three ways: without a seat, on one long segment, and on two collinear segments that meet under
the block's base (the joint is a seat point the base slides over). The scenes:

- every scene of configs/accuracy_suite.json (its "scenes"[i]["scene"], as given: the adaptive
  solver at its default tolerance);
- N random scenes from a fixed seed: rectangles and convex polygons (4 to 10 vertices) of sizes
  0.1 to 5 m, friction 0.1 to 1.2, restitution 0 to 1 (10 % exactly 0), one of the sine, cosine,
  rectangular, Makris C_n, Ricker and Mavroeidis-Papageorgiou pulses (its peak 0.5 to 4 times the
  block's smaller threshold, either sign; records are left out: their strong motion starts late),
  5 % with a vertical pulse and 10 % on a dam crest, half with the adaptive solver (tolerance
  1e-8) and half with RK4 (dt 0.00025 s), and a fixed duration of 3 to 6 s.

Each seat's summary is compared with the flat ground's where both runs ended (status "ok"): the
verdicts (overturned, fell, settled, and whether each onset time exists) exactly; times in s,
angles in rad, slides over R (the block's farthest corner from its centre of mass). The report
gives the counts per group (the suite, the random scenes by solver: the agreement depends on it),
the largest |difference| per field with its scene and seat and how many scenes exceed 1e-9 on
either seat, what the values over 1e-9 are made of (the flat ground runs twice more: with g changed
in its 15th digit, which tells a chaotic value from a determined one, and nearer the converged
motion, the reference both engines' errors are measured against: an adaptive scene at tolerance
1e-12, an RK4 scene with a seat value over 1e-9 at a hundredth of its step), the verdict
differences, the runs without a result (refused by the seat's engine, or
stopped by the budgets: 10,000 events, 6 s of CPU time) and the bookkeeping fields the engines are not expected to share
(what each counts as an impact or an event, the steps each takes). --figure draws, per field, the
fraction of seat runs whose difference is at least x.

    /usr/bin/python3 tests/benchmarks/flat_seat_crosscheck.py --blockfrag build/mpi_driver/blockfrag \\
        --figure docs/flat_seat_crosscheck.png

About 45 s on 2 idle cores for the suite and 1,000 random scenes, most of it in the seat runs.
Each scene's files are written into a fresh temporary folder, removed after its runs.
"""

import argparse
import concurrent.futures
import json
import math
import random
import resource
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from shoelace import centroid

SOURCE = Path(__file__).resolve().parents[2]
SUITE = SOURCE / "configs" / "accuracy_suite.json"

TOLERANCE = 1e-9
# The seat's ends, either side of the base's middle (m): far past any slide of a few seconds.
SEAT_HALF_LENGTH = 100.0
# Where the two collinear segments meet, as a fraction of the base from its left corner: the
# suite's scenes all at one place; a random scene draws its own.
SUITE_JOINT = 0.37
SEATS = ("one_segment", "two_segments")
# exit code of blockfrag simulate for a scene that breaks a rule (refused before any work)
REFUSED = 2
# Every run's event budget (solver.max_events, both engines), far below the default 1,000,000: a
# block whose contact state keeps changing fails in seconds instead of minutes. The most events a
# run that ended took over the suite and 1,000 random scenes: 3,473 on the flat ground (rest under
# a ringing dam crest), 3,414 on a seat (random-0875, e = 0.95).
EVENT_BUDGET = 10000
# s of CPU time: a run that has used this much has no summary (a seat's storm of contact changes
# among three contacts costs up to 10 ms an event); the slowest run that ended took 0.26 s on a
# seat (random-0108) and 0.02 s on the flat ground. CPU time, not wall time: a machine loaded by other
# work slows a run's clock, not its work, and a limit on the clock turned slow runs into failures.
DEFAULT_RUN_TIMEOUT = 6.0
# A run that has not ended after this many times its CPU limit of wall time is stopped too: one
# that waits without working would never reach the CPU limit.
WALL_LIMIT_FACTOR = 20

# Two more runs of the flat ground tell what a seat's difference over the tolerance is made of:
# - PERTURBED, g * (1 + G_PERTURBATION) (5 ulps of 9.81): a change of the input no engine's
#   rounding could tell from none; a field it moves by more than SENSITIVE (a thousand times the
#   change) is amplified chaotically, and two implementations' roundings part as far (up to
#   AMPLIFICATION times as far: their roundings differ at every step, not in one input);
# - TIGHT, an adaptive scene at tolerance TIGHT_TOLERANCE, an RK4 scene at its step over
#   RK4_REFINEMENT: the reference both engines' errors at the scene's tolerance or step are
#   measured against. Two discretizations each that far from it differ by up to the sum of their
#   errors, whatever the tolerance asked of their agreement. An RK4 scene takes it only where a
#   seat's value is over the tolerance: at a hundredth of the step it costs a hundred runs.
PERTURBED = "flat_perturbed"
TIGHT = "flat_tight"
DEFAULT_G = 9.81
G_PERTURBATION = 1e-15
SENSITIVE = 1e-12
# A chaotic value's seat difference is at most this many times the flat ground's own change under
# g's: two implementations' roundings differ by far more than 5 ulps of one input, but a seat
# difference 1e5 to 1e7 times the flat ground's own change is a difference of rules (random-0690
# and random-0774 of --seed 7: the flat ground's lay_flat adding kinetic energy).
AMPLIFICATION = 1000
TIGHT_TOLERANCE = 1e-12
RK4_REFINEMENT = 100
DEFAULT_RK4_STEP = 2.5e-4  # s: the scene's default (docs/scenes.md)

VERDICTS = ("overturned", "fell", "settled")
# Each compared field with its unit: "R" is divided by the block's size before comparing.
COMPARED = {
    "max_abs_theta": "rad", "final_theta": "rad",
    "final_slide": "R", "max_abs_slide": "R",
    "rock_start_time": "s", "slide_start_time": "s", "first_impact_time": "s",
    "overturn_time": "s", "settle_time": "s", "end_time": "s",
}
# Fields both summaries have whose values count the engines' own work or diagnose their contacts:
# what each counts as an impact or an event, the steps each takes and where each measures
# penetration and the contact laws differ, so these are reported, not held to the tolerance.
BOOKKEEPING = ("impacts", "events", "steps", "rhs_evaluations", "painleve_events",
               "max_penetration", "max_contact_violation", "max_impact_energy_gain")
# The suite's scenes, and the random ones by solver: the two engines' agreement depends on it.
GROUPS = ("suite", "random, adaptive", "random, rk4")


# --- The block's frame: where its base is and how big it is ----------------------------------

def block_vertices(block):
    """The block's vertices in the frame the seat is given in: a rectangle's about its centre."""
    if "polygon" in block:
        return [tuple(v) for v in block["polygon"]]
    a, b = block["half_width"], block["half_height"]
    return [(-a, -b), (a, -b), (a, b), (-a, b)]


def block_size(vertices):
    """R: the farthest corner from the centre of mass, the unit of the slides compared."""
    cx, cy = centroid(vertices)
    return max(math.hypot(x - cx, y - cy) for x, y in vertices)


def base_of(vertices):
    """The base's height and its two ends' x (the block rests on its lowest edge)."""
    lowest = min(y for _, y in vertices)
    xs = sorted(x for x, y in vertices if y == lowest)
    return lowest, xs[0], xs[-1]


def flat_seats(block, joint_fraction):
    """The two flat seats under the block's base: one long segment, and two that meet under it."""
    y, left, right = base_of(block_vertices(block))
    middle = 0.5 * (left + right)
    start, end = [middle - SEAT_HALF_LENGTH, y], [middle + SEAT_HALF_LENGTH, y]
    joint = [left + joint_fraction * (right - left), y]
    return {"one_segment": [start, end], "two_segments": [start, joint, end]}


# --- Random scenes ----------------------------------------------------------------------------
# Only Random.random() is drawn from, so a seed gives the same scenes with every Python 3.

def uniform(rng, low, high):
    return low + (high - low) * rng.random()


def log_uniform(rng, low, high):
    return math.exp(uniform(rng, math.log(low), math.log(high)))


def pick(rng, options):
    return options[min(int(rng.random() * len(options)), len(options) - 1)]


def random_rectangle(rng):
    half_width = log_uniform(rng, 0.05, 1.5)
    return {"half_width": half_width, "half_height": half_width * log_uniform(rng, 0.5, 6.0)}


def random_convex_polygon(rng):
    """A convex polygon on its base (0, 0)-(w, 0): its other vertices on a half ellipse over the
    base, sheared so that the centre of mass stays over the middle 70 % of the base."""
    width = log_uniform(rng, 0.1, 3.0)
    height = width * log_uniform(rng, 0.5, 4.0)
    count = 2 + int(uniform(rng, 2, 9))
    # Angles 15 to 165 degrees and at least 5 apart: no vertex just above the base, no straight corner.
    angles = []
    while len(angles) < count - 2:
        angle = uniform(rng, math.radians(15), math.radians(165))
        if all(abs(angle - other) > math.radians(5) for other in angles):
            angles.append(angle)
    upper = [(0.5 * width * (1 + math.cos(a)), height * math.sin(a)) for a in sorted(angles)]
    centre_x, centre_y = centroid([(0.0, 0.0), (width, 0.0)] + upper)
    shear = (uniform(rng, 0.15, 0.85) * width - centre_x) / centre_y
    polygon = [[0.0, 0.0], [width, 0.0]] + [[x + shear * y, y] for x, y in upper]
    return {"polygon": polygon}


def tipping_threshold(block):
    """The smaller of the base corners' static tipping thresholds (horizontal arm over height)."""
    vertices = block_vertices(block)
    y, left, right = base_of(vertices)
    cx, cy = centroid(vertices)
    return min(cx - left, right - cx) / (cy - y)


def random_pulse(rng, amplitude):
    """One pulse of each kind the engine has (records aside: their strong motion starts late) and
    where it ends (s)."""
    kind = pick(rng, ("sine_pulse", "cosine_pulse", "rectangular_pulse", "makris_c", "ricker",
                      "mavroeidis_papageorgiou"))
    period = uniform(rng, 0.3, 2.0)
    if kind in ("sine_pulse", "cosine_pulse"):
        cycles = pick(rng, (0.5, 1, 1, 2))
        return {"type": kind, "amplitude_g": amplitude, "period": period, "cycles": cycles}, cycles * period
    if kind == "rectangular_pulse":
        duration = uniform(rng, 0.05, 1.0)
        return {"type": kind, "amplitude_g": amplitude, "duration": duration}, duration
    if kind == "makris_c":
        n = pick(rng, (1, 2))
        return {"type": kind, "amplitude_g": amplitude, "period": period, "n": n}, (n + 0.5) * period
    if kind == "ricker":
        period = uniform(rng, 0.3, 1.2)
        return {"type": kind, "amplitude_g": amplitude, "period": period}, 3 * period
    gamma = uniform(rng, 1.5, 3.0)
    # Its peak acceleration is about 2 pi Vp / Tp: Vp from the amplitude wanted.
    velocity = amplitude * 9.81 * period / (2 * math.pi)
    pulse = {"type": kind, "velocity_amplitude": velocity, "period": period, "gamma": gamma,
             "phase": uniform(rng, 0.0, 2 * math.pi)}
    return pulse, gamma * period


def random_solver(rng):
    if rng.random() < 0.5:
        return {"method": "adaptive"}
    return {"method": "rk4"}


def random_scene(rng):
    """A cheap random scene (a few seconds, fixed duration) and where its seat's joint is."""
    block = random_rectangle(rng) if rng.random() < 0.5 else random_convex_polygon(rng)
    friction = uniform(rng, 0.1, 1.2)
    restitution = 0.0 if rng.random() < 0.1 else rng.random()
    threshold = min(friction, tipping_threshold(block))
    sign = -1.0 if rng.random() < 0.5 else 1.0
    motion, motion_end = random_pulse(rng, sign * threshold * log_uniform(rng, 0.5, 4.0))
    scene = {"block": block, "contact": {"friction": friction, "restitution": restitution},
             "ground_motion": motion}
    if rng.random() < 0.05:
        vertical, _ = random_pulse(rng, uniform(rng, -0.5, 0.5))
        if vertical["type"] == "mavroeidis_papageorgiou":
            vertical = {"type": "sine_pulse", "amplitude_g": uniform(rng, -0.5, 0.5), "period": 0.5}
        scene["vertical_motion"] = vertical
    if rng.random() < 0.1:
        scene["dam"] = {"period": uniform(rng, 0.1, 0.4), "damping": 0.05}
    scene["solver"] = random_solver(rng)
    scene["duration"] = min(6.0, max(3.0, motion_end + 1.5))
    return scene, uniform(rng, 0.15, 0.85)


def random_cases(count, seed):
    rng = random.Random(seed)
    cases = []
    for index in range(count):
        scene, joint = random_scene(rng)
        group = f"random, {scene['solver']['method']}"
        cases.append(make_case(group, f"random-{index:04d}", scene, joint))
    return cases


def with_adaptive_tolerance(cases, tolerance):
    """The cases with every adaptive solver at this tolerance (the default's drift against a tighter one)."""
    for case in cases:
        solver = case["scene"].get("solver", {})
        if solver.get("method", "adaptive") == "adaptive":
            case["scene"]["solver"] = dict(solver, method="adaptive", tolerance=tolerance)
    return cases


def suite_cases():
    suite = json.loads(SUITE.read_text())
    cases = []
    for entry in suite["scenes"]:
        scene = json.loads(json.dumps(entry["scene"]))
        motion = scene["ground_motion"]
        if motion.get("type") == "record":  # a record's file is relative to the suite's folder
            motion["file"] = str((SUITE.parent / motion["file"]).resolve())
        cases.append(make_case("suite", entry["name"], scene, SUITE_JOINT))
    return cases


def make_case(group, name, scene, joint_fraction):
    return {"group": group, "name": name, "scene": scene, "seats": flat_seats(scene["block"], joint_fraction),
            "size": block_size(block_vertices(scene["block"]))}


# --- Running ----------------------------------------------------------------------------------

def with_event_budget(scene):
    solver = dict(scene.get("solver", {}))
    solver["max_events"] = min(solver.get("max_events", EVENT_BUDGET), EVENT_BUDGET)
    return dict(scene, solver=solver)


def cpu_limit(seconds):
    """The CPU time (s) a run may use: `seconds` rounded up to whole seconds, as the kernel counts it."""
    return max(1, math.ceil(seconds))


def children_cpu_seconds():
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def simulate(blockfrag, scene, path, timeout):
    """The summary of one run, or {"refused": message} / {"error": message}; with its wall time
    ("seconds") and CPU time ("cpu_seconds")."""
    path.write_text(json.dumps(with_event_budget(scene)))
    cpu = cpu_limit(timeout)

    def limit_cpu():  # in the child, before it runs blockfrag: the kernel stops it (SIGXCPU) there
        resource.setrlimit(resource.RLIMIT_CPU, (cpu, cpu + 1))

    started, cpu_started = time.monotonic(), children_cpu_seconds()
    try:
        result = subprocess.run([blockfrag, "simulate", str(path), "--summary-json"], capture_output=True,
                                text=True, timeout=WALL_LIMIT_FACTOR * cpu, check=False, preexec_fn=limit_cpu)
    except subprocess.TimeoutExpired:
        # subprocess.run has killed and waited for the child: its CPU time is counted.
        return {"error": f"no summary within {WALL_LIMIT_FACTOR * cpu:g} s of wall time",
                "seconds": time.monotonic() - started, "cpu_seconds": children_cpu_seconds() - cpu_started}
    seconds, cpu_seconds = time.monotonic() - started, children_cpu_seconds() - cpu_started
    if result.returncode in (-signal.SIGXCPU, -signal.SIGKILL):
        return {"error": f"no summary within {cpu:g} s of CPU time", "seconds": seconds, "cpu_seconds": cpu_seconds}
    message = result.stderr.strip().splitlines()[-1] if result.stderr.strip() else f"exit {result.returncode}"
    if result.returncode == REFUSED:
        return {"refused": message.replace(str(path), path.name), "seconds": seconds, "cpu_seconds": cpu_seconds}
    try:
        return dict(json.loads(result.stdout), seconds=seconds, cpu_seconds=cpu_seconds)
    except json.JSONDecodeError:
        return {"error": f"exit {result.returncode}: {message}", "seconds": seconds, "cpu_seconds": cpu_seconds}


def perturbed(scene):
    """The scene with g changed in its 15th digit: a change no engine's rounding could tell."""
    return dict(scene, g=scene.get("g", DEFAULT_G) * (1.0 + G_PERTURBATION))


def tightened(scene):
    """The scene at TIGHT_TOLERANCE if it is adaptive and looser, else None (its own run is the reference)."""
    solver = scene.get("solver", {})
    if solver.get("method", "adaptive") != "adaptive" or solver.get("tolerance", 1e-8) <= TIGHT_TOLERANCE:
        return None
    return dict(scene, solver=dict(solver, tolerance=TIGHT_TOLERANCE))


def refined(scene):
    """The scene at a step RK4_REFINEMENT times shorter if it is RK4, else None."""
    solver = scene.get("solver", {})
    if solver.get("method", "adaptive") != "rk4":
        return None
    return dict(scene, solver=dict(solver, dt=solver.get("dt", DEFAULT_RK4_STEP) / RK4_REFINEMENT))


def over_tolerance(runs, seats, size):
    """Whether a seat's field differs from the flat ground's by more than TOLERANCE."""
    flat = runs["flat"]
    if outcome(flat) != "ok":
        return False
    for seat in seats:
        if outcome(runs[seat]) != "ok":
            continue
        differences = [field_difference(flat, runs[seat], field, size) for field in COMPARED]
        if any(d is not None and d > TOLERANCE for d in differences):
            return True
    return False


def run_case(blockfrag, timeout, case):
    """The flat ground's summary and each seat's, in a fresh folder."""
    with tempfile.TemporaryDirectory(prefix="flat_seat_") as folder:
        folder = Path(folder)
        runs = {"flat": simulate(blockfrag, case["scene"], folder / "flat.json", timeout)}
        runs[PERTURBED] = simulate(blockfrag, perturbed(case["scene"]), folder / "perturbed.json", timeout)
        tight = tightened(case["scene"])
        if tight is not None:
            runs[TIGHT] = simulate(blockfrag, tight, folder / "tight.json", timeout)
        for seat, points in case["seats"].items():
            runs[seat] = simulate(blockfrag, dict(case["scene"], seat=points), folder / f"{seat}.json", timeout)
        fine = refined(case["scene"])
        if fine is not None and over_tolerance(runs, case["seats"], case["size"]):
            runs[TIGHT] = simulate(blockfrag, fine, folder / "tight.json", timeout * RK4_REFINEMENT)
    return dict(case, runs=runs)


def run_all(blockfrag, cases, jobs, timeout):
    count = len(cases)
    with concurrent.futures.ProcessPoolExecutor(max_workers=jobs) as pool:
        return list(pool.map(run_case, [blockfrag] * count, [timeout] * count, cases, chunksize=4))


# --- Comparing --------------------------------------------------------------------------------

def compare(flat, seat, size):
    """Per compared field |difference| (None where neither has the value) and the verdicts that differ
    (an onset time only one of them has is one)."""
    verdicts = [f"{field}: {flat.get(field)} flat, {seat.get(field)} seat"
                for field in VERDICTS if flat.get(field) != seat.get(field)]
    differences = {}
    for field in COMPARED:
        difference = field_difference(flat, seat, field, size)
        differences[field] = None if difference == math.inf else difference
        if difference == math.inf:
            verdicts.append(f"{field}: {number(flat.get(field))} flat, {number(seat.get(field))} seat")
    bookkeeping = {field: abs(flat[field] - seat[field]) for field in BOOKKEEPING}
    bookkeeping["modes"] = [m for _, m in flat["modes"]] != [m for _, m in seat["modes"]]
    return differences, verdicts, bookkeeping


def field_difference(a, b, field, size):
    """|a - b| in the field's unit; infinite where only one run has the value, None where neither."""
    x, y = a.get(field), b.get(field)
    if x is None and y is None:
        return None
    if x is None or y is None:
        return math.inf
    return abs(x - y) / (size if COMPARED[field] == "R" else 1.0)


def references(result, seat):
    """Per field, the flat ground's sensitivity (|flat - flat with g changed in its 15th digit|), and
    the flat ground's and the seat's errors (|run - the flat ground's reference run|; None without it)."""
    runs, size = result["runs"], result["size"]
    perturbed_run, tight = runs[PERTURBED], runs.get(TIGHT)

    def error(run, field):
        if tight is None:
            return None
        return field_difference(run, tight, field, size) if outcome(tight) == "ok" else math.inf

    return {"flat_sensitivity": {field: field_difference(runs["flat"], perturbed_run, field, size)
                                 if outcome(perturbed_run) == "ok" else math.inf for field in COMPARED},
            "flat_error": {field: error(runs["flat"], field) for field in COMPARED},
            "seat_error": {field: error(runs[seat], field) for field in COMPARED}}


# What a seat's difference over the tolerance is made of, in the order they are tried: a chaotic
# value's reference is as chaotic as the engines, so only a determined one is measured against it.
EXPLANATIONS = {
    "chaotic": f"chaotic (the flat ground's own value moves by more than {SENSITIVE:g} when g changes in its "
               f"15th digit, and by at least 1/{AMPLIFICATION} of the difference)",
    "as accurate": "the seat as near the reference as the flat ground",
    "within 10x": "the seat's error within 10 times the flat ground's",
    "neither": "neither",
}


def explanation(record, field):
    """One of EXPLANATIONS' keys for a seat run's field over the tolerance."""
    sensitivity = record["flat_sensitivity"][field]
    if sensitivity is not None and sensitivity > SENSITIVE and \
            record["differences"][field] <= AMPLIFICATION * sensitivity:
        return "chaotic"
    flat_error, seat_error = record["flat_error"][field], record["seat_error"][field]
    if flat_error is None or seat_error is None:
        return "neither"
    if seat_error <= flat_error:
        return "as accurate"
    return "within 10x" if seat_error <= 10 * flat_error else "neither"


def outcome(run):
    """"ok", or why a run gave no result to compare."""
    if "refused" in run:
        return "refused: " + run["refused"]
    if "error" in run:
        return run["error"]
    if run["status"] != "ok":
        return f"failed at t = {run['end_time']:.4g} s: {run['status_reason']}"
    return "ok"


def is_refusal(outcome_text):
    return outcome_text.startswith("refused")


def comparisons(results):
    """One record per scene and seat: the differences where both engines ran to the end, else why not."""
    compared, unfinished = [], []
    for result in results:
        flat = result["runs"]["flat"]
        for seat in SEATS:
            run = result["runs"][seat]
            where = {"group": result["group"], "scene": result["name"], "seat": seat}
            flat_outcome, seat_outcome = outcome(flat), outcome(run)
            if flat_outcome != "ok" or seat_outcome != "ok":
                unfinished.append(dict(where, flat_outcome=flat_outcome, seat_outcome=seat_outcome))
                continue
            differences, verdicts, bookkeeping = compare(flat, run, result["size"])
            record = dict(where, differences=differences, verdicts=verdicts, bookkeeping=bookkeeping,
                          **references(result, seat))
            record["explanations"] = {field: explanation(record, field) for field, d in differences.items()
                                      if d is not None and d > TOLERANCE}
            compared.append(record)
    return compared, unfinished


def field_maximum(records, field, key="differences"):
    """The largest value of a field over records, where it is (scene and seat), and how many scenes
    exceed the tolerance on either seat."""
    best, where, over = None, "-", set()
    for record in records:
        value = record[key].get(field)
        if value is None:
            continue
        value = float(value)
        if best is None or value > best:
            best, where = value, f"{record['scene']} ({record['seat'].replace('_', ' ')})"
        if value > TOLERANCE:
            over.add(record["scene"])
    return best, where, len(over)


# --- Reporting --------------------------------------------------------------------------------

def number(value):
    if value is None:
        return "null"
    if isinstance(value, bool):
        return str(value).lower()
    return "0" if value == 0 else f"{value:.3g}"


def by_group(records, group):
    return [record for record in records if record["group"] == group]


def scenes_of(records):
    return len({record["scene"] for record in records})


def markdown(header, rows):
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    return lines + ["| " + " | ".join(row) + " |" for row in rows]


def counts_table(results, compared, unfinished):
    """Per group: scenes, seat runs compared, with a verdict difference, unfinished by which engine."""
    header = ["scenes", "count", "seat runs compared", "with a verdict difference", "refused",
              "seat failed or stopped, flat ran", "flat failed, seat ran", "both failed"]
    rows = []
    for group in GROUPS:
        mine = by_group(unfinished, group)
        refused = [r for r in mine if is_refusal(r["flat_outcome"]) or is_refusal(r["seat_outcome"])]
        others = [r for r in mine if r not in refused]
        rows.append([group, str(sum(1 for r in results if r["group"] == group)), str(len(by_group(compared, group))),
                     str(sum(1 for r in by_group(compared, group) if r["verdicts"])), str(len(refused)),
                     str(sum(1 for r in others if r["flat_outcome"] == "ok")),
                     str(sum(1 for r in others if r["seat_outcome"] == "ok")),
                     str(sum(1 for r in others if "ok" not in (r["flat_outcome"], r["seat_outcome"])))])
    return markdown(header, rows)


def maxima_table(compared):
    header = ["field", "unit"]
    for group in GROUPS:
        header += [f"{group}: max \\|d\\|", "where", f"> {TOLERANCE:g}"]
    rows = []
    for field, unit in COMPARED.items():
        row = [f"`{field}`", unit]
        for group in GROUPS:
            value, where, over = field_maximum(by_group(compared, group), field)
            row += ["-" if value is None else number(value), where, str(over)]
        rows.append(row)
    return markdown(header, rows)


def verdict_kinds_table(compared):
    """Per verdict field, how many scenes of each group differ in it on either seat."""
    kinds = list(VERDICTS) + list(COMPARED)
    rows = []
    for kind in kinds:
        counts = [scenes_of([r for r in by_group(compared, group)
                             if any(v.startswith(kind + ":") for v in r["verdicts"])]) for group in GROUPS]
        if any(counts):
            rows.append([f"`{kind}`"] + [str(c) for c in counts])
    return markdown(["verdict differing"] + list(GROUPS), rows) if rows else ["none"]


def per_scene_lines(records, describe):
    """One line per scene: both seats together when they say the same."""
    lines, by_scene = [], {}
    for record in records:
        by_scene.setdefault((record["group"], record["scene"]), []).append(record)
    for (group, scene), mine in by_scene.items():
        texts = {describe(r) for r in mine}
        if len(texts) == 1 and len(mine) == len(SEATS):
            lines.append(f"- {scene} ({group}, both seats): {texts.pop()}")
        else:
            lines += [f"- {scene} ({group}, {r['seat'].replace('_', ' ')}): {describe(r)}" for r in mine]
    return lines


def explained_table(compared):
    """Per group, the (seat run, field) values over the tolerance by what they are made of."""
    header = ["scenes", "values over the tolerance"] + list(EXPLANATIONS.values())
    rows = []
    for group in GROUPS:
        over = [(r, field) for r in by_group(compared, group) for field in COMPARED
                if r["differences"][field] is not None and r["differences"][field] > TOLERANCE]
        kinds = [r["explanations"][field] for r, field in over]
        cells = []
        for kind in EXPLANATIONS:
            mine = [r for (r, _), k in zip(over, kinds) if k == kind]
            cells.append(f"{len(mine)} ({scenes_of(mine)} scenes)")
        rows.append([group, f"{len(over)} ({scenes_of([r for r, _ in over])} scenes)"] + cells)
    return markdown(header, rows)


def unexplained_lines(compared):
    lines = []
    for r in compared:
        for field in COMPARED:
            d = r["differences"][field]
            if d is not None and d > TOLERANCE and r["explanations"][field] == "neither":
                flat_error, seat_error = r["flat_error"][field], r["seat_error"][field]
                lines.append(f"- {r['scene']} ({r['group']}, {r['seat'].replace('_', ' ')}): `{field}` {number(d)}; "
                             f"the flat ground's sensitivity {number(r['flat_sensitivity'][field])}"
                             + ("" if flat_error is None else
                                f", errors: flat ground {number(flat_error)}, seat {number(seat_error)}"))
    return lines or ["none"]


def bookkeeping_table(compared):
    header = ["field"] + [f"{group}: max \\|d\\|" for group in GROUPS] + [f"{group}: scenes" for group in GROUPS]
    rows = []
    for field in BOOKKEEPING + ("modes",):
        row = [f"`{field}`" if field != "modes" else "the modes' sequence"]
        for group in GROUPS:
            value, _, _ = field_maximum(by_group(compared, group), field, key="bookkeeping")
            row.append("-" if field == "modes" or value is None else number(value))
        for group in GROUPS:
            row.append(str(scenes_of([r for r in by_group(compared, group) if r["bookkeeping"][field]])))
        rows.append(row)
    return markdown(header, rows)


def timing_line(results, seconds, jobs):
    def summed(key, runs):
        return sum(r["runs"][run][key] for r in results for run in runs if run in r["runs"])
    return (f"{seconds:.0f} s with {jobs} jobs; runs' CPU time summed: flat ground "
            f"{summed('cpu_seconds', ['flat']):.0f} s, seats {summed('cpu_seconds', SEATS):.0f} s, the flat "
            f"ground's reference runs {summed('cpu_seconds', [PERTURBED, TIGHT]):.0f} s "
            f"(wall time {summed('seconds', ['flat']):.0f} s, {summed('seconds', SEATS):.0f} s and "
            f"{summed('seconds', [PERTURBED, TIGHT]):.0f} s)")


def report(results, compared, unfinished, seconds, jobs):
    lines = [timing_line(results, seconds, jobs), ""]
    lines += counts_table(results, compared, unfinished)
    lines += ["", f"Largest |difference| over the seat runs both engines ran to the end (seat against flat "
              f"ground; `> {TOLERANCE:g}`: scenes over it on either seat):", ""]
    lines += maxima_table(compared)
    lines += ["", f"What the values over {TOLERANCE:g} are made of (a seat run's field each; g changed in "
              f"its 15th digit: g (1 + {G_PERTURBATION:g}); errors: against the flat ground at tolerance "
              f"{TIGHT_TOLERANCE:g} for an adaptive scene, at a {RK4_REFINEMENT}th of its step for an RK4 "
              f"one):", ""]
    lines += explained_table(compared)
    lines += ["", "Neither:", ""] + unexplained_lines(compared)
    lines += ["", "Verdict differences (scenes, either seat; an onset time only one engine has counts):", ""]
    lines += verdict_kinds_table(compared)
    lines += [""] + per_scene_lines([r for r in compared if r["verdicts"]], lambda r: "; ".join(r["verdicts"]))
    lines += ["", "Runs without a result to compare:" if unfinished else "Runs without a result to compare: none", ""]
    lines += per_scene_lines(unfinished, lambda r: f"flat {r['flat_outcome']}; seat {r['seat_outcome']}")
    lines += ["", "Bookkeeping (what each engine counts; not expected to agree):", ""]
    lines += bookkeeping_table(compared)
    return "\n".join(lines)


def draw_figure(compared, path):
    """Per field, the fraction of seat runs whose |difference| is at least x, by group."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fields = list(COMPARED)
    columns = 5
    rows = math.ceil(len(fields) / columns)
    figure, axes = plt.subplots(rows, columns, figsize=(3.4 * columns, 3.1 * rows), sharey=True, squeeze=False)
    colours = dict(zip(GROUPS, ("#D55E00", "#0072B2", "#009E73")))
    for axis, field in zip(axes.flat, fields):
        for group in GROUPS:
            values = [r["differences"][field] for r in by_group(compared, group)
                      if r["differences"][field] is not None]
            if not values:
                continue
            positive = sorted((v for v in values if v > 0), reverse=True)
            fraction = [(i + 1) / len(values) for i in range(len(positive))]
            label = f"{group}: {len(values) - len(positive)} of {len(values)} equal"
            if positive:
                axis.step(positive, fraction, where="post", color=colours[group], label=label)
            else:
                axis.plot([], [], color=colours[group], label=label)
        # The flat ground against itself with g changed in its 15th digit: how far a summary moves
        # under a change no rounding could tell, over the random scenes (each scene once).
        own = [r["flat_sensitivity"][field] for r in compared
               if r["group"] != "suite" and r["seat"] == SEATS[0] and r["flat_sensitivity"][field] is not None]
        if own:
            positive = sorted((min(v, 10.0) for v in own if v > 0), reverse=True)
            axis.step(positive, [(i + 1) / len(own) for i in range(len(positive))], where="post",
                      color="grey", linestyle=":", label="flat ground, g (1 + 1e-15): random")
        axis.axvline(TOLERANCE, color="black", linestyle="--", linewidth=0.8)
        axis.set_xscale("log")
        axis.set_yscale("log")
        axis.set_xlim(1e-17, 10)
        axis.set_title(f"{field} [{COMPARED[field]}]", fontsize=9)
        axis.legend(fontsize=6, loc="lower left")
        axis.tick_params(labelsize=7)
    for axis in axes.flat[len(fields):]:
        axis.set_visible(False)
    for axis in axes[:, 0]:
        axis.set_ylabel("fraction of seat runs with |d| >= x", fontsize=8)
    for axis in axes[-1, :]:
        axis.set_xlabel("|seat - flat ground|", fontsize=8)
    figure.suptitle("A flat seat (one segment, two collinear ones) against the flat ground, runs both ended; "
                    f"dashed: {TOLERANCE:g}", fontsize=10)
    figure.tight_layout()
    figure.savefig(path, dpi=110)
    plt.close(figure)


def write_json(path, results, compared, unfinished, seconds):
    scenes = [{key: r[key] for key in ("group", "name", "scene", "seats", "size", "runs")} for r in results]
    path.write_text(json.dumps({"tolerance": TOLERANCE, "seconds": seconds, "compared": compared,
                                "unfinished": unfinished, "scenes": scenes}, indent=1))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--blockfrag", required=True, help="the blockfrag executable")
    parser.add_argument("--random", type=int, default=1000, help="how many random scenes (default 1000)")
    parser.add_argument("--seed", type=int, default=20261127, help="the random scenes' seed")
    parser.add_argument("--jobs", type=int, default=2, help="runs at once (default 2)")
    parser.add_argument("--no-suite", action="store_true", help="the random scenes only")
    parser.add_argument("--timeout", type=float, default=DEFAULT_RUN_TIMEOUT,
                        help=f"s of CPU time a run may use before it counts as without a summary, rounded up "
                             f"to whole seconds (default {DEFAULT_RUN_TIMEOUT:g}; a run is also stopped after "
                             f"{WALL_LIMIT_FACTOR} times this of wall time)")
    parser.add_argument("--adaptive-tolerance", type=float,
                        help="run every adaptive scene (the suite's too) at this tolerance instead of its own")
    parser.add_argument("--figure", type=Path, help="write the differences' distributions here (PNG)")
    parser.add_argument("--json", type=Path, help="write every scene, run and comparison here")
    args = parser.parse_args()
    if args.random < 0 or args.jobs < 1 or args.timeout <= 0:
        parser.error("--random must be >= 0, --jobs >= 1 and --timeout > 0")

    started = time.monotonic()
    cases = ([] if args.no_suite else suite_cases()) + random_cases(args.random, args.seed)
    if args.adaptive_tolerance:
        cases = with_adaptive_tolerance(cases, args.adaptive_tolerance)
    results = run_all(args.blockfrag, cases, args.jobs, args.timeout)
    compared, unfinished = comparisons(results)
    seconds = time.monotonic() - started
    print(report(results, compared, unfinished, seconds, args.jobs))
    if args.figure:
        draw_figure(compared, args.figure)
    if args.json:
        write_json(args.json, results, compared, unfinished, seconds)
    return 0


if __name__ == "__main__":
    sys.exit(main())
