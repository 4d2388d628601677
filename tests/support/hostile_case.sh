# Sourced by the hostile-input tests (tests/cli/hostile_*_test.sh) after script_test.sh: each case
# runs under a time limit and a memory limit, so a regression fails there instead of hanging CI or
# exhausting the machine. With BLOCKFRAG_HOSTILE_TABLE=1 each case also prints a table row: case,
# exit code, seconds.
B=$BLOCKFRAG
export OMPI_MCA_rmaps_base_oversubscribe=1
table=${BLOCKFRAG_HOSTILE_TABLE:-0}
# AddressSanitizer reserves terabytes of address space for its shadow memory, so a sanitized build
# runs without the 4 GB address-space limit (the timeouts still hold, and the unsanitized run
# checks the memory), and its peak RSS bound is ASan's quarantine and shadow pages above ours.
if [[ ${BLOCKFRAG_SANITIZED:-OFF} == ON ]]; then
  address_limit_kb=unlimited
  peak_limit_kb=1048576
else
  address_limit_kb=4194304
  peak_limit_kb=262144
fi

# run_case NAME EXPECTED_EXIT EXPECTED_TEXT COMMAND...: runs under `timeout 60` and a 4 GB
# address-space limit; checks the exit code and that stderr (or stdout) holds the text.
run_case() {
  local name=$1 expected=$2 text=$3
  shift 3
  local start_ns code
  start_ns=$(date +%s%N)
  (ulimit -v "$address_limit_kb"; timeout 60 "$@") >"$name.out" 2>"$name.err"
  code=$?
  local seconds
  seconds=$(awk -v ns=$(($(date +%s%N) - start_ns)) 'BEGIN { printf "%.2f", ns / 1e9 }')
  [[ $table == 1 ]] && printf '| %s | %s | %s |\n' "$name" "$code" "$seconds"
  if [[ $code -ne $expected ]]; then
    fail "$name: exit $code, expected $expected: $(head -c 300 "$name.err")"
  elif ! grep -qF -- "$text" "$name.err" "$name.out"; then
    fail "$name: output lacks '$text': $(head -c 300 "$name.err")"
  else
    pass
  fi
}

# scene_with KEY_PATH JSON_VALUE > file: the paper's scene with one value replaced.
scene_with() {
  "$PYTHON" - "$1" "$2" <<'PY'
import json, sys
scene = {"block": {"half_width": 0.5, "half_height": 1.0},
         "contact": {"friction": 0.6, "restitution": 0.6},
         "ground_motion": {"type": "cosine_pulse", "amplitude_g": 1.0, "period": 2.0, "cycles": 1},
         "duration": 4.0}
keys, value = sys.argv[1].split("/"), json.loads(sys.argv[2])
node = scene
for key in keys[:-1]:
    node = node.setdefault(key, {})
node[keys[-1]] = value
print(json.dumps(scene))
PY
}

# study_with JSON_PATCH > file: the example study with top-level keys (or "inputs"/"intensity_measure"
# members) replaced, writing into this folder.
study_with() {
  "$PYTHON" - "$BLOCKFRAG_SOURCE_DIR/configs/example_study.json" "$1" <<'PY'
import json, sys
study = json.load(open(sys.argv[1]))
patch = json.loads(sys.argv[2])
for key, value in patch.items():
    if key in ("inputs", "intensity_measure", "scene") and isinstance(value, dict):
        study[key].update(value)
    else:
        study[key] = value
study["output"] = "out.h5"
print(json.dumps(study))
PY
}
