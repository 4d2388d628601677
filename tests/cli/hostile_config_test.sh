#!/usr/bin/env bash
# Configs a hostile or careless user can give to simulate, run and spectrum whose fault shows only
# in several values together or in a whole token: each must be refused before any work with exit
# code 2 and a message naming the file and the JSON path (or line), quoting no more than a short
# excerpt of the file and leaving no file behind. Every case runs under a time limit and a memory
# limit (tests/support/hostile_case.sh).
set -u
source "$(dirname "$0")/../support/script_test.sh"
source "$(dirname "$0")/../support/hostile_case.sh"
cd "$work" || exit 1

# no_files_left NAME FILE...: one pass when none of the files exists.
no_files_left() {
  local name=$1 file
  shift
  for file in "$@"; do
    if [[ -e $file ]]; then
      fail "$name left $file"
      return
    fi
  done
  pass
}

# --- A seat fixes the block's geometry ------------------------------------------------------------
# seat_study INPUTS_JSON > file: a study of a rectangle on a flat seat, drawing INPUTS_JSON.
seat_study() {
  "$PYTHON" - "$1" <<'PY'
import json, sys
study = {"scene": {"block": {"half_width": 0.5, "half_height": 1.0}, "seat": [[-2, -1], [2, -1]],
                   "contact": {"friction": 0.7, "restitution": 0.7},
                   "ground_motion": {"type": "cosine_pulse", "amplitude_g": 1.0, "period": 1.0, "cycles": 1}},
         "inputs": json.loads(sys.argv[1]),
         "intensity_measure": {"type": "pga", "levels": [0.5, 1.0]}, "samples_per_level": 10,
         "limit_states": [{"name": "overturn", "type": "overturning"}], "seed": 1, "output": "seat.h5"}
print(json.dumps(study))
PY
}
seat_study '{"half_height": {"distribution": "uniform", "min": 0.5, "max": 2.0}}' >seat_height.json
run_case seat_sampled_half_height 2 \
  "seat_height.json: /inputs/half_height: varies the block's size, but /scene/seat fixes the block's geometry" \
  "$B" run seat_height.json
no_files_left seat_sampled_half_height seat.h5 seat.h5.lock seat.h5.records seat.h5.checkpoint
seat_study '{"alpha": {"distribution": "uniform", "min": 0.3, "max": 0.6}, "R": {"distribution": "fixed", "value": 1.2}}' >seat_alpha.json
run_case seat_sampled_alpha_R 2 "seat_alpha.json: /inputs/R: varies the block's size" "$B" run seat_alpha.json
grep -qF "seat_alpha.json: /inputs/alpha: varies the block's size" seat_sampled_alpha_R.err && pass ||
  fail "seat_sampled_alpha_R: /inputs/alpha not refused: $(head -c 300 seat_sampled_alpha_R.err)"
no_files_left seat_sampled_alpha_R seat.h5 seat.h5.lock seat.h5.records
# Friction still varies on a seat: the study runs.
seat_study '{"friction": {"distribution": "uniform", "min": 0.6, "max": 0.9}}' >seat_friction.json
run_case seat_sampled_friction 0 "wrote seat.h5" "$B" run seat_friction.json --samples-per-level 2

# A seat's simulation watches every seat point and block vertex, 38 at most: 40 points and the
# rectangle's 4 corners are refused at /seat, by the reader.
"$PYTHON" - <<'PY' >seat_40_points.json
import json
seat = [[-2 + 4 * k / 39, -1] for k in range(40)]
print(json.dumps({"block": {"half_width": 0.5, "half_height": 1.0}, "seat": seat,
                  "contact": {"friction": 0.6, "restitution": 0.6},
                  "ground_motion": {"type": "cosine_pulse", "amplitude_g": 1.0, "period": 1.0}, "duration": 1.0}))
PY
run_case seat_40_points 2 \
  "seat_40_points.json: /seat: has 40 points; with the block's 4 vertices they number 44, more than the 38" \
  "$B" simulate seat_40_points.json

# --- JSON syntax errors quote an excerpt of the broken token ---------------------------------------
# An unterminated string of 1 MB: the lexer's token is all of it.
"$PYTHON" -c "print('{\"block\": \"' + 'x' * 1000000)" >unterminated.json
for command in simulate run spectrum; do
  run_case "unterminated_string_1mb_$command" 2 "unterminated.json:1:1000012: malformed JSON: syntax error" \
    "$B" "$command" unterminated.json
  size=$(stat -c %s "unterminated_string_1mb_$command.err")
  [[ $size -lt 400 ]] && pass || fail "unterminated_string_1mb_$command: $size bytes of stderr"
done
# A string broken by a newline: the token is the line up to it.
"$PYTHON" -c "print('{\"block\": \"' + 'y' * 200 + 'PRIVATE-TAIL'); print('\"}')" >broken_string.json
run_case string_broken_by_newline 2 "broken_string.json:1:224: malformed JSON: syntax error" \
  "$B" simulate broken_string.json
grep -q "PRIVATE-TAIL" string_broken_by_newline.err && fail "string_broken_by_newline echoed the line" || pass

# --- A dam too stiff for every sample's run -------------------------------------------------------
# A 0.001 s dam under a 10 s pulse, settling: 70 s of crest at 1e-5 s a node, 7,000,003 nodes.
scene_with dam '{"period": 0.001}' >dam_stiff.json
"$PYTHON" - dam_stiff.json <<'PY'
import json, sys
scene = json.load(open(sys.argv[1]))
del scene["duration"]
scene["ground_motion"]["period"] = 10.0
json.dump(scene, open(sys.argv[1], "w"))
PY
run_case dam_period_0.001_pulse_10s 2 \
  "dam_stiff.json: /dam: the dam's period (0.001 s) is too short for the run (70 s): the crest motion would need 7000003 nodes" \
  "$B" simulate dam_stiff.json
# The example study on that dam: its every sample's run is at least 60 s.
study_with '{"scene": {"dam": {"period": 0.001}}}' >dam_study.json
run_case dam_study_period_0.001 2 "dam_study.json: /scene/dam: the dam's period (0.001 s) is too short for the run" \
  "$B" run dam_study.json
no_files_left dam_study_period_0.001 out.h5 out.h5.lock out.h5.records out.h5.checkpoint
# A 0.25 s dam under a 99,900 s record: 99,960 s of crest at 0.0025 s a node, as one record and as
# a suite of it.
printf '0 0\n0.5 0.1\n99900 0\n' >long_record.txt
# dam_record_study GROUND_MOTION > file: the example study on a 0.25 s dam under that motion, its
# geometry and contact fixed.
dam_record_study() {
  study_with "{\"scene\": {\"dam\": {\"period\": 0.25}, \"ground_motion\": $1}}" | "$PYTHON" -c '
import json, sys
study = json.load(sys.stdin)
study["inputs"] = {}
study["intensity_measure"] = {"type": "pga", "levels": [0.5, 1.0]}
print(json.dumps(study))'
}
dam_record_study '{"type": "record", "file": "long_record.txt"}' >dam_record.json
run_case dam_period_0.25_record_99900s 2 \
  "dam_record.json: /scene/dam: the dam's period (0.25 s) is too short for the run (99960 s)" "$B" run dam_record.json
no_files_left dam_period_0.25_record_99900s out.h5 out.h5.lock out.h5.records
dam_record_study '{"type": "record_suite", "records": ["long_record.txt"]}' >dam_suite.json
run_case dam_period_0.25_suite_99900s 2 \
  "dam_suite.json: /scene/dam: no sample could run (each would be rejected): with the record long_record.txt: the dam's period (0.25 s) is too short for the run (99960 s)" \
  "$B" run dam_suite.json
no_files_left dam_period_0.25_suite_99900s out.h5 out.h5.lock out.h5.records

# --- Spectra ---------------------------------------------------------------------------------------
spectrum_with() {
  "$PYTHON" - "$BLOCKFRAG_SOURCE_DIR/configs/paper_block_spectrum.json" "$1" <<'PY'
import json, sys
spec = json.load(open(sys.argv[1]))
spec.update(json.loads(sys.argv[2]))
print(json.dumps(spec))
PY
}
# alpha 1e-300 makes a half-width outside its domain: reported once, at the key the file has.
spectrum_with '{"block": {"alpha": 1e-300, "R": 1.0}, "output": "tiny.h5"}' >spectrum_alpha.json
run_case spectrum_alpha_1e-300 2 "spectrum_alpha.json: /block/R: with this alpha gives the half_width 1e-300 m" \
  "$B" spectrum spectrum_alpha.json
grep -q "/block/half_width" spectrum_alpha_1e-300.err && fail "spectrum_alpha_1e-300 named /block/half_width" || pass

# Another spectrum's map checkpoint at the output's name: stopped in its map, then another spec.
spectrum_with '{"frequency_ratio": {"from": 1, "to": 6, "count": 100}, "amplitude_ratio": {"from": 1, "to": 6, "count": 100}, "output": "map.h5", "checkpoint_interval_s": 0.05}' >map_a.json
spectrum_with '{"frequency_ratio": {"from": 1, "to": 6, "count": 100}, "amplitude_ratio": {"from": 1, "to": 6, "count": 100}, "output": "map.h5", "contact": {"friction": 0.7, "restitution": 0.6}}' >map_b.json
"$B" spectrum map_a.json >map_a.out 2>&1 &
map_pid=$!
for _ in $(seq 100); do
  [[ -e map.h5.checkpoint ]] && break
  sleep 0.1
done
kill -TERM "$map_pid"
wait "$map_pid"
map_code=$?
if [[ $map_code -ne 4 || ! -e map.h5.checkpoint ]]; then
  fail "spectrum_checkpoint_of_another_spec: the first spectrum exited $map_code without its checkpoint"
else
  run_case spectrum_checkpoint_of_another_spec 2 \
    "refusing to resume: the checkpoint map.h5.checkpoint belongs to a different spectrum spec (checkpoint spec hash" \
    "$B" spectrum map_b.json
  grep -q "run the original spec to finish it" spectrum_checkpoint_of_another_spec.err && pass ||
    fail "spectrum_checkpoint_of_another_spec: $(head -c 300 spectrum_checkpoint_of_another_spec.err)"
fi

echo "$passed passed, $failed failed"
[[ $failed -eq 0 ]]
