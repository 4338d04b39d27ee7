#!/usr/bin/env bash
# Issue #29's GPU table in one run, for a machine with a GPU (a lab's server, through a bundle from
# scripts/bundle.sh): every style at 512x512 and 2048x2048 on the torus (100 K triangles), the
# 16-layer quad stack and the meshes given (`tlab bench all`), then `tlab bench floor` for constant
# and smart on the torus and the stack (each pass's bytes against this GL's own streaming copy).
# Then the seeds' own comparisons with their papers' settings (tlab bench buckets, dynamic, peel),
# each within COMPARISON_S seconds. Writes OUT_DIR/machine.txt, all.json, floor-WxH.json,
# COMPARISON.txt and table.md (Markdown, bench/gpu_table.py, the comparisons' text after it) and
# prints the table. A failing step is recorded in OUT_DIR/failed.txt and the others still run;
# the exit code is then 1. Nothing is timed unless the first picture renders through the GL asked.
#
# Usage: bash bench/gpu_table.sh TLAB OUT_DIR [MESH.gltf ...]
#   TLAB     a bundle's launcher (dist/tlab-bundle/tlab) or build/bin/tlab
#   MESH     glTF meshes, e.g. bench/bench_meshes.py's teapot, fandisk and bunny00 (README,
#            "Exact transparency against VTK"), seen from +z with the camera tlab fits
# Environment: SIZES (512x512,2048x2048), FRAMES (20: timed frames per row, median), GL (egl),
#   COPY_MIB (1024: the floor's streaming copy; larger than a GPU's cache), COMPARISONS
#   (buckets,dynamic,peel, or none), COMPARISON_S (120)
set -uo pipefail
[ $# -ge 2 ] || { echo "usage: bash bench/gpu_table.sh TLAB OUT_DIR [MESH.gltf ...]" >&2; exit 2; }
tlab=$1
out=$2
shift 2
here=$(cd "$(dirname "$0")" && pwd)
sizes=${SIZES:-512x512,2048x2048}
frames=${FRAMES:-20}
gl=${GL:-egl}
copy_mib=${COPY_MIB:-1024}
comparisons=${COMPARISONS:-buckets,dynamic,peel}
comparison_s=${COMPARISON_S:-120}
for mesh in "$@"; do
  [ -r "$mesh" ] || { echo "gpu_table: $mesh: no such mesh file" >&2; exit 2; }
done
mkdir -p "$out"
rm -f "$out/failed.txt"

scenes="builtin:torus?triangles=100000,builtin:quad-stack?n=16"
for mesh in "$@"; do scenes="$scenes,$mesh"; done

failed() {
  echo "$1" >> "$out/failed.txt"
  echo "gpu_table: FAILED: $1" >&2
}

{
  echo "date: $(date -u +%FT%TZ)"
  echo "host: $(uname -srm)"
  command -v nvidia-smi > /dev/null &&
    nvidia-smi --query-gpu=name,driver_version,memory.total,clocks.max.sm --format=csv,noheader | sed 's/^/gpu: /'
  grep -m1 'model name' /proc/cpuinfo | sed 's/.*: /cpu: /'
  echo "tlab: $("$tlab" version 2>/dev/null || echo unknown)"
} > "$out/machine.txt"
cat "$out/machine.txt"

# The first picture, through the GL asked for: without it nothing below means anything.
if ! "$tlab" render "builtin:torus" --style constant --size 64x64 --gl "$gl" -o "$out/probe.png" \
      --stats-json "$out/probe.json" > /dev/null; then
  failed "tlab render --gl $gl"
  exit 1
fi

"$tlab" bench all --gl "$gl" --sizes "$sizes" --frames "$frames" --comparisons none --scenes "$scenes" --json \
  > "$out/all.json" || failed "tlab bench all"

IFS=, read -r -a size_list <<< "$sizes"
for size in "${size_list[@]}"; do
  "$tlab" bench floor --gl "$gl" --size "$size" --frames "$frames" --copy-mib "$copy_mib" --json \
    --scenes "builtin:torus?triangles=100000,builtin:quad-stack?n=16" --styles constant,smart \
    > "$out/floor-$size.json" || failed "tlab bench floor --size $size"
done

python3 "$here/gpu_table.py" "$out" > "$out/table.md" || failed "bench/gpu_table.py $out"
cat "$out/table.md"

[ "$comparisons" = none ] && comparisons=
IFS=, read -r -a comparison_list <<< "$comparisons"
for comparison in "${comparison_list[@]}"; do
  timeout "$comparison_s" "$tlab" bench "$comparison" --gl "$gl" > "$out/$comparison.txt" ||
    failed "tlab bench $comparison (exit $?; $comparison_s s allowed)"
  printf '\n`tlab bench %s --gl %s`:\n\n' "$comparison" "$gl" >> "$out/table.md"
  sed 's/^/    /' "$out/$comparison.txt" >> "$out/table.md"
  cat "$out/$comparison.txt"
done
[ ! -e "$out/failed.txt" ]
