#!/usr/bin/env bash
# A study killed with SIGKILL at random moments, once certainly inside a checkpoint write (the
# test executable $BLOCKFRAG_PAUSED_CHECKPOINTS holds each write between its complete temporary
# file and the rename), and resumed each time with the same command, ends bitwise identical to an
# uninterrupted run, with every sample exactly once. SIGTERM writes a checkpoint and exits with code
# 4 ("interrupted"), and the resume completes; a second run while one is going is refused. A
# resume with a changed config (seed, sample count) is refused with exit code 2 and a clear
# message, leaving the checkpoint as it was.
set -u
source "$(dirname "$0")/../support/script_test.sh"

COMPARE="$BLOCKFRAG_SOURCE_DIR/tests/mpi/compare_study_outputs.py"

cd "$work" || exit 1

# write_study FILE SEED SAMPLES_PER_LEVEL: cheap samples, a checkpoint every 0.1 s.
write_study() {
  cat >"$1" <<JSON
{
  "scene": {
    "block": {"half_width": 0.5, "half_height": 1.0},
    "contact": {"friction": 0.7, "restitution": 0.7},
    "ground_motion": {"type": "cosine_pulse", "amplitude_g": 1.0, "period": 1.0},
    "duration": 2.0
  },
  "inputs": {
    "friction": {"distribution": "uniform", "min": 0.55, "max": 0.9},
    "restitution": {"distribution": "uniform", "min": 0.5, "max": 0.9},
    "period": {"distribution": "lognormal", "median": 0.8, "beta": 0.3, "lower": 0.3, "upper": 2.0},
    "direction": {"distribution": "random_sign"}
  },
  "intensity_measure": {"from": 0.3, "to": 1.8, "count": 10},
  "samples_per_level": $3,
  "design": "latin_hypercube",
  "limit_states": [
    {"name": "overturn", "type": "overturning"},
    {"name": "slide_2cm", "type": "residual_slide", "threshold_m": 0.02}
  ],
  "seed": $2,
  "output": "study.h5",
  "checkpoint_interval_s": 0.1
}
JSON
}

# The study's size follows this machine's speed (and the build's: sanitizers are slow), so that an
# uninterrupted run on 2 ranks lasts about 4 s and every kill below lands while it is running. The
# rate is measured between two probe runs, so start-up time does not count.
probe_seconds() {
  write_study probe.json 99 "$1"
  local start_ns
  start_ns=$(date +%s%N)
  "$BLOCKFRAG" run probe.json --output "probe$1.h5" 2>probe.err ||
    { echo "FAIL: the probe run failed: $(cat probe.err)" >&2; exit 1; }
  awk -v ns=$(($(date +%s%N) - start_ns)) 'BEGIN { print ns / 1e9 }'
}
small_s=$(probe_seconds 10)
large_s=$(probe_seconds 500)
per_level=$(awk -v t="$large_s" -v t0="$small_s" 'BEGIN {
  rate = 4900 / (t - t0 > 0.01 ? t - t0 : 0.01); n = int(rate * 4.0 * 1.8 / 10);
  if (n < 400) n = 400; if (n > 200000) n = 200000; print n }')
total=$((per_level * 10))
write_study study.json 99 "$per_level"
write_study changed_seed.json 100 "$per_level"

if ! "$BLOCKFRAG" run study.json --output reference.h5 2>reference.err; then
  echo "FAIL: the uninterrupted reference run failed: $(cat reference.err)" >&2
  exit 1
fi

# start_job: mpirun -n 2 in the background, its pid in $job; returns once rank 0 has started the
# study (its "study ..." line), so that a kill timed from here lands in the run, not in mpirun's
# start-up (slow on a loaded machine).
start_job() {
  touch job.err
  local started
  started=$(grep -c "^study " job.err)
  mpirun -n 2 --oversubscribe "$BLOCKFRAG_PAUSED_CHECKPOINTS" "${pause:-0}" run study.json \
    2>>job.err &
  job=$!
  for _ in $(seq 1 1500); do
    [[ $(grep -c "^study " job.err) -gt $started ]] && return
    kill -0 "$job" 2>/dev/null || return
    sleep 0.02
  done
}
# wait_for_checkpoint: until a checkpoint exists.
wait_for_checkpoint() {
  for _ in $(seq 1 300); do
    [[ -e study.h5.checkpoint ]] && return
    sleep 0.02
  done
}
# kill_job SIGNAL: the ranks first, then mpirun (as a node failure would), and wait for it.
kill_job() {
  local ranks
  ranks=$(pgrep -P "$job")
  [[ -n "$ranks" ]] && kill "-$1" $ranks 2>/dev/null
  [[ "$1" == KILL ]] && kill -KILL "$job" 2>/dev/null
  wait "$job" 2>/dev/null
  code=$?
}

# --- SIGKILL at random moments, the first one inside a checkpoint write ----------------------------
# Each kill must land mid-run: the job still running when it is sent, no output written after it.
kills=0
mid_run=0
inside_write=0
pause=0.2
start_job
# Wait until a checkpoint write is paused between its temporary file (study.h5.checkpoint.tmp.XXXXXX)
# and the rename, then kill.
for _ in $(seq 1 250); do
  compgen -G 'study.h5.checkpoint.tmp.*' >/dev/null && break
  sleep 0.02
done
compgen -G 'study.h5.checkpoint.tmp.*' >/dev/null && inside_write=1
kill -0 "$job" 2>/dev/null && alive=1 || alive=0
kill_job KILL
kills=$((kills + 1))
[[ $alive -eq 1 && ! -e study.h5 ]] && mid_run=$((mid_run + 1))
# Then five kills at random moments 0.1 to 0.4 s into a run (each resume goes on from the last
# checkpoint, so the runs add up: five late kills of up to 0.7 s could finish a 4 s study).
pause=0
for _ in 1 2 3 4 5; do
  start_job
  sleep "$(awk -v r=$RANDOM 'BEGIN { printf "%.2f", 0.1 + 0.3 * r / 32768 }')"
  kill -0 "$job" 2>/dev/null && alive=1 || alive=0
  kill_job KILL
  kills=$((kills + 1))
  [[ $alive -eq 1 && ! -e study.h5 ]] && mid_run=$((mid_run + 1))
done
[[ $inside_write -eq 1 ]] && pass || fail "no kill landed inside a checkpoint write"
[[ $mid_run -eq $kills ]] && pass || fail "only $mid_run of $kills kills landed mid-run (study of $total samples)"
start_job
wait "$job"
code=$?
if [[ $code -eq 0 && -e study.h5 ]]; then pass; else fail "the resumed study did not finish (exit $code): $(tail -5 job.err)"; fi
grep -q "resumed from study.h5.checkpoint: [0-9]* of $total samples already done" job.err && pass ||
  fail "no run resumed from a checkpoint"
"$PYTHON" "$COMPARE" reference.h5 study.h5 && pass || fail "killed and resumed study differs from the reference"
[[ ! -e study.h5.checkpoint ]] && pass || fail "the checkpoint is left after completion"
# The temporary files of the writes the kills interrupted are cleared by the next run's start.
compgen -G 'study.h5*.tmp.*' >/dev/null && fail "temporary files left: $(ls study.h5*.tmp.*)" || pass

# --- SIGTERM: checkpoint, exit code 4, resume ------------------------------------------------------
rm -f study.h5 study.h5.checkpoint* job.err
pause=0.2
"$BLOCKFRAG_PAUSED_CHECKPOINTS" "$pause" run study.json 2>term.err &
job=$!
wait_for_checkpoint
# Meanwhile the same command again is refused: two runs would overwrite each other's checkpoints.
"$BLOCKFRAG" run study.json 2>concurrent.err
code=$?
[[ $code -eq 2 ]] && grep -q "another run of this study is in progress" concurrent.err && pass ||
  fail "a concurrent run: exit $code, $(cat concurrent.err)"
kill -TERM "$job"
wait "$job"
code=$?
if [[ $code -eq 4 ]] && grep -q "interrupted: checkpoint written to study.h5.checkpoint; resume with the same command" term.err \
    && [[ -e study.h5.checkpoint && ! -e study.h5 ]]; then
  pass
else
  fail "SIGTERM on one rank: exit $code, $(cat term.err)"
fi

# Under mpirun the ranks get the signal (as from Slurm), rank 0 gathers and checkpoints, all exit 4.
start_job
sleep 0.2
kill_job TERM
if [[ $code -eq 4 ]] && grep -q "resumed from" job.err && grep -q "interrupted: checkpoint written" job.err; then
  pass
else
  fail "SIGTERM under mpirun: exit $code, $(cat job.err)"
fi

# --- A changed config is refused, the checkpoint left alone ------------------------------------------
checkpoint_sum=$(md5sum <study.h5.checkpoint)
"$BLOCKFRAG" run changed_seed.json --output study.h5 2>changed.err
code=$?
if [[ $code -eq 2 ]] && grep -q "refusing to resume: the checkpoint study.h5.checkpoint belongs to a different study config" changed.err; then
  pass
else
  fail "changed seed: exit $code, $(cat changed.err)"
fi
"$BLOCKFRAG" run study.json --samples-per-level $((per_level / 2)) 2>changed.err
code=$?
[[ $code -eq 2 ]] && grep -q "different study config" changed.err && pass || fail "changed sample count: exit $code, $(cat changed.err)"
[[ "$(md5sum <study.h5.checkpoint)" == "$checkpoint_sum" ]] && pass || fail "a refused resume changed the checkpoint"

# Then the same command finishes it, identical to the reference.
mpirun -n 2 --oversubscribe "$BLOCKFRAG" run study.json 2>final.err
code=$?
[[ $code -eq 0 ]] && pass || fail "final resume: exit $code, $(cat final.err)"
"$PYTHON" "$COMPARE" reference.h5 study.h5 && pass || fail "SIGTERM-interrupted study differs from the reference"

echo "$passed passed, $failed failed ($kills kills, $total samples)"
[[ $failed -eq 0 ]]
