#!/usr/bin/env bash
# Installs the Debian 12 packages Transparency Lab builds and runs with. Idempotent and
# non-interactive; as root it installs, otherwise it prints the sudo command to run.
set -euo pipefail

packages=(
  build-essential cmake pkg-config git python3 python3-glad
  libglfw3-dev libglm-dev libtinygltf-dev libosmesa6-dev libgl-dev libegl-dev
  libsqlite3-dev sqlite3 libboost-dev libtomlplusplus-dev nlohmann-json3-dev libstb-dev libcli11-dev
  libcgal-dev libeigen3-dev libcairo2-dev libssl-dev libfreetype-dev fonts-dejavu-core
  libre2-dev libpoppler-cpp-dev libxml2-dev
  libnlopt-dev  # BOBYQA for the mixed models (lme4's default optimizer)
  libgtest-dev libgmock-dev libbenchmark-dev
  xvfb xdotool imagemagick chromium chromium-driver python3-selenium
  ffmpeg  # tlab replay -o: the video of an interactive trial's frames
  libcpp-httplib-dev libpqxx-dev postgresql  # tlab serve and the PostgreSQL store
  libpng-dev  # tlab serve's live frames: lossless PNG at zlib's fastest level
  libjpeg62-turbo-dev  # tlab serve's live frames when [online] frames = "jpeg" (lossy, logged)
  nginx  # the TLS reverse proxy of docs/nginx-tlab.conf, tested on loopback
  clang libclang-rt-14-dev time e2fsprogs
  python3-vtk9  # bench/vtk_compare.py (run by hand)
  libcgal-demo  # its data/meshes (fandisk, the bunny): the public meshes of issue #29's table, one tested
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} Debian packages are installed"
  exit 0
fi

echo "setup: installing ${missing[*]}"
if [ "$(id -u)" -ne 0 ]; then
  echo "setup: not root - run: sudo apt-get update && sudo apt-get install -y ${missing[*]}" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "setup: done"
