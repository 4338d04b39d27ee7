#!/usr/bin/env bash
# Fails when an #include "..." points up a floor (ARCHITECTURE.md "Floors"), so the layering
# cannot regress silently; run by ctest as check_layers. Three orders are checked:
#   folders:    app → study → {tasks, stimuli} → renderer → core;  study → analysis → core
#   renderer/:  pipeline → styles → compose → ops → {buffer, kbuffer, peel} → frame → params
#               → {scene, gpu}   (renderer/CMakeLists.txt says what each floor holds); the
#               shaders' #include "floor/piece.glsl" (resolved inside renderer/) follow it too
#   study/:     {window, serve, simulate, replay} → analyze → run → store → design
#               (study/CMakeLists.txt says what each floor holds); only window/ includes GLFW
# A file may include its own folder and any folder below it; siblings ({tasks, stimuli},
# {buffer, kbuffer, peel}, {scene, gpu}, {window, serve, simulate, replay}) do not include each other.
# app/ may include bench/measure (tlab bench). Outside the floors: bench/ and fuzz/ may include
# anything below app/; tests/X/ may include X/, what X/ may include, and tests/support/ (which may
# include anything below app/); the few tests that need a sibling floor are listed in `crossing`.
# `check_layers.sh --self-test` proves the check can fail: it copies the sources to a temporary
# folder, checks the copy passes, then plants wrong includes (folders, renderer/ C++ and shaders,
# study/, GLFW) and expects exactly those to fail (the ctest check_layers_self_test).
set -euo pipefail

if [[ ${1:-} == --self-test ]]; then
  script=$(realpath "$0")
  cd "${2:-$(dirname "$0")/..}"
  tmp=$(mktemp -d)
  trap 'rm -rf "$tmp"' EXIT
  find app study tasks stimuli renderer core analysis bench fuzz tests -type f \
    \( -name '*.cpp' -o -name '*.hpp' -o -name '*.h' -o -name '*.glsl' -o -name '*.comp' \
       -o -name '*.frag' -o -name '*.vert' \) -exec cp --parents -t "$tmp" {} +
  bash "$script" "$tmp" >/dev/null || { echo "self-test: the unchanged copy fails" >&2; exit 1; }
  # Each plant: the file to append to, the include line, the floor rule that must catch it.
  plants=(
    'core/seeded_random.hpp|#include "renderer/scene/camera.hpp"|core/ may include only'
    'renderer/compose/blend.comp|#include "styles/planted.glsl"|renderer/compose/ may include only floors below'
    'renderer/kbuffer/kbuffer_insert.frag|#include "peel/planted.glsl"|renderer/kbuffer/ may include only floors below'
    'study/store/store.hpp|#include "study/run/responder.hpp"|study/store/ may include only floors below'
    'study/window/trial_screen.hpp|#include "study/serve/trial_page.hpp"|study/window/ may include only floors below'
    'study/run/trial_runner.cpp|#include <GLFW/glfw3.h>|only study/window/ may'
  )
  for plant in "${plants[@]}"; do
    IFS='|' read -r file line rule <<<"$plant"
    [[ -f $tmp/$file ]] || { echo "self-test: $file is gone; update the plants" >&2; exit 1; }
    echo "$line" >>"$tmp/$file"
  done
  if out=$(bash "$script" "$tmp" 2>&1); then
    echo "self-test: the planted upward includes pass the check" >&2
    exit 1
  fi
  for plant in "${plants[@]}"; do
    IFS='|' read -r file line rule <<<"$plant"
    target=${line#*\"}
    target=${target%\"}
    [[ $file == *.@(glsl|comp|frag|vert) ]] && target=renderer/$target  # a shader names a file of renderer/
    [[ $line == *'<GLFW/'* ]] && target=GLFW
    [[ $out == *"$file includes $target: $rule"* ]] ||
      { echo "self-test: $file with $line: expected '$rule' in: $out" >&2; exit 1; }
  done
  [[ $out == *"check_layers: ${#plants[@]} include(s) point up a floor or out of their floor"* ]] ||
    { echo "self-test: more than the planted includes failed: $out" >&2; exit 1; }
  echo "check_layers --self-test: ${#plants[@]} planted wrong includes caught"
  exit 0
fi
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
# The floors inside renderer/ and study/: a higher number may include a lower one.
declare -A rank=([renderer/pipeline]=7 [renderer/styles]=6 [renderer/compose]=5 [renderer/ops]=4
                 [renderer/buffer]=3 [renderer/kbuffer]=3 [renderer/peel]=3 [renderer/frame]=2
                 [renderer/params]=1 [renderer/scene]=0 [renderer/gpu]=0
                 [study/window]=4 [study/serve]=4 [study/simulate]=4 [study/replay]=4 [study/analyze]=3 [study/run]=2
                 [study/store]=1 [study/design]=0)

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
  elif [[ $from == "$to" && ($from == renderer || $from == study) ]]; then
    rest=${file#*/}
    inner_from=$from/${rest%%/*}
    rest=${target#*/}
    inner_to=$to/${rest%%/*}
    [[ $inner_from == "$inner_to" ]] && continue
    if [[ ! -v rank[$inner_from] || ! -v rank[$inner_to] ]]; then
      fail "$file includes $target: $inner_from or $inner_to has no floor in check_layers.sh"
    elif ((rank[$inner_to] >= rank[$inner_from])); then
      fail "$file includes $target: $inner_from/ may include only floors below it (check_layers.sh)"
    fi
  fi
done < <(
  grep -rnoE --include='*.cpp' --include='*.hpp' --include='*.h' '^#include "[^"]+"' \
    app study tasks stimuli renderer core analysis bench fuzz tests | sed -E 's/:[0-9]+:#include "/::/; s/"$//'
  # The shaders' includes name a file inside renderer/ (renderer/gpu/shader_program.hpp).
  grep -rnoE --include='*.glsl' --include='*.comp' --include='*.frag' --include='*.vert' \
    '^[[:space:]]*#include "[^"]+"' renderer | sed -E 's/:[0-9]+:[[:space:]]*#include "/::renderer\//; s/"$//'
)

# Inside study/, only the window front end talks to GLFW (the session flow below it is the same for
# every front end).
while IFS=: read -r file _; do
  [[ $file == study/window/* ]] || fail "$file includes GLFW: only study/window/ may (check_layers.sh)"
done < <(grep -rnE --include='*.cpp' --include='*.hpp' '^#include <GLFW/' study || true)

if ((failures > 0)); then
  echo "check_layers: $failures include(s) point up a floor or out of their floor" >&2
  exit 1
fi
echo "check_layers: every include points down"
