#!/usr/bin/env bash
# Hostile inputs to the records and to the accuracy and bench commands: a record under the file
# size cap that would need gigabytes, a record of more knots than the event budget, and options
# whose values overflow or would fail every scene later. Each is refused before any work (exit 2,
# naming the file and line or the option) or runs to a correct result.
set -u
source "$(dirname "$0")/../support/script_test.sh"
source "$(dirname "$0")/../support/hostile_case.sh"
cd "$work" || exit 1

# --- Records: memory ----------------------------------------------------------------------------
# 134 million samples declared (a 268 MB file at DT 0.00074 s lies under the size and duration
# caps, and needed about 23 GB): refused at line 4, before a value is read.
printf 'PEER NGA STRONG MOTION DATABASE RECORD\nhostile\nACCELERATION TIME SERIES IN UNITS OF G\nNPTS= 134000000, DT= 0.00074 SEC\n 0.1 0.2 0.3 0.4\n' >huge.AT2
scene_with ground_motion '{"type": "record", "file": "huge.AT2"}' >huge_at2.json
run_case at2_npts_134e6 2 'huge_at2.json: /ground_motion/file: huge.AT2:4: NPTS = "134000000" is more than 4000000 samples' \
  "$B" simulate huge_at2.json
# A two-column record of one sample more than the cap: refused at that line.
awk 'BEGIN { for (k = 0; k <= 4000000; ++k) printf "%.3f 0\n", k * 0.001 }' >over_cap.txt
scene_with ground_motion '{"type": "record", "file": "over_cap.txt"}' >over_cap.json
run_case two_column_over_sample_cap 2 "over_cap.json: /ground_motion/file: over_cap.txt:4000001: more than 4000000 samples" \
  "$B" simulate over_cap.json

# --- Records: knots are not events ----------------------------------------------------------------
# 1,100,000 samples of 0.01 g, far below friction and tipping: the block never moves, and its
# 1,100,000 knots are not 1,100,000 contact events (the event budget is 1,000,000).
awk 'BEGIN { for (k = 0; k < 1100000; ++k) printf "%.2f %.4f\n", k * 0.01, 0.01 * sin(k * 0.1) }' >long.txt
scene_with ground_motion '{"type": "record", "file": "long.txt"}' >long.json
"$PYTHON" - long.json <<'PY'
import json, sys
scene = json.load(open(sys.argv[1])); del scene["duration"]; json.dump(scene, open(sys.argv[1], "w"))
PY
run_case record_of_1.1e6_samples_at_rest 0 '"status":"ok"' "$B" simulate long.json --summary-json
"$PYTHON" - record_of_1.1e6_samples_at_rest.out <<'PY' && pass || fail "record_of_1.1e6_samples_at_rest: $(head -c 300 record_of_1.1e6_samples_at_rest.out)"
import json, sys
summary = json.load(open(sys.argv[1]))
assert summary["events"] <= 2 and summary["max_abs_theta"] == 0 and summary["max_abs_slide"] == 0, summary
PY

# --- accuracy and bench options ---------------------------------------------------------------------
suite="$BLOCKFRAG_SOURCE_DIR/configs/accuracy_suite.json"
run_case accuracy_min_batch_ms_1e300 2 "--min-batch-ms: Value 1e300 not in range" \
  "$B" accuracy "$suite" --setting adaptive:1e-4 --min-batch-ms 1e300 --output acc.h5
[[ ! -e acc.h5 ]] && pass || fail "accuracy_min_batch_ms_1e300 wrote acc.h5"
run_case accuracy_setting_rk4_1e-300 2 '--setting: setting "rk4:1e-300": a step dt must be in [1e-07, 10] s' \
  "$B" accuracy "$suite" --setting rk4:1e-300 --output acc.h5
run_case accuracy_setting_tolerance_1e-20 2 '--setting: setting "adaptive:1e-20": a tolerance must be in [1e-14, 0.1]' \
  "$B" accuracy "$suite" --setting adaptive:1e-20 --output acc.h5
# A billion timed runs reserved 8 GB before the first.
run_case bench_repeat_1e9 2 "--repeat: Value 1000000000 not in range" \
  "$B" bench "$BLOCKFRAG_SOURCE_DIR/configs/paper_example.json" --repeat 1000000000

echo "$passed passed, $failed failed"
[[ $failed -eq 0 ]]
