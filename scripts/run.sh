#!/usr/bin/env bash
# The main job: set up, build, and run Transparency Lab's end-to-end demo (for now: a gallery of
# every transparency style rendered headless into out/).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
build/bin/tlab gallery --out out/gallery
