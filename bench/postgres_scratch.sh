#!/usr/bin/env bash
# A scratch PostgreSQL 15 server for benchmarks (run by hand; tests start their own through
# tests/support/postgres_cluster): initdb into DIR, listening only on a Unix socket in DIR, as the
# user `nobody` when run as root (PostgreSQL refuses root). Prints the database URL to give
# `tlab serve --db` and bench/serve_load.sh.
#
#   bash bench/postgres_scratch.sh start /tmp/tlab-pg    # → postgresql:///tlab_bench?host=/tmp/tlab-pg&port=5499&user=tlab
#   bash bench/postgres_scratch.sh stop /tmp/tlab-pg     # stops the server and removes DIR
set -euo pipefail
action=${1:?usage: bash bench/postgres_scratch.sh start|stop DIR}
dir=${2:?usage: bash bench/postgres_scratch.sh start|stop DIR}
bin=/usr/lib/postgresql/15/bin
port=5499
as() { if [ "$(id -u)" -eq 0 ]; then runuser -u nobody -- "$@"; else "$@"; fi; }
case "$action" in
  start)
    [ -x "$bin/initdb" ] || { echo "postgres_scratch: $bin/initdb is missing: run scripts/setup.sh" >&2; exit 1; }
    mkdir -p "$dir"
    [ "$(id -u)" -eq 0 ] && chown nobody "$dir"
    as "$bin/initdb" -D "$dir/data" -U tlab --auth=trust -E UTF8 >/dev/null
    as "$bin/pg_ctl" -D "$dir/data" -l "$dir/log" -w -o "-c listen_addresses='' -c unix_socket_directories=$dir -p $port -c max_connections=300" start >/dev/null
    as "$bin/createdb" -h "$dir" -p "$port" -U tlab tlab_bench
    echo "postgresql:///tlab_bench?host=$dir&port=$port&user=tlab"
    ;;
  stop)
    as "$bin/pg_ctl" -D "$dir/data" -m fast -w stop >/dev/null || true
    rm -rf "$dir"
    ;;
  *) echo "usage: bash bench/postgres_scratch.sh start|stop DIR" >&2; exit 1 ;;
esac
