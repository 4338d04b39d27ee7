#!/usr/bin/env python3
"""The README's advice for the internet, tested: nginx (Debian's) with docs/nginx-tlab.conf as a TLS
reverse proxy in front of `tlab serve`, all on loopback. The example's ports and certificate are
replaced by free loopback ports and a self-signed certificate made here (each replacement must
match exactly once, so the example and this test stay one); then a participant arrives over
HTTPS, gets the page and starts the session through the proxy, and plain HTTP is redirected.

    tests/study/serve_nginx_test.py --tlab build/bin/tlab --experiment tests/study/data/serve_tiny.toml
"""
import argparse
import http.client
import json
import os
import re
import shutil
import signal
import socket
import ssl
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
NGINX = "/usr/sbin/nginx"


def check(condition, message):
    if not condition:
        raise AssertionError(message)


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def wait_for_port(port, process, what):
    deadline = time.monotonic() + 60
    while time.monotonic() < deadline:
        check(process.poll() is None, f"{what} ended early with status {process.returncode}")
        try:
            socket.create_connection(("127.0.0.1", port), timeout=1).close()
            return
        except OSError:
            time.sleep(0.1)
    raise AssertionError(f"{what} did not listen on {port} within 60 s")


def start_serve(tlab, experiment, work):
    process = subprocess.Popen([tlab, "serve", experiment, "--db", str(work / "study.db"), "--listen", "127.0.0.1:0", "--quiet"],
                               stdout=subprocess.PIPE, stderr=open(work / "serve.log", "wb"), text=True)
    for line in process.stdout:  # ends when tlab serve does
        m = re.match(r"participants: http://127\.0\.0\.1:(\d+)/s/([^?]+)\?(\w+)=", line)
        if m:
            return process, int(m.group(1)), m.group(2), m.group(3)
    raise AssertionError(f"tlab serve printed no link (status {process.wait()}; log {work / 'serve.log'})")


def replace_once(text, old, new):
    check(text.count(old) == 1, f"docs/nginx-tlab.conf: expected '{old}' once, found it {text.count(old)} times")
    return text.replace(old, new)


def nginx_config(example, work, serve_port, http_port, https_port):
    site = example.read_text()
    site = replace_once(site, "server 127.0.0.1:8080;", f"server 127.0.0.1:{serve_port};")
    site = replace_once(site, "listen 80;", f"listen 127.0.0.1:{http_port};")
    site = replace_once(site, "listen 443 ssl;", f"listen 127.0.0.1:{https_port} ssl;")
    site = replace_once(site, "/etc/letsencrypt/live/study.example.org/fullchain.pem", str(work / "cert.pem"))
    site = replace_once(site, "/etc/letsencrypt/live/study.example.org/privkey.pem", str(work / "key.pem"))
    temp = "\n".join(f"    {kind}_temp_path {work / kind};" for kind in ("client_body", "proxy", "fastcgi", "uwsgi", "scgi"))
    # One process in the foreground (no user switch, whoever runs the test); the site as shipped.
    return (f"daemon off;\nmaster_process off;\npid {work / 'nginx.pid'};\nerror_log {work / 'nginx-error.log'};\n"
            f"events {{ worker_connections 64; }}\nhttp {{\n    access_log off;\n{temp}\n{site}\n}}\n")


def https(port, cafile):
    context = ssl.create_default_context(cafile=str(cafile))  # verified against the certificate made here
    return http.client.HTTPSConnection("127.0.0.1", port, timeout=30, context=context)


def session_through_proxy(port, cafile, study, parameter):
    c = https(port, cafile)
    c.request("GET", f"/s/{study}?{parameter}=via-proxy")
    r = c.getresponse()
    r.read()
    check(r.status == 303 and r.getheader("Location", "").startswith("/p/"), f"the arrival over HTTPS: {r.status} {r.getheaders()}")
    token = r.getheader("Location")[3:]
    c.request("GET", "/p/" + token)
    r = c.getresponse()
    page = r.read().decode()
    check(r.status == 200 and "participant.js" in page, f"the participant page over HTTPS: {r.status}")
    check(r.getheader("Strict-Transport-Security", "").startswith("max-age="), "no HSTS header from the proxy")
    check(r.getheader("X-Frame-Options") == "DENY", "tlab serve's own headers do not come through")
    display = json.dumps({"screen_width": 1920, "screen_height": 1080, "device_pixel_ratio": 1, "refresh_hz": 60})
    c.request("POST", f"/api/{token}/display", body=display, headers={"Content-Type": "application/json"})
    r = c.getresponse()
    screen = json.loads(r.read())
    check(r.status == 200 and screen.get("kind") == "message", f"the first screen through the proxy: {r.status} {screen}")
    c.request("POST", f"/api/{token}/reply", body=json.dumps({"seq": screen["seq"], "type": "continue"}), headers={"Content-Type": "application/json"})
    r = c.getresponse()
    after = json.loads(r.read())
    check(r.status == 200 and after.get("kind") == "consent", f"the screen after the welcome: {r.status} {after}")
    c.close()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--tlab", default=str(HERE.parents[1] / "build" / "bin" / "tlab"))
    parser.add_argument("--experiment", default=str(HERE / "data" / "serve_tiny.toml"))
    parser.add_argument("--example", default=str(HERE.parents[1] / "docs" / "nginx-tlab.conf"))
    args = parser.parse_args()
    if not os.access(NGINX, os.X_OK):
        print(f"FAIL: {NGINX} is missing: install Debian's nginx (scripts/setup.sh)", file=sys.stderr)
        return 1
    work = Path(tempfile.mkdtemp(prefix="tlab-nginx-"))
    serve = nginx = None
    try:
        made = subprocess.run(["openssl", "req", "-x509", "-newkey", "rsa:2048", "-nodes", "-days", "1", "-subj", "/CN=127.0.0.1",
                               "-addext", "subjectAltName=IP:127.0.0.1", "-keyout", str(work / "key.pem"), "-out", str(work / "cert.pem")],
                              capture_output=True, text=True, timeout=60)
        check(made.returncode == 0, f"openssl could not make a certificate: {made.stderr}")
        serve, serve_port, study, parameter = start_serve(args.tlab, args.experiment, work)
        http_port, https_port = free_port(), free_port()
        (work / "nginx.conf").write_text(nginx_config(Path(args.example), work, serve_port, http_port, https_port))
        tested = subprocess.run([NGINX, "-t", "-p", str(work), "-c", str(work / "nginx.conf"), "-e", str(work / "nginx-error.log")],
                                capture_output=True, text=True, timeout=60)
        check(tested.returncode == 0, f"nginx -t refuses the example: {tested.stderr}")
        nginx = subprocess.Popen([NGINX, "-p", str(work), "-c", str(work / "nginx.conf"), "-e", str(work / "nginx-error.log")],
                                 stderr=subprocess.DEVNULL)
        wait_for_port(https_port, nginx, "nginx")
        plain = http.client.HTTPConnection("127.0.0.1", http_port, timeout=30)
        plain.request("GET", f"/s/{study}?{parameter}=x")
        r = plain.getresponse()
        r.read()
        check(r.status == 301 and r.getheader("Location", "").startswith("https://"), f"plain HTTP: {r.status} {r.getheader('Location')}")
        session_through_proxy(https_port, work / "cert.pem", study, parameter)
        serve.send_signal(signal.SIGTERM)
        check(serve.wait(timeout=60) == 0, "tlab serve did not stop cleanly")
        print("PASS: a session started over HTTPS through nginx with docs/nginx-tlab.conf")
        shutil.rmtree(work, ignore_errors=True)
        return 0
    except AssertionError as error:
        print(f"FAIL: {error} (files in {work})", file=sys.stderr)
        return 1
    finally:
        for process in (nginx, serve):
            if process and process.poll() is None:
                process.kill()
                process.wait()
    # the files stay for a look after a failure (the message names the folder)


if __name__ == "__main__":
    sys.exit(main())
