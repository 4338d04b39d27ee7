#!/usr/bin/env bash
# Live views benchmark of `tlab serve` (run by hand; not a test, issue #30): simulated participants
# explore an orbit trial (and, for Elmqvist, walk) rendered live by the server's GL worker, sending
# input as fast as frames come back (`tlab loadtest --live-seconds`), and the figures are printed:
# frames a second per participant and input → frame p50/p95 on loopback, for 1 and 4 participants
# (and PARTICIPANTS_MAX, e.g. 10 on a GPU) in each style. Goals on a 2-core machine without a GPU:
# one participant orbiting at 512² in `constant` ≥ 10 frames/s with p95 ≤ 150 ms; 4 participants
# at once each ≥ 4 frames/s.
#
#   bash bench/live_views.sh [SECONDS] [SIZE]        # default 10 s of exploring per trial, 512
#
# Environment: TLAB (default build/bin/tlab), STYLES (default "constant dynamic smart"),
# COUNTS (participants at once, default "1 4"), FRAMES (png, the default, or jpeg: [online] frames),
# LIVE_RENDERERS (tlab serve --live-renderers: threads rendering live views at once; default 1).
# The GL backend tlab serve renders with is printed
# by its first line (TLAB_GL=egl|osmesa picks one).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-10}
size=${2:-512}
tlab=${TLAB:-build/bin/tlab}
work=$(mktemp -d)
server=
trap '[ -n "$server" ] && kill "$server" 2>/dev/null; wait 2>/dev/null; rm -rf "$work"' EXIT

experiment() {  # one orbit trial of Elmqvist's ABSTRACT world in style $1 (dynamic: the active lens)
  local settings='[]'
  [ "$1" = dynamic ] && settings='["targets=all", "mode=active"]'
  cat <<TOML
id = "live-bench"
title = "Live views benchmark"
seed = 1
participants = 1000
counterbalancing = "fixed"
welcome = "Benchmark."

[stimulus]
scene = "builtin:abstract?seed=1"
style = "$1"
settings = $settings
size = "${size}x${size}"

[[tasks]]
id = "orbit"
navigation = "orbit"
task = "counting"
time_limit = 600
TOML
  [ "${FRAMES:-png}" = jpeg ] && printf '\n[online]\nframes = "jpeg"\n'
  return 0
}

printf '%-10s %4s  %-38s  %-24s  %s\n' style n "frames/s per participant" "input -> frame (ms)" "first frame (ms, max)"
stages=
for style in ${STYLES:-constant dynamic smart}; do
  experiment "$style" >"$work/$style.toml"
  : >"$work/serve.out"
  "$tlab" serve "$work/$style.toml" --db "$work/$style.db" --listen 127.0.0.1:0 --quiet ${LIVE_RENDERERS:+--live-renderers "$LIVE_RENDERERS"} >"$work/serve.out" 2>"$work/serve.err" &
  server=$!
  until grep -qs '^admin: ' "$work/serve.out"; do
    if ! kill -0 "$server" 2>/dev/null; then cat "$work/serve.err" >&2; exit 1; fi
    sleep 0.2
  done
  link=$(sed -n 's/^participants: \(http:[^?]*\)?.*/\1/p' "$work/serve.out")
  for n in ${COUNTS:-1 4}; do
    out=$("$tlab" loadtest "$link" --participants "$n" --concurrency "$n" --think 0 --live-seconds "$seconds" --pid-prefix "$style-$n-")
    fps=$(sed -n 's/^live frames: [0-9]*; frames\/s per participant: //p' <<<"$out")
    lat=$(sed -n 's/^live input -> frame (ms, n=[0-9]*): \(p50 [0-9.]*  p95 [0-9.]*\).*/\1/p' <<<"$out")
    first=$(sed -n 's/^live first frame of a trial (ms, n=[0-9]*): .*max \([0-9.]*\)$/\1/p' <<<"$out")
    printf '%-10s %4s  %-38s  %-24s  %s\n' "$style" "$n" "$fps" "$lat" "$first"
    stages+=$(printf '%-10s %4s %s' "$style" "$n" "$(sed -n 's/^live frame on the server (ms, p50\/p95)://p' <<<"$out")")$'\n'

  done
  kill "$server"
  wait "$server" 2>/dev/null || true
  server=
done
echo "each stage of a frame on the server (ms, p50/p95; Server-Timing):"
printf '%s' "$stages"
sed -n 's/.*(GL: \(.*\))$/GL: \1/p' "$work/serve.out"
