#!/usr/bin/env bash
# `blockfrag run` refuses every study of tests/data/bad_studies before any work: exit code 2, each
# message fragment of the .expected file on stderr (the first fragment starts with the JSON path), no output
# or checkpoint written. Under mpirun the refusal is the same and printed once, not once per rank.
set -u
source "$(dirname "$0")/../support/script_test.sh"

cd "$work" || exit 1

# check_refusal NAME EXPECTED: exit code 2 and every fragment of EXPECTED in $work/err.
check_refusal() {
  local name=$1 expected=$2 missing=0
  if [[ $code -ne 2 ]]; then
    fail "$name: exit code $code, expected 2 (stderr: $(head -c 300 err))"
    return
  fi
  [[ "$(head -n 1 "$expected")" == /* ]] || { fail "$name: the first expected fragment names no JSON path"; missing=1; }
  while IFS= read -r fragment; do
    [[ -z "$fragment" ]] && continue
    if ! grep -qF -- "$fragment" err; then
      fail "$name: stderr lacks '$fragment'; it was: $(cat err)"
      missing=1
    fi
  done <"$expected"
  if ls ./*.h5* >/dev/null 2>&1; then
    fail "$name: wrote $(ls ./*.h5*) although the config is refused"
    rm -f ./*.h5*
    missing=1
  fi
  [[ $missing -eq 0 ]] && pass
}

corpus=("$BLOCKFRAG_SOURCE_DIR"/tests/data/bad_studies/*.json)
[[ ${#corpus[@]} -ge 10 ]] && pass || fail "the bad-study corpus has only ${#corpus[@]} files"
for study in "${corpus[@]}"; do
  name=$(basename "$study" .json)
  expected="${study%.json}.expected"
  [[ -s "$expected" ]] || { fail "$name: no $expected"; continue; }
  "$BLOCKFRAG" run "$study" >out 2>err
  code=$?
  check_refusal "$name" "$expected"
  grep -qF "$study: /" err || fail "$name: the message does not start with the file name and a path: $(cat err)"
done

# Under mpirun: same refusal, one copy of the message.
for name in friction_below_zero top_level_typo; do
  study="$BLOCKFRAG_SOURCE_DIR/tests/data/bad_studies/$name.json"
  mpirun -n 2 --oversubscribe "$BLOCKFRAG" run "$study" >out 2>err
  code=$?
  check_refusal "$name under mpirun" "${study%.json}.expected"
  first=$(head -n 1 "${study%.json}.expected")
  count=$(grep -cF -- "$first" err)
  [[ $count -eq 1 ]] && pass || fail "$name under mpirun: the message appears $count times"
done

# Command-line values are checked too: a non-positive --samples-per-level is refused.
"$BLOCKFRAG" run "$BLOCKFRAG_SOURCE_DIR/configs/example_study.json" --samples-per-level 0 >out 2>err
code=$?
[[ $code -eq 2 ]] && pass || fail "--samples-per-level 0: exit code $code"

echo "$passed passed, $failed failed"
[[ $failed -eq 0 ]]
