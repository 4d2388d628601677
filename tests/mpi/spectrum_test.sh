#!/usr/bin/env bash
# `blockfrag spectrum` end to end. A small spectrum of the paper's block gives a bitwise identical
# file (h5diff: every dataset and attribute) on 1 rank (no mpirun), 2 ranks, and 3 ranks with
# chunks of one point; killed with SIGKILL during the map, at the start of the bisection, inside a
# bisection round and in the minimum's refinement, and resumed each time with the same command, it
# ends identical too, with its own files gone; SIGTERM exits with code 4 and the rerun completes; a finished spectrum run again
# is reported complete and left alone. A bad config is refused before any work (exit 2, the file
# and each JSON path named, nothing written). Every spectrum in configs/ runs, on a coarser grid.
set -u
source "$(dirname "$0")/../support/script_test.sh"

cd "$work" || exit 1

# write_spectrum FILE: the paper's block under one-cycle cosine pulses around its own (T = 2 s is
# omega_p / p = 1.2247), 24 x 40 points, bisected to 1e-6, a checkpoint every 2 ms (so that even a
# bisection round of a few milliseconds writes one, and a kill can land inside it).
write_spectrum() {
  cat >"$1" <<JSON
{
  "block": {"half_width": 0.5, "half_height": 1.0},
  "contact": {"friction": 0.6, "restitution": 0.6},
  "pulse": {"type": "cosine_pulse"},
  "frequency_ratio": {"from": 0.8, "to": 2.0, "count": 24, "spacing": "log"},
  "amplitude_ratio": {"from": 1.0, "to": 3.0, "count": 40},
  "bisection": {"tolerance": 1e-6},
  "output": "s.h5",
  "checkpoint_interval_s": 0.002
}
JSON
}

# same FILE FILE: h5diff finds no difference.
same() { h5diff "$1" "$2" >/dev/null 2>&1; }

# --- 1, 2 and 3 ranks ------------------------------------------------------------------------------
for ranks in 1 2 3; do
  mkdir "r$ranks"
  write_spectrum "r$ranks/s.json"
  if [[ $ranks == 1 ]]; then
    (cd r1 && "$BLOCKFRAG" spectrum s.json 2>run.err)
  else
    chunk=()
    [[ $ranks == 3 ]] && chunk=(--max-chunk 1)
    (cd "r$ranks" && mpirun -n "$ranks" --oversubscribe "$BLOCKFRAG" spectrum s.json "${chunk[@]}" 2>run.err)
  fi
  code=$?
  [[ $code -eq 0 && -e "r$ranks/s.h5" ]] && pass || fail "$ranks ranks: exit code $code: $(cat "r$ranks/run.err")"
done
same r1/s.h5 r2/s.h5 && pass || fail "1 and 2 ranks differ: $(h5diff r1/s.h5 r2/s.h5 | head -5)"
same r1/s.h5 r3/s.h5 && pass || fail "1 and 3 ranks differ: $(h5diff r1/s.h5 r3/s.h5 | head -5)"
grep -q "[1-9][0-9]* map chunks handed out" r3/run.err && pass ||
  fail "3 ranks with --max-chunk 1 handed out no chunks: $(grep wrote r3/run.err)"
# The run's own files are gone; the map has crossings to bisect, islands among them.
compgen -G 'r1/s.h5.*' >/dev/null && fail "files left beside the output: $(ls r1/s.h5.*)" || pass
if "$PYTHON" - r1/s.h5 <<'PY'
import sys, h5py, numpy as np
with h5py.File(sys.argv[1], "r") as f:
    verdict = f["map/verdict"][()]
    assert verdict.shape == (24, 40), verdict.shape
    assert set(np.unique(verdict)) <= {0, 1, 2, 3}, np.unique(verdict)
    direction = f["boundary/direction"][()]
    assert (f["boundary/state"][()] == 1).all()
    assert (direction == 1).sum() >= 24 and (direction == -1).sum() >= 1, direction
    low, high = f["boundary/amplitude_low"][()], f["boundary/amplitude_high"][()]
    assert ((high - low) <= 1e-6 * high).all()
    m = f["minimum_overturning"]
    assert (m["state"][()] == 1).all(), m["state"][()]
    refined, unrefined = m["amplitude_ratio"][()], m["map_amplitude_ratio"][()]
    assert (m["amplitude_high"][()] <= m["amplitude_low"][()] * (1 + 1.001e-3)).all()
    # Never above the map's own minimum (within the map bisection's 1e-6).
    assert (refined <= unrefined * (1 + 1e-6)).all(), (refined, unrefined)
PY
then pass; else fail "the 1-rank output is not a complete spectrum"; fi

# Run again: complete, the file untouched.
sum=$(md5sum <r1/s.h5)
(cd r1 && "$BLOCKFRAG" spectrum s.json 2>again.err)
code=$?
[[ $code -eq 0 ]] && grep -q "spectrum already complete: s.h5" r1/again.err && [[ "$(md5sum <r1/s.h5)" == "$sum" ]] &&
  pass || fail "a finished spectrum run again: exit $code, $(cat r1/again.err)"

# --- SIGKILL in each phase, then resume ------------------------------------------------------------
# Each checkpoint write held 0.1 s (the test hook), so every phase lasts a while.
mkdir killed
write_spectrum killed/s.json
cd killed || exit 1
start_job() {
  mpirun -n 2 --oversubscribe "$BLOCKFRAG_PAUSED_CHECKPOINTS" 0.1 spectrum s.json 2>>job.err &
  job=$!
}
# wait_for FILE: until it exists or the job ends.
wait_for() {
  for _ in $(seq 1 1500); do
    [[ -e $1 ]] && return
    kill -0 "$job" 2>/dev/null || return
    sleep 0.01
  done
}
# kill_job: SIGKILL to the ranks and mpirun; landed is 1 when the job was still running.
kill_job() {
  kill -0 "$job" 2>/dev/null && landed=1 || landed=0
  local ranks
  ranks=$(pgrep -P "$job")
  [[ -n "$ranks" ]] && kill -KILL $ranks 2>/dev/null
  kill -KILL "$job" 2>/dev/null
  wait "$job" 2>/dev/null
}
start_job
wait_for s.h5.checkpoint
kill_job
[[ $landed -eq 1 && ! -e s.h5.bisection && ! -e s.h5 ]] && pass || fail "the first kill missed the map phase"
start_job
wait_for s.h5.bisection
kill_job
[[ $landed -eq 1 && -e s.h5.bisection && ! -e s.h5 ]] && pass || fail "the second kill missed the bisection"
start_job
wait_for s.h5.round-checkpoint
kill_job
[[ $landed -eq 1 && ! -e s.h5 ]] && pass || fail "the third kill missed the bisection"
start_job
wait_for s.h5.minimum
kill_job
[[ $landed -eq 1 && -e s.h5.minimum && ! -e s.h5 ]] && pass || fail "the fourth kill missed the minimum's refinement"
start_job
wait "$job"
code=$?
[[ $code -eq 0 ]] && pass || fail "the resumed spectrum: exit $code, $(tail -5 job.err)"
grep -q "resumed from s.h5.checkpoint" job.err && pass || fail "no run resumed the map: $(cat job.err)"
same ../r1/s.h5 s.h5 && pass || fail "killed and resumed differs: $(h5diff ../r1/s.h5 s.h5 | head -5)"
compgen -G 's.h5.*' >/dev/null && fail "files left beside the output: $(ls s.h5.*)" || pass

# --- SIGTERM: exit code 4, then the rerun completes ------------------------------------------------
rm -f s.h5 job.err
start_job
wait_for s.h5.bisection
ranks=$(pgrep -P "$job")
[[ -n "$ranks" ]] && kill -TERM $ranks
wait "$job"
code=$?
[[ $code -eq 4 && ! -e s.h5 ]] && grep -q "interrupted: checkpoint written next to s.h5" job.err && pass ||
  fail "SIGTERM: exit $code, $(tail -3 job.err)"
"$BLOCKFRAG" spectrum s.json 2>final.err
code=$?
[[ $code -eq 0 ]] && same ../r1/s.h5 s.h5 && pass || fail "after SIGTERM: exit $code, $(tail -3 final.err)"
cd "$work" || exit 1

# --- A bad config: every error at its path, before any work ---------------------------------------
mkdir bad
cat >bad/bad.json <<'JSON'
{
  "block": {"half_width": 0.5, "half_height": 1.0},
  "contact": {"friction": -0.1, "restitution": 0.6},
  "pulse": {"type": "cosine_pulse", "amplitude_g": 0.5},
  "frequency_ratio": {"from": 2.0, "to": 1.0, "count": 10},
  "amplitude_ratio": {"from": 1.0, "to": 3.0, "count": 10},
  "bisection": {"tolerance": 0},
  "outptu": "x.h5"
}
JSON
(cd bad && "$BLOCKFRAG" spectrum bad.json 2>bad.err)
code=$?
expected=("bad.json: /contact/friction:" "bad.json: /pulse/amplitude_g: is set at each point"
  "bad.json: /frequency_ratio/to: must be greater than from" "bad.json: /bisection/tolerance:"
  "bad.json: /outptu: unknown key")
missing=""
for message in "${expected[@]}"; do
  grep -qF "$message" bad/bad.err || missing+=" [$message]"
done
[[ $code -eq 2 && -z "$missing" ]] && pass || fail "bad config: exit $code, missing$missing in: $(cat bad/bad.err)"
[[ -z "$(ls bad | grep -v '^bad\.')" ]] && pass || fail "a refused config left files: $(ls bad)"

# --- configs/*spectrum*.json, on a coarser grid ----------------------------------------------------
for config in "$BLOCKFRAG_SOURCE_DIR"/configs/*spectrum*.json; do
  name=$(basename "$config" .json)
  "$PYTHON" - "$config" "$name.json" <<'PY'
import json, sys
spec = json.load(open(sys.argv[1]))
spec["frequency_ratio"]["count"] = 8
spec["amplitude_ratio"]["count"] = 10
json.dump(spec, open(sys.argv[2], "w"))
PY
  mpirun -n 2 --oversubscribe "$BLOCKFRAG" spectrum "$name.json" --output "$name.h5" 2>"$name.err"
  code=$?
  [[ $code -eq 0 && -e "$name.h5" ]] && pass || fail "$name: exit code $code: $(cat "$name.err")"
done

echo "$passed passed, $failed failed"
[[ $failed -eq 0 ]]
