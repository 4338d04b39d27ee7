#!/usr/bin/env bash
# Load test: N simulated participants (default 1 000) of the Elmqvist-shaped design
# (tests/study/data/elmqvist_shape.toml: 2x2 within, Latin square, 4 tasks x 3 trials + training)
# into one database, then `tlab analyze` and `tlab export` on it. Prints wall time and peak
# memory (GNU time) per step. Uses build/bin/tlab (scripts/build.sh).
#   bash scripts/load.sh [N] [work folder]
set -euo pipefail
cd "$(dirname "$0")/.."
n=${1:-1000}
work=${2:-$(mktemp -d)}
mkdir -p "$work"
tlab=build/bin/tlab
measure() {
  local name=$1
  shift
  /usr/bin/time -f "load: $name: %e s wall, %M KiB peak RSS" "$@"
}
measure simulate $tlab simulate tests/study/data/elmqvist_shape.toml --participants "$n" --db "$work/load.db" | tail -1
measure analyze $tlab analyze "$work/load.db" >"$work/analyze.txt"
measure export $tlab export "$work/load.db" --csv "$work/csv" >/dev/null
echo "load: database $(du -h "$work/load.db" | cut -f1), $(sqlite3 "$work/load.db" 'SELECT count(*) FROM responses') responses, CSV $(du -sh "$work/csv" | cut -f1)"
