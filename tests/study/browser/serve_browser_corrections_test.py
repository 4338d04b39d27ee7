#!/usr/bin/env python3
"""Refused answers corrected the other ways a participant corrects them (tests/study/data/online.toml
in headless Chromium, the harness of serve_browser_test.py, which corrects each refusal by typing
or clicking the way it first answered). Here, trial by trial:

- training (layer number): 0 refused by the server, then 1 typed and the Submit button clicked;
- layer number: Enter on the empty box (the page's own refusal: nothing is sent), then 0 (the
  server's refusal), then the page reloaded, and 2 typed into the trial that comes back;
- count: 1000001 refused, then 3 typed over it and Enter pressed twice (one answer is sent);
- label: a refused click on a hit box, then the label's button below the picture;
- label set: two labels chosen and Done refused, then Done again with the choice the page kept;
- floor point: a refused click, then a click on the plan;
- letter: a refused key press, then the corrected letter typed on the keyboard.

Every corrected answer must be the one stored, each trial answered once; the server's refusals
are kept as refused-reply events (7), the page's own refusal is never sent.

    tests/study/browser/serve_browser_corrections_test.py --tlab build/bin/tlab
"""
import json
import re
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import serve_browser_test as base  # noqa: E402
from serve_browser_test import ActionChains, Keys, check  # noqa: E402


def error_texts(p):
    """The texts of the refusal messages on show, read in the page at once (a message the page
    replaces while Selenium reads it would be a stale element)."""
    return p.driver.execute_script("return Array.from(document.querySelectorAll('#screen .error'), (e) => e.textContent);")


def refusal_shown(p, what, containing=""):
    """Waits for the page's message of a refusal (containing a given text) and checks the trial stays."""
    seq = p.state()["seq"]
    text = p.until(lambda: [t for t in error_texts(p) if t and containing in t], what)[0]
    check(p.state()["seq"] == seq and p.state()["kind"] == "trial", f"{what}: the trial was left")
    return text


def correct_training(p):
    p.type_number(0)
    refusal_shown(p, "training: the refusal of 0")
    p.find("#answer").send_keys("1")  # typed over the refused 0, which the page selected
    p.find("#submit").click()
    return "1"


def correct_layer_number(p, seq):
    base.record_replies(p)
    p.type_number("")  # Enter on the empty box: the page refuses it itself
    text = refusal_shown(p, "the page's own refusal of an empty answer")
    check("whole number" in text, f"the page's refusal of an empty answer says: {text!r}")
    check(len(base.sent_replies(p, "answer")) == 0, "the page sent an empty answer to the server")
    p.type_number(0, select_all=True)
    refusal_shown(p, "the server's refusal of 0", "1")
    p.screenshot("layer-number-refused")
    p.driver.refresh()  # the refused answer is not an answer: the same trial comes back
    again = p.next_screen(-1)
    check(again["seq"] == seq and again["kind"] == "trial", f"after the reload: {again}, expected trial screen {seq}")
    p.trial_ready()
    check(not [t for t in error_texts(p) if t], "the refusal's message is still shown after the reload")
    p.type_number(2, select_all=True)
    return "2"


def correct_count(p):
    p.type_number(1000001)
    refusal_shown(p, "count: the refusal of 1000001")
    base.record_replies(p)
    box = p.find("#answer")
    box.send_keys(Keys.CONTROL, "a")
    box.send_keys("3", Keys.ENTER, Keys.ENTER)  # a double Enter sends one answer
    p.until(lambda: p.state()["kind"] != "trial", "the count trial to end")
    sent = len(base.sent_replies(p, "answer"))
    check(sent == 1, f"{sent} answers sent for one corrected count")
    return "3"


def correct_label(p):
    base.corrupt_next_answer(p, "ZZ")
    p.press_at(p.finds("#stage .hit")[0])
    refusal_shown(p, "label: the refused click")
    button = p.finds("#screen button.label")[-1]
    label = button.get_attribute("data-label")  # read before the click: the next screen replaces the button
    p.press_at(button)
    return label


def correct_label_set(p):
    hits = p.finds("#stage .hit")
    check(len(hits) >= 2, f"label set: {len(hits)} labels to click")
    for hit in hits[:2]:
        p.press_at(hit)
        p.until(lambda: "selected" in hit.get_attribute("class"), "a clicked label to be marked")
    base.corrupt_next_answer(p, ["ZZ"])
    p.find("#submit").click()
    refusal_shown(p, "label set: the refused Done")
    kept = [h.get_attribute("data-label") for h in p.finds("#stage .hit.selected")]
    chosen = [h.get_attribute("data-label") for h in hits[:2]]
    check(sorted(kept) == sorted(chosen), f"after the refusal the page shows {kept} chosen, the participant chose {chosen}")
    p.find("#submit").click()
    return ",".join(chosen)


def correct_floor_point(p):
    base.corrupt_next_answer(p, {"x": -1, "y": -1})
    p.press_at(p.find("#floor-plan"))
    refusal_shown(p, "floor point: the refused click")
    p.press_at(p.find("#floor-plan"))
    return None  # world coordinates: checked for their form


def correct_letter(p):
    base.corrupt_next_answer(p, "?")
    ActionChains(p.driver).send_keys("c").perform()
    refusal_shown(p, "letter: the refused key")
    ActionChains(p.driver).send_keys("k").perform()
    return "K"


def answer_trial(p, s):
    kind = s["answer"]
    if p.driver.execute_script("return current.phase;") == "training":
        return "training", correct_training(p)
    corrections = {"layer-number": lambda: correct_layer_number(p, s["seq"]), "count": lambda: correct_count(p),
                   "label": lambda: correct_label(p), "label-set": lambda: correct_label_set(p),
                   "floor-point": lambda: correct_floor_point(p), "letter": lambda: correct_letter(p)}
    check(kind in corrections, f"an answer kind the test does not know: {kind}")
    return kind, corrections[kind]()


def walk(p, server):
    """The whole session; returns the corrected answers by answer kind ("training" for the practice)."""
    answers = {}
    p.driver.get(server.link(base.PARTICIPANT))
    p.until(lambda: "/p/" in p.driver.current_url, "the redirect to the session page")
    s = p.next_screen(-1)
    while s["kind"] != "end":
        kind, seq = s["kind"], s["seq"]
        if kind in ("message", "feedback"):
            p.find("#continue").click()
        elif kind == "consent":
            p.find("#accept").click()
        elif kind == "form":
            base.fill_form(p)
            p.find("#submit").click()
        elif kind == "break":
            go = p.find("#continue")
            p.until(go.is_enabled, "the break's Continue button to be enabled")
            go.click()
        elif kind == "trial":
            p.trial_ready()
            key, answer = answer_trial(p, s)
            answers[key] = answer
        else:
            raise AssertionError(f"unexpected screen kind {kind!r}")
        s = p.next_screen(seq)
    return answers


def corrections(args, p, server, db, work):
    answers = walk(p, server)
    check(len(answers) == 7, f"answered {sorted(answers)}, expected the practice and the 6 answer kinds")
    server.stop()
    result = subprocess.run([args.tlab, "export", db, "--csv", str(work / "csv")], capture_output=True, text=True, timeout=120)
    check(result.returncode == 0, f"tlab export failed: {result.stderr}")
    trials = base.read_csv(work / "csv", "trials.csv")
    check(len(trials) == 7, f"{len(trials)} trial rows, expected 7")
    for t in trials:
        what = f"trial {t['sequence']} ({t['phase']}, {t['answer_kind']})"
        check(t["responded"] == "1" and t["answered"] == "1", f"{what}: not answered: {t}")
        expected = answers["training" if t["phase"] == "training" else t["answer_kind"]]
        if expected is None:
            check(re.fullmatch(r"-?\d+\.\d{4},-?\d+\.\d{4}", t["raw_answer"]), f"{what}: raw_answer {t['raw_answer']!r}")
        else:
            check(t["raw_answer"] == expected, f"{what}: stored {t['raw_answer']!r}, the corrected answer was {expected!r}")
        reloaded = t["phase"] == "test" and t["answer_kind"] == "layer-number"
        check(t["showings"] == ("2" if reloaded else "1"), f"{what}: shown {t['showings']} times")
    events = base.read_csv(work / "csv", "events.csv")
    refused = [json.loads(e["detail"]) for e in events if e["kind"] == "refused-reply"]
    check(len(refused) == 7 and all('"answer"' in r["body"] for r in refused),
          f"refused replies (expected the first answer the server saw of each of the 7 trials): {refused}")
    check(not [e for e in events if e["kind"] == "late-answer"], "an answer arrived for a trial that had gone")


def main():
    args = base.parse_arguments(__doc__.split("\n")[0], "online.toml")
    return base.run_in_browser(args, lambda p, server, db, work: corrections(args, p, server, db, work))


if __name__ == "__main__":
    sys.exit(main())
