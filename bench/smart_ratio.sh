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
declare -A frames_of  # per scene and build: each round's "constant,smart" frame ms
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
print(f"{cm!r},{sm!r}\t{sm / cm:.2f}\tconstant {cm:.1f} ms ({passes(c)})\tsmart {sm:.1f} ms ({passes(s)})")
' "$json")
      echo -e "round $r\t$scene\t$b\tsmart/constant ${line#*$'\t'}\tload $(cut -d' ' -f1 /proc/loadavg)"
      frames_of["$scene|$b"]+=" ${line%%$'\t'*}"
    done
  done
done
# Both summaries from the rounds' frames of one scene and build (SCENE BUILD "c,s c,s ...").
summary() {
  python3 -c '
import statistics, sys
scene, build, what = sys.argv[1:4]
frames = [tuple(map(float, pair.split(","))) for pair in sys.argv[4].split()]
if what == "best":
    c, s = min(f[0] for f in frames), min(f[1] for f in frames)
    print(f"  {scene}\t{build}\tconstant {c:.1f} ms\tsmart {s:.1f} ms\t{s / c:.2f}")
else:
    r = [s / c for c, s in frames]
    print(f"  {scene}\t{build}\t{statistics.median(r):.2f} ({min(r):.2f}, {max(r):.2f})")
' "$@"
}
echo "best frame of each style over $rounds round(s), and smart / constant of the two:"
for scene in $scenes; do
  for b in "${builds[@]}"; do summary "$scene" "$b" best "${frames_of[$scene|$b]}"; done
done
echo "the rounds' own smart / constant: median (lowest, highest) over $rounds round(s):"
for scene in $scenes; do
  for b in "${builds[@]}"; do summary "$scene" "$b" median "${frames_of[$scene|$b]}"; done
done
