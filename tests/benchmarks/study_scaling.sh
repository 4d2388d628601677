#!/usr/bin/env bash
# Not a test: prints, as a markdown table, the example study's scenes per second on 1 and 2 ranks,
# the parallel efficiency (rate on 2 ranks / (2 x rate on 1 rank)), and the checkpoint overhead (a
# checkpoint every 0.01 s, and every 1 s, against none) on 2 ranks. Wall times include start-up
# and writing the output, as a user sees them; user CPU seconds show the work apart from the
# machine's load.
#
#   BLOCKFRAG=build/mpi_driver/blockfrag tests/benchmarks/study_scaling.sh [--markdown] [SAMPLES_PER_LEVEL]
#
# --markdown prints under the table the line docs/performance.md shows under it: the version, the
# cores and the load average that measured it, and this command (as tests/benchmarks/markdown_stamp.py
# words it). The machine should be otherwise idle: the 2-rank runs need 2 free cores.
set -eu

: "${BLOCKFRAG:?path of the blockfrag executable}"
source_dir=${BLOCKFRAG_SOURCE_DIR:-$(cd "$(dirname "$0")/../.." && pwd)}
markdown=false
if [[ ${1:-} == --markdown ]]; then
  markdown=true
  shift
fi
samples_per_level=${1:-1500}
export OMPI_ALLOW_RUN_AS_ROOT=${OMPI_ALLOW_RUN_AS_ROOT:-1} OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=${OMPI_ALLOW_RUN_AS_ROOT_CONFIRM:-1}
load_before=$(cut -d' ' -f1 /proc/loadavg)
version=$("$BLOCKFRAG" --version | awk '{print $2}')

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
study="$source_dir/configs/example_study.json"
sed -e 's/"checkpoint_interval_s": [0-9.e+]*/"checkpoint_interval_s": 1e6/' "$study" >"$work/none.json"
sed -e 's/"checkpoint_interval_s": [0-9.e+]*/"checkpoint_interval_s": 0.01/' "$study" >"$work/often.json"
sed -e 's/"checkpoint_interval_s": [0-9.e+]*/"checkpoint_interval_s": 1/' "$study" >"$work/second.json"

# run LABEL RANKS CONFIG: one row of the table; the rate in $rate.
run() {
  local label=$1 ranks=$2 config=$3 output="$work/out-$RANDOM.h5" seconds user samples checkpoints
  local launcher=()
  [[ $ranks -gt 1 ]] && launcher=(mpirun -n "$ranks")
  # mpirun waits for its ranks, so its user time includes theirs.
  /usr/bin/time -f "%e %U" -o "$work/time" "${launcher[@]}" "$BLOCKFRAG" run "$config" --output "$output" \
    --samples-per-level "$samples_per_level" 2>"$work/err"
  read -r seconds user <"$work/time"
  samples=$(sed -n 's/.*(\([0-9]*\) samples computed in this run.*/\1/p' "$work/err")
  checkpoints=$(sed -n 's/.*, \([0-9]*\) checkpoints taking \([0-9.e-]*\) s).*/\1 (\2 s)/p' "$work/err")
  rate=$(awk -v n="$samples" -v s="$seconds" 'BEGIN { printf "%.0f", n / s }')
  cpu=$user
  printf "| %s | %d | %d | %s | %s | %s | %s |\n" "$label" "$ranks" "$samples" "$seconds" "$user" "$rate" "${checkpoints:-0}"
  rm -f "$output"
}

echo "| run | ranks | samples | wall s | user s | scenes/s | checkpoints (time writing) |"
echo "|---|---|---|---|---|---|---|"
run "no checkpoints" 1 "$work/none.json"
rate1=$rate
cpu1=$cpu
run "no checkpoints" 2 "$work/none.json"
rate2=$rate
cpu2=$cpu
run "checkpoint every 0.01 s" 2 "$work/often.json"
rate2c=$rate
run "checkpoint every 1 s" 2 "$work/second.json"
rate2s=$rate
if $markdown; then
  shown_blockfrag=$BLOCKFRAG
  [[ $shown_blockfrag == "$source_dir"/* ]] && shown_blockfrag=${shown_blockfrag#"$source_dir"/}
  echo
  printf 'Measured with blockfrag %s on %s cores, load average %s before and %s after, by `%s`.\n' \
    "$version" "$(nproc)" "$load_before" "$(cut -d' ' -f1 /proc/loadavg)" \
    "BLOCKFRAG=$shown_blockfrag bash tests/benchmarks/study_scaling.sh --markdown $samples_per_level"
fi
echo
awk -v r1="$rate1" -v r2="$rate2" -v rc="$rate2c" -v rs="$rate2s" -v c1="$cpu1" -v c2="$cpu2" 'BEGIN {
  printf "- parallel efficiency, 2 ranks: %.2f\n", r2 / (2 * r1)
  printf "- CPU-time efficiency, 2 ranks (user s on 1 rank / user s on 2 ranks; MPI polling counts as work): %.2f\n", c1 / c2
  printf "- checkpoint overhead, 2 ranks: every 0.01 s %.1f %%, every 1 s %.1f %%\n", 100 * (r2 - rc) / r2, 100 * (r2 - rs) / r2
}'
