# Sourced by the script tests (tests/*/*_test.sh): the environment ctest gives them, a scratch
# folder removed on exit, and the pass/fail counters behind their closing 'N passed, M failed' line.
: "${BLOCKFRAG:?path of the blockfrag executable}"
: "${BLOCKFRAG_SOURCE_DIR:?path of the source tree}"
PYTHON=${BLOCKFRAG_PYTHON:-/usr/bin/python3}

passed=0
failed=0
pass() { passed=$((passed + 1)); }
fail() {
  echo "FAIL: $*" >&2
  failed=$((failed + 1))
}

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# Every temporary file of the test's runs, Open MPI's session folders too, in its scratch folder:
# a run the test kills with SIGKILL leaves nothing behind in the machine's temporary directory.
mkdir "$work/tmp"
export TMPDIR="$work/tmp"

# check NAME COMMAND...: one pass when COMMAND succeeds, one fail named NAME when it does not.
check() {
  local name=$1
  shift
  if "$@"; then pass; else fail "$name"; fi
}

# run ARGUMENTS...: blockfrag with them; stdout in $work/out, stderr in $work/err, exit code in $code.
run() {
  "$BLOCKFRAG" "$@" >"$work/out" 2>"$work/err"
  code=$?
}
