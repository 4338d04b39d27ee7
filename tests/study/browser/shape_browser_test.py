#!/usr/bin/env python3
"""The shape tasks in a real browser (headless Chromium driven by Selenium, the harness of
serve_browser_test.py): tests/study/data/shape_online.toml's gauge-figure trial is turned by real
pointer drags on the picture and by arrow keys, and its relative-depth trial is answered by a click.
Each trial first gets a reply the server refuses (the page must then take the corrected answer). The
stored answer must be the direction the page showed: it is recomputed here from the question's
frame (its "directions") and the slant and tilt the page displayed when Done was pressed.

    tests/study/browser/shape_browser_test.py --tlab build/bin/tlab
"""
import json
import math
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import serve_browser_test as base  # noqa: E402
from serve_browser_test import ActionChains, Keys, check  # noqa: E402

base.EXPERIMENT_ID = "shape-online"


def gauge_state(p):
    stage = p.find("#stage")
    return float(stage.get_attribute("data-slant")), float(stage.get_attribute("data-tilt"))


def turn_gauge(p):
    """Drags from the gauge's centre outwards, right and up: the stick follows the pointer (tilt
    between 0 and 90, slant grows with the distance); then the arrow keys turn it further."""
    widget = p.driver.execute_script("return current.widget.gauge;")
    img = p.find("#stage img")
    scale = img.size["width"] / p.driver.execute_script("return current.image.width;")
    start = gauge_state(p)
    check(abs(start[0] - widget["start"][0]) < 1e-3 and abs(start[1] - widget["start"][1]) < 1e-3,
          f"the gauge starts at {start}, the question's logged start is {widget['start']}")
    centre = (widget["x"] * scale - img.size["width"] / 2, widget["y"] * scale - img.size["height"] / 2)
    reach = widget["radius"] * scale * 0.5  # half the radius: slant 30°
    actions = ActionChains(p.driver).move_to_element_with_offset(img, int(centre[0]), int(centre[1])).click_and_hold()
    for step in range(1, 6):
        actions.move_to_element_with_offset(img, int(centre[0] + reach * step / 5), int(centre[1] - reach * step / 5))
    actions.release().perform()
    slant, tilt = gauge_state(p)
    check(20 < slant < 55 and 30 < tilt < 60, f"after dragging up and right the gauge is at slant {slant}, tilt {tilt}")
    p.screenshot("trial-gauge-dragged")
    ActionChains(p.driver).send_keys(Keys.ARROW_UP, Keys.ARROW_UP, Keys.ARROW_LEFT).perform()
    after = gauge_state(p)
    check(abs(after[0] - (slant + 4)) < 1e-6 and abs(after[1] - (tilt + 5) % 360) < 1e-6, f"the arrow keys turned the gauge from {(slant, tilt)} to {after}")
    return after


def walk(p, server):
    shown = {}

    def answer(seq):
        widget = p.driver.execute_script("return current.widget.kind;")
        p.screenshot(f"trial-{widget}")
        if widget == "gauge":
            hint = p.find("#hint").text
            check("Drag" in hint and "Done" in hint, f"the gauge hint: {hint!r}")
            base.corrupt_next_answer(p, {"slant": 120, "tilt": 0})  # a slant no gauge has: refused
            p.find("#submit").click()
            error = p.until(lambda: [e for e in p.finds("#screen .error") if e.text], "the refused gauge answer's message")[0]
            reason = error.get_attribute("title") or ""
            check(error.text and "slant" in reason, f"the refusal says {error.text!r}, its reason {reason!r}")
            check(p.state()["seq"] == seq, "the gauge trial was left after a refused answer")
            shown["gauge"] = turn_gauge(p)
            p.find("#submit").click()
        elif widget == "pick-label":
            base.corrupt_next_answer(p, "ZZ")
            p.press_at(p.finds("#stage .hit")[0])
            p.until(lambda: [e for e in p.finds("#screen .error") if e.text], "the refused label's message")
            hits = p.finds("#stage .hit")
            check(sorted(h.get_attribute("data-label") for h in hits) == ["A", "B"], "relative depth offers A and B")
            shown["depth"] = hits[1].get_attribute("data-label")
            p.press_at(hits[1])
        else:
            raise AssertionError(f"a widget the test does not know: {widget}")

    base.walk_trials(p, server, answer)
    return shown


def check_stored(tlab, db, folder, shown):
    result = subprocess.run([tlab, "export", db, "--csv", str(folder)], capture_output=True, text=True, timeout=120)
    check(result.returncode == 0, f"tlab export failed: {result.stderr}")
    trials = base.read_csv(folder, "trials.csv")
    check(len(trials) == 2, f"{len(trials)} trial rows")
    by_task = {t["task"]: t for t in trials}
    gauge = by_task["gauge-figure"]
    question = json.loads(gauge["question"]) if gauge["question"].startswith("{") else None
    check(gauge["answer_kind"] == "direction" and gauge["answered"] == "1", f"the gauge trial: {gauge}")
    stored = [float(v) for v in gauge["raw_answer"].split(",")]
    truth = json.loads(gauge["truth"])
    error = math.degrees(math.acos(max(-1.0, min(1.0, sum(a * b for a, b in zip(stored, truth))))))
    check(abs(float(gauge["error"]) - error) < 1e-3, f"the stored error {gauge['error']} is not the angle {error} between {stored} and {truth}")
    if question:  # the question's frame: the direction the page showed
        d = question["directions"]
        s, t = (math.radians(v) for v in shown["gauge"])
        expected = [math.sin(s) * math.cos(t) * u + math.sin(s) * math.sin(t) * v + math.cos(s) * w
                    for u, v, w in zip(d["right"], d["up"], d["toward-eye"])]
        check(all(abs(a - b) < 2e-6 for a, b in zip(stored, expected)), f"stored {stored}, the page showed {expected}")
    depth = by_task["relative-depth"]
    check(depth["raw_answer"] == shown["depth"] and depth["correct"] == ("1" if depth["truth"] == json.dumps(shown["depth"]) else "0"),
          f"the depth trial: {depth}")
    events = base.read_csv(folder, "events.csv")
    refused = [e for e in events if e["kind"] == "refused-reply"]
    check(len(refused) == 2, f"{len(refused)} refused replies, expected one per trial")


def session(args, p, server, db, work):
    shown = walk(p, server)
    print(f"answered: {shown}")
    server.stop()
    check_stored(args.tlab, db, work / "csv", shown)


def main():
    args = base.parse_arguments(__doc__.split("\n")[0], "shape_online.toml")
    return base.run_in_browser(args, lambda p, server, db, work: session(args, p, server, db, work))


if __name__ == "__main__":
    sys.exit(main())
