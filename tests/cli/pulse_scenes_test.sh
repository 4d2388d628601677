#!/usr/bin/env bash
# `blockfrag simulate` on one scene per near-fault pulse type (tests/data/pulse_scenes): a block
# with a/b = 0.25 that cannot slide (mu = 10, e = 0) starts to rock where |lambda| first passes
# a/b (Shenton 1996), at the time computed here from each pulse's published formula.
# Prints "N passed, M failed" last; exits non-zero on any failure.
set -u
source "$(dirname "$0")/../support/script_test.sh"

for scene in "$BLOCKFRAG_SOURCE_DIR"/tests/data/pulse_scenes/*.json; do
  name=$(basename "$scene" .json)
  if ! "$BLOCKFRAG" simulate "$scene" --summary-json >"$work/out" 2>"$work/err"; then
    fail "$name: exit code $? ($(head -c 300 "$work/err"))"
    continue
  fi
  if "$PYTHON" - "$scene" "$work/out" <<'PY'; then pass; else fail "$name"; fi
import json, math, sys
scene = json.load(open(sys.argv[1]))
summary = json.load(open(sys.argv[2]))
m, g = scene["ground_motion"], 9.81
beta = scene["block"]["half_width"] / scene["block"]["half_height"]

def bisect(f, a, b):  # f(a) < 0 <= f(b)
    for _ in range(200):
        mid = 0.5 * (a + b)
        a, b = (a, mid) if f(mid) >= 0 else (mid, b)
    return b

def first_crossing(f, a, b, n=20000):  # first t with f(t) >= 0
    step = (b - a) / n
    for i in range(1, n + 1):
        t = a + i * step
        if f(t) >= 0:
            return bisect(f, t - step, t)
    raise SystemExit("no crossing")

A, Tp = m.get("amplitude_g"), m["period"]
w = 2 * math.pi / Tp
if m["type"] == "makris_a":      # A sin(w t)
    expected = math.asin(beta / A) / w
elif m["type"] == "makris_b":    # A cos(w t), above beta from the start
    expected = 0.0
elif m["type"] == "makris_c":    # A cos(w t + phi), 2 cos(phi) = (3 pi - 2 phi) sin(phi); below beta at 0
    phi = bisect(lambda p: (3 * math.pi - 2 * p) * math.sin(p) - 2 * math.cos(p), 0.0, math.pi / 2)
    assert A * math.cos(phi) < beta
    expected = (math.acos(-beta / A) - phi) / w
elif m["type"] == "ricker":      # A (1 - 2u^2) exp(-u^2), u = pi (t - 1.5 Tp) / Tp
    r = lambda t: A * (1 - 2 * (math.pi * (t - 1.5 * Tp) / Tp) ** 2) * math.exp(-(math.pi * (t - 1.5 * Tp) / Tp) ** 2)
    expected = first_crossing(lambda t: abs(r(t)) - beta, 0.0, 3 * Tp)
else:                            # -v'/g, v = Vp/2 [1 + cos(w tau / gamma)] cos(w tau + nu)
    vp, gamma, nu = m["velocity_amplitude"], m["gamma"], m["phase"]
    t0 = gamma * Tp / 2
    v = lambda t: 0.5 * vp * (1 + math.cos(w * (t - t0) / gamma)) * math.cos(w * (t - t0) + nu)
    h = 1e-6
    lam = lambda t: -(v(t + h) - v(t - h)) / (2 * h) / g
    expected = first_crossing(lambda t: abs(lam(t)) - beta, 0.0, 2 * t0)
ok = summary["status"] == "ok" and summary["slide_start_time"] is None and summary["rock_start_time"] is not None
tolerance = 1e-9  # the onset is placed 1e-12 past the threshold; v' by central differences errs ~1e-10
if not ok or abs(summary["rock_start_time"] - expected) > tolerance:
    print(f'{m["type"]}: rock_start_time {summary["rock_start_time"]}, expected {expected}', file=sys.stderr)
    sys.exit(1)
PY
done

echo "$passed passed, $failed failed"
[[ $failed -eq 0 && $passed -eq 5 ]]
