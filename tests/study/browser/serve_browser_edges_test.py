#!/usr/bin/env python3
"""The edges of an online session in headless Chromium (tests/study/data/online_edges.toml):

* the credit-card size calibration ("virtual chinrest"): the slider is moved until the card is
  as wide as it should be, and the session's display JSON stores the pixels per centimetre;
* a participant who declines consent: the page says so and only the decision is stored;
* a trial whose time limit runs out in the browser: the countdown reaches 0, the page says "Time is
  up", the next screen comes by itself, and the trial is stored as missing ("time limit reached in the browser").

Uses the browser, server and participant helpers of serve_browser_test.py.

    tests/study/browser/serve_browser_edges_test.py --tlab build/bin/tlab
"""
import json
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import serve_browser_test as base  # noqa: E402
from serve_browser_test import By, check  # noqa: E402

base.EXPERIMENT_ID = "online-edges"
CARD_CSS_PX = 400  # where the test puts the slider: 400 CSS px for 8.56 cm


def calibrate(p, name):
    slider = p.until(lambda: p.finds("#card-size"), "the size calibration screen")[0]
    p.driver.execute_script(f"arguments[0].value = '{CARD_CSS_PX}'; arguments[0].dispatchEvent(new Event('input'));", slider)
    width = p.driver.execute_script("return document.getElementById('card').getBoundingClientRect().width;")
    check(abs(width - CARD_CSS_PX) < 0.5, f"the card is {width} px wide after the slider moved to {CARD_CSS_PX}")
    p.screenshot(name)
    p.find("#calibrated").click()


def arrive(p, server, participant):
    p.driver.get(server.base + "/")
    p.driver.execute_script("sessionStorage.clear();")  # a new participant calibrates anew
    p.driver.get(server.link(participant))


def decline(p, server):
    arrive(p, server, "decliner")
    calibrate(p, "calibration")
    s = p.next_screen(0)
    check(s["kind"] == "message", f"welcome expected, got {s}")
    p.find("#continue").click()
    s = p.next_screen(s["seq"])
    check(s["kind"] == "consent", f"consent expected, got {s}")
    p.screenshot("consent")
    p.find("#decline").click()
    s = p.next_screen(s["seq"])
    if s["kind"] == "message":  # "You chose not to take part ..."
        p.find("#continue").click()
        s = p.next_screen(s["seq"])
    check(s["kind"] == "end", f"the end page expected after declining, got {s}")
    body = p.driver.find_element(By.TAG_NAME, "body").text
    check("not to take part" in body, f"the end page after declining says: {body!r}")
    p.screenshot("declined")


def time_out_then_answer(p, server):
    arrive(p, server, "slow")
    calibrate(p, "calibration-2")
    seq = 0
    while True:
        s = p.next_screen(seq)
        seq = s["seq"]
        if s["kind"] == "trial":
            break
        p.find("#accept" if s["kind"] == "consent" else "#continue").click()
    p.trial_ready()
    p.screenshot("trial-before-time-out")
    # Nobody answers: the countdown runs out, the page says "Time is up" on the trial, and sends the
    # time-out itself. What the page showed is recorded as it changes (no sampling that could miss it).
    p.driver.execute_script(
        "window.timeUpOn = []; const m = document.getElementById('screen');"
        "new MutationObserver(() => { const t = document.getElementById('time-up');"
        " if (t && !timeUpOn.includes(m.dataset.seq)) timeUpOn.push(m.dataset.seq, t.textContent); })"
        ".observe(m, {childList: true, subtree: true});")
    s = p.next_screen(seq)
    check(s["kind"] == "trial", f"the second trial expected after the time-out, got {s}")
    shown = p.driver.execute_script("return window.timeUpOn;")
    check(shown == [str(seq), "Time is up"], f"'Time is up' on the timed-out trial before the next screen: {shown}")
    p.trial_ready()
    p.type_number(1)
    s = p.next_screen(s["seq"])
    check(s["kind"] == "end", f"the end page expected, got {s}")


def check_database(tlab, db, folder):
    import subprocess
    result = subprocess.run([tlab, "export", db, "--csv", str(folder)], capture_output=True, text=True, timeout=120)
    check(result.returncode == 0, f"tlab export failed: {result.stderr}")
    consent = {r["participant"]: r["decision"] for r in base.read_csv(folder, "consent.csv")}
    check(consent == {"decliner": "declined", "slow": "accepted"}, f"consent decisions: {consent}")
    participants = [r["participant"] for r in base.read_csv(folder, "participants.csv")]
    check(participants == ["slow"], f"only the participant who agreed has a slot: {participants}")
    trials = [t for t in base.read_csv(folder, "trials.csv") if t["participant"] == "slow"]
    check(len(trials) == 2, f"{len(trials)} trials of the slow participant")
    first, second = trials
    check(first["responded"] == "1" and first["answered"] == "0" and first["raw_answer"] == "", f"the timed-out trial: {first}")
    check("time limit" in first["note"], f"the timed-out trial's note: {first['note']!r}")
    check(second["answered"] == "1" and second["raw_answer"] == "1", f"the answered trial: {second}")
    sessions = [s for s in base.read_csv(folder, "sessions.csv") if s["participant"] == "slow"]
    browser = json.loads(sessions[0]["display"])["browser"]
    expected = CARD_CSS_PX * browser["device_pixel_ratio"] / 8.56
    check(abs(browser["px_per_cm"] - expected) < 0.01, f"px_per_cm {browser.get('px_per_cm')} (expected {expected:.3f})")


def edges(tlab, p, server, db, work):
    decline(p, server)
    time_out_then_answer(p, server)
    server.stop()
    check_database(tlab, db, work / "csv")


def main():
    args = base.parse_arguments(__doc__.split("\n")[0], "online_edges.toml")
    return base.run_in_browser(args, lambda p, server, db, work: edges(args.tlab, p, server, db, work))


if __name__ == "__main__":
    sys.exit(main())
