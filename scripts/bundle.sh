#!/usr/bin/env bash
# Writes a relocatable tlab bundle for a machine with no build tools and no Debian packages (a lab's
# GPU server): bin/tlab, the shared libraries it needs that a bare glibc >= 2.36 system lacks,
# the DejaVu fonts for labels and the study window, the examples, bench/gpu_table.sh (with its
# Markdown formatter), and a `tlab` launcher that points
# the loader and the fonts at the bundle. Left out: glibc itself and the GL driver (libEGL/libGL,
# and Mesa's OSMesa/LLVM): the server's GPU driver provides libEGL.so.1, and tlab opens it at run
# time (--gl egl). Usage: scripts/bundle.sh [OUT_DIR]   (default dist/tlab-bundle; build first)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-dist/tlab-bundle}
exe=${TLAB_EXE:-build/bin/tlab}  # the tlab to pack (ctest names its build)
limit_mib=60
[ -x "$exe" ] || { echo "bundle: $exe is missing - build first (scripts/build.sh)" >&2; exit 1; }

rm -rf "$out"
mkdir -p "$out/bin" "$out/lib" "$out/fonts" "$out/examples"
cp "$exe" "$out/bin/tlab"
strip "$out/bin/tlab"

# Every library the loader resolves for tlab, except glibc's own and the GL driver's.
skip='^(linux-vdso|ld-linux|libc\.so|libm\.so|libdl\.so|libpthread\.so|librt\.so|libresolv\.so|libutil\.so|libEGL|libGL|libGLX|libGLdispatch|libOSMesa|libLLVM|libglapi)'
ldd "$exe" | awk '/=> \// {print $1, $3}' | while read -r name path; do
  [[ $name =~ $skip ]] && continue
  cp -L "$path" "$out/lib/$name"
done
strip --strip-unneeded "$out"/lib/*

fontdir=/usr/share/fonts/truetype/dejavu
cp "$fontdir/DejaVuSans.ttf" "$fontdir/DejaVuSans-Bold.ttf" "$out/fonts/"
cp -r examples/. "$out/examples/"
mkdir -p "$out/bench"  # the one run to make on a GPU (README, Benchmarks): the tables need python3 there
cp bench/gpu_table.sh bench/gpu_table.py "$out/bench/"

# The launcher: POSIX sh built-ins only (no dirname, no readlink), so it runs on a bare system.
cat > "$out/tlab" <<'LAUNCHER'
#!/bin/sh
# tlab from a relocatable bundle (scripts/bundle.sh): the bundle's libraries and fonts, the
# machine's glibc and GPU driver.
case "$0" in */*) here=${0%/*} ;; *) here=. ;; esac
here=$(cd "$here" && pwd)
export LD_LIBRARY_PATH="$here/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
export TLAB_FONT_DIR="${TLAB_FONT_DIR:-$here/fonts}"
exec "$here/bin/tlab" "$@"
LAUNCHER
chmod +x "$out/tlab"

size_kib=$(du -sk "$out" | cut -f1)
if [ "$size_kib" -gt $((limit_mib * 1024)) ]; then
  echo "bundle: $out is $((size_kib / 1024)) MiB, over the $limit_mib MiB limit" >&2
  exit 1
fi
echo "bundle: wrote $out ($((size_kib / 1024)) MiB, $(ls "$out/lib" | wc -l) libraries); run $out/tlab"
