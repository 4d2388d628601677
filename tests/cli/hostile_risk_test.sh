#!/usr/bin/env bash
# `blockfrag risk` on hazard files, study outputs, options and output paths a hostile or careless
# user can give: each is refused before any work with exit code 2 and a short message naming the
# file and the line or JSON path (the option for a command line), never hangs on a FIFO, never
# reads more than the 64 MB a hazard file may have, and never writes a file it does not own.
# Every case runs under a time limit and a memory limit (tests/support/hostile_case.sh).
set -u
source "$(dirname "$0")/../support/script_test.sh"
source "$(dirname "$0")/../support/hostile_case.sh"
cd "$work" || exit 1
hazard=$BLOCKFRAG_SOURCE_DIR/tests/data/hazard
oq=$hazard/hazard_curve-mean-PGA_1.csv

study_with '{"samples_per_level": 30, "bootstrap_resamples": 20, "intensity_measure": {"from": 0.4, "to": 2.0, "count": 5}}' >small.json
"$B" run small.json --output small.h5 >small_run.out 2>&1 || { fail "the small study: $(tail -3 small_run.out)"; exit 1; }
"$PYTHON" - "$oq" <<'PY' || fail "the altered files could not be made"
import shutil
import sys
import h5py

lines = open(sys.argv[1]).read().splitlines()
def oq(name, metadata=None, header=None, rows=None):
    text = [metadata or lines[0], header or lines[1]] + (rows or lines[2:])
    open(name, "w").write("\n".join(text) + "\n")
oq("no_time.csv", metadata=lines[0].replace("investigation_time=50.0, ", ""))
oq("sa_1s.csv", metadata=lines[0].replace("imt='PGA'", "imt='SA(1.0)'"))
oq("imt_text.csv", metadata=lines[0].replace("imt='PGA'", "imt='MMI'"))
oq("poe_above_1.csv", rows=[lines[2].replace("8.801498E-01", "1.5"), lines[3]])
oq("short_row.csv", rows=[lines[2], lines[3].rsplit(",", 2)[0]])
oq("rising.csv", rows=[lines[2].replace("8.247808E-01", "9.0E-01")])
oq("levels_down.csv", header=lines[1].replace("poe-0.0070000", "poe-0.0010000"))
oq("wide_header.csv", header="lon,lat,depth," + ",".join("poe-%d" % k for k in range(1, 100_001)))
oq("all_poe_one.csv", rows=["11.0,46.0,0.0," + ",".join(["1.000000E+00"] * 19)])
open("not_json.json", "w").write("{\"response\": [")
open("deep.json", "w").write("{\"response\": " + "[" * 1_000_000 + "]" * 1_000_000 + "}")
open("no_imt_table.csv", "w").write("0.1,1e-3\n0.2,1e-4\n")
open("table_rising.csv", "w").write("0.1,1e-3\n0.2,1e-2\n")
open("big.csv", "w").write("0.1,1e-3\n" * 8_000_000)
open("notes.json", "w").write("my notes\n")
import json
usgs = json.load(open(sys.argv[1].replace("hazard_curve-mean-PGA_1.csv", "usgs_hazard.json")))
usgs["response"][1]["data"][1]["component"] = "Sum"
json.dump(usgs, open("no_total.json", "w"))
usgs["response"][1]["data"][1]["component"] = "Total"
usgs["response"][1]["data"][1]["yvalues"].pop()
json.dump(usgs, open("short_y.json", "w"))
usgs["status"] = "error"
json.dump(usgs, open("status_error.json", "w"))

def altered(name):
    shutil.copy("small.h5", name)
    return h5py.File(name, "r+")
with altered("no_trials.h5") as f:
    del f["fragility/overturn/trials"]
with altered("exceed_trials.h5") as f:
    data = f["fragility/overturn/exceedances"][:]
    data[0] = f["fragility/overturn/trials"][0] + 1
    f["fragility/overturn/exceedances"][...] = data
with altered("no_seed.h5") as f:
    f.attrs["config"] = "{}"
with altered("pulse.h5") as f:
    f["fragility"].attrs["im_name"] = "pulse_amplitude"
with altered("trials_6e8.h5") as f:
    del f["fragility/overturn/trials"]
    f.create_dataset("fragility/overturn/trials", shape=(600_000_000,), dtype="i8")
PY
mkfifo hazard.fifo
ln -s notes.json link.json

r=(risk small.h5 --hazard)
# --- Hazard files -----------------------------------------------------------------------------------
run_case missing_hazard 2 "nothing.csv: no such file" "$B" "${r[@]}" nothing.csv
run_case fifo_hazard 2 "hazard.fifo: " "$B" "${r[@]}" hazard.fifo
run_case no_investigation_time 2 "no_time.csv: line 1: no investigation_time" "$B" "${r[@]}" no_time.csv
run_case other_measure 2 "sa_1s.csv: its curves are of SA(1), the study's intensity measure is PGA: a fragility" \
  "$B" "${r[@]}" sa_1s.csv
run_case unknown_imt 2 "imt_text.csv: line 1: no imt=" "$B" "${r[@]}" imt_text.csv
run_case poe_above_1 2 "poe_above_1.csv: line 3, column 4: \"1.5\" is not a probability" \
  "$B" "${r[@]}" poe_above_1.csv
run_case short_row 2 "short_row.csv: line 4: 20 fields, the header has 22" "$B" "${r[@]}" short_row.csv
run_case rising_curve 2 "rising.csv: line 3, column poe-0.007: the rate of exceedance" \
  "$B" "${r[@]}" rising.csv
run_case levels_down 2 "levels_down.csv: line 2, column 5: \"poe-0.0010000\" is not poe-<level>" \
  "$B" "${r[@]}" levels_down.csv
run_case wide_header 2 "wide_header.csv: line 2: more than 10000 levels" "$B" "${r[@]}" wide_header.csv
run_case all_poe_one 2 "all_poe_one.csv: the curve has fewer than two levels" "$B" "${r[@]}" all_poe_one.csv
run_case site_beyond 2 "--site 2 but the file has 2 sites" "$B" "${r[@]}" "$oq" --site 2
run_case imt_option_other 2 "--imt SA(1.0) but the file's curves are of PGA" \
  "$B" "${r[@]}" "$oq" --imt "SA(1.0)"
run_case not_json 2 "not_json.json: not JSON (byte" "$B" "${r[@]}" not_json.json
run_case deep_json 2 "deep.json: /response/0: is not an object" "$B" "${r[@]}" deep.json
run_case no_total 2 "no_total.json: /response/1/data: has no component \"Total\"" "$B" "${r[@]}" no_total.json
run_case short_yvalues 2 "short_y.json: /response/1/data/1/yvalues: holds 18 values for 19 xvalues" \
  "$B" "${r[@]}" short_y.json
run_case status_error 2 "status_error.json: /status: is \"error\"" "$B" "${r[@]}" status_error.json
run_case table_without_imt 2 "no_imt_table.csv: a two-column hazard table does not name its intensity measure" \
  "$B" "${r[@]}" no_imt_table.csv
run_case table_rising 2 "table_rising.csv: line 2: the rate of exceedance" \
  "$B" "${r[@]}" table_rising.csv --imt PGA
run_case hazard_over_64mb 2 "big.csv: " "$B" "${r[@]}" big.csv --imt PGA

# --- Study outputs ------------------------------------------------------------------------------------
run_case no_trials 2 "no_trials.h5: /fragility/overturn/trials is missing" \
  "$B" risk no_trials.h5 --hazard "$oq"
run_case exceedances_above_trials 2 "exceed_trials.h5: /fragility/overturn has more exceedances than trials" \
  "$B" risk exceed_trials.h5 --hazard "$oq"
run_case config_without_seed 2 "no_seed.h5: the config attribute of / is not a study config with a seed" \
  "$B" risk no_seed.h5 --hazard "$oq"
run_case pulse_amplitude 2 "pulse.h5: the study's intensity measure is pulse_amplitude, which no hazard curve has" \
  "$B" risk pulse.h5 --hazard "$oq"
run_case unallocated_6e8_trials 2 "trials_6e8.h5: dataset /fragility/overturn/trials holds 600000000 values" \
  "$B" risk trials_6e8.h5 --hazard "$oq"

# --- Options ------------------------------------------------------------------------------------------
run_case weights_not_one 2 "--study: the weights sum to 0.9, not 1" \
  "$B" risk --study small.h5:0.5 --study small.h5:0.4 --hazard "$oq"
run_case weight_text 2 "--study small.h5:half: not FILE:WEIGHT" \
  "$B" risk --study small.h5:half --hazard "$oq"
run_case results_and_study 2 "give one study output (RESULTS.h5) or several as --study" \
  "$B" risk small.h5 --study small.h5:1 --hazard "$oq"

# --- Outputs ------------------------------------------------------------------------------------------
run_case output_symlink 2 "link.json" "$B" "${r[@]}" "$oq" --output link.json
grep -qx "my notes" notes.json && pass || fail "output_symlink changed the file the link names"
run_case output_foreign_file 2 "notes.json" "$B" "${r[@]}" "$oq" --output notes.json
grep -qx "my notes" notes.json && pass || fail "output_foreign_file replaced notes.json"
run_case output_is_hazard 2 "hazard_curve-mean-PGA_1.csv" "$B" "${r[@]}" "$oq" --csv "$oq"
run_case output_is_study 2 "small.h5" "$B" "${r[@]}" "$oq" --output small.h5
run_case writes_and_rewrites 0 "mean annual frequency" "$B" "${r[@]}" "$oq" --output risk.json --csv risk.csv
run_case rewrites_its_own 0 "mean annual frequency" "$B" "${r[@]}" "$oq" --output risk.json --csv risk.csv

echo "$passed passed, $failed failed"
[[ $failed -eq 0 ]]
