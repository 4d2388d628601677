#!/usr/bin/env bash
# `blockfrag statics` end to end: the type A block with the water at the crest and at 5 m freeboard
# against hand computations (hydrostatic 1/2 rho g d^2, uplift 1/2 rho g d B, Westergaard's
# (7/12) rho sqrt(H) d^(3/2), the yield accelerations' closed forms and the pseudo-static factors
# of engine/water/block_statics.hpp), the type B block's folded crack against its hand integral,
# both wet configs simulated with the post-earthquake keys in their summaries (and none in a dry
# one's), a dry block's keys with zero water, the report, the zero_in_gap step scenes of
# tests/data/uplift_steps/ (at rest after one event), and bad input:
# a bad scene and a bad --coefficient exit 2 with the reason on stderr and nothing on stdout. Prints
# "N passed, M failed" last; exits non-zero on any failure.
set -u
source "$(dirname "$0")/../support/script_test.sh"

wet="$BLOCKFRAG_SOURCE_DIR/configs/dam_block_type_a_reservoir.json"
dry="$BLOCKFRAG_SOURCE_DIR/configs/dam_block_type_a.json"

# --- The type A block, wet: at the crest and at 5 m freeboard ------------------------------------
"$PYTHON" - "$wet" "$work/freeboard.json" <<'PY'
import json, sys
scene = json.load(open(sys.argv[1]))
scene["reservoir"]["level"] = 16.7 - 5.0
json.dump(scene, open(sys.argv[2], "w"))
PY
for case in "$wet:0" "$work/freeboard.json:5"; do
  scene=${case%:*}
  freeboard=${case##*:}
  run statics "$scene" --coefficient 0.1 --summary-json
  check "statics at freeboard $freeboard m exits 0 (got $code: $(head -c 300 "$work/err"))" test "$code" -eq 0
  check "statics at freeboard $freeboard m matches the hand computations" "$PYTHON" - "$work/out" "$freeboard" <<'PY'
import json, math, sys
out = json.loads(open(sys.argv[1]).read())
d = 16.7 - float(sys.argv[2])
rho, g, H, B, m, mu, K = 1000.0, 9.81, 100.0, 12.55, 411204.0, 1.05, 0.1
area = 167.0 + 4.335
x_g, y_g = (167 * 5 + 4.335 * 10.85) / area, (167 * 8.35 + 4.335 * 3.4 / 3) / area
W = m * g
P = 0.5 * rho * g * d * d
U = 0.5 * rho * g * d * B
Ma = 7 / 12 * rho * math.sqrt(H) * d ** 1.5
Sb = 7 / 30 * rho * math.sqrt(H) * d ** 2.5
hand = {
    "weight_N": W, "uplift_force_N": U, "added_mass_kg": Ma,
    "slide_downstream": (mu * (W - U) - P) / ((m + Ma) * g),
    "slide_upstream": (mu * (W - U) + P) / ((m + Ma) * g),
    "rock_downstream": (W * (B - x_g) - P * d / 3 - U * 2 * B / 3) / ((m * y_g + Sb) * g),
    "rock_upstream": (W * x_g + P * d / 3 - U * B / 3) / ((m * y_g + Sb) * g),
    "sliding_safety_factor": mu * (W - U) / (P + K * W + K * g * Ma),
    "overturning_safety_factor": W * (B - x_g) / (P * d / 3 + U * 2 * B / 3 + K * W * y_g + K * g * Sb),
}
got = dict(out, **out["yield_acceleration_g"])
for key, value in hand.items():
    assert math.isclose(got[key], value, rel_tol=1e-11), (key, got[key], value)
assert math.isclose(out["hydrostatic_force_N"][0], P, rel_tol=1e-12) and out["hydrostatic_force_N"][1] == 0
assert out["uplift_horizontal_force_N"] == 0 and out["coefficient"] == 0.1
PY
done

# --- The type B block on its folded seat, wet: the crack's horizontal push ---------------------------
run statics "$BLOCKFRAG_SOURCE_DIR/configs/dam_block_type_b_reservoir.json" --summary-json
check "type B statics exits 0" test "$code" -eq 0
check "type B's folded crack pushes it upstream as the hand integral says" "$PYTHON" - "$work/out" <<'PY'
import json, math, sys
out = json.loads(open(sys.argv[1]).read())
# Head 21.7 m at the heel, p(s) = rho g h (1 - s/S) along the base (L1 = 703/120 m) and the incline
# (8.333 m, slope (0.8, 0.6), pressing along (-0.6, 0.8)).
p = 1000.0 * 9.81 * 21.7
L1 = 703 / 120
L2 = math.hypot(12.525 - L1, 5.0)
S = L1 + L2
base, incline = p * (L1 - L1 * L1 / (2 * S)), p * L2 * L2 / (2 * S)
assert math.isclose(out["uplift_horizontal_force_N"], -0.6 * incline, rel_tol=1e-12), out
assert math.isclose(out["uplift_force_N"], base + 0.8 * incline, rel_tol=1e-12), out
assert math.isclose(out["hydrostatic_force_N"][0], 0.5 * p * 21.7, rel_tol=1e-12), out
PY

# --- Both wet configs simulate, their summaries with the post-earthquake keys -------------------------
for block in a b; do
  run simulate "$BLOCKFRAG_SOURCE_DIR/configs/dam_block_type_${block}_reservoir.json" --summary-json
  check "type $block with its reservoir simulates (got $code)" test "$code" -eq 0
  check "type $block's summary has the post-earthquake keys" "$PYTHON" -c '
import json, sys
summary = json.loads(open(sys.argv[1]).read())
assert "post_earthquake_sliding_safety_factor" in summary and "post_earthquake_overturning_safety_factor" in summary
' "$work/out"
done
run simulate "$dry" --summary-json
check "a dry scene's summary has no post-earthquake keys" "$PYTHON" -c '
import json, sys
assert "post_earthquake_sliding_safety_factor" not in json.loads(open(sys.argv[1]).read())
' "$work/out"

# --- Dry: the same keys, zero water; the yields are mu and the tip thresholds -----------------------
run statics "$dry" --summary-json
check "dry statics exits 0" test "$code" -eq 0
check "dry statics has zero water, no factors without --coefficient" "$PYTHON" - "$work/out" <<'PY'
import json, math, sys
out = json.loads(open(sys.argv[1]).read())
assert out["hydrostatic_force_N"] == [0.0, 0.0] and out["uplift_force_N"] == 0 and out["added_mass_kg"] == 0
assert "sliding_safety_factor" not in out
y = out["yield_acceleration_g"]
assert math.isclose(y["slide_downstream"], 1.05) and math.isclose(y["slide_upstream"], 1.05)
PY

# --- The report --------------------------------------------------------------------------------------
run statics "$wet" --coefficient 0.1
check "the report exits 0" test "$code" -eq 0
check "the report names the water and each yield" grep -qE "^  slide downstream: 0\.2252" "$work/out"
check "the report gives the pseudo-static factors" grep -qE "^  sliding safety factor: +1\.45" "$work/out"

# --- zero_in_gap between the closed and the open crack's rocking yields: at rest, one event ----------
for scene in "$BLOCKFRAG_SOURCE_DIR"/tests/data/uplift_steps/*.json; do
  run simulate "$scene" --summary-json
  check "$(basename "$scene") exits 0 (got $code)" test "$code" -eq 0
  check "$(basename "$scene") stays at rest after one event" "$PYTHON" - "$work/out" <<'PY'
import json, sys
out = json.loads(open(sys.argv[1]).read())
assert out["events"] == 1, out["events"]
assert out["modes"][-1][1] == "rest", out["modes"][-1]
PY
done

# --- Bad input ---------------------------------------------------------------------------------------
run statics "$BLOCKFRAG_SOURCE_DIR/tests/data/bad_scenes/reservoir_without_level.json"
check "a bad scene exits 2 (got $code)" test "$code" -eq 2
check "a bad scene names its file and path" grep -qF "reservoir_without_level.json: /reservoir/level: is required" "$work/err"
check "a bad scene writes nothing on stdout" test ! -s "$work/out"
for coefficient in -0.1 nan inf abc; do
  run statics "$wet" --coefficient "$coefficient"
  check "--coefficient $coefficient exits 2 (got $code)" test "$code" -eq 2
  check "--coefficient $coefficient writes nothing on stdout" test ! -s "$work/out"
done

echo "$passed passed, $failed failed"
[[ $failed -eq 0 ]]
