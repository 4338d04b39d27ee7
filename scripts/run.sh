#!/usr/bin/env bash
# The main job: set up, build, and run Transparency Lab's end-to-end demo — the Carnecky 2013
# replication: stimuli with exact ground truth, 36 simulated participants through the
# counterbalanced design into out/demo/study.db, the planned analysis into out/demo/report.html.
# A demo folder is never overwritten: an earlier out/demo is moved aside to out/demo.<time>.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
if [ -e out/demo/study.db ]; then mv out/demo "out/demo.$(date +%Y%m%d-%H%M%S)"; fi
build/bin/tlab demo --out out/demo "$@"
