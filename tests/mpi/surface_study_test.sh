#!/usr/bin/env bash
# A fragility-surface study (pulse amplitude x pulse period) gives bitwise identical /samples,
# /results, /fragility and /fragility_surface with 1 rank, 2 ranks and 3 ranks of one-sample
# chunks (so no schedule enters a sample); its grid counts are the successful samples
# of each cell recounted from /results, they sum over the periods to /fragility's counts, each
# sample ran its cell's period, and the fitted surface rises with the amplitude. A surface with a
# sampled period is refused at its JSON path before any work (exit code 2, no file written).
set -u
source "$(dirname "$0")/../support/script_test.sh"

COMPARE="$BLOCKFRAG_SOURCE_DIR/tests/mpi/compare_study_outputs.py"

cd "$work" || exit 1

# 4 amplitudes x 3 periods x 12 samples = 144 scenes of at most 3 s.
cat >surface.json <<'JSON'
{
  "scene": {
    "block": {"half_width": 0.5, "half_height": 1.0},
    "contact": {"friction": 0.7, "restitution": 0.7},
    "ground_motion": {"type": "cosine_pulse", "amplitude_g": 1.0, "period": 1.0},
    "duration": 3.0
  },
  "inputs": {
    "friction": {"distribution": "uniform", "min": 0.55, "max": 0.9},
    "restitution": {"distribution": "uniform", "min": 0.6, "max": 0.9},
    "direction": {"distribution": "random_sign"}
  },
  "intensity_measure": {"type": "pulse_amplitude", "levels": [0.3, 0.6, 1.0, 1.6],
                        "second": {"type": "pulse_period", "levels": [0.5, 1.0, 2.0]}},
  "samples_per_level": 12,
  "design": "latin_hypercube",
  "limit_states": [
    {"name": "overturn", "type": "overturning"},
    {"name": "slide_2cm", "type": "residual_slide", "threshold_m": 0.02}
  ],
  "seed": 77,
  "output": "unused.h5",
  "checkpoint_interval_s": 0.05
}
JSON

"$BLOCKFRAG" run surface.json --output one.h5 2>one.err
code=$?
[[ $code -eq 0 ]] && pass || fail "1 rank: exit code $code: $(cat one.err)"
grep -q "144 samples (4 x 3 cells x 12)" one.err && pass || fail "the run does not name its grid: $(head -n 1 one.err)"
mpirun -n 2 --oversubscribe "$BLOCKFRAG" run surface.json --output two.h5 2>two.err
code=$?
[[ $code -eq 0 ]] && pass || fail "2 ranks: exit code $code: $(cat two.err)"
mpirun -n 3 --oversubscribe "$BLOCKFRAG" run surface.json --output three.h5 --max-chunk 1 2>three.err
code=$?
[[ $code -eq 0 ]] && pass || fail "3 ranks: exit code $code: $(cat three.err)"

if "$PYTHON" "$COMPARE" one.h5 two.h5 three.h5; then pass; else fail "outputs differ"; fi

if "$PYTHON" - one.h5 <<'PY'
import sys, h5py, numpy as np
with h5py.File(sys.argv[1], "r") as f:
    surface = f["fragility_surface"]
    assert surface.attrs["im1_name"] == "pulse_amplitude" and surface.attrs["im2_units"] == "s"
    im2 = f["samples/im2"][()]
    cells = f["samples/level"][()]
    assert np.array_equal(f["samples/im"][()], np.array([0.3, 0.6, 1.0, 1.6])[cells // 3])
    assert np.array_equal(im2, np.array([0.5, 1.0, 2.0])[cells % 3])
    # PGV/PGA of a cosine pulse is g T / (2 pi) (PGA in g, the scene's g 9.81): each sample ran
    # its cell's period.
    ratio = f["samples/pgv_m_s"][()] / f["samples/pga_g"][()]
    assert np.allclose(ratio, 9.81 * im2 / (2 * np.pi), rtol=1e-9), (ratio[:5], im2[:5])
    group = surface["overturn"]
    assert group["trials"].shape == (4, 3) and group["probability"].shape == (4, 3)
    z, n = group["exceedances"][()], group["trials"][()]
    assert 0 < z.sum() < n.sum(), z
    p = group["probability"][()]
    assert np.allclose(p, z / n) and (group["ci_low"][()] <= p).all() and (p <= group["ci_high"][()]).all()
    status = group.attrs["fit_status"]
    assert status in ("ok", "separated", "not_increasing"), status
    if status == "ok":
        b0, b1, b2 = group.attrs["coefficients"]
        assert b1 > 0 and np.all(group.attrs["standard_errors"] > 0)
        assert np.isclose(group.attrs["beta1"], 1 / b1)
        median = group["median_im1"][()]
        assert np.allclose(np.log(median), -(b0 + b2 * np.log([0.5, 1.0, 2.0])) / b1)
PY
then pass; else fail "the surface's grid or fit is wrong"; fi

# A period drawn per sample conflicts with the period axis: refused before any work.
"$PYTHON" - surface.json >bad.json <<'PY'
import json, sys
study = json.load(open(sys.argv[1]))
study["inputs"]["period"] = {"distribution": "uniform", "min": 0.5, "max": 2.0}
study["output"] = "bad.h5"
print(json.dumps(study))
PY
mpirun -n 2 --oversubscribe "$BLOCKFRAG" run bad.json 2>bad.err
code=$?
if [[ $code -eq 2 ]] && grep -q "bad.json: /inputs/period: draws the pulse's period" bad.err && [[ ! -e bad.h5 ]]; then
  pass
else
  fail "a sampled period with a period axis: exit $code, $(cat bad.err)"
fi

echo "$passed passed, $failed failed"
[[ $failed -eq 0 ]]
