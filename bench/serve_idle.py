#!/usr/bin/env python3
"""Idle connections against `tlab serve` (run by hand; not a test): N connections are opened on
127.0.0.1 and held without a byte sent (or with half a request header, --half), and meanwhile a
participant's page asks for its screen R times, each on a fresh connection (a browser that opens
one). Prints the request latencies (p50, p95, p99, max), the requests that failed, and how many of
the held connections the server closed (its per-address cap or its time-outs). Goal (issue 26):
with 1 000 idle connections held, p99 <= 100 ms.

    bench/serve_idle.py --tlab build/bin/tlab [--idle 1000] [--requests 200] [--half] [--timeout 20]

Loopback only; every loop is bounded (the connections, the requests, a time-out per request).
"""
import argparse
import http.client
import os
import re
import select
import shutil
import socket
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent


def start_server(tlab, experiment, db, extra):
    process = subprocess.Popen([tlab, "serve", experiment, "--db", db, "--listen", "127.0.0.1:0", "--quiet", *extra],
                               stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    deadline = time.monotonic() + 300
    while time.monotonic() < deadline:
        line = process.stdout.readline()
        if not line:
            sys.exit(f"tlab serve ended early (status {process.wait()})")
        m = re.match(r"participants: http://127\.0\.0\.1:(\d+)/s/([^?]+)\?", line)
        if m:
            return process, int(m.group(1)), m.group(2)
    sys.exit("tlab serve printed no link within 300 s")


def arrive(port, study, timeout):
    c = http.client.HTTPConnection("127.0.0.1", port, timeout=timeout)
    c.request("GET", f"/s/{study}?PROLIFIC_PID=idle-bench")
    r = c.getresponse()
    r.read()
    token = r.getheader("Location", "").split("/")[-1]
    c.close()
    if len(token) != 64:
        sys.exit(f"no session token from the arrival (status {r.status})")
    return token


def hold(port, count, half):
    held = []
    for _ in range(count):
        s = socket.create_connection(("127.0.0.1", port), timeout=10)
        if half:
            s.sendall(b"GET /api/ HTTP/1.1\r\nHost: 127.0.0.1\r\n")  # a header that never ends
        held.append(s)
    return held


def closed_by_server(held):
    closed = 0
    for s in held:
        readable, _, _ = select.select([s], [], [], 0)
        if readable:
            try:
                closed += s.recv(1, socket.MSG_PEEK) == b""
            except OSError:
                closed += 1
    return closed


def measure(port, token, requests, timeout):
    seconds, failed = [], 0
    for _ in range(requests):
        start = time.monotonic()
        try:
            c = http.client.HTTPConnection("127.0.0.1", port, timeout=timeout)
            c.request("GET", f"/api/{token}/screen")
            r = c.getresponse()
            r.read()
            c.close()
            ok = r.status == 200
        except OSError:
            ok = False
        if ok:
            seconds.append(time.monotonic() - start)
        else:
            failed += 1
    return seconds, failed


def percentile(values, p):
    if not values:
        return float("nan")
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(round(p / 100 * (len(ordered) - 1))))]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--tlab", default=str(HERE.parent / "build" / "bin" / "tlab"))
    parser.add_argument("--experiment", default=str(HERE.parent / "tests" / "study" / "data" / "serve_tiny.toml"))
    parser.add_argument("--idle", type=int, default=1000)
    parser.add_argument("--requests", type=int, default=200)
    parser.add_argument("--timeout", type=float, default=20.0, help="seconds one request may take before it counts as failed")
    parser.add_argument("--half", action="store_true", help="held connections send half a request header")
    parser.add_argument("--serve-arg", action="append", default=[], help="an extra argument of tlab serve (repeatable)")
    args = parser.parse_args()
    work = Path(tempfile.mkdtemp(prefix="tlab-idle-"))
    server, port, study = start_server(args.tlab, args.experiment, str(work / "study.db"), args.serve_arg)
    held = []
    try:
        token = arrive(port, study, args.timeout)
        before, _ = measure(port, token, 20, args.timeout)
        held = hold(port, args.idle, args.half)
        seconds, failed = measure(port, token, args.requests, args.timeout)
        closed = closed_by_server(held)
        ms = [s * 1000 for s in seconds]
        print(f"tlab serve at 127.0.0.1:{port}; {args.idle} {'half-open' if args.half else 'idle'} connections held; {args.requests} requests")
        print(f"without idle connections: median {statistics.median(before) * 1000:.2f} ms")
        print(f"with them: p50 {percentile(ms, 50):.2f} ms, p95 {percentile(ms, 95):.2f} ms, p99 {percentile(ms, 99):.2f} ms, "
              f"max {max(ms) if ms else float('nan'):.2f} ms; failed (no answer within {args.timeout:g} s): {failed}")
        print(f"held connections closed by the server meanwhile: {closed} of {len(held)}")
    finally:
        for s in held:
            s.close()
        server.terminate()
        server.wait(timeout=60)
        shutil.rmtree(work, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
