#!/usr/bin/env bash
# The files every command writes, replaces or removes: a regular file of its own or nothing at
# each name (never a link, a FIFO, a device, one of its inputs or another output, refused with exit
# code 2 before any work), side files no other output's can share, only provably own files
# removed, and a full disk reported (exit code 1) with the checkpoint kept. Never the real
# /dev/null: the FIFOs, links and devices are made here, in the scratch folder.
set -u
source "$(dirname "$0")/../support/script_test.sh"
source "$(dirname "$0")/../support/hostile_case.sh"
cd "$work" || exit 1

# unchanged FILE CHECKSUM: the file's content is still what `md5sum` gave.
unchanged() { [[ "$(md5sum <"$1")" == "$2" ]]; }

scene="$BLOCKFRAG_SOURCE_DIR/configs/paper_example.json"
cp "$scene" scene.json
echo data >victim.txt
victim_sum=$(md5sum <victim.txt)
study_with '{"samples_per_level": 20}' >small.json
"$B" run small.json --output study.h5 2>/dev/null
study_sum=$(md5sum <study.h5)

# --- simulate --history ----------------------------------------------------------------------------
mkfifo fifo.csv
run_case history_fifo 2 "fifo.csv (--history): is a FIFO" "$B" simulate scene.json --history fifo.csv
[[ -p fifo.csv ]] && pass || fail "history_fifo: the FIFO was replaced"
ln -s /dev/zero zero.csv
run_case history_device_link 2 "zero.csv (--history): is a symbolic link" \
  "$B" simulate scene.json --history zero.csv
[[ "$(readlink zero.csv)" == /dev/zero ]] && pass || fail "history_device_link: the link was replaced"
ln -s victim.txt victim.csv
run_case history_link 2 "victim.csv (--history): is a symbolic link" \
  "$B" simulate scene.json --history victim.csv
[[ -L victim.csv ]] && unchanged victim.txt "$victim_sum" && pass || fail "history_link: replaced or followed"
cp scene.json own.json
scene_sum=$(md5sum <own.json)
run_case history_is_the_scene 2 "own.json (--history): is this command's input, the scene" \
  "$B" simulate own.json --history own.json
unchanged own.json "$scene_sum" && pass || fail "history_is_the_scene: the scene was replaced"
cp study.h5 study_copy1.h5
run_case history_over_study_output 2 "is not a history CSV (a blockfrag study or spectrum output" \
  "$B" simulate scene.json --history study_copy1.h5
unchanged study_copy1.h5 "$study_sum" && pass || fail "history_over_study_output: the study output was replaced"
run_case history_over_notes 2 "victim.txt (--history): refusing to replace an existing file" \
  "$B" simulate scene.json --history victim.txt
unchanged victim.txt "$victim_sum" && pass || fail "history_over_notes: the notes were replaced"
run_case history_empty 2 "--history: must not be empty" "$B" simulate scene.json --history ""
run_case history_side_file_name 2 'must not end in ".checkpoint"' \
  "$B" simulate scene.json --history study.h5.checkpoint
run_case history_written 0 "verdict:" "$B" simulate scene.json --history h.csv
run_case history_rewritten 0 "verdict:" "$B" simulate scene.json --history h.csv

# --- export --output -------------------------------------------------------------------------------
mkfifo fifo.xml
run_case export_fifo 2 "fifo.xml (--output): is a FIFO" \
  "$B" export study.h5 --format openquake --output fifo.xml --fitted-only
cp study.h5 other.h5
run_case export_over_study_output 2 "other.h5 (--output): refusing to replace an existing file" \
  "$B" export study.h5 --format openquake --output other.h5 --fitted-only
unchanged other.h5 "$study_sum" && pass || fail "export_over_study_output: another study's output was replaced"
run_case export_over_its_input 2 "is this command's input, the study output" \
  "$B" export study.h5 --format openquake --output study.h5 --fitted-only
mkdir dl
ln -s ../victim.txt dl/fragility.json
run_case export_pelicun_link 2 "dl/fragility.json (--output): is a symbolic link" \
  "$B" export study.h5 --format pelicun --output dl --fitted-only
unchanged victim.txt "$victim_sum" && [[ ! -e dl/fragility.csv ]] && pass ||
  fail "export_pelicun_link: the link was followed or a file written"
run_case export_empty 2 "--output: must not be empty" \
  "$B" export study.h5 --format openquake --output "" --fitted-only
run_case export_written 0 "wrote model.xml" \
  "$B" export study.h5 --format openquake --output model.xml --fitted-only
run_case export_rewritten 0 "wrote model.xml" \
  "$B" export study.h5 --format openquake --output model.xml --fitted-only

# --- accuracy --output and --table (each refused before the suite runs) ---------------------------
"$PYTHON" - "$BLOCKFRAG_SOURCE_DIR/configs/accuracy_suite.json" <<'PY' >suite.json
import json, sys
suite = json.load(open(sys.argv[1]))
print(json.dumps({"scenes": [s for s in suite["scenes"] if s["name"] == "rock_free_release"]}))
PY
mkfifo fifo.h5
run_case accuracy_output_fifo 2 "fifo.h5 (--output): is a FIFO" \
  "$B" accuracy suite.json --setting rk4:0.001 --output fifo.h5
cp suite.json own_suite.json
suite_sum=$(md5sum <own_suite.json)
run_case accuracy_output_is_the_suite 2 "own_suite.json (--output): is this command's input, the suite" \
  "$B" accuracy own_suite.json --setting rk4:0.001 --output own_suite.json
unchanged own_suite.json "$suite_sum" && pass || fail "accuracy_output_is_the_suite: the suite was replaced"
cp study.h5 study_copy2.h5
run_case accuracy_output_over_study 2 "study_copy2.h5 (--output): refusing to replace an existing file" \
  "$B" accuracy suite.json --setting rk4:0.001 --output study_copy2.h5
unchanged study_copy2.h5 "$study_sum" && pass || fail "accuracy_output_over_study: the study output was replaced"
ln -s victim.txt table_link.md
run_case accuracy_table_link 2 "table_link.md (--table): is a symbolic link" \
  "$B" accuracy suite.json --setting rk4:0.001 --output acc.h5 --table table_link.md
[[ -L table_link.md && ! -e acc.h5 ]] && unchanged victim.txt "$victim_sum" && pass ||
  fail "accuracy_table_link: the link was replaced or the study ran"
run_case accuracy_output_empty 2 "--output: must not be empty" \
  "$B" accuracy suite.json --setting rk4:0.001 --output ""
run_case accuracy_table_empty 2 "--table: must not be empty" \
  "$B" accuracy suite.json --setting rk4:0.001 --output acc.h5 --table ""
run_case accuracy_same_file_twice 2 "names the same file as another of this command's outputs" \
  "$B" accuracy suite.json --setting rk4:0.001 --output acc.h5 --table ./acc.h5

# --- run: names no other output's files can take ---------------------------------------------------
run_case run_output_side_file_name 2 'must not end in ".records"' "$B" run small.json --output x.h5.records

# --- spectrum: another run's files, and its own checked before the map -----------------------------
# spectrum_with AMPLITUDE_FROM AMPLITUDE_TO > file: a 4 x 5 spectrum of the paper's block, its
# minima refined as coarsely as its boundaries are bisected (its round records stay small).
spectrum_with() {
  cat <<JSON
{"block": {"half_width": 0.5, "half_height": 1.0}, "contact": {"friction": 0.6, "restitution": 0.6},
 "pulse": {"type": "cosine_pulse"}, "frequency_ratio": {"from": 0.8, "to": 2.0, "count": 4},
 "amplitude_ratio": {"from": $1, "to": $2, "count": 5}, "bisection": {"tolerance": 1e-2},
 "minimum_overturning": {"tolerance": 1e-2, "resolution": 1e-2}, "output": "X.h5"}
JSON
}
# A study X.h5.round interrupted (its checkpoint and records kept), then a spectrum X.h5 that finds
# no crossing to bisect and so finishes at once: the study's files are not the spectrum's.
study_with '{"samples_per_level": 1000, "checkpoint_interval_s": 0.01}' >long.json
"$B" run long.json --output X.h5.round 2>long.err &
long_run=$!
# Waits up to 20 s for the first checkpoint: a loaded machine can take seconds to start the run.
for _ in $(seq 1000); do [[ -e X.h5.round.checkpoint ]] && break; sleep 0.02; done
kill -TERM "$long_run"
wait "$long_run"
long_code=$?
if [[ $long_code -eq 4 && -e X.h5.round.checkpoint && -e X.h5.round.records ]]; then
  checkpoint_sum=$(md5sum <X.h5.round.checkpoint)
  records_sum=$(md5sum <X.h5.round.records)
  spectrum_with 0.1 0.5 >safe_spectrum.json
  run_case spectrum_beside_round_study 0 "wrote X.h5" "$B" spectrum safe_spectrum.json
  unchanged X.h5.round.checkpoint "$checkpoint_sum" && unchanged X.h5.round.records "$records_sum" &&
    pass || fail "spectrum_beside_round_study: the study's checkpoint or records were removed or changed"
  run_case round_study_resumes 0 "resumed from X.h5.round.checkpoint" "$B" run long.json --output X.h5.round
else
  fail "the study to interrupt: exit $long_code, $(tail -c 300 long.err)"
fi
# A bisection state or minimum refinement that is not this spectrum's is refused before the map,
# not after it.
spectrum_with 1.0 3.0 >spectrum.json
sed 's/"X.h5"/"S.h5"/' spectrum.json >s_spectrum.json
printf 'someone else' >S.h5.bisection
run_case spectrum_foreign_bisection 2 "S.h5.bisection: not a usable blockfrag bisection state" \
  "$B" spectrum s_spectrum.json
[[ ! -e S.h5.records && ! -e S.h5.checkpoint ]] && pass ||
  fail "spectrum_foreign_bisection: the map ran before the bisection state was checked"
rm S.h5.bisection
printf 'someone else' >S.h5.minimum
run_case spectrum_foreign_minimum 2 "S.h5.minimum: not a usable blockfrag minimum refinement" \
  "$B" spectrum s_spectrum.json
[[ ! -e S.h5.records && ! -e S.h5.checkpoint ]] && pass ||
  fail "spectrum_foreign_minimum: the map ran before the minimum refinement was checked"
rm S.h5.minimum
mkfifo S.h5.round-records
run_case spectrum_round_records_fifo 2 "S.h5.round-records: not a regular file" \
  "$B" spectrum s_spectrum.json
[[ -p S.h5.round-records && ! -e S.h5.records ]] && pass ||
  fail "spectrum_round_records_fifo: the FIFO was replaced or the map ran"

# --- a full disk during the final write ------------------------------------------------------------
# 1,000 samples: 120 kB of records, a 236 kB output. The output cannot be written: exit code 1 with
# the reason, the checkpoint and records kept, and the rerun, with room, writes the output from them
# without computing a sample.
full_disk_case() {
  local name=$1 folder=$2
  shift 2
  run_case "$name" 1 "cannot write $folder/full.h5: HDF5: " "$@" \
    "$B" run "$BLOCKFRAG_SOURCE_DIR/configs/example_study.json" --samples-per-level 100 \
    --output "$folder/full.h5"
  grep -qE "No space left on device|File too large" "$name.err" && [[ ! -e $folder/full.h5 ]] &&
    pass || fail "$name: no reason given, or an output left: $(head -c 300 "$name.err")"
  mkdir "$name.roomy"
  cp "$folder/full.h5.checkpoint" "$folder/full.h5.records" "$name.roomy/" || true
  run_case "$name.rerun" 0 "resumed from $name.roomy/full.h5.checkpoint: 1000 of 1000 samples" \
    "$B" run "$BLOCKFRAG_SOURCE_DIR/configs/example_study.json" --samples-per-level 100 \
    --output "$name.roomy/full.h5"
}
# Each write past 200 kB fails with EFBIG (SIGXFSZ ignored), as on a disk that is full.
mkdir limited
full_disk_case full_disk_file_size_limit limited bash -c 'trap "" XFSZ; ulimit -f 200; exec "$@"' --
# A spectrum: 2 kB of map records, a 16 kB output; the rerun computes no point again.
mkdir limited_spectrum
sed 's/"X.h5"/"limited_spectrum\/sp.h5"/' spectrum.json >limited_spectrum.json
run_case full_disk_spectrum 1 "cannot write limited_spectrum/sp.h5: HDF5: " \
  bash -c 'trap "" XFSZ; ulimit -f 8; exec "$@"' -- "$B" spectrum limited_spectrum.json
[[ -e limited_spectrum/sp.h5.checkpoint && -e limited_spectrum/sp.h5.bisection ]] && pass ||
  fail "full_disk_spectrum: the checkpoint or the bisection state is gone"
run_case full_disk_spectrum.rerun 0 \
  "(0 map points and 0 bisection midpoints and 0 minimum refinement midpoints computed in this run" \
  "$B" spectrum limited_spectrum.json
# A real full disk where a tmpfs can be mounted (as root).
mkdir full
trap 'umount "$work/full" 2>/dev/null; rm -rf "$work"' EXIT
if mount -t tmpfs -o size=256k tmpfs full 2>/dev/null; then
  full_disk_case full_disk_tmpfs full
  umount full
fi

echo "$passed passed, $failed failed"
[[ $failed -eq 0 ]]
