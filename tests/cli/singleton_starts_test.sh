#!/usr/bin/env bash
# Many runs started at once without mpirun, as a shell loop or xargs -P starts them: every one
# starts MPI, reads its study and refuses it (exit code 2, the file named first), and leaves
# nothing in the temporary directory. Open MPI gives every isolated singleton one session
# directory; two creating it together failed MPI_Init in 3 of 200 such runs.
# Prints "N passed, M failed" last; exits non-zero on any failure.
set -u
source "$(dirname "$0")/../support/script_test.sh"

"$PYTHON" - "$BLOCKFRAG_SOURCE_DIR/configs/example_study.json" "$work/bad.json" <<'PY'
import json, sys
study = json.load(open(sys.argv[1]))
study["inputs"]["friction"] = {"distribution": "uniform", "min": 0.9, "max": 0.5}
study["output"] = "never_written.h5"
json.dump(study, open(sys.argv[2], "w"))
PY

mkdir "$work/runs"
cd "$work" || exit 1
runs=200
seq 1 "$runs" | xargs -P 8 -I{} sh -c \
  '"$0" run "$1/bad.json" >"$1/runs/{}.out" 2>"$1/runs/{}.err"; echo $? >"$1/runs/{}.code"' \
  "$BLOCKFRAG" "$work"

refused=0
first_failure=""
for i in $(seq 1 "$runs"); do
  code=$(cat "$work/runs/$i.code")
  if [[ $code == 2 ]] && head -n 1 "$work/runs/$i.err" | grep -q "^$work/bad.json: /inputs/friction/max: "; then
    refused=$((refused + 1))
  elif [[ -z $first_failure ]]; then
    first_failure="; the first other: run $i, exit code $code, stderr $(head -c 300 "$work/runs/$i.err")"
  fi
done
check "all $runs runs refused the study with its error ($refused did$first_failure)" \
  test "$refused" -eq "$runs"
check "the runs left nothing in TMPDIR: $(ls -A "$TMPDIR" | head -c 200)" test -z "$(ls -A "$TMPDIR")"
check "no run wrote its output" test ! -e "$work/never_written.h5"

echo "$passed passed, $failed failed"
[[ $failed -eq 0 ]]
