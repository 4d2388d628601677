#!/usr/bin/env bash
# Adaptive studies whose data give the level chooser nothing to fit: a limit state past at every
# level, a record or a pulse no level within its scale's cap makes exceed, and a step-like limit
# state that separates the data. Each must end normally (exit 0, the output written) with the reason in
# the batch log and in /adaptive's stop_reason, every level within the caps fixed levels obey and
# no level repeating one that told nothing; under the time and memory limits of hostile_case.sh.
set -u
source "$(dirname "$0")/../support/script_test.sh"
source "$(dirname "$0")/../support/hostile_case.sh"
cd "$work" || exit 1

# adaptive_study NAME SCENE LEVELS LIMIT_STATE MAX_SAMPLES > file: 10 samples a level of friction
# in [0.55, 0.9] (none for a record), the given first levels of PGA, one limit state.
adaptive_study() {
  "$PYTHON" - "$@" <<'PY'
import json, sys
name, scene, levels, limit_state, budget = sys.argv[1:]
scene = json.loads(scene)
record = scene["ground_motion"]["type"] == "record"
print(json.dumps({
    "scene": scene,
    "inputs": {} if record else {"friction": {"distribution": "uniform", "min": 0.55, "max": 0.9}},
    "intensity_measure": {"type": "pga", "levels": json.loads(levels)},
    "samples_per_level": 2 if record else 10,
    "design": {"adaptive": {"max_samples": int(budget)}},
    "limit_states": [json.loads(limit_state)],
    "seed": 1, "output": name + ".h5"}))
PY
}

# adaptive_output_holds NAME OUTPUT PYTHON_ASSERTIONS: the assertions hold on the output (f: the
# file, a: its /adaptive group, levels: its levels in the order run, reason: its stop_reason).
adaptive_output_holds() {
  local name=$1
  if "$PYTHON" - "$2" "$3" <<'PY' 2>"$name.check"
import sys, h5py, numpy as np
with h5py.File(sys.argv[1], "r") as f:
    a = f["adaptive"]
    levels = a["level_im"][()]
    reason = a.attrs["stop_reason"]
    reason = reason.decode() if isinstance(reason, bytes) else reason
    exec(sys.argv[2])
PY
  then pass; else fail "$name: $(tail -c 300 "$name.check")"; fi
}

pulse='{"block": {"half_width": 0.5, "half_height": 1.0},
        "contact": {"friction": 0.7, "restitution": 0.7},
        "ground_motion": {"type": "cosine_pulse", "amplitude_g": 1.0, "period": 1.0, "cycles": 1},
        "duration": 1.0}'

# Released at 0.1 rad, the block is past a tenth of alpha before the ground moves: every level
# exceeds, and the batches look down only to a thousandth of the smallest level (they halved until
# the levels were 0, 536 batches, then exit 5).
tilted=$("$PYTHON" -c "import json, sys; s = json.loads(sys.argv[1]); s['initial'] = {'theta': 0.1}; print(json.dumps(s))" "$pulse")
adaptive_study every_level "$tilted" '[0.2, 0.4]' \
  '{"name": "rock", "type": "max_rotation", "theta_over_alpha": 0.1}' 100000 >every_level.json
run_case every_level_exceeded 0 \
  "; every level exceeded down to 2e-04, a thousandth of the study's smallest level" \
  "$B" run every_level.json
adaptive_output_holds every_level_exceeded every_level.h5 '
assert reason.startswith("every level exceeded down to 2e-04"), reason
assert levels.min() >= 0.0002 and len(levels) == 12, levels
assert (f["fragility/rock/exceedances"][()] == 10).all()'

# A stocky block (tan alpha 10, no sliding) under one record of PGA 0.185 g: no level a scale of
# 100 reaches overturns it, and the batches stop there (they went on to 51.2 g, a scale of 277).
record="$BLOCKFRAG_SOURCE_DIR/configs/records/Kocaeli_1999_ATS-090.csv"
adaptive_study record_cap "{\"block\": {\"half_width\": 10.0, \"half_height\": 1.0},
  \"contact\": {\"friction\": 1e4, \"restitution\": 0.5},
  \"ground_motion\": {\"type\": \"record\", \"file\": \"$record\"}}" '[0.2, 0.4]' \
  '{"name": "overturn", "type": "overturning"}' 1000 >record_cap.json
run_case record_scale_cap 0 "Kocaeli_1999_ATS-090.csv (its PGA is 0.18488" "$B" run record_cap.json
adaptive_output_holds record_scale_cap record_cap.h5 '
assert reason.startswith("no exceedance up to 18.48"), reason
assert "the largest level a scale of 100 gives" in reason, reason
assert f["samples/scale"][()].max() <= 100, f["samples/scale"][()].max()
assert np.isclose(levels.max(), 100 * f["samples/pga_g"][0] / f["samples/scale"][0]), levels'

# The same block under a Mavroeidis-Papageorgiou pulse, which its velocity defines: the batches
# stop where the pulse reaches 100 m/s, the end of its domain (past it every sample was refused,
# and the study exited 3).
adaptive_study velocity_cap '{"block": {"half_width": 10.0, "half_height": 1.0},
  "contact": {"friction": 1e4, "restitution": 0.5}, "duration": 3.0,
  "ground_motion": {"type": "mavroeidis_papageorgiou", "velocity_amplitude": 0.5, "period": 1.0, "gamma": 2.0}}' \
  '[0.2, 0.4]' '{"name": "overturn", "type": "overturning"}' 1000 >velocity_cap.json
run_case pulse_velocity_cap 0 "the largest level within the pulse's velocity_amplitude domain" \
  "$B" run velocity_cap.json
adaptive_output_holds pulse_velocity_cap velocity_cap.h5 '
assert reason.startswith("no exceedance up to 58.0"), reason
assert (f["results/status"][()] == 0).all(), f["results/status"][()]'

# Rocking past a thousandth of alpha starts at one amplitude for every friction: no sample rocks
# below it, all above. The batches narrow the gap without repeating a level and stop when it is
# within the target width (they repeated 0.497 and 0.547 g until the budget was spent).
adaptive_study separated "$pulse" '[0.2, 0.4]' \
  '{"name": "rock", "type": "max_rotation", "theta_over_alpha": 0.001}' 300 >separated.json
run_case separated_data 0 ", a gap within the target width" "$B" run separated.json
adaptive_output_holds separated_data separated.h5 '
assert reason.startswith("separated data: the median lies between "), reason
assert len(np.unique(levels)) == len(levels), levels
assert a["batch_samples"][-1] < 300, a["batch_samples"][()]'

echo "$passed passed, $failed failed"
[[ $failed -eq 0 ]]
