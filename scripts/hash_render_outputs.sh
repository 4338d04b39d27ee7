#!/usr/bin/env bash
# Hashes the pictures the renderer produces — every style on the six built-in scenes, smart
# transparency's variants (adaptive α, halos or silhouettes off, Eq. 8 spreading, the profile
# modifiers of Eqs. 10-11, several components), `--fill list`, the three lighting models, IRIS's modes (buffer and peeling), 512² `constant` and `smart` on the timing scenes, 512² `constant` on
# the live views' `builtin:abstract?seed=1`, any glTF meshes
# given in $TLAB_HASH_MESHES, and every PNG of `tlab figures` — so that a change to the fills,
# the sort, the connect pass or the compositors can prove its pictures byte-identical:
#   bash scripts/hash_render_outputs.sh OLD_TLAB > before.txt; bash scripts/hash_render_outputs.sh NEW_TLAB > after.txt
#   diff before.txt after.txt
# A render that fails prints "failed" in place of its hash (the same on both sides is no change).
set -uo pipefail
tlab=$(realpath -m "${1:-build/bin/tlab}")
[ -x "$tlab" ] || { echo "hash_render_outputs.sh: $tlab: not an executable tlab (build it first, or give its path)" >&2; exit 2; }
meshes=()  # absolute paths: the renders run in a temporary folder
for mesh in ${TLAB_HASH_MESHES:-}; do
  [ -f "$mesh" ] || { echo "hash_render_outputs.sh: TLAB_HASH_MESHES: $mesh: no such file" >&2; exit 2; }
  meshes+=("$(realpath "$mesh")")
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
styles="opaque constant unsorted smart angle normal-variation iris view-dependent dynamic curvature"
scenes="sphere nested-spheres cube torus open-cylinders quad-stack?n=8"
render() {  # name, then tlab render arguments
  local name=$1
  shift
  if "$tlab" render "$@" -o "$name.png" > /dev/null 2>&1; then
    echo "$(sha256sum < "$name.png" | cut -d' ' -f1)  $name"
  else
    echo "failed  $name"
  fi
}
for scene in $scenes; do
  for style in $styles; do render "$style-$scene" "builtin:$scene" --style "$style" --size 160x128; done
  for fill in list; do
    render "constant-$fill-$scene" "builtin:$scene" --style constant --fill "$fill" --size 160x128
    render "smart-$fill-$scene" "builtin:$scene" --style smart --fill "$fill" --size 160x128
  done
  render "smart-adaptive-$scene" "builtin:$scene" --style smart --set alpha_init=adaptive --size 160x128
  render "smart-nohalos-$scene" "builtin:$scene" --style smart --set halos=off --size 160x128
  render "smart-nosilhouettes-$scene" "builtin:$scene" --style smart --set silhouettes=off --size 160x128
  render "smart-diffusion-$scene" "builtin:$scene" --style smart --set spread=diffusion --set wz=4 --size 160x128
  render "smart-pow-$scene" "builtin:$scene" --style smart --set modifier=pow --set p=2 --size 160x128
  render "smart-nomodifier-$scene" "builtin:$scene" --style smart --set modifier=none --size 160x128
done
for scene in 'torus?triangles=100000' 'quad-stack?n=16'; do
  for style in constant smart; do render "$style-512-$scene" "builtin:$scene" --style "$style" --size 512x512; done
done
# every lighting model through the fills and the raster pass, which compile it in (withLighting)
for lighting in none headlight pbr; do
  for style in opaque constant unsorted smart; do
    render "$style-$lighting-torus" builtin:torus --style "$style" --set lighting="$lighting" --size 160x128
  done
  render "constant-list-$lighting-torus" builtin:torus --style constant --fill list --set lighting="$lighting" --size 160x128
done
# IRIS's modes, which the illustrative shaders compile in (IllustrativeSettings::defines), through
# the buffer and through depth peeling
for renderer in buffer peel; do
  for mode in "opacity=constant" "opacity=angle" "shading=phong" "shading=gooch" "lighting=pbr" "lighting=none" \
              "stripes=t" "stripes=both" "stripes=lic" "silhouettes=off" "window_layers=2"; do
    render "iris-$renderer-$mode-torus" builtin:torus --style iris --renderer "$renderer" --set "$mode" --size 160x128
  done
done
# the live views' scene (issue #30), whose lists run up to 18 long: both paths of compose/blend.comp's sort
render "constant-512-abstract" "builtin:abstract?seed=1" --style constant --size 512x512
for mesh in "${meshes[@]}"; do
  for style in constant smart; do render "$style-$(basename "$mesh")" "$mesh" --style "$style" --size 384x384; done
done
if "$tlab" figures --out figures > /dev/null 2>&1; then
  (cd figures && sha256sum -- *.png)
else
  echo "failed  figures"
fi
