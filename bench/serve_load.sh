#!/usr/bin/env bash
# Load benchmark of `tlab serve` (run by hand; not a test): simulated participants walk whole
# sessions of an experiment over HTTP (`tlab loadtest`) against a server on this machine, and the
# loadtest figures are printed — throughput and the answer → acknowledgement latency (goal: p99
# <= 100 ms for 300 participants of the Carnecky design, 100 at a time).
#
#   bash bench/serve_load.sh DB [PARTICIPANTS] [CONCURRENCY] [THINK_MS] [EXPERIMENT]
#   bash bench/serve_load.sh /tmp/tlab-bench/carnecky.db                 # SQLite: 300 × Carnecky, 100 at a time
#   bash bench/serve_load.sh postgresql://tlab@localhost/tlab_bench      # the same against PostgreSQL
#
# DB is passed to `tlab serve --db` as is, so both stores run the same scenario. Each run uses
# new participant ids (bench-<time>-NNN), so one database serves several runs; the stimuli are
# prepared once (kept beside a SQLite database; the preparation time is printed) — the first run
# of the Carnecky design prepares 396 images of 800 × 800 and takes minutes on a 2-core machine.
# Environment: TLAB (default build/bin/tlab), SERVE_THREADS (HTTP worker threads, default 160:
# cpp-httplib keeps a thread per keep-alive connection, so fewer threads than participants at a
# time queue their requests), SLOTS (--slots: counterbalancing slots to prepare; default the
# server's), SEED (default 1).
set -euo pipefail
cd "$(dirname "$0")/.."
db=${1:?usage: bash bench/serve_load.sh DB [PARTICIPANTS] [CONCURRENCY] [THINK_MS] [EXPERIMENT]}
participants=${2:-300}
concurrency=${3:-100}
think=${4:-1000}
experiment=${5:-examples/carnecky2013.toml}
tlab=${TLAB:-build/bin/tlab}
work=$(mktemp -d)
trap 'kill "$server" 2>/dev/null || true; wait "$server" 2>/dev/null || true; rm -rf "$work"' EXIT

slots=()
[ -n "${SLOTS:-}" ] && slots=(--slots "$SLOTS")
start=$(date +%s.%N)
"$tlab" serve "$experiment" --db "$db" --listen 127.0.0.1:0 --quiet --threads "${SERVE_THREADS:-160}" "${slots[@]}" >"$work/serve.out" 2>"$work/serve.err" &
server=$!
until grep -qs '^participants: ' "$work/serve.out"; do
  if ! kill -0 "$server" 2>/dev/null; then cat "$work/serve.err" >&2; exit 1; fi
  sleep 0.5
done
link=$(sed -n 's/^participants: \(http:[^?]*\)?.*/\1/p' "$work/serve.out")
param=$(sed -n 's/^participants: [^?]*?\([^=]*\)=.*/\1/p' "$work/serve.out")
head -1 "$work/serve.out"
printf 'server ready after %.1f s (preparation included); store: %s\n' "$(echo "$(date +%s.%N) - $start" | bc)" "$db"
# Participants retry through a lost connection as the page does; the reconnections are printed.
echo "+ $tlab loadtest $link --participants $participants --concurrency $concurrency --think $think --param $param --seed ${SEED:-1} --retry-seconds 30"
status=0
"$tlab" loadtest "$link" --participants "$participants" --concurrency "$concurrency" --think "$think" --param "$param" \
  --seed "${SEED:-1}" --retry-seconds 30 --pid-prefix "bench-$(date +%s)-" || status=$?
echo "server refusals and errors: $(grep -c '^serve: [45]' "$work/serve.err" || true)"
if ! kill -0 "$server" 2>/dev/null; then
  wait "$server" || echo "the server ended during the run (exit status $?); its last messages:" >&2
  tail -20 "$work/serve.err" >&2
fi
exit "$status"
