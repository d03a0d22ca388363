#!/usr/bin/env bash
# docs/input.md documents every input variable: each variable of the input table
# (printed by list_input_variables) has a row "| `name` |" or "| `name(i)` |" in the
# section "## &group" of its group.
# usage: check_docs_complete.sh LIST_INPUT_VARIABLES docs/input.md
set -uo pipefail
lister=$1; doc=$2
passed=0; failed=0
while read -r group name kind extent rest; do
  section=$(awk -v header="## &$group" '$0 == header || index($0, header " ") == 1 {inside = 1; next}
                                         /^## / {inside = 0} inside' "$doc")
  # a here-string, not a pipe: grep -q stops at the first match, and with pipefail the
  # writer's SIGPIPE would count as a failure
  if grep -q -E "^\| \`$name(\(i\))?\` \|" <<< "$section"; then
    passed=$((passed + 1))
  else
    failed=$((failed + 1)); echo "FAIL docs/input.md: no row for &$group $name in section '## &$group'"
  fi
done < <("$lister")
echo "check_docs_complete: $passed passed, $failed failed"
[ $failed -eq 0 ]
