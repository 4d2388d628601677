#!/usr/bin/env bash
# Configs a hostile or careless user can give to simulate, run and spectrum whose fault shows only
# in several values together or in a whole token: each must be refused before any work with exit
# code 2 and a message naming the file and the JSON path (or line), quoting no more than a short
# excerpt of the file and leaving no file behind. Every case runs under a time limit and a memory
# limit (tests/support/hostile_case.sh).
set -u
source "$(dirname "$0")/../support/script_test.sh"
source "$(dirname "$0")/../support/hostile_case.sh"
cd "$work" || exit 1

# --- JSON syntax errors quote an excerpt of the broken token ---------------------------------------
# An unterminated string of 1 MB: the lexer's token is all of it.
"$PYTHON" -c "print('{\"block\": \"' + 'x' * 1000000)" >unterminated.json
for command in simulate run spectrum; do
  run_case "unterminated_string_1mb_$command" 2 "unterminated.json:1:1000012: malformed JSON: syntax error" \
    "$B" "$command" unterminated.json
  size=$(stat -c %s "unterminated_string_1mb_$command.err")
  [[ $size -lt 400 ]] && pass || fail "unterminated_string_1mb_$command: $size bytes of stderr"
done
# A string broken by a newline: the token is the line up to it.
"$PYTHON" -c "print('{\"block\": \"' + 'y' * 200 + 'PRIVATE-TAIL'); print('\"}')" >broken_string.json
run_case string_broken_by_newline 2 "broken_string.json:1:224: malformed JSON: syntax error" \
  "$B" simulate broken_string.json
grep -q "PRIVATE-TAIL" string_broken_by_newline.err && fail "string_broken_by_newline echoed the line" || pass

echo "$passed passed, $failed failed"
[[ $failed -eq 0 ]]
