#!/usr/bin/env bash
# `blockfrag export` on study outputs a hostile or careless user can give: each is refused before
# anything is written with exit code 2 and a short message naming the file and the object, never
# hangs on a link out of the file, never allocates what a dataset declares but does not hold, and
# never writes a file the tools cannot read. The outputs are a real small study's, altered with
# h5py. Every case runs under a time limit and a memory limit (tests/support/hostile_case.sh).
set -u
source "$(dirname "$0")/../support/script_test.sh"
source "$(dirname "$0")/../support/hostile_case.sh"
cd "$work" || exit 1

study_with '{"samples_per_level": 40, "intensity_measure": {"from": 0.4, "to": 2.0, "count": 5}}' >small.json
"$B" run small.json --output small.h5 >small_run.out 2>&1 || { fail "the small study: $(tail -3 small_run.out)"; exit 1; }
"$PYTHON" - <<'PY' || fail "h5py could not make the altered outputs"
import shutil
import h5py

def altered(name):
    shutil.copy("small.h5", name)
    return h5py.File(name, "r+")

with h5py.File("other.h5", "w") as f:
    f.create_group("x")
with altered("link_fifo.h5") as f:
    del f["fragility/overturn"]
    f["fragility/overturn"] = h5py.ExternalLink("ext.fifo", "/x")
with altered("link_file.h5") as f:
    del f["fragility/overturn"]
    f["fragility/overturn"] = h5py.ExternalLink("other.h5", "/x")
with altered("soft_link.h5") as f:
    f["fragility"].move("overturn", "overturn_data")
    f["fragility/overturn"] = h5py.SoftLink("/fragility/overturn_data")
with altered("storage_fifo.h5") as f:
    del f["fragility/overturn/im"]
    f.create_dataset("fragility/overturn/im", shape=(5,), dtype="f8", external=[("ext.fifo", 0, 40)])
with altered("levels_6e8.h5") as f:
    del f["fragility/overturn/im"]
    f.create_dataset("fragility/overturn/im", shape=(600_000_000,), dtype="f8")
with altered("type_1mb.h5") as f:
    f["fragility/overturn"].attrs["type"] = "x" * 1_000_000
with altered("label_10mb.h5") as f:
    f["fragility"].attrs["im_label"] = "PGA" + "\n" * 10_000_000
with altered("hash.h5") as f:
    f.attrs["config_hash"] = "=cmd|x"
for case, name in [("space", "over turn"), ("newline", "over\nturn"), ("control", "over\x01turn"),
                   ("utf8", b"over\xffturn")]:
    with altered(f"name_{case}.h5") as f:
        f["fragility"].move("overturn", name)
        order = f["fragility"].attrs["severity_order"]
        text = name.decode("latin-1") if isinstance(name, bytes) else name
        f["fragility"].attrs["severity_order"] = order.replace("overturn", text)
with altered("beta_40.h5") as f:
    f["fragility/overturn"].attrs["beta"] = 40.0
with altered("beta_denormal.h5") as f:
    f["fragility/overturn"].attrs["beta"] = 5e-324
with altered("pulse.h5") as f:
    f["fragility"].attrs["im_name"] = "pulse_amplitude"
    f["fragility"].attrs["im_label"] = "pulse amplitude"
# Flipped bytes in slide_5cm's object header: its link is there, the object is not readable.
with h5py.File("small.h5", "r") as f:
    address = h5py.h5o.get_info(f["fragility/slide_5cm"].id).addr
data = bytearray(open("small.h5", "rb").read())
for k in range(address, address + 16):
    data[k] ^= 0xFF
open("flipped.h5", "wb").write(data)
open("truncated.h5", "wb").write(open("small.h5", "rb").read()[:20000])
PY
# After the files that name it exist: HDF5 would create a missing external file as a regular one.
rm -f ext.fifo
mkfifo ext.fifo

oq=(--format openquake --output)
# nothing_written NAME FILE: the export refused FILE and left no output beside it.
nothing_written() {
  [[ ! -e ${2%.h5}.xml ]] && pass || fail "$1: wrote ${2%.h5}.xml"
}
# short_message NAME: the case's stderr is one short line, whatever size the file's texts are.
short_message() {
  local bytes
  bytes=$(stat -c %s "$1.err")
  ((bytes < 400)) && pass || fail "$1: a message of $bytes bytes"
}

# --- Objects outside the file ----------------------------------------------------------------------
run_case external_link_to_fifo 2 "link_fifo.h5: /fragility/overturn is an external link" \
  "$B" export link_fifo.h5 "${oq[@]}" link_fifo.xml
nothing_written external_link_to_fifo link_fifo.h5
run_case external_link_to_file 2 "link_file.h5: /fragility/overturn is an external link" \
  "$B" export link_file.h5 "${oq[@]}" link_file.xml
run_case soft_link 2 "soft_link.h5: /fragility/overturn is a soft link" \
  "$B" export soft_link.h5 "${oq[@]}" soft_link.xml
run_case external_storage_fifo 2 "storage_fifo.h5: dataset /fragility/overturn/im keeps its values in other files" \
  "$B" export storage_fifo.h5 "${oq[@]}" storage_fifo.xml

# --- Extents ---------------------------------------------------------------------------------------
run_case unallocated_6e8_levels 2 "levels_6e8.h5: dataset /fragility/overturn/im holds 600000000 values, more than" \
  "$B" export levels_6e8.h5 "${oq[@]}" levels_6e8.xml
nothing_written unallocated_6e8_levels levels_6e8.h5

# --- Attributes quoted in full, or blamed on the command line --------------------------------------
run_case type_1mb 2 "type_1mb.h5: attribute type of /fragility/overturn is 1000000 bytes long" \
  "$B" export type_1mb.h5 "${oq[@]}" type_1mb.xml
short_message type_1mb
run_case im_label_10mb 2 "label_10mb.h5: attribute im_label of /fragility is 10000003 bytes long" \
  "$B" export label_10mb.h5 "${oq[@]}" label_10mb.xml
short_message im_label_10mb
run_case config_hash_malformed 2 "hash.h5: attribute config_hash of / is \"=cmd|x\", not a config hash" \
  "$B" export hash.h5 "${oq[@]}" hash.xml
grep -q -- "--id" config_hash_malformed.err && fail "config_hash_malformed blames --id" || pass

# --- What would make an invalid file ---------------------------------------------------------------
# The name as the message quotes it: bytes outside printable ASCII become '?'.
declare -A shown_name=([space]="over turn" [newline]="over?turn" [control]="over?turn" [utf8]="over?turn")
for case in space newline control utf8; do
  run_case "name_$case" 2 \
    "name_$case.h5: /fragility has a member \"${shown_name[$case]}\", not a limit state name" \
    "$B" export "name_$case.h5" "${oq[@]}" "name_$case.xml"
  nothing_written "name_$case" "name_$case.h5"
done
run_case beta_40 2 "beta_40.h5: /fragility/overturn has fit_status \"ok\" but median" \
  "$B" export beta_40.h5 "${oq[@]}" beta_40.xml
grep -qF "and beta 40 (" beta_40.err && pass || fail "beta_40: $(cat beta_40.err)"
nothing_written beta_40 beta_40.h5
run_case beta_denormal 2 "and beta 5e-324 (an exported fit has" \
  "$B" export beta_denormal.h5 "${oq[@]}" beta_denormal.xml
nothing_written beta_denormal beta_denormal.h5

# --- Damaged files ---------------------------------------------------------------------------------
run_case truncated 2 "truncated.h5: HDF5 cannot open it" "$B" export truncated.h5 "${oq[@]}" truncated.xml
# HDF5 1.10 loops forever on the first file's global heap and reads freed memory iterating the
# second's attributes (found by tests/fuzz/hdf5_reader_fuzzer.cpp): export reads in a child.
findings=$BLOCKFRAG_SOURCE_DIR/tests/data/fuzz_findings
run_case global_heap_loop 2 "hdf5_global_heap_loop.h5: still not read after 10 s: a damaged file" \
  "$B" export "$findings/hdf5_global_heap_loop.h5" "${oq[@]}" loop.xml
nothing_written global_heap_loop loop.h5
# HDF5 allocates what this 17 kB file's metadata declares, 6 GB: the child's address space is
# limited to 1 GB (not in a sanitized build, whose shadow memory needs terabytes of it). Under 8 GB
# (not the cases' 4 GB, which alone would make the allocation fail), the peak stays small.
if [[ ${BLOCKFRAG_SANITIZED:-OFF} != ON ]]; then
  (ulimit -v 8388608; timeout 60 /usr/bin/time -f %M -o allocates.peak \
    "$B" export "$findings/hdf5_allocates_6gb.h5" "${oq[@]}" allocates.xml) >allocates.out 2>allocates.err
  allocates_code=$?
  allocates_peak=$(tail -1 allocates.peak)
  if [[ $allocates_code -eq 2 ]] && grep -q "hdf5_allocates_6gb.h5: " allocates.err &&
    ((allocates_peak < peak_limit_kb)); then
    pass
  else
    fail "hdf5_allocates_6gb: exit $allocates_code, peak ${allocates_peak} kB: $(head -c 300 allocates.err)"
  fi
fi
run_case attribute_use_after_free 2 "hdf5_attribute_use_after_free.h5: " \
  "$B" export "$findings/hdf5_attribute_use_after_free.h5" "${oq[@]}" freed.xml
nothing_written attribute_use_after_free freed.h5
run_case flipped_bytes 2 "flipped.h5: HDF5 cannot open /fragility/slide_5cm" \
  "$B" export flipped.h5 "${oq[@]}" flipped.xml

# --- Messages and streams --------------------------------------------------------------------------
run_case pulse_amplitude 2 "pulse.h5: its intensity measure is the pulse amplitude, which neither" \
  "$B" export pulse.h5 "${oq[@]}" pulse.xml
grep -qF "(pulse amplitude)" pulse_amplitude.err && fail "pulse_amplitude: $(cat pulse_amplitude.err)" || pass
run_case success_on_stdout 0 "wrote small.xml (BF.BLOCK." "$B" export small.h5 "${oq[@]}" small.xml
grep -q "^wrote small.xml" success_on_stdout.out && ! grep -q "wrote" success_on_stdout.err && pass ||
  fail "success_on_stdout: stdout '$(cat success_on_stdout.out)', stderr '$(cat success_on_stdout.err)'"

# --- Adaptive pairs far in the tails ---------------------------------------------------------------
study_with '{"samples_per_level": 10, "design": {"adaptive": {"pair_probability": 1e-300, "max_samples": 1000}}}' >pair.json
run_case pair_probability_1e-300 2 "pair.json: /design/adaptive/pair_probability: must be in [0.01, 0.49]" \
  "$B" run pair.json
[[ ! -e out.h5 ]] && pass || fail "pair_probability_1e-300 wrote out.h5"

echo "$passed passed, $failed failed"
[[ $failed -eq 0 ]]
