#!/usr/bin/env bash
# An adaptive study (design "adaptive") is a pure function of its config: 1 rank, 2 ranks and 3
# ranks with chunks of one sample write bitwise identical files, /adaptive included; a run killed
# with SIGKILL after its second batch and one stopped with SIGTERM, each resumed with the same
# command, end identical to them too. Its batches add two levels each, beyond the first batch's,
# until the median's interval is as narrow as asked, and the file says so.
set -u
source "$(dirname "$0")/../support/script_test.sh"

COMPARE="$BLOCKFRAG_SOURCE_DIR/tests/mpi/compare_study_outputs.py"

cd "$work" || exit 1

cat >study.json <<JSON
{
  "scene": {
    "block": {"half_width": 0.5, "half_height": 1.0},
    "contact": {"friction": 0.7, "restitution": 0.7},
    "ground_motion": {"type": "cosine_pulse", "amplitude_g": 1.0, "period": 1.0},
    "duration": 2.0
  },
  "inputs": {
    "friction": {"distribution": "uniform", "min": 0.55, "max": 0.9},
    "restitution": {"distribution": "uniform", "min": 0.6, "max": 0.9},
    "period": {"distribution": "lognormal", "median": 1.0, "beta": 0.3, "lower": 0.3, "upper": 3.0},
    "direction": {"distribution": "random_sign"}
  },
  "intensity_measure": {"type": "pga", "from": 0.4, "to": 2.0, "count": 3},
  "samples_per_level": 100,
  "design": {"adaptive": {"limit_state": "overturn", "target_relative_width": 0.08,
                          "max_samples": 5000}},
  "limit_states": [
    {"name": "rock_half", "type": "max_rotation", "theta_over_alpha": 0.5},
    {"name": "overturn", "type": "overturning"}
  ],
  "seed": 77,
  "output": "study.h5",
  "checkpoint_interval_s": 0.05
}
JSON

"$BLOCKFRAG" run study.json --output one.h5 2>one.err
code=$?
[[ $code -eq 0 ]] && pass || fail "1 rank: exit code $code: $(cat one.err)"
for ranks in 2 3; do
  chunk=()
  [[ $ranks == 3 ]] && chunk=(--max-chunk 1)
  mpirun -n "$ranks" --oversubscribe "$BLOCKFRAG" run study.json --output "ranks$ranks.h5" \
    "${chunk[@]}" 2>"ranks$ranks.err"
  code=$?
  [[ $code -eq 0 ]] && pass || fail "$ranks ranks: exit code $code: $(cat "ranks$ranks.err")"
done
"$PYTHON" "$COMPARE" one.h5 ranks2.h5 ranks3.h5 && pass || fail "outputs differ between rank counts"

# The batches: several, each two levels, the last one reaching the target within the budget.
if "$PYTHON" - one.h5 <<'PY'
import sys, h5py, numpy as np
with h5py.File(sys.argv[1], "r") as f:
    a = f["adaptive"]
    batch = a["level_batch"][()]
    assert (batch[:3] == 0).all() and len(batch) >= 7, batch
    assert (np.bincount(batch)[1:] == 2).all(), batch
    assert np.array_equal(a["level_im"][()], f["fragility/overturn/im"][()])
    samples = a["batch_samples"][()]
    assert np.array_equal(samples, 300 + 200 * np.arange(len(samples))), samples
    assert samples[-1] == f.attrs["total_samples"] <= 5000
    width = a["batch_relative_width"][()]
    assert a.attrs["stop_reason"] == "target reached", a.attrs["stop_reason"]
    assert width[-1] <= 0.08 < width[-2], width
    assert a.attrs["limit_state"] == "overturn"
PY
then pass; else fail "the adaptive batches are not as documented"; fi

# start STEM COMMAND...: runs in the background until rank 0 has logged its second batch. The runs
# to be stopped hold each checkpoint write for 0.2 s (the test hook) so that the run is still
# going when the signal comes: unheld, the batches after the second took less time on a loaded
# machine than the test took to send it.
start_until_second_batch() {
  : >job.err
  "$@" 2>>job.err &
  job=$!
  for _ in $(seq 1 3000); do
    grep -q "^batch 1:" job.err && return
    kill -0 "$job" 2>/dev/null || return
    sleep 0.01
  done
}

# SIGKILL on 1 rank, then resume.
start_until_second_batch "$BLOCKFRAG_PAUSED_CHECKPOINTS" 0.2 run study.json --output killed.h5
kill -KILL "$job" 2>/dev/null
wait "$job" 2>/dev/null
if [[ -e killed.h5 ]]; then
  fail "the run finished before the kill (the test did not test a resume)"
else
  pass
  "$BLOCKFRAG" run study.json --output killed.h5 2>resume.err
  code=$?
  [[ $code -eq 0 ]] && grep -q "resumed from" resume.err && pass ||
    fail "resuming after SIGKILL: exit $code: $(cat resume.err)"
  "$PYTHON" "$COMPARE" one.h5 killed.h5 && pass || fail "the resumed run differs"
fi

# SIGTERM on 2 ranks: exit code 4, a checkpoint, and the resume completes identically.
start_until_second_batch mpirun -n 2 --oversubscribe "$BLOCKFRAG_PAUSED_CHECKPOINTS" 0.2 run study.json \
  --output termed.h5
ranks=$(pgrep -P "$job")
[[ -n "$ranks" ]] && kill -TERM $ranks 2>/dev/null
wait "$job" 2>/dev/null
code=$?
if [[ $code -eq 4 && -e termed.h5.checkpoint && ! -e termed.h5 ]]; then
  pass
  mpirun -n 2 --oversubscribe "$BLOCKFRAG" run study.json --output termed.h5 2>resume2.err
  code=$?
  [[ $code -eq 0 ]] && pass || fail "resuming after SIGTERM: exit $code: $(cat resume2.err)"
  "$PYTHON" "$COMPARE" one.h5 termed.h5 && pass || fail "the run resumed after SIGTERM differs"
else
  fail "SIGTERM: exit code $code (expected 4), checkpoint $(ls termed.h5* 2>&1)"
fi

echo "$passed passed, $failed failed"
[[ $failed -eq 0 ]]
