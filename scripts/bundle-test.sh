#!/usr/bin/env bash
# Proves a bundle from scripts/bundle.sh runs on a bare system: a chroot holding only glibc, /bin/sh
# and a GL driver (Mesa's libEGL + llvmpipe and OSMesa here, standing in for a GPU server's
# driver), with an empty environment. There `tlab render` (through EGL and through OSMesa),
# `tlab stimuli` and `tlab bench` must run, and the pictures must equal those of the build tree.
# Needs root (chroot; exit 77 = skipped otherwise). Usage: scripts/bundle-test.sh [BUNDLE_DIR]
# (default dist/tlab-bundle). ctest runs it on a fresh bundle (bundle_in_bare_chroot).
set -euo pipefail
cd "$(dirname "$0")/.."
bundle=$(cd "${1:-dist/tlab-bundle}" && pwd)
[ "$(id -u)" -eq 0 ] || { echo "bundle-test: skipped: needs root (chroot)" >&2; exit 77; }
root=$(mktemp -d /tmp/tlab-bare-XXXXXX)
trap 'rm -rf "$root"' EXIT
libdir=/usr/lib/x86_64-linux-gnu

# Copies files and the libraries they load (ldd) into the chroot at the same paths.
install_with_deps() {
  for f in "$@"; do
    mkdir -p "$root$(dirname "$f")"
    cp -L "$f" "$root$f"
    ldd "$f" 2>/dev/null | awk '/=> \// {print $3} /^\t\/lib/ {print $1}' | while read -r dep; do
      [ -e "$root$dep" ] || { mkdir -p "$root$(dirname "$dep")"; cp -L "$dep" "$root$dep"; }
    done
  done
}

# The bare system: glibc and /bin/sh.
install_with_deps /bin/sh
mkdir -p "$root/lib64" "$root/tmp" "$root/dev"
cp -L /lib64/ld-linux-x86-64.so.2 "$root/lib64/"
for l in libc.so.6 libm.so.6 libdl.so.2 libpthread.so.0 librt.so.1 libresolv.so.2 libutil.so.1; do install_with_deps "$libdir/$l"; done
# The "GPU driver": libglvnd's libEGL with Mesa's vendor library and llvmpipe, and OSMesa.
install_with_deps "$libdir/libEGL.so.1" "$libdir/libEGL_mesa.so.0" "$libdir/dri/swrast_dri.so" "$libdir/libOSMesa.so.8"
mkdir -p "$root/usr/share/glvnd/egl_vendor.d"
cp /usr/share/glvnd/egl_vendor.d/50_mesa.json "$root/usr/share/glvnd/egl_vendor.d/"
mknod -m 666 "$root/dev/null" c 1 3
cp -r "$bundle" "$root/tlab"

# Every library tlab loads at start comes from the bundle or glibc, not from the driver's files.
chroot "$root" /lib64/ld-linux-x86-64.so.2 --library-path /tlab/lib --list /tlab/bin/tlab | awk '/=>/ {print $3}' |
  while read -r lib; do
    case "$lib" in
      /tlab/lib/*|*/libc.so.6|*/libm.so.6|*/libdl.so.2|*/libpthread.so.0|*/librt.so.1|*/libresolv.so.2|*/libutil.so.1|*/ld-linux-x86-64.so.2) ;;
      *) echo "bundle-test: FAILED: tlab loads $lib from outside the bundle" >&2; exit 1 ;;
    esac
  done

run() { chroot "$root" /usr/bin/env -i /tlab/tlab "$@" 2>&1 || { echo "bundle-test: FAILED: tlab $*" >&2; exit 1; }; }
[ -x "$root/usr/bin/env" ] || install_with_deps /usr/bin/env
for gl in egl osmesa; do
  run render builtin:nested-spheres?n=3 --style smart --size 96x96 --gl $gl -o /tmp/$gl.png --stats-json /tmp/$gl.json
  "${TLAB_EXE:-build/bin/tlab}" render builtin:nested-spheres?n=3 --style smart --size 96x96 --gl $gl -o "$root/tmp/host-$gl.png" >/dev/null
  cmp "$root/tmp/$gl.png" "$root/tmp/host-$gl.png" || { echo "bundle-test: FAILED: the bundle's $gl picture differs" >&2; exit 1; }
  grep -q '"backend"' "$root/tmp/$gl.json"
done
run stimuli /tlab/examples/stimulus-sets/technical-mugs.toml -o /tmp/set --quiet --gl egl > /dev/null
[ -s "$root/tmp/set/manifest.json" ] || { echo "bundle-test: FAILED: no stimulus manifest" >&2; exit 1; }
run bench render --scene builtin:torus --style constant,smart --size 64x64 --frames 1 --gl egl | tail -3
echo "bundle-test: the bundle ran render (EGL, OSMesa: pictures equal the build tree's), stimuli and bench in a bare chroot"
