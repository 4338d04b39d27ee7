#!/usr/bin/env python3
"""A phone the study allows (tests/study/data/online_phone.toml: [online] devices = ["desktop",
"phone"]) in headless Chromium's mobile emulation (390 x 844 CSS px, devicePixelRatio 3, touch):
the phone is not refused, the 160-px picture is shown in whole device pixels at its CSS size (160
CSS px = 480 device px: the page upscales by 3, never below the intended size), a refused answer
(0) is followed by the corrected one typed on the phone (1), and the session, its display (a phone,
touch points) and the shown size are stored. Uses the helpers of serve_browser_size_test.py.

    tests/study/browser/serve_browser_phone_test.py --tlab build/bin/tlab
"""
import json
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import serve_browser_test as base  # noqa: E402
import serve_browser_size_test as size  # noqa: E402
from serve_browser_test import Keys, check  # noqa: E402

base.EXPERIMENT_ID = "online-phone"
SCALE = 3


def phone_session(server, shots):
    profile = Path(tempfile.mkdtemp(prefix="tlab-phone-"))
    driver = size.browser(profile, mobile=size.PHONE)
    try:
        p = base.Participant(driver, shots)
        s = size.first_trial(p, server, "phone-1")  # the instructions, not a refusal
        m = size.measure(p)
        view = driver.execute_script("return {w: innerWidth, touch: navigator.maxTouchPoints};")
        print(f"phone: {view['w']} CSS px wide, {view['touch']} touch points; the {m['natural']}-px picture is {m['css']} CSS px"
              f" = {m['device']} device px at devicePixelRatio {m['dpr']}")
        check(view["w"] == 390 and view["touch"] > 0, f"not the emulated phone: {view}")
        check(m["dpr"] == SCALE and m["css"] == size.PICTURE and m["device"] == size.PICTURE * SCALE,
              f"the picture on the phone: {m}")
        p.screenshot("phone-trial")
        p.type_number(0)
        error = p.until(lambda: [e for e in p.finds("#screen .error") if e.text], "the refused answer's message")[0]
        check("whole number, 1 or more" in error.text, f"the refusal on the phone says: {error.text!r}")
        p.screenshot("phone-refused-answer")
        box = p.find("#answer")
        box.send_keys(Keys.CONTROL, "a")
        box.send_keys("1", Keys.ENTER)
        s = p.next_screen(s["seq"])
        check(s["kind"] == "end", f"the end expected after the corrected answer, got {s}")
        p.screenshot("phone-end")
    finally:
        driver.quit()
        shutil.rmtree(profile, ignore_errors=True)


def phone(args, p, server, db, work):
    phone_session(server, p.shots)
    server.stop()
    result = subprocess.run([args.tlab, "export", db, "--csv", str(work / "csv")], capture_output=True, text=True, timeout=120)
    check(result.returncode == 0, f"tlab export failed: {result.stderr}")
    trials = base.read_csv(work / "csv", "trials.csv")
    check([(t["participant"], t["raw_answer"]) for t in trials] == [("phone-1", "1")], f"the phone's trial: {trials}")
    display = json.loads(base.read_csv(work / "csv", "sessions.csv")[0]["display"])["browser"]
    check(display["device"] == "phone" and display["max_touch_points"] > 0, f"the session's display: {display}")
    shown = [json.loads(e["detail"])["shown"] for e in base.read_csv(work / "csv", "events.csv") if e["kind"] == "onset"]
    check(len(shown) == 1 and shown[0]["css_width"] == size.PICTURE and shown[0]["device_width"] == size.PICTURE * SCALE
          and shown[0]["device_pixel_ratio"] == SCALE, f"the stored shown size: {shown}")


def main():
    args = base.parse_arguments(__doc__.split("\n")[0], "online_phone.toml")
    return base.run_in_browser(args, lambda p, server, db, work: phone(args, p, server, db, work))


if __name__ == "__main__":
    sys.exit(main())
