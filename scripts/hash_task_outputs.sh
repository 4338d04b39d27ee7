#!/usr/bin/env bash
# Hashes what the tasks produce — `tlab task probe --json` of every seed task, and two simulated
# studies (their stimuli, by SHA-256 name, and their exported trials without the wall-clock
# recorded_at) — so that a refactoring of tasks/ or study/ can prove its outputs byte-identical:
#   bash scripts/hash_task_outputs.sh OLD_TLAB > before.txt; bash scripts/hash_task_outputs.sh NEW_TLAB > after.txt
#   diff before.txt after.txt
set -euo pipefail
tlab=$(realpath "${1:-build/bin/tlab}")
examples=$(realpath "$(dirname "$0")/../examples")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
probe() { "$tlab" task probe "$1" --task "$2" --count "$3" --size 256x256 --json > "probe-$2.json"; }
probe 'builtin:nested-spheres?n=3' layer-index 3
probe builtin:bubble follow-boundary 3
probe builtin:pretzel nearest-point 2
probe 'builtin:abstract-pattern?letter=2&seed=2' pattern 1
probe 'builtin:walkthrough?seed=3' counting 1
probe 'builtin:walkthrough?seed=3' target-discovery 1
"$tlab" simulate "$examples/carnecky2013.toml" --participants 3 --size 384x384 --db carnecky.db > /dev/null
"$tlab" simulate "$examples/elmqvist.toml" --participants 3 --size 240x240 --db elmqvist.db > /dev/null
for study in carnecky elmqvist; do
  "$tlab" export "$study.db" --csv "csv-$study" > /dev/null
  sed -E 's/[0-9]{4}-[0-9]{2}-[0-9]{2}T[0-9:.]+Z//g' "csv-$study/trials.csv" > "trials-$study.csv"
  ls "$study-stimuli" > "stimuli-$study.txt"
done
sha256sum probe-*.json trials-*.csv stimuli-*.txt
