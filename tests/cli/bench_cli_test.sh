#!/usr/bin/env bash
# `blockfrag bench` and `blockfrag accuracy` end to end: bench prints exactly one JSON object with its
# keys (and the production default solver for a scene that names none); accuracy runs a 3-scene mini
# suite with 2 settings, writes its HDF5 file and its table, and refuses bad settings and suites;
# plot_work_precision.py draws the diagram from that file. Prints "N passed, M failed" last.
set -u
source "$(dirname "$0")/../support/script_test.sh"


suite="$BLOCKFRAG_SOURCE_DIR/configs/accuracy_suite.json"


# --- bench --------------------------------------------------------------------------------------------
run bench "$BLOCKFRAG_SOURCE_DIR/configs/paper_example.json" --repeat 3
check "bench exits 0 (got $code: $(head -c 300 "$work/err"))" test "$code" -eq 0
check "bench prints one JSON object with its keys" "$PYTHON" - "$work/out" <<'PY'
import json, sys
lines = open(sys.argv[1]).read().splitlines()
assert len(lines) == 1, lines
r = json.loads(lines[0])
for key in ("median_us", "min_us", "max_us", "steps", "rhs_evaluations", "summary", "solver", "repeat"):
    assert key in r, key
assert r["repeat"] == 3
assert 0 < r["min_us"] <= r["median_us"] <= r["max_us"], r
assert r["steps"] > 0 and r["rhs_evaluations"] >= r["steps"], r
assert r["summary"]["status"] == "ok" and r["summary"]["steps"] == r["steps"]
assert r["solver"]["method"] == "adaptive" and r["solver"]["tolerance"] == 1e-8, r["solver"]
PY

# A scene without "solver" runs with the production default (SolverSettings: adaptive, 1e-8).
"$PYTHON" - "$suite" "$work/no_solver.json" <<'PY'
import json, sys
suite = json.load(open(sys.argv[1]))
scene = next(s["scene"] for s in suite["scenes"] if s["name"] == "rock_free_release")
assert "solver" not in scene
json.dump(scene, open(sys.argv[2], "w"))
PY
run bench "$work/no_solver.json"
check "bench of a scene without a solver exits 0" test "$code" -eq 0
check "a scene without a solver gets the default" "$PYTHON" -c '
import json, sys
r = json.loads(open(sys.argv[1]).read())
assert r["solver"]["method"] == "adaptive" and r["solver"]["tolerance"] == 1e-8 and r["repeat"] == 20, r
' "$work/out"

run bench "$BLOCKFRAG_SOURCE_DIR/configs/paper_example.json" --repeat 0
check "bench --repeat 0 exits 2 (got $code)" test "$code" -eq 2

# --- accuracy on a mini suite -------------------------------------------------------------------------
"$PYTHON" - "$suite" "$work/mini.json" <<'PY'
import json, sys
suite = json.load(open(sys.argv[1]))
names = ["rock_free_release", "slide_rectangular", "overturn_rectangular"]
json.dump({"scenes": [s for s in suite["scenes"] if s["name"] in names]}, open(sys.argv[2], "w"))
PY
run accuracy "$work/mini.json" --setting rk4:0.001 --setting adaptive:1e-6 --output "$work/mini.h5" \
  --table "$work/table.md" --min-batch-ms 0.5
check "accuracy exits 0 (got $code: $(head -c 300 "$work/err"))" test "$code" -eq 0
check "the table has a row per setting" grep -q '^| rk4 dt=0.001 |' "$work/out"
check "the table has the adaptive row" grep -q '^| adaptive tol=1e-06 |' "$work/out"
check "the table reports the reference check" grep -q '^Reference: adaptive tol=1e-14; check: gsl_rk8pd tol=1e-14 on 3 scenes' "$work/out"
check "--table writes the same table" cmp -s "$work/out" "$work/table.md"
check "the HDF5 file holds the study" "$PYTHON" - "$work/mini.h5" <<'PY'
import math, sys
import h5py
with h5py.File(sys.argv[1], "r") as f:
    assert f.attrs["scene_count"] == 3 and f.attrs["setting_count"] == 2
    assert f["scenes"].attrs["names"].split("\n") == ["rock_free_release", "slide_rectangular", "overturn_rectangular"]
    assert list(f["scenes/reference_overturned"][...]) == [0, 0, 1]
    assert f["summary"].attrs["labels"].split("\n") == ["rk4 dt=0.001", "adaptive tol=1e-06"]
    assert f["summary"].attrs["methods"].split("\n") == ["rk4", "adaptive"]
    for key in ("median_seconds", "p95_seconds", "median_rhs_evaluations", "max_error_max_abs_theta",
                "wrong_verdict_rate", "max_error_first_impact_time"):
        assert f["summary/" + key].shape == (2,), key
    assert all(f["summary/median_seconds"][...] > 0)
    for group in ("settings/00", "settings/01"):
        errors = f[group + "/error_max_abs_theta"][...]
        assert errors.shape == (3,) and all(math.isfinite(e) for e in errors), errors
        assert all(f[group + "/repeats"][...] >= 1)
        assert all(f[group + "/rhs_evaluations"][...] > 0)
    # rk4 with a coarse step is not exact; the reference check agrees far more tightly in max |theta|.
    assert max(f["settings/00/error_final_slide"][...]) > 0
    assert f["scenes/check_error_max_abs_theta"][...].max() < 1e-9
PY

check "the work-precision diagram is drawn" "$PYTHON" "$BLOCKFRAG_SOURCE_DIR/postproc/plots/plot_work_precision.py" \
  "$work/mini.h5" "$work/wp.png"
check "the diagram is a PNG" "$PYTHON" -c 'import sys; assert open(sys.argv[1], "rb").read(8) == b"\x89PNG\r\n\x1a\n"' "$work/wp.png"

run accuracy "$work/mini.json" --setting euler:0.001 --output "$work/bad.h5"
check "an unknown method exits 2 (got $code)" test "$code" -eq 2
check "an unknown method is named" grep -q 'euler:0.001' "$work/err"
check "no HDF5 file for a refused command" test ! -e "$work/bad.h5"

"$PYTHON" - "$work/mini.json" "$work/with_solver.json" <<'PY'
import json, sys
suite = json.load(open(sys.argv[1]))
suite["scenes"][0]["scene"]["solver"] = {"method": "rk4"}
json.dump(suite, open(sys.argv[2], "w"))
PY
run accuracy "$work/with_solver.json" --setting rk4:0.001 --output "$work/bad.h5"
check "a suite that sets a solver exits 2 (got $code)" test "$code" -eq 2
check "its message names the path" grep -q '/scenes/0/scene/solver: must be absent' "$work/err"

# --- the fragility comparison on a tiny study ---------------------------------------------------------
"$PYTHON" - "$BLOCKFRAG_SOURCE_DIR/configs/example_study.json" "$work/tiny_study.json" <<'PY'
import json, sys
study = json.load(open(sys.argv[1]))
study["samples_per_level"] = 3
json.dump(study, open(sys.argv[2], "w"))
PY
run accuracy "$work/mini.json" --setting adaptive:1e-6 --output "$work/frag.h5" --fragility-study "$work/tiny_study.json" \
  --replicates 2 --design-sizes 2 3 --reference-samples 4 --min-batch-ms 0.1
check "accuracy --fragility-study exits 0 (got $code: $(head -c 300 "$work/err"))" test "$code" -eq 0
check "the fragility table has a row per limit state" \
  test "$(grep -c '^| adaptive tol=1e-06 | \(overturn\|rocking_half_alpha\|slide_5cm\) |' "$work/out")" -eq 3
check "the design table has both designs" grep -q '^| latin_hypercube | 3 | overturn |' "$work/out"
check "the design table has Monte Carlo" grep -q '^| monte_carlo | 2 | overturn |' "$work/out"

echo "$passed passed, $failed failed"
test "$failed" -eq 0
