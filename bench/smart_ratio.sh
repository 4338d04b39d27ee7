#!/usr/bin/env bash
# Smart transparency against exact `constant` (issue #29's goals: smart ≤ 1.5× constant on the
# torus, ≤ 2.5× on the 16-layer stack), timed by `tlab bench render` in alternating rounds for one
# or more builds, so that every build meets the same load; prints each round's passes and ratio, and
# per scene and build the best frame of each style over the rounds and their ratio (a round's own
# ratio moves with whichever style the load hit harder in it), and the median of the rounds' own
# ratios with their range (each round's two styles met the same moment of the machine). Run by hand
# (speed is never a test):
#
#   bash bench/smart_ratio.sh [ROUNDS] [TLAB ...]     # default 3 rounds of build/bin/tlab
#
# Environment: SCENES (default the torus of 100,000 triangles and the 16-layer stack), SIZE (512x512),
# FRAMES (3, the median of which each round takes).
set -euo pipefail
rounds=${1:-3}
shift || true
builds=("$@")  # paths as given, from the current folder
[ ${#builds[@]} -eq 0 ] && builds=("$(dirname "$0")/../build/bin/tlab")
[[ $rounds =~ ^[1-9][0-9]*$ ]] || { echo "smart_ratio.sh: ROUNDS must be a whole number of at least 1, not '$rounds'" >&2; exit 2; }
for b in "${builds[@]}"; do
  [ -x "$b" ] || { echo "smart_ratio.sh: $b: not an executable tlab (build it first, or give its path)" >&2; exit 2; }
done
scenes=${SCENES:-"builtin:torus?triangles=100000 builtin:quad-stack?n=16"}
size=${SIZE:-512x512}
frames=${FRAMES:-3}
echo "load average at the start: $(cut -d' ' -f1-3 /proc/loadavg)"
declare -A best ratios
for r in $(seq 1 "$rounds"); do
  for scene in $scenes; do
    for b in "${builds[@]}"; do
      json=$("$b" bench render --scene "$scene" --style constant,smart --size "$size" --frames "$frames" --json)
      line=$(python3 -c '
import json, sys
rows = {r["style"]: r for r in json.loads(sys.argv[1])["rows"]}
c, s = rows["constant"], rows["smart"]
passes = lambda r: ", ".join(f"{k} {v:.1f}" for k, v in r["pass_ms"].items())
cm, sm = c["frame_ms"], s["frame_ms"]
print(f"{cm:.3f} {sm:.3f}\t{sm / cm:.2f}\tconstant {cm:.1f} ms ({passes(c)})\tsmart {sm:.1f} ms ({passes(s)})")
' "$json")
      times=${line%%$'\t'*}
      echo -e "round $r\t$scene\t$b\tsmart/constant ${line#*$'\t'}\tload $(cut -d' ' -f1 /proc/loadavg)"
      key="$scene|$b"
      ratios[$key]="${ratios[$key]:-} $(python3 -c 'import sys; c, s = map(float, sys.argv[1].split()); print(s / c)' "$times")"
      best[$key]=$(python3 -c "
import sys
c, s = map(float, sys.argv[1].split()); old = sys.argv[2].split()
if old: c, s = min(c, float(old[0])), min(s, float(old[1]))
print(c, s)" "$times" "${best[$key]:-}")
    done
  done
done
echo "best frame of each style over $rounds round(s), and smart / constant of the two:"
for scene in $scenes; do
  for b in "${builds[@]}"; do
    read -r c s <<< "${best[$scene|$b]}"
    python3 -c "import sys; c, s = float(sys.argv[3]), float(sys.argv[4]); print(f'  {sys.argv[1]}\t{sys.argv[2]}\tconstant {c:.1f} ms\tsmart {s:.1f} ms\t{s / c:.2f}')" "$scene" "$b" "$c" "$s"
  done
done
echo "the rounds' own smart / constant: median (lowest, highest) over $rounds round(s):"
for scene in $scenes; do
  for b in "${builds[@]}"; do
    python3 -c "
import statistics, sys
r = [float(x) for x in sys.argv[3].split()]
print(f'  {sys.argv[1]}\t{sys.argv[2]}\t{statistics.median(r):.2f} ({min(r):.2f}, {max(r):.2f})')" "$scene" "$b" "${ratios[$scene|$b]}"
  done
done
