#!/usr/bin/env bash
# Fails when an #include "..." points up a floor (ARCHITECTURE.md "Floors"), so the layering
# cannot regress silently; run by ctest as check_layers. Two orders are checked:
#   folders:    app → study → {tasks, stimuli} → renderer → core;  study → analysis → core
#   renderer/:  pipeline → styles → compose → ops → {buffer, kbuffer, peel} → frame → params
#               → {scene, gpu}   (renderer/CMakeLists.txt says what each floor holds)
# A file may include its own folder and any folder below it; siblings ({tasks, stimuli},
# {buffer, kbuffer, peel}, {scene, gpu}) do not include each other. app/ may include
# bench/measure (tlab bench). Outside the floors: bench/ and fuzz/ may include anything below
# app/; tests/X/ may include X/, what X/ may include, and tests/support/ (which may include
# anything below app/); the few tests that need a sibling floor are listed in `crossing`.
set -euo pipefail
cd "${1:-$(dirname "$0")/..}"

# Which top-level folders each folder may include (besides itself).
declare -A below=(
  [app]="bench study tasks stimuli renderer analysis core"
  [study]="tasks stimuli renderer analysis core"
  [tasks]="renderer core"
  [stimuli]="renderer core"
  [renderer]="core"
  [analysis]="core"
  [core]=""
  [bench]="study tasks stimuli renderer analysis core"
  [fuzz]="study tasks stimuli renderer analysis core"
)
for dir in tests/*/; do
  dir=${dir%/}
  x=${dir#tests/}
  if [[ $x == support ]]; then
    below[$dir]="study tasks stimuli renderer analysis core"
  elif [[ -v below[$x] ]]; then
    below[$dir]="$x ${below[$x]} tests/support"
  fi
done
# Tests that check one floor with a sibling's code, each with its reason.
declare -A crossing=(
  # the letter patterns of the abstract scenes checked with the tasks library's bitmaps and matcher
  [tests/stimuli/scenes_test.cpp:tasks]=1
  # the stimulus-set booklet's PDF read back with analysis' PDF text extraction
  [tests/stimuli/stimulus_set_cli_test.cpp:analysis]=1
)
# The floors inside renderer/: a higher number may include a lower one.
declare -A rank=([pipeline]=7 [styles]=6 [compose]=5 [ops]=4 [buffer]=3 [kbuffer]=3 [peel]=3
                 [frame]=2 [params]=1 [scene]=0 [gpu]=0)

failures=0
fail() {
  echo "$1" >&2
  failures=$((failures + 1))
}

while IFS=: read -r file _ target; do
  from=${file%%/*}
  to=${target%%/*}
  # tests/X counts as a folder of its own.
  if [[ $from == tests ]]; then rest=${file#tests/}; from=tests/${rest%%/*}; fi
  if [[ $to == tests ]]; then rest=${target#tests/}; to=tests/${rest%%/*}; fi
  [[ -v below[$to] ]] || continue  # a system or third-party header
  if [[ -v crossing[$file:$to] ]]; then
    continue
  elif [[ $to != "$from" && " ${below[$from]} " != *" $to "* ]]; then
    fail "$file includes $target: $from/ may include only ${below[$from]:-nothing} (check_layers.sh)"
  elif [[ $from == renderer && $to == renderer ]]; then
    inner_from=$(cut -d/ -f2 <<<"$file")
    inner_to=$(cut -d/ -f2 <<<"$target")
    [[ $inner_from == "$inner_to" ]] && continue
    if [[ ! -v rank[$inner_from] || ! -v rank[$inner_to] ]]; then
      fail "$file includes $target: renderer/$inner_from or renderer/$inner_to has no floor in check_layers.sh"
    elif ((rank[$inner_to] >= rank[$inner_from])); then
      fail "$file includes $target: renderer/$inner_from/ may include only floors below it (check_layers.sh)"
    fi
  fi
done < <(grep -rnoE --include='*.cpp' --include='*.hpp' --include='*.h' '^#include "[^"]+"' \
           app study tasks stimuli renderer core analysis bench fuzz tests | sed -E 's/:[0-9]+:#include "/::/; s/"$//')

if ((failures > 0)); then
  echo "check_layers: $failures include(s) point up a floor" >&2
  exit 1
fi
echo "check_layers: every include points down"
