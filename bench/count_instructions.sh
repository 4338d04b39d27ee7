#!/usr/bin/env bash
# The CPU instructions each pass of a frame executes, counted by valgrind's callgrind (issue #29):
# on a shared machine a frame's milliseconds move by a third from one run to the next, the count
# of instructions does not, so it is the measure that compares two builds, or two styles, pass by
# pass. Run by hand (speed is never a test; needs `apt-get install valgrind`):
#
#   bash bench/count_instructions.sh [SCENE] [STYLES]   # default: the 100 K-triangle torus; constant,smart
#
# For every pass P of a style's frame (as `tlab bench render` lists them), `tlab bench render
# --until P` runs under callgrind with --frames 1 and --frames 3: half the difference is one frame
# up to the end of P (set-up, shader compilation and the warm-up frame cancel), and a pass's own
# count is that minus the same for the pass before it. llvmpipe runs on one thread
# (LP_NUM_THREADS=1) and compiles every shader afresh (no shader cache), so every run executes
# the same instructions. Environment: TLAB (build/bin/tlab), SIZE (512x512), JOBS (2 runs at a time).
# Each run takes a minute or two on the torus at 512².
set -euo pipefail
cd "$(dirname "$0")/.."
scene=${1:-builtin:torus?triangles=100000}
styles=${2:-constant,smart}
tlab=${TLAB:-build/bin/tlab}
size=${SIZE:-512x512}
jobs=${JOBS:-2}
command -v valgrind > /dev/null || { echo "count_instructions.sh: needs valgrind (apt-get install valgrind)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The passes of STYLE's frame, in the order they run (the last column of `tlab bench render`).
passes_of() {
  "$tlab" bench render --scene "$scene" --style "$1" --size "$size" --frames 1 | tail -1 |
    python3 -c 'import sys; row = sys.stdin.read().split(None, 7); print(" ".join(p.split()[0] for p in row[7].split(", ")))'
}

# One callgrind run: STYLE PASS FRAMES -> the file $work/STYLE.PASS.FRAMES holds the instruction count.
count() {
  local out=$work/$1.$2.$3
  MESA_SHADER_CACHE_DISABLE=true LP_NUM_THREADS=1 valgrind --tool=callgrind --callgrind-out-file=/dev/null \
    "$tlab" bench render --scene "$scene" --style "$1" --size "$size" --frames "$3" --until "$2" > /dev/null 2> "$out.log"
  grep -o 'Collected : [0-9]*' "$out.log" | awk '{print $3}' > "$out"
  [ -s "$out" ] || { echo "count_instructions.sh: no count for $1 --until $2 (see below)" >&2; tail -3 "$out.log" >&2; exit 1; }
}
export -f count
export tlab scene size work

declare -A order
runs=()
for style in ${styles//,/ }; do
  order[$style]=$(passes_of "$style")
  for pass in ${order[$style]}; do runs+=("$style $pass 1" "$style $pass 3"); done
done
echo "load average at the start: $(cut -d' ' -f1-3 /proc/loadavg); ${#runs[@]} callgrind runs, $jobs at a time"
printf '%s\n' "${runs[@]}" | xargs -P "$jobs" -L 1 bash -c 'count "$0" "$1" "$2"'

echo "millions of instructions per frame, $scene at $size ($("$tlab" version | head -1))"
first_total=""
for style in ${styles//,/ }; do
  previous=0
  line=""
  for pass in ${order[$style]}; do
    upto=$(python3 -c "print(($(cat "$work/$style.$pass.3") - $(cat "$work/$style.$pass.1")) / 2 / 1e6)")
    own=$(python3 -c "print(f'{$upto - $previous:.1f}')")
    line+="${line:+, }$pass $own"
    previous=$upto
  done
  total=$(python3 -c "print(f'{$previous:.1f}')")
  [ -z "$first_total" ] && first_total=$total
  ratio=$(python3 -c "print(f'{$total / $first_total:.2f}')")
  printf '%-16s total %9s M  (%s× %s)  %s\n' "$style" "$total" "$ratio" "${styles%%,*}" "$line"
done
