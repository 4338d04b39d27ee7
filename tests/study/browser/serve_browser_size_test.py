#!/usr/bin/env python3
"""Stimuli at a known size, on every display, in headless Chromium (tests/study/data/online_size.toml,
[online] stimulus_size = "native"): the same 160-px picture at device scale factor 1 and 2 is shown
in whole device pixels and never below its CSS size (1x: 160 CSS = 160 device px; 2x: 160 CSS = 320
device px, where the page used to show 80 CSS px), the shown size is stored with each onset, and a
phone (Chromium's mobile emulation: 390 x 844 CSS px, 3x, touch) is refused with a page that says
why, nothing stored. Each browser answers its trial by typing; the sizes are printed.

    tests/study/browser/serve_browser_size_test.py --tlab build/bin/tlab
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import serve_browser_test as base  # noqa: E402
from serve_browser_test import By, check, webdriver, Service  # noqa: E402

base.EXPERIMENT_ID = "online-size"
PICTURE = 160
PHONE = {"deviceMetrics": {"width": 390, "height": 844, "pixelRatio": 3.0, "touch": True},
         "userAgent": "Mozilla/5.0 (Linux; Android 13; Pixel 7) AppleWebKit/537.36 (KHTML, like Gecko) Chrome/120.0 Mobile Safari/537.36"}


def browser(profile, scale=None, mobile=None):
    options = webdriver.ChromeOptions()
    options.binary_location = base.CHROMIUM
    for argument in ("--headless=new", f"--window-size={base.WINDOW[0]},{base.WINDOW[1]}", f"--user-data-dir={profile}", "--no-first-run",
                     "--disable-dev-shm-usage", "--disable-extensions", "--hide-scrollbars", "--lang=en-US"):
        options.add_argument(argument)
    if scale:
        options.add_argument(f"--force-device-scale-factor={scale}")
    if mobile:
        options.add_experimental_option("mobileEmulation", mobile)
    if os.geteuid() == 0:
        options.add_argument("--no-sandbox")
    return webdriver.Chrome(service=Service(base.CHROMEDRIVER), options=options)


def measure(p):
    return p.driver.execute_script(
        "const i = document.querySelector('#stage img'); const r = i.getBoundingClientRect();"
        "return {css: r.width, css_h: r.height, dpr: devicePixelRatio, device: r.width * devicePixelRatio, natural: i.naturalWidth,"
        " rendering: getComputedStyle(i).imageRendering};")


def first_trial(p, server, participant):
    """Arrives, continues past the instructions and waits for the trial's picture; returns the trial screen."""
    p.driver.get(server.link(participant))
    s = p.next_screen(-1)
    check(s["kind"] == "message", f"{participant}: the instructions expected, got {s}")
    p.find("#continue").click()
    s = p.next_screen(s["seq"])
    check(s["kind"] == "trial", f"{participant}: the trial expected, got {s}")
    p.trial_ready()
    return s


def desktop_trial(p, server, participant, scale, shots):
    s = first_trial(p, server, participant)
    m = measure(p)
    print(f"{scale}x: the {m['natural']}-px picture is {m['css']} x {m['css_h']} CSS px = {m['device']} device px at devicePixelRatio {m['dpr']}"
          f" (image-rendering {m['rendering']})")
    check(m["dpr"] == scale, f"devicePixelRatio {m['dpr']}, expected {scale}")
    check(m["css"] == PICTURE and m["device"] == PICTURE * scale, f"{scale}x: the picture is {m['css']} CSS px, {m['device']} device px")
    check(m["rendering"] == "pixelated", f"{scale}x: whole device pixels are drawn {m['rendering']}")
    p.screenshot(f"trial-{scale}x")
    p.type_number(1)
    s = p.next_screen(s["seq"])
    check(s["kind"] == "end", f"{participant}: the end expected, got {s}")
    return m


def phone_refused(server, shots):
    profile = Path(tempfile.mkdtemp(prefix="tlab-phone-"))
    driver = browser(profile, mobile=PHONE)
    try:
        p = base.Participant(driver, shots)
        p.count = 10
        driver.get(server.link("phone-1"))
        s = p.next_screen(-1)
        text = p.find("#screen").text
        check(s["kind"] == "end" and "cannot be done on a phone" in text and "desktop or laptop" in text, f"the phone's page: {s}, {text!r}")
        m = driver.execute_script("return {w: innerWidth, dpr: devicePixelRatio, touch: navigator.maxTouchPoints};")
        print(f"phone: {m['w']} CSS px wide at devicePixelRatio {m['dpr']}, {m['touch']} touch points: refused")
        p.screenshot("phone-refused")
    finally:
        driver.quit()
        shutil.rmtree(profile, ignore_errors=True)


def sizes(args, p, server, db, work):
    shots = p.shots
    desktop_trial(p, server, "desktop-1x", 1, shots)
    profile = Path(tempfile.mkdtemp(prefix="tlab-2x-"))
    driver = browser(profile, scale=2)
    try:
        q = base.Participant(driver, shots)
        q.count = 5
        desktop_trial(q, server, "desktop-2x", 2, shots)
    finally:
        driver.quit()
        shutil.rmtree(profile, ignore_errors=True)
    phone_refused(server, shots)
    server.stop()
    result = subprocess.run([args.tlab, "export", db, "--csv", str(work / "csv")], capture_output=True, text=True, timeout=120)
    check(result.returncode == 0, f"tlab export failed: {result.stderr}")
    participants = sorted(r["participant"] for r in base.read_csv(work / "csv", "participants.csv"))
    check(participants == ["desktop-1x", "desktop-2x"], f"the phone was stored: {participants}")
    onsets = {e["participant"]: json.loads(e["detail"])["shown"] for e in base.read_csv(work / "csv", "events.csv") if e["kind"] == "onset"}
    displays = {s["participant"]: json.loads(s["display"])["browser"] for s in base.read_csv(work / "csv", "sessions.csv")}
    for who, scale in (("desktop-1x", 1), ("desktop-2x", 2)):
        d = displays[who]
        check(d["stimulus_size"] == "native" and d["stimulus_css_width"] == PICTURE and d["stimulus_device_width"] == PICTURE * scale,
              f"{who}: the session's display JSON {d}")
        shown = onsets[who]
        check(shown["mode"] == "native" and shown["css_width"] == PICTURE and shown["device_width"] == PICTURE * scale
              and shown["device_pixel_ratio"] == scale and "cm_width" not in shown, f"{who}: the stored shown size {shown}")


def main():
    args = base.parse_arguments(__doc__.split("\n")[0], "online_size.toml")
    return base.run_in_browser(args, lambda p, server, db, work: sizes(args, p, server, db, work))


if __name__ == "__main__":
    sys.exit(main())
