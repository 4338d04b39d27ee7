#!/usr/bin/env python3
"""The edges of an online session in headless Chromium (tests/study/data/online_edges.toml):

* the credit-card size calibration ("virtual chinrest") after consent: "Done" before any change
  is refused on the page; the rectangle is then sized by the arrow keys and the − and + buttons,
  the calibration event stores the pixels per centimetre and the number of adjustments, a new tab
  of the same participant is not asked again (the server keeps the value), nor after a restart of
  the server (the value is read back from the store: one calibration event), and the trial's picture
  is 5 cm wide by that calibration ([online] stimulus_size = "5cm"); another participant says "I
  have no card" (stored as skipped);
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
from serve_browser_test import ActionChains, By, Keys, check  # noqa: E402

base.EXPERIMENT_ID = "online-edges"
CARD_START = 320  # the rectangle's width in CSS px before any adjustment
ADJUSTED = CARD_START + 4 * 0.25 + 2 * 0.25 - 0.25  # four arrow keys, + twice, − once
CM = 5  # [online] stimulus_size of online_edges.toml


def calibrate(p, name):
    """Sizes the card with real key presses and clicks after a refused "Done"; returns the page's width."""
    p.until(lambda: p.state()["kind"] == "calibration", "the size calibration screen after consent")
    slider = p.find("#card-size")
    check(slider.size["width"] >= 600, f"the slider is {slider.size['width']} CSS px wide")
    p.find("#calibrated").click()
    error = p.until(lambda: [e for e in p.finds("#screen .error") if e.text], "the refusal of an unadjusted card")[0]
    check("not been changed" in error.text, f"Done without any change says: {error.text!r}")
    p.screenshot(name + "-not-moved")
    for _ in range(4):
        ActionChains(p.driver).send_keys(Keys.ARROW_RIGHT).perform()
    p.find("#card-larger").click()
    p.find("#card-larger").click()
    p.find("#card-smaller").click()
    p.until(lambda: abs(float(slider.get_attribute("value")) - ADJUSTED) < 1e-9, f"the card at {ADJUSTED} CSS px")
    width = p.driver.execute_script("return document.getElementById('card').getBoundingClientRect().width;")
    check(abs(width - ADJUSTED) < 0.01, f"the card is {width} px wide, the slider says {ADJUSTED}")
    p.screenshot(name)
    seq = p.state()["seq"]
    p.find("#calibrated").click()
    return p.next_screen(seq)


def arrive(p, server, participant):
    p.driver.get(server.link(participant))


def to_consent(p, server, participant):
    arrive(p, server, participant)
    s = p.next_screen(-1)
    check(s["kind"] == "message", f"welcome expected, got {s}")
    p.find("#continue").click()
    s = p.next_screen(s["seq"])
    check(s["kind"] == "consent", f"consent expected, got {s}")
    return s


def decline(p, server):
    to_consent(p, server, "decliner")
    p.screenshot("consent")
    seq = p.state()["seq"]
    p.find("#decline").click()
    s = p.next_screen(seq)
    if s["kind"] == "message":  # "You chose not to take part ..."
        p.find("#continue").click()
        s = p.next_screen(s["seq"])
    check(s["kind"] == "end", f"the end page expected after declining (no calibration), got {s}")
    body = p.driver.find_element(By.TAG_NAME, "body").text
    check("not to take part" in body, f"the end page after declining says: {body!r}")
    p.screenshot("declined")


def time_out_then_answer(p, server, restart):
    s = to_consent(p, server, "slow")
    p.find("#accept").click()
    s = calibrate(p, "calibration")
    check(s["kind"] == "message", f"the instructions expected after the calibration, got {s}")
    # The same participant in a new tab: the server knows the calibration, nothing is asked again.
    p.driver.switch_to.new_window("tab")
    arrive(p, server, "slow")
    s = p.next_screen(-1)
    check(s["kind"] == "message", f"a new tab of a calibrated participant shows {s}, not the instructions")
    # The server restarts (another port): the participant comes back and is not asked again either.
    server = restart(server)
    p.driver.switch_to.new_window("tab")
    arrive(p, server, "slow")
    s = p.next_screen(-1)
    check(s["kind"] == "message", f"after a server restart a calibrated participant sees {s}, not the welcome back")
    p.screenshot("after-restart-welcome-back")
    p.find("#continue").click()
    s = p.next_screen(s["seq"])
    check(s["kind"] == "message", f"after the welcome back the instructions, not the calibration: {s}")
    p.screenshot("after-restart-no-calibration")
    p.find("#continue").click()
    s = p.next_screen(s["seq"])
    seq = s["seq"]
    check(s["kind"] == "trial", f"the trial expected, got {s}")
    p.trial_ready()
    shown = p.driver.execute_script(
        "const r = document.querySelector('#stage img').getBoundingClientRect(); return {w: r.width, dpr: devicePixelRatio};")
    expected = CM * ADJUSTED / 8.56  # CSS px: 5 cm by the card's CSS px per 8.56 cm
    check(abs(shown["w"] - expected) < 0.01, f"the picture is {shown['w']} CSS px wide, {CM} cm are {expected:.3f}")
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
    return server


def no_card(p, server):
    s = to_consent(p, server, "nocard")
    p.find("#accept").click()
    p.until(lambda: p.state()["kind"] == "calibration", "the size calibration screen")
    p.screenshot("calibration-no-card-offered")
    seq = p.state()["seq"]  # read before the click: the next screen may come before a later read
    p.find("#no-card").click()
    s = p.next_screen(seq)
    check(s["kind"] == "message", f"the instructions expected after 'I have no card', got {s}")


def check_database(tlab, db, folder):
    import subprocess
    result = subprocess.run([tlab, "export", db, "--csv", str(folder)], capture_output=True, text=True, timeout=120)
    check(result.returncode == 0, f"tlab export failed: {result.stderr}")
    consent = {r["participant"]: r["decision"] for r in base.read_csv(folder, "consent.csv")}
    check(consent == {"decliner": "declined", "slow": "accepted", "nocard": "accepted"}, f"consent decisions: {consent}")
    participants = sorted(r["participant"] for r in base.read_csv(folder, "participants.csv"))
    check(participants == ["nocard", "slow"], f"only the participants who agreed have a slot: {participants}")
    trials = [t for t in base.read_csv(folder, "trials.csv") if t["participant"] == "slow"]
    check(len(trials) == 2, f"{len(trials)} trials of the slow participant")
    first, second = trials
    check(first["responded"] == "1" and first["answered"] == "0" and first["raw_answer"] == "", f"the timed-out trial: {first}")
    check("time limit" in first["note"], f"the timed-out trial's note: {first['note']!r}")
    check(second["answered"] == "1" and second["raw_answer"] == "1", f"the answered trial: {second}")
    events = base.read_csv(folder, "events.csv")
    calibrations = {e["participant"]: json.loads(e["detail"]) for e in events if e["kind"] == "calibration"}
    slow_calibrations = [e for e in events if e["kind"] == "calibration" and e["participant"] == "slow"]
    check(len(slow_calibrations) == 1, f"one calibration of the slow participant over the restart: {slow_calibrations}")
    check(set(calibrations) == {"slow", "nocard"}, f"calibration events: {calibrations}")
    slow = calibrations["slow"]
    check(slow["skipped"] is False and slow["adjustments"] == 7 and abs(slow["card_css_px"] - ADJUSTED) < 1e-9
          and abs(slow["px_per_cm"] - ADJUSTED * slow["device_pixel_ratio"] / 8.56) < 1e-9, f"the calibration stored: {slow}")
    check(calibrations["nocard"] == {"skipped": True, "px_per_cm": None, "adjustments": 0}, f"'I have no card' stored: {calibrations['nocard']}")
    onsets = [json.loads(e["detail"]) for e in events if e["kind"] == "onset" and e["participant"] == "slow"]
    check(onsets and all(o["shown"]["mode"] == "cm" and abs(o["shown"]["cm_width"] - CM) < 1e-6 for o in onsets), f"the onsets' shown sizes: {onsets}")


def edges(tlab, experiment, p, server, db, work):
    decline(p, server)
    restarted = []

    def restart(old):
        old.stop()
        restarted.append(base.Server(tlab, experiment, db, work / "serve.log"))
        return restarted[-1]
    try:
        server = time_out_then_answer(p, server, restart)
        no_card(p, server)
        server.stop()
    finally:
        for s in restarted:
            s.kill()
    check_database(tlab, db, work / "csv")


def main():
    args = base.parse_arguments(__doc__.split("\n")[0], "online_edges.toml")
    return base.run_in_browser(args, lambda p, server, db, work: edges(args.tlab, args.experiment, p, server, db, work))


if __name__ == "__main__":
    sys.exit(main())
