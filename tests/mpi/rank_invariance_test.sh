#!/usr/bin/env bash
# `blockfrag run` gives bitwise identical /samples, /results and /fragility with 1 rank (no mpirun),
# 2 and 3 ranks (oversubscribed; 3 with chunks of one sample, so the chunking differs as much as
# it can, and the run's last line shows as many chunks as samples handed out), for a Latin hypercube and a Monte Carlo study; every sample is
# present exactly once; running a finished study again reports it complete and leaves the file alone.
set -u
source "$(dirname "$0")/../support/script_test.sh"

COMPARE="$BLOCKFRAG_SOURCE_DIR/tests/mpi/compare_study_outputs.py"

cd "$work" || exit 1

# write_study FILE DESIGN: a small study (90 samples, 2 s scenes) with every kind of input and limit state.
write_study() {
  cat >"$1" <<JSON
{
  "scene": {
    "block": {"half_width": 0.5, "half_height": 1.0, "mass": 4800},
    "contact": {"friction": 0.7, "restitution": 0.7},
    "ground_motion": {"type": "cosine_pulse", "amplitude_g": 1.0, "period": 1.0},
    "reservoir": {"level": 0.0, "depth": 100.0},
    "duration": 2.0
  },
  "inputs": {
    "friction": {"distribution": "uniform", "min": 0.55, "max": 0.9},
    "restitution": {"distribution": "normal", "mean": 0.75, "std_dev": 0.1, "lower": 0.0, "upper": 1.0},
    "half_width": {"distribution": "lognormal", "median": 0.5, "beta": 0.1, "lower": 0.2, "upper": 1.2},
    "period": {"distribution": "lognormal", "median": 0.8, "beta": 0.3, "lower": 0.3, "upper": 2.0},
    "reservoir_level": {"distribution": "uniform", "min": -1.5, "max": 0.5},
    "direction": {"distribution": "random_sign"}
  },
  "intensity_measure": {"from": 0.3, "to": 1.8, "count": 6},
  "samples_per_level": 15,
  "design": "$2",
  "limit_states": [
    {"name": "overturn", "type": "overturning"},
    {"name": "rock_half", "type": "max_rotation", "theta_over_alpha": 0.5},
    {"name": "slide_2cm", "type": "residual_slide", "threshold_m": 0.02},
    {"name": "unstable_after", "type": "post_earthquake_unstable", "threshold": 2.5}
  ],
  "seed": 1234,
  "output": "unused.h5",
  "checkpoint_interval_s": 0.05
}
JSON
}

for design in latin_hypercube monte_carlo; do
  write_study "$design.json" "$design"
  "$BLOCKFRAG" run "$design.json" --output "$design-1.h5" 2>"$design-1.err"
  code=$?
  [[ $code -eq 0 ]] && pass || fail "$design, 1 rank: exit code $code: $(cat "$design-1.err")"
  for ranks in 2 3; do
    chunk=()
    [[ $ranks == 3 ]] && chunk=(--max-chunk 1)
    mpirun -n "$ranks" --oversubscribe "$BLOCKFRAG" run "$design.json" --output "$design-$ranks.h5" \
      "${chunk[@]}" 2>"$design-$ranks.err"
    code=$?
    [[ $code -eq 0 ]] && pass || fail "$design, $ranks ranks: exit code $code: $(cat "$design-$ranks.err")"
  done
  if "$PYTHON" "$COMPARE" "$design-1.h5" "$design-2.h5" "$design-3.h5"; then
    pass
    # Rank 0 computes samples too, so how many reach the workers depends on the timing; whatever
    # did, each went alone.
    handed=$(sed -n 's/.* \([0-9]*\) chunks handed out (\([0-9]*\) samples).*/\1 \2/p' "$design-3.err")
    read -r chunks samples <<<"$handed"
    [[ -n "$chunks" && "$chunks" -ge 1 && "$chunks" == "$samples" ]] && pass ||
      fail "$design, 3 ranks: --max-chunk 1 did not give one chunk per sample: $(grep wrote "$design-3.err")"
  else
    fail "$design: outputs differ between rank counts"
  fi
done

# The two designs draw differently (else the comparison above could not tell them apart).
if "$PYTHON" "$COMPARE" latin_hypercube-1.h5 monte_carlo-1.h5 >/dev/null 2>&1; then
  fail "the Latin hypercube and Monte Carlo studies are identical"
else
  pass
fi

# Something happened in the study: the physics ran (a block at rest may take no step, not all of
# them) and some blocks overturned, some did not.
if "$PYTHON" - latin_hypercube-1.h5 <<'PY'
import sys, h5py, numpy as np
with h5py.File(sys.argv[1], "r") as f:
    status = f["results/status"][()]
    assert (status == 0).all(), status
    assert (f["results/steps"][()] > 0).sum() > len(status) // 2
    z = f["fragility/overturn/exceedances"][()]
    assert 0 < z.sum() < f["fragility/overturn/trials"][()].sum(), z
    # Exceeding is monotone in the limit: every overturned block also rocked past half its alpha.
    assert (f["fragility/rock_half/exceedances"][()] >= z).all()
PY
then pass; else fail "the study's results look empty"; fi

# A finished study run again: reported complete, file untouched.
before=$(stat -c %Y.%s latin_hypercube-2.h5)
mpirun -n 2 --oversubscribe "$BLOCKFRAG" run latin_hypercube.json --output latin_hypercube-2.h5 2>again.err
code=$?
after=$(stat -c %Y.%s latin_hypercube-2.h5)
if [[ $code -eq 0 && "$before" == "$after" ]] && grep -q "already complete" again.err; then
  pass
else
  fail "rerunning a finished study: exit $code, $(cat again.err)"
fi

echo "$passed passed, $failed failed"
[[ $failed -eq 0 ]]
