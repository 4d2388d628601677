#!/usr/bin/env bash
# Builds the fuzz targets (tests/fuzz/*_fuzzer.cpp) with clang, libFuzzer, ASan and UBSan in
# build-fuzz, then runs each for SECONDS from a copy of the seed corpus (tests/data, configs), so the
# repository is not modified. Fails if any target finds a crash, a sanitizer report, an exception
# other than InvalidInput, a hang (-timeout=10) or a huge allocation (-rss_limit_mb=2048).
#   tests/fuzz/run_fuzzers.sh SECONDS [TARGET...]     e.g. 30, or 600 scene_json_fuzzer
# Environment: BUILD_DIR (default build-fuzz; a folder configured with BLOCKFRAG_BUILD_FUZZERS is
# built as it is configured); JOBS, targets run at once (default 1; each uses one
# core); FUZZ_WORK, a folder for the corpora, logs and crash inputs (default a temporary folder,
# removed unless a target failed); FUZZ_ARGS, more libFuzzer options.
# The corpus a run grows is FUZZ_WORK/corpus/TARGET; a crash input is FUZZ_WORK/artifacts/TARGET/.
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds=${1:?usage: tests/fuzz/run_fuzzers.sh SECONDS [TARGET...]}
shift
build=${BUILD_DIR:-build-fuzz}
jobs=${JOBS:-1}

# A build folder configured with BLOCKFRAG_BUILD_FUZZERS (CI's sanitized build, which also builds
# the tests) is used as it is; otherwise the fuzz build: only the config library (engine, sampling,
# JSON) and the fuzz targets, at -O1.
if ! grep -qs '^BLOCKFRAG_BUILD_FUZZERS:BOOL=ON$' "$build/CMakeCache.txt"; then
  CC=clang CXX=clang++ cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE=-O1 \
    -DBLOCKFRAG_BUILD_FUZZERS=ON -DBLOCKFRAG_BUILD_TESTS=OFF -DBLOCKFRAG_BUILD_DRIVER=OFF -DBLOCKFRAG_WERROR=ON >/dev/null
fi
cmake --build "$build" --target blockfrag_fuzzers -j "$(nproc)"

targets=("$@")
if ((${#targets[@]} == 0)); then
  for source in tests/fuzz/*_fuzzer.cpp; do
    target=$(basename "$source" .cpp)
    # hdf5_reader_fuzzer needs BLOCKFRAG_BUILD_DRIVER, which the default fuzz build leaves off.
    if [ ! -x "$build/tests/fuzz/$target" ] && [ "$target" = hdf5_reader_fuzzer ]; then
      echo "== $target is not built in $build (it needs BLOCKFRAG_BUILD_DRIVER=ON): skipped"
      continue
    fi
    targets+=("$target")
  done
fi

keep_work=${FUZZ_WORK:+yes}
work=${FUZZ_WORK:-$(mktemp -d)}
mkdir -p "$work"
work=$(cd "$work" && pwd)

# The seeds of a target, by what it reads.
seeds() {
  case "$1" in
    at2_record_fuzzer)
      find tests/data/records tests/data/bad_records -maxdepth 1 -type f -iname '*.at2' ;;
    two_column_record_fuzzer)
      find tests/data/records tests/data/bad_records -maxdepth 1 -type f \
        ! -iname '*.at2' ! -name '*.json' ! -name '*.py' ;;
    spectrum_spec_fuzzer)
      ls tests/data/spectrum_specs/*.json configs/*.json tests/data/bad_scenes/*.json ;;
    adaptive_design_fuzzer)
      ls tests/data/adaptive_studies/* tests/data/bad_studies/*.json configs/*.json ;;
    hdf5_reader_fuzzer)
      ls tests/data/study_outputs/*.h5 ;;
    *)
      ls tests/data/bad_scenes/*.json tests/data/bad_studies/*.json tests/data/pulse_scenes/*.json \
        tests/data/records/*.json configs/*.json ;;
  esac
}
dictionary() {
  case "$1" in
    *_record_fuzzer) echo tests/fuzz/records.dict ;;
    hdf5_reader_fuzzer) echo tests/fuzz/hdf5.dict ;;
    *) echo tests/fuzz/json.dict ;;
  esac
}

# hdf5_reader_fuzzer meets HDF5 1.10's own bugs on damaged files within seconds (docs/developing.md,
# "Fuzzing"): it runs in fork mode, which goes on past a crash, a hang or an out-of-memory, and
# every input it saved is replayed (triage below).
mode_args() {
  case "$1" in
    hdf5_reader_fuzzer) echo "-fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1" ;;
  esac
}

# Replays TARGET's saved inputs; each is blockfrag's finding (an escaped exception, or a report
# whose innermost frame in either libhdf5 or blockfrag's code is blockfrag's), HDF5's, an
# out-of-memory or a hang whose report holds no frame of either (the reader's own allocations are
# bounded by the schema's caps, so such a report is set apart, not counted as blockfrag's), or not
# reproduced alone. Prints the tally; fails when one is blockfrag's.
triage() {
  local target=$1 ours=0 library=0 unplaced=0 gone=0 input report frame
  for input in "$work/artifacts/$target"/*; do
    [ -e "$input" ] || continue
    report=$(TMPDIR="$work/tmp/$target" LSAN_OPTIONS="suppressions=$PWD/tests/fuzz/lsan.supp" \
      timeout 60 "$build/tests/fuzz/$target" -timeout=10 -rss_limit_mb=2048 "$input" 2>&1 || true)
    if grep -q "FINDING" <<<"$report"; then
      ours=$((ours + 1)) && echo "blockfrag's: $input"
    elif ! grep -qE "ERROR|SUMMARY" <<<"$report"; then
      gone=$((gone + 1))
    else
      # An out-of-memory past the RSS limit lists the live allocations, largest first: the largest
      # is the culprit, and a smaller one of blockfrag's beside it is not.
      if grep -q "Live Heap Allocations" <<<"$report"; then
        report=$(awk '/byte\(s\) \(/ { n++ } n == 1' <<<"$report")
      fi
      frame=$(grep -E '^ +#[0-9]+ ' <<<"$report" | grep -E 'libhdf5|blockfrag::' | head -1)
      if [[ $frame == *libhdf5* ]]; then
        library=$((library + 1))
      elif [[ -z $frame ]] && grep -qE "out-of-memory|timeout|byte\(s\) \(" <<<"$report"; then
        unplaced=$((unplaced + 1)) && echo "without a frame: $input"
      else
        ours=$((ours + 1)) && echo "blockfrag's: $input"
      fi
    fi
  done
  echo "$target: saved inputs: $library in libhdf5, $unplaced out-of-memory or hangs without a" \
    "frame of either, $gone not reproduced alone, $ours blockfrag's"
  ((ours == 0))
}

# Runs one target; its log is $work/TARGET.log, its exit code $work/TARGET.rc.
run_target() {
  local target=$1 corpus="$work/corpus/$1" artifacts="$work/artifacts/$1/" tmp="$work/tmp/$1"
  mkdir -p "$corpus" "$artifacts" "$tmp"
  seeds "$target" | while read -r seed; do cp "$seed" "$corpus/seed-$(basename "$seed")"; done
  local rc=0
  # TMPDIR: each target's private record folder (tests/fuzz/fuzz_support.hpp) is made in there.
  TMPDIR="$tmp" UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    LSAN_OPTIONS="suppressions=$PWD/tests/fuzz/lsan.supp" \
    "$build/tests/fuzz/$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -dict="$(dictionary "$target")" -artifact_prefix="$artifacts" -print_final_stats=1 \
    $(mode_args "$target") ${FUZZ_ARGS:-} "$corpus" >"$work/$target.log" 2>&1 || rc=$?
  if [ -n "$(mode_args "$target")" ]; then
    rc=0
    triage "$target" >>"$work/$target.log" 2>&1 || rc=1
  fi
  echo "$rc" >"$work/$target.rc"
}

echo "== fuzzing ${targets[*]} for ${seconds} s each, $jobs at a time, in $work"
start=$(date +%s)
running=0
for target in "${targets[@]}"; do
  if [ ! -x "$build/tests/fuzz/$target" ]; then
    echo "no fuzz target $target (tests/fuzz/$target.cpp)" >&2
    exit 2
  fi
  run_target "$target" &
  running=$((running + 1))
  if ((running >= jobs)); then
    wait -n || true
    running=$((running - 1))
  fi
done
wait

passed=0 failed=0
for target in "${targets[@]}"; do
  rc=$(cat "$work/$target.rc")
  stat() { sed -n "s/^stat::$1: *//p" "$work/$target.log" | tail -1; }
  coverage=$(grep -oE 'cov: [0-9]+ ft: [0-9]+ corp: [0-9]+' "$work/$target.log" | tail -1 || true)
  grep -h "saved inputs:" "$work/$target.log" || true
  if [ "$rc" = 0 ]; then
    passed=$((passed + 1))
    echo "PASS $target: $(stat number_of_executed_units) runs, $(stat average_exec_per_sec) exec/s, $coverage"
  else
    failed=$((failed + 1))
    keep_work=yes
    echo "FAIL $target (exit $rc): the input is in $work/artifacts/$target/; the end of its log:"
    tail -n 80 "$work/$target.log"
  fi
done
echo "== fuzzing took $(($(date +%s) - start)) s"
[ -n "$keep_work" ] || rm -rf "$work"
echo "fuzz: $passed passed, $failed failed"
((failed == 0))
