#!/usr/bin/env bash
# `blockfrag simulate` end to end: every scene of tests/data/bad_scenes is refused with exit code 2
# and the messages of its .expected file on stderr; the paper's example gives exactly one JSON
# object with every summary key, a report, and a history CSV; command-line errors exit 2, I/O
# errors 1, a failed simulation 3; a scene with a recorded ground motion named relative to its
# folder runs, and a missing record exits 2. Prints "N passed, M failed" last; exits non-zero on any
# failure.
set -u
source "$(dirname "$0")/../support/script_test.sh"

example="$BLOCKFRAG_SOURCE_DIR/configs/paper_example.json"

# --- The bad-scene corpus ---------------------------------------------------------------------------
corpus=("$BLOCKFRAG_SOURCE_DIR"/tests/data/bad_scenes/*.json)
check "the bad-scene corpus has at least 15 files (has ${#corpus[@]})" test "${#corpus[@]}" -ge 15
for scene in "${corpus[@]}"; do
  name=$(basename "$scene" .json)
  expected="${scene%.json}.expected"
  run simulate "$scene"
  if [[ $code -ne 2 ]]; then
    fail "$name: exit code $code, expected 2 (stderr: $(head -c 300 "$work/err"))"
    continue
  fi
  if [[ -s "$work/out" ]]; then
    fail "$name: wrote to stdout"
    continue
  fi
  missing=0
  while IFS= read -r fragment; do
    [[ -z "$fragment" ]] && continue
    if ! grep -qF -- "$fragment" "$work/err"; then
      fail "$name: stderr lacks '$fragment'; it was: $(cat "$work/err")"
      missing=1
    fi
  done <"$expected"
  [[ $missing -eq 0 ]] && pass
done

# --- The paper's example as one JSON object ---------------------------------------------------------
run simulate "$example" --summary-json
check "paper example --summary-json exits 0 (got $code: $(head -c 300 "$work/err"))" test "$code" -eq 0
cp "$work/out" "$work/summary.json"
check "stdout is exactly one JSON object with every summary key" "$PYTHON" -c '
import json, math, sys
text = open(sys.argv[1]).read()
summary = json.loads(text)  # refuses anything after the object ("Extra data")
assert isinstance(summary, dict), "not an object"
keys = {"status", "status_reason", "overturned", "overturn_time", "max_abs_theta", "final_theta",
        "final_slide", "max_abs_slide", "rock_start_time", "slide_start_time", "first_impact_time",
        "impacts", "modes", "end_time", "steps", "rhs_evaluations", "events", "max_impact_energy_gain",
        "fell", "fell_time"}
assert keys <= set(summary), ("missing", keys - set(summary))  # the engine may report more
assert summary["fell"] is False and summary["fell_time"] is None  # the flat ground has no ends
assert summary["status"] == "ok" and summary["status_reason"] is None, summary["status"]
assert isinstance(summary["overturned"], bool)
assert (summary["overturn_time"] is None) != summary["overturned"]
for key in ("impacts", "steps", "rhs_evaluations", "events"):
    assert isinstance(summary[key], int) and summary[key] >= 0, key
assert 0 < summary["end_time"] <= 4.0
names = {"rest", "slide", "rock", "slide_rock", "flight"}
times = [t for t, mode in summary["modes"]]
assert summary["modes"] and all(mode in names for t, mode in summary["modes"]), summary["modes"][:5]
assert times == sorted(times) and 0 <= times[0], times[:5]
assert abs(summary["final_theta"]) <= summary["max_abs_theta"] < math.pi / 2 + 1e-9 or summary["overturned"]
' "$work/summary.json"

run simulate "$example" --summary-json
check "a second run prints the same bytes" cmp -s "$work/out" "$work/summary.json"

# --- The report ----------------------------------------------------------------------------------------
run simulate "$example"
check "paper example report exits 0" test "$code" -eq 0
check "the report has a verdict and the rotation against alpha" \
  grep -qE "^verdict: (did not overturn|overturned at t = )" "$work/out"
check "the report gives max |theta| as a fraction of alpha" grep -qE "^max \|theta\|: .* rad = .* alpha" "$work/out"
check "the report's impact count is the summary's" "$PYTHON" -c '
import json, re, sys
impacts = json.load(open(sys.argv[1]))["impacts"]
report = open(sys.argv[2]).read()
assert re.search(r"impacts: %d\n" % impacts, report), (impacts, report)
' "$work/summary.json" "$work/out"

# --- The history CSV -------------------------------------------------------------------------------------
run simulate "$example" --summary-json --history "$work/history.csv" --history-interval 0.01
check "--history exits 0 (got $code: $(head -c 300 "$work/err"))" test "$code" -eq 0
check "--history leaves no temporary file" test ! -e "$work/history.csv.tmp"
check "--history writes the header and rows from rest at t = 0 to the end time" "$PYTHON" -c '
import csv, json, math, sys
summary = json.load(open(sys.argv[2]))
with open(sys.argv[1], newline="") as f:
    rows = list(csv.reader(f))
assert rows[0] == ["t", "x", "y", "theta", "vx", "vy", "omega", "mode", "friction_per_weight",
                   "normal_per_weight"], rows[0]
data = rows[1:]
assert all(len(row) == 10 for row in data)
names = {"rest", "slide", "rock", "slide_rock", "flight"}
assert all(row[7] in names for row in data), {row[7] for row in data} - names
values = [[float(x) for i, x in enumerate(row) if i != 7] for row in data]
assert all(math.isfinite(x) for row in values for x in row)
t = [row[0] for row in values]
end = summary["end_time"]
# rows at 0, 0.01, 0.02, ... and at the end time
assert t[0] == 0 and t[-1] == end, (t[0], t[-1], end)
assert len(t) in (math.floor(end / 0.01 + 1e-9) + 1, math.floor(end / 0.01 + 1e-9) + 2), len(t)
assert all(abs(b - a - 0.01) < 1e-9 for a, b in zip(t[:-2], t[1:-1])), "uneven spacing"
# Released from rest, flat on its base: x = 0, y = b = 1, theta = 0, no velocity.
x, y, theta, vx, vy, omega = values[0][1:7]
assert (x, y, theta, vx, vy, omega) == (0, 1.0, 0, 0, 0, 0), values[0]
' "$work/history.csv" "$work/out"
check "the summary does not depend on whether the history is recorded" "$PYTHON" -c '
import json, sys
plain, observed = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
for key in ("status", "overturned", "overturn_time", "max_abs_theta", "final_theta", "final_slide",
            "max_abs_slide", "rock_start_time", "slide_start_time", "first_impact_time", "impacts",
            "modes", "end_time"):
    assert plain[key] == observed[key], (key, plain[key], observed[key])
' "$work/summary.json" "$work/out"

# --- A recorded ground motion --------------------------------------------------------------------------------
# The scene names its record by a path relative to the scene file's folder, not to the working folder.
# Scaled to a PGA of 0.15 g, below a/b = 0.2 and mu = 0.7, the block cannot move at all; scaled to 0.5 g
# it rocks.
record_scene="$BLOCKFRAG_SOURCE_DIR/tests/data/records/record_scene.json"
(cd "$work" && "$BLOCKFRAG" simulate "$record_scene" --summary-json >"$work/out" 2>"$work/err")
code=$?
check "a scene with a relative record exits 0 from another folder (got $code: $(head -c 300 "$work/err"))" \
  test "$code" -eq 0
check "below a/b and mu the record does not move the block" "$PYTHON" -c '
import json, sys
summary = json.load(open(sys.argv[1]))
assert summary["status"] == "ok", summary["status"]
assert summary["max_abs_theta"] == 0 and summary["final_slide"] == 0, summary
assert [mode for t, mode in summary["modes"]] == ["rest"], summary["modes"]
' "$work/out"
"$PYTHON" -c '
import json, sys
scene = json.load(open(sys.argv[1]))
scene["ground_motion"]["file"] = sys.argv[3] + "/decaying_sine.AT2"
scene["ground_motion"]["target_pga_g"] = 0.5
json.dump(scene, open(sys.argv[2], "w"))
scene["ground_motion"]["file"] = "no_such_record.AT2"
json.dump(scene, open(sys.argv[2] + ".missing", "w"))
' "$record_scene" "$work/record_strong.json" "$(dirname "$record_scene")"
run simulate "$work/record_strong.json" --summary-json
check "the record scaled to 0.5 g rocks the block (exit $code)" "$PYTHON" -c '
import json, sys
summary = json.load(open(sys.argv[1]))
assert summary["status"] == "ok" and summary["max_abs_theta"] > 1e-3, summary
' "$work/out"
run simulate "$work/record_strong.json.missing"
check "a missing record exits 2 naming the file (got $code: $(head -c 300 "$work/err"))" \
  grep -qF "/ground_motion/file: $work/no_such_record.AT2: no such file" "$work/err"
check "and exits 2" test "$code" -eq 2

# --- Exit codes --------------------------------------------------------------------------------------------
run simulate "$work/no_such_scene.json"
check "a missing scene file exits 2 (got $code)" test "$code" -eq 2
run simulate "$example" --no-such-option
check "an unknown option exits 2 (got $code)" test "$code" -eq 2
run
check "no subcommand exits 2 (got $code)" test "$code" -eq 2
for interval in 0 -1 nan inf abc; do
  run simulate "$example" --history "$work/h.csv" --history-interval "$interval"
  check "--history-interval $interval exits 2 (got $code)" test "$code" -eq 2
done
run simulate "$example" --history "$work/no/such/folder/h.csv"
check "a history file in a missing folder exits 2 before the run (got $code)" test "$code" -eq 2
check "a history file in a missing folder is named with the folder" \
  grep -q "the folder $work/no/such/folder does not exist" "$work/err"
run --version
check "--version exits 0 and prints the version (got $code)" grep -qE "^blockfrag [0-9]+\.[0-9]+\.[0-9]+" "$work/out"
run simulate --help
check "simulate --help exits 0 (got $code) and names the options" grep -q -- "--history-interval" "$work/out"

"$PYTHON" -c '
import json, sys
scene = json.load(open(sys.argv[1]))
scene["solver"]["max_steps"] = 1
json.dump(scene, open(sys.argv[2], "w"))
' "$example" "$work/budget.json"
run simulate "$work/budget.json" --summary-json
check "a simulation over its step budget exits 3 (got $code)" test "$code" -eq 3
check "and still prints its summary with status failed and a reason" "$PYTHON" -c '
import json, sys
summary = json.load(open(sys.argv[1]))
assert summary["status"] == "failed" and isinstance(summary["status_reason"], str) and summary["status_reason"]
' "$work/out"

echo "$passed passed, $failed failed"
[[ $failed -eq 0 ]]
