#!/usr/bin/env bash
# Makes the small study outputs of this folder, the seeds of tests/fuzz/hdf5_reader_fuzzer.cpp:
# tiny real studies (a pulse at PGA stripes with three limit states, PGV stripes with one that no
# sample exceeds, a record suite at Sa stripes, a cloud of records), each cut down with h5py to
# what `blockfrag export` reads (the root's attributes, /fragility's and its limit states', and
# their levels), a few kB each.
#   tests/data/study_outputs/make_study_outputs.sh BLOCKFRAG
set -euo pipefail
blockfrag=$(realpath "${1:?usage: make_study_outputs.sh BLOCKFRAG}")
here=$(cd "$(dirname "$0")" && pwd)
records=$(cd "$here/../records" && pwd)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cd "$scratch"

pulse='{"block": {"half_width": 0.5, "half_height": 1.0},
        "contact": {"friction": 0.7, "restitution": 0.7},
        "ground_motion": {"type": "cosine_pulse", "amplitude_g": 1.0, "period": 1.0, "cycles": 1}}'
suite="{\"block\": {\"half_width\": 0.3, \"half_height\": 1.0},
        \"contact\": {\"friction\": 0.6, \"restitution\": 0.7},
        \"ground_motion\": {\"type\": \"record_suite\",
                          \"records\": [\"$records/decaying_sine.AT2\", \"$records/cosine_pulse.txt\"]}}"
pulse_inputs='{"friction": {"distribution": "uniform", "min": 0.55, "max": 0.9},
               "restitution": {"distribution": "uniform", "min": 0.6, "max": 0.9},
               "period": {"distribution": "lognormal", "median": 1.0, "beta": 0.3, "lower": 0.3, "upper": 3.0},
               "direction": {"distribution": "random_sign"}}'
record_inputs='{"friction": {"distribution": "uniform", "min": 0.4, "max": 0.9},
                "direction": {"distribution": "random_sign"}}'
limit_states='[{"name": "slide_5cm", "type": "residual_slide", "threshold_m": 0.05},
               {"name": "rock_half", "type": "max_rotation", "theta_over_alpha": 0.5},
               {"name": "overturn", "type": "overturning"}]'
study() {
  local name=$1 scene=$2 inputs=$3 measure=$4 states=$5
  cat >"$name.json" <<JSON
{"scene": $scene,
 "inputs": $inputs,
 "intensity_measure": $measure, "samples_per_level": 25, "bootstrap_resamples": 20,
 "limit_states": $states, "seed": 11, "output": "$name.full.h5"}
JSON
  "$blockfrag" run "$name.json" >/dev/null
}
study pga_stripes "$pulse" "$pulse_inputs" '{"type": "pga", "from": 0.4, "to": 2.0, "count": 5}' "$limit_states"
study pgv_stripes "$pulse" "$pulse_inputs" '{"type": "pgv", "from": 0.5, "to": 5.0, "count": 4}' \
  '[{"name": "overturn", "type": "overturning"},
    {"name": "slide_10m", "type": "residual_slide", "threshold_m": 10, "overturned_exceeds": false}]'
study sa_suite "$suite" "$record_inputs" '{"type": "sa", "period": 0.5, "from": 0.5, "to": 8.0, "count": 5}' "$limit_states"
study pga_cloud "$suite" "$record_inputs" '{"type": "pga", "scaling": "none", "scale": 3}' "$limit_states"

/usr/bin/python3 - "$here" pga_stripes pgv_stripes sa_suite pga_cloud <<'PY'
import sys
import h5py
folder, names = sys.argv[1], sys.argv[2:]
for name in names:
    with h5py.File(f"{name}.full.h5", "r") as full, h5py.File(f"{folder}/{name}.h5", "w") as cut:
        for key, value in full.attrs.items():
            cut.attrs[key] = value
        fragility = cut.create_group("fragility")
        for key, value in full["fragility"].attrs.items():
            fragility.attrs[key] = value
        # Of the datasets, export reads only the levels.
        for state_name, state in full["fragility"].items():
            kept = fragility.create_group(state_name)
            for key, value in state.attrs.items():
                kept.attrs[key] = value
            state.copy("im", kept)
PY
ls -l "$here"/*.h5
