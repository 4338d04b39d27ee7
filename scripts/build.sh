#!/usr/bin/env bash
# Configures and builds Transparency Lab in Release with two jobs: build/bin/tlab.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j2
