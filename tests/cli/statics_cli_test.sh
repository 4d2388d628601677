#!/usr/bin/env bash
# `blockfrag statics` end to end: the type A block with the water at the crest and at 5 m freeboard
# against hand computations (hydrostatic 1/2 rho g d^2, uplift 1/2 rho g d B, Westergaard's
# (7/12) rho sqrt(H) d^(3/2), the yield accelerations' closed forms and the pseudo-static factors
# of engine/water/block_statics.hpp), a dry block's keys with zero water, the report, and bad input:
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
