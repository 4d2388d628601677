#!/usr/bin/env bash
# Inputs a hostile or careless user can give: each must be refused before any work with exit
# code 2 and a message naming the file and the JSON path or line (or run to a correct result),
# never hang, exhaust memory, leak a file's content or write outside the program's own files.
# Every case runs under a time limit and a memory limit (tests/support/hostile_case.sh); the newer
# commands' cases are in hostile_*_test.sh beside this file.
set -u
source "$(dirname "$0")/../support/script_test.sh"
source "$(dirname "$0")/../support/hostile_case.sh"
cd "$work" || exit 1

# --- Hangs ------------------------------------------------------------------------------------------
scene_with ground_motion/period 5e-324 >period.json
run_case period_5e-324 2 "period.json: /ground_motion/period: must be in" "$B" simulate period.json
scene_with solver '{"method": "rk4", "dt": 1e-300}' >dt.json
run_case rk4_dt_1e-300 2 "dt.json: /solver/dt: must be in" "$B" simulate dt.json
scene_with solver '{"method": "rk4", "dt": 1e-7, "max_steps": 1000}' >dt_budget.json
run_case rk4_dt_over_budget 2 "dt_budget.json: /solver/dt: needs 4e+07 steps" "$B" simulate dt_budget.json
scene_with ground_motion '{"type": "mavroeidis_papageorgiou", "velocity_amplitude": 0.5, "period": 1.0, "gamma": 1e308}' >gamma.json
run_case mp_gamma_1e308 2 "gamma.json: /ground_motion/gamma: must be in" "$B" simulate gamma.json
"$PYTHON" - <<'PY' >polygon.json
import json, math
n = 100000
v = [[-1.0, 0.0], [1.0, 0.0]] + [[math.cos(math.pi * k / (n - 1)), 1 + 0.5 * math.sin(math.pi * k / (n - 1))] for k in range(1, n - 1)]
print(json.dumps({"block": {"polygon": v}, "contact": {"friction": 0.6, "restitution": 0.6},
                  "ground_motion": {"type": "none"}, "duration": 1.0}))
PY
run_case polygon_100000_vertices 2 "polygon.json: /block/polygon: has 100000 vertices, more than 10000" \
  "$B" simulate polygon.json
"$PYTHON" -c "print('[' * 100000 + ']' * 100000)" >nested.json
run_case nested_brackets 2 "nested.json:1:65: malformed JSON: nested deeper than 64 levels" "$B" simulate nested.json
mkfifo fifo.txt
scene_with ground_motion '{"type": "record", "file": "fifo.txt"}' >fifo_record.json
run_case record_fifo 2 "fifo_record.json: /ground_motion/file: " "$B" simulate fifo_record.json
grep -q "is a FIFO, not a regular file" record_fifo.err && pass || fail "record_fifo: $(cat record_fifo.err)"
ln -s /dev/urandom urandom.txt
scene_with ground_motion '{"type": "record", "file": "urandom.txt"}' >urandom_record.json
run_case record_urandom_link 2 "is a character device, not a regular file" "$B" simulate urandom_record.json

# --- Memory ----------------------------------------------------------------------------------------
scene_with ground_motion '{"type": "record", "file": "/dev/zero"}' >zero_record.json
run_case record_dev_zero 2 "zero_record.json: /ground_motion/file: /dev/zero: is a character device" \
  "$B" simulate zero_record.json
scene_with ground_motion/cycles 1e9 >cycles.json
run_case cycles_1e9 2 "cycles.json: /ground_motion/cycles: must be in (0, 10000]" "$B" simulate cycles.json
run_case history_interval_1e-9 2 "--history-interval: 1e-09 s" \
  "$B" simulate "$BLOCKFRAG_SOURCE_DIR/configs/paper_example.json" --history h.csv --history-interval 1e-9
[[ ! -e h.csv ]] && pass || fail "history_interval_1e-9 wrote h.csv"

study_with '{"samples_per_level": 2147483649}' >too_many.json
run_case samples_per_level_2147483649 2 "too_many.json: /samples_per_level: must be in [1, 2147483648]" "$B" run too_many.json
# A cloud's per-sample fit holds every sample: one beyond what rank 0 can hold is refused.
"$PYTHON" - "$BLOCKFRAG_SOURCE_DIR/configs/record_suite_study.json" >huge_cloud.json <<'PY'
import json, os, sys
study = json.load(open(sys.argv[1]))
folder = os.path.dirname(sys.argv[1])
records = study["scene"]["ground_motion"]["records"]
study["scene"]["ground_motion"]["records"] = [os.path.join(folder, r) for r in records]
study["intensity_measure"] = {"type": "pga", "scaling": "none"}
study["samples_per_level"] = 200000000
study["design"] = "monte_carlo"
study["output"] = "out.h5"
print(json.dumps(study))
PY
run_case cloud_of_2e8 2 "huge_cloud.json: /samples_per_level: a cloud of 200000000 samples, more than the 100000000" "$B" run huge_cloud.json

# A billion Monte Carlo samples of stripes start, run and checkpoint in bounded memory (records
# stream to disk, the checkpoint lists ranges): SIGTERM after 5 s, under the same 4 GB
# address-space limit.
study_with '{"samples_per_level": 100000000, "design": "latin_hypercube"}' >huge_lhs.json
run_case latin_hypercube_level_1e8 2 "huge_lhs.json: /samples_per_level: a Latin hypercube level of 100000000 samples" "$B" run huge_lhs.json
study_with '{"samples_per_level": 100000000, "design": "monte_carlo", "checkpoint_interval_s": 1}' >billion.json
(ulimit -v "$address_limit_kb"; exec "$B" run billion.json --output billion.h5) >billion.out 2>billion.err &
billion_pid=$!
sleep 5
# and, on a loaded machine that was slow to start it, until its first checkpoint (25 s at most)
for _ in $(seq 250); do [[ -e billion.h5.checkpoint ]] && break; sleep 0.1; done
peak_kb=$(awk '/^VmHWM/ { print $2 }' "/proc/$billion_pid/status" 2>/dev/null || echo 0)
kill -TERM "$billion_pid"
wait "$billion_pid"
billion_code=$?
checkpoint_bytes=$(stat -c %s billion.h5.checkpoint 2>/dev/null || echo missing)
[[ $table == 1 ]] && printf '| %s | %s | %s |\n' billion_samples_interrupted "$billion_code" "peak RSS ${peak_kb} kB"
if [[ $billion_code -ne 4 || $peak_kb -le 0 || $peak_kb -gt $peak_limit_kb || $checkpoint_bytes == missing ||
      $checkpoint_bytes -gt 65536 || -e billion.h5 ]]; then
  fail "billion_samples_interrupted: exit $billion_code (expected 4), peak RSS ${peak_kb} kB (at most $((peak_limit_kb / 1024)) MB), checkpoint ${checkpoint_bytes} bytes: $(head -c 300 billion.err)"
else
  pass
fi
rm -f billion.h5.checkpoint billion.h5.records billion.h5.lock
study_with '{"intensity_measure": {"from": 0.2, "to": 2.0, "count": 1000000000}}' >count.json
run_case level_count_1e9 2 "count.json: /intensity_measure/count: must be in [2, 1e+06]" "$B" run count.json

# --- Leaks -----------------------------------------------------------------------------------------
printf '0.0 0.1\n0.01 PRIVATE-KEY-0123456789abcdefghijklmnopqrstuvwxyz-0123456789-SECRET-TAIL\n' >secret.txt
scene_with ground_motion '{"type": "record", "file": "secret.txt"}' >secret_record.json
run_case record_quotes_excerpt 2 "secret.txt:2: not a number" "$B" simulate secret_record.json
grep -q "SECRET-TAIL" record_quotes_excerpt.err && fail "the whole secret line was echoed" || pass
"$PYTHON" -c "print('0.0 0.1'); print('0.01 ' + 'x' * 10000000)" >long_line.txt
scene_with ground_motion '{"type": "record", "file": "long_line.txt"}' >long_line.json
run_case record_10mb_line 2 "long_line.txt:2: not a number" "$B" simulate long_line.json
[[ $(stat -c %s record_10mb_line.err) -lt 1000 ]] && pass || fail "a 10 MB line gave $(stat -c %s record_10mb_line.err) bytes of stderr"

# --- Wrong exit codes, nonsense accepted ----------------------------------------------------------
scene_with block/half_width 1e308 >wide.json
run_case half_width_1e308 2 "wide.json: /block/half_width: must be in [1e-04, 10000]" "$B" simulate wide.json
scene_with block/half_width 1e-300 >thin.json
run_case half_width_1e-300 2 "thin.json: /block/half_width: must be in [1e-04, 10000]" "$B" simulate thin.json
scene_with block/half_height 5e-324 >flat.json
run_case half_height_5e-324 2 "flat.json: /block/half_height: must be in" "$B" simulate flat.json
scene_with ground_motion/amplitude_g 1e308 >amplitude.json
run_case amplitude_1e308 2 "amplitude.json: /ground_motion/amplitude_g: must be in [-1000, 1000]" "$B" simulate amplitude.json
scene_with g 1e308 >g.json
run_case g_1e308 2 "g.json: /g: must be in [0.01, 1000]" "$B" simulate g.json
scene_with solver '{"tolerance": 1e-300}' >tolerance.json
run_case tolerance_1e-300 2 "tolerance.json: /solver/tolerance: must be in [1e-14, 0.1]" "$B" simulate tolerance.json
scene_with ground_motion '{"type": "ricker", "amplitude_g": 1.0, "period": 1.0, "t0": 1e308}' >ricker.json
run_case ricker_t0_1e308 2 "ricker.json: /ground_motion/t0: must be in" "$B" simulate ricker.json
scene_with dam '{"period": 1e-300}' >dam.json
run_case dam_period_1e-300 2 "dam.json: /dam/period: must be in [0.001, 10]" "$B" simulate dam.json
printf 'PEER NGA STRONG MOTION DATABASE RECORD\nhostile\nACCELERATION TIME SERIES IN UNITS OF G\nNPTS=     4, DT=   1e308 SEC\n 0.1 0.2 0.3 0.4\n' >huge_dt.AT2
scene_with ground_motion '{"type": "record", "file": "huge_dt.AT2"}' >huge_dt.json
run_case at2_dt_1e308 2 "huge_dt.AT2:4: the record lasts" "$B" simulate huge_dt.json
scene_with ground_motion '{"type": "record", "file": "huge_dt.AT2", "scale": 1e308}' >scale.json
run_case record_scale_1e308 2 "scale.json: /ground_motion/scale: must be in [-1000, 1000]" "$B" simulate scale.json
printf 'PEER NGA STRONG MOTION DATABASE RECORD\nhostile\nACCELERATION TIME SERIES IN UNITS OF G\nNPTS=     4, DT=   0.01 SEC\n 0.1 0x1p3 0.3 0.4\n' >hex.AT2
scene_with ground_motion '{"type": "record", "file": "hex.AT2"}' >hex.json
run_case at2_hex_float 2 'hex.AT2:5: not a number: "0x1p3"' "$B" simulate hex.json
printf 'PEER NGA STRONG MOTION DATABASE RECORD\nhostile\nACCELERATION TIME SERIES IN UNITS OF G\nNPTS=     4, DT=   0.01 SEC\n 0.1 0.\0002 0.3 0.4\n' >nul.AT2
scene_with ground_motion '{"type": "record", "file": "nul.AT2"}' >nul.json
run_case at2_nul_byte 2 "nul.AT2:5: contains a NUL byte" "$B" simulate nul.json
scene_with ground_motion '{"type": "record", "file": "huge_dt.AT2", "target_pga_g": 1e308}' >target.json
run_case target_pga_1e308 2 "target.json: /ground_motion/target_pga_g: must be in (0, 1000]" "$B" simulate target.json

# No result depends on the mass: 5e-324 and 1e308 give mass 1's summary.
"$B" simulate "$BLOCKFRAG_SOURCE_DIR/configs/paper_example.json" --summary-json >mass_1.json
for mass in 5e-324 1e308; do
  scene_with block/mass "$mass" >"mass_$mass.scene.json"
  "$PYTHON" - "$BLOCKFRAG_SOURCE_DIR/configs/paper_example.json" "mass_$mass.scene.json" <<'PY'
import json, sys
paper = json.load(open(sys.argv[1])); mine = json.load(open(sys.argv[2]))
paper["block"]["mass"] = mine["block"]["mass"]
json.dump(paper, open(sys.argv[2], "w"))
PY
  run_case "mass_$mass" 0 '"overturned":true' "$B" simulate "mass_$mass.scene.json" --summary-json
  cmp -s "mass_$mass.out" mass_1.json && pass || fail "mass $mass: the summary differs from mass 1's"
done

# Studies whose samples would all be rejected or fail: refused up front.
study_with '{"scene": {"block": {"half_width": 1e308, "half_height": 1.0}}}' >study_wide.json
run_case study_half_width_1e308 2 "study_wide.json: /scene/block/half_width: must be in" "$B" run study_wide.json
study_with '{"inputs": {"half_height": {"distribution": "uniform", "min": 1e200, "max": 2e200}}}' >study_tall.json
run_case study_half_height_1e200 2 "study_tall.json: /inputs/half_height: every value must be in [1e-04, 10000]" \
  "$B" run study_tall.json
study_with '{"inputs": {"period": {"distribution": "lognormal", "median": 1.0, "beta": 1e6}}}' >study_period.json
run_case study_period_lognormal_unbounded 2 "study_period.json: /inputs/period: every value must be in [0.001, 1000]" \
  "$B" run study_period.json
study_with '{"inputs": {"friction": {"distribution": "uniform", "min": 0.5, "max": 1e308}}}' >study_friction.json
run_case study_friction_1e308 2 "study_friction.json: /inputs/friction: every value must be in [0, 10000]" \
  "$B" run study_friction.json
study_with '{"intensity_measure": {"from": 0.2, "to": 1e308, "count": 10}}' >study_to.json
run_case study_level_1e308 2 "study_to.json: /intensity_measure/to: must be in (0, 1000]" "$B" run study_to.json
for name in . ..; do
  study_with "{\"limit_states\": [{\"name\": \"$name\", \"type\": \"overturning\"}]}" >"study_name$name.json"
  run_case "limit_state_name_$name" 2 "/limit_states/0/name: must start with a letter" "$B" run "study_name$name.json"
done
run_case output_in_proc 2 "/proc/x.h5: cannot create a file in the folder /proc" \
  "$B" run "$BLOCKFRAG_SOURCE_DIR/configs/example_study.json" --output /proc/x.h5
study_with '{"output": "out\u0000.h5"}' >study_nul.json
"$PYTHON" - study_nul.json <<'PY'
import json, sys
study = json.load(open(sys.argv[1])); study["output"] = "out\u0000.h5"; json.dump(study, open(sys.argv[1], "w"))
PY
run_case output_name_nul 2 "study_nul.json: /output: must not contain a NUL byte" "$B" run study_nul.json

# --- Writes where it must not ---------------------------------------------------------------------
study_with '{"samples_per_level": 20}' >small.json
echo data >victim.txt
ln -s victim.txt out7.h5.tmp
ln -s victim.txt out7.h5.checkpoint.tmp
run_case planted_temporary_links 0 "wrote out7.h5" "$B" run small.json --output out7.h5
[[ "$(cat victim.txt)" == data && -f out7.h5 && ! -L out7.h5 ]] && pass ||
  fail "a planted link was followed: victim.txt is '$(head -c 20 victim.txt)', out7.h5 $(stat -c %F out7.h5)"
ln -s dangling.h5 dangling_link.h5
run_case output_dangling_link 2 "dangling_link.h5: is a symbolic link" "$B" run small.json --output dangling_link.h5
[[ -L dangling_link.h5 && ! -e dangling.h5 ]] && pass || fail "the dangling link was replaced or followed"
ln -s out7.h5 alias.h5
study_with '{"samples_per_level": 30}' >other.json
run_case output_link_to_other_study 2 "alias.h5: is a symbolic link to another study's output" \
  "$B" run other.json --output alias.h5
# Study B's finished output X.h5 with study A's checkpoint beside it: A must not replace B.
cp out7.h5 X.h5
"$B" run other.json --output A.h5 2>/dev/null
printf 'not used' >X.h5.checkpoint
run_case checkpoint_beside_other_output 2 "X.h5: refusing to replace an existing file that is not this study's output" \
  "$B" run other.json --output X.h5
cmp -s out7.h5 X.h5 && pass || fail "study B's output X.h5 was changed"
mkfifo fifo.h5.checkpoint
run_case checkpoint_fifo 2 "fifo.h5.checkpoint: is a FIFO, not a regular file" "$B" run small.json --output fifo.h5
ln -s victim.txt linked.h5.checkpoint
run_case checkpoint_link 2 "linked.h5.checkpoint: is a symbolic link" "$B" run small.json --output linked.h5
echo "someone's notes" >notes.h5.records
run_case foreign_records_file 2 "notes.h5.records: not blockfrag's records file" "$B" run small.json --output notes.h5
[[ "$(cat notes.h5.records)" == "someone's notes" && ! -e notes.h5 ]] && pass ||
  fail "the foreign notes.h5.records was changed or the study ran"
ln -s victim.txt linked_records.h5.records
run_case records_link 2 "linked_records.h5.records: a link" "$B" run small.json --output linked_records.h5
[[ "$(cat victim.txt)" == data ]] && pass || fail "the records link was followed"

echo "$passed passed, $failed failed"
[[ $failed -eq 0 ]]
