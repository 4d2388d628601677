#!/usr/bin/env bash
# `cmake --install` into a temporary prefix, then the installed product run from there, in a
# folder outside the source and build trees: bin/blockfrag --version prints the version of
# CMakeLists.txt's project() and the commit of the source tree (git rev-parse --short HEAD, or
# "unknown" outside a git checkout); every config and plot script of the source tree is installed;
# an installed scene simulates as the built executable simulates the source's; an installed
# record-suite study runs (its records found beside it); an installed plot script draws its output
# and refuses a bad input with exit code 2. Prints "N passed, M failed" last.
set -u
source "$(dirname "$0")/../support/script_test.sh"
: "${BLOCKFRAG_BUILD_DIR:?path of the build tree}"

prefix=$work/prefix
cmake --install "$BLOCKFRAG_BUILD_DIR" --prefix "$prefix" >"$work/install.log" 2>&1
check "cmake --install exits 0: $(tail -3 "$work/install.log")" test $? -eq 0
installed=$prefix/bin/blockfrag
configs=$prefix/share/blockfrag/configs
plots=$prefix/share/blockfrag/plots
check "bin/blockfrag is an executable" test -x "$installed"

# What is installed: every config (records too) and every plot script of the source tree.
same_files() {
  diff <(cd "$1" && find . -type f -name "$3" | sort) <(cd "$2" && find . -type f -name "$3" | sort)
}
check "every config and record file is installed" same_files "$BLOCKFRAG_SOURCE_DIR/configs" "$configs" "*"
check "every plot script is installed, with what they share" \
  same_files "$BLOCKFRAG_SOURCE_DIR/postproc/plots" "$plots" "*.py"
check "the plots' shared module is among them" test -f "$plots/plot_support.py"

mkdir "$work/elsewhere"
cd "$work/elsewhere" || exit 1

# --version: the version of project() in CMakeLists.txt and the source tree's commit.
version=$(sed -nE 's/^project\(blockfrag VERSION ([0-9.]+) .*/\1/p' "$BLOCKFRAG_SOURCE_DIR/CMakeLists.txt")
commit=unknown
if top=$(git -C "$BLOCKFRAG_SOURCE_DIR" rev-parse --show-toplevel 2>/dev/null) &&
  [[ $(realpath "$top") == $(realpath "$BLOCKFRAG_SOURCE_DIR") ]]; then
  commit=$(git -C "$BLOCKFRAG_SOURCE_DIR" rev-parse --short HEAD)
fi
"$installed" --version >version.out 2>&1
code=$?
check "--version exits 0 (got $code)" test $code -eq 0
check "--version prints 'blockfrag $version (commit $commit)', got '$(cat version.out)'" \
  test "$(cat version.out)" == "blockfrag $version (commit $commit)"

# An installed scene gives what the built executable gives for the source's.
"$installed" simulate "$configs/paper_example.json" --summary-json >installed.json 2>simulate.err
code=$?
check "simulate of the installed paper_example.json exits 0 (got $code: $(cat simulate.err))" test $code -eq 0
"$BLOCKFRAG" simulate "$BLOCKFRAG_SOURCE_DIR/configs/paper_example.json" --summary-json >built.json 2>/dev/null
check "the installed scene simulates as the source's" cmp -s installed.json built.json
check "its summary is a simulation's" "$PYTHON" -c '
import json, sys
summary = json.load(open(sys.argv[1]))
assert summary["status"] == "ok" and summary["max_abs_theta"] > 0, summary
' installed.json

# An installed study of records: its record files are found beside it, wherever the run starts.
"$installed" run "$configs/record_suite_study.json" --samples-per-level 1 --output study.h5 2>run.err
code=$?
check "run of the installed record_suite_study.json exits 0 (got $code: $(tail -3 run.err))" test $code -eq 0
check "its output holds every record" "$PYTHON" -c '
import h5py, sys
with h5py.File(sys.argv[1], "r") as f:
    assert len(f["records/file"]) == 18, len(f["records/file"])
    assert f.attrs["blockfrag_version"] == sys.argv[2], f.attrs["blockfrag_version"]
' study.h5 "$version"

# An installed plot script draws it, and refuses a file that is not a study.
"$PYTHON" "$plots/plot_fragility.py" study.h5 -o fragility.png --summary >summary.out 2>plot.err
code=$?
check "the installed plot_fragility.py exits 0 (got $code: $(cat plot.err))" test $code -eq 0
check "it writes a PNG" "$PYTHON" -c 'import sys; assert open(sys.argv[1], "rb").read(8) == b"\x89PNG\r\n\x1a\n"' \
  fragility.png
check "its summary names the study's limit states" grep -q "dislocation_10cm" summary.out
"$PYTHON" "$plots/plot_fragility.py" installed.json --summary >/dev/null 2>plot.err
code=$?
check "a bad input exits 2 (got $code)" test $code -eq 2
check "and is named in one line: $(cat plot.err)" grep -q "installed.json: not a readable HDF5 file" plot.err

echo "$passed passed, $failed failed"
[[ $failed -eq 0 ]]
