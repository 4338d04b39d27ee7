#!/usr/bin/env python3
"""A German session in headless Chromium (tests/study/data/online_de.toml: language = "de", one
key overridden in [text]): every screen shows the participant text table's German words, never
the English ones, and the overridden key shows the file's text.

The expected texts are the table `tlab texts` prints for the file (German, with the override);
the English table (`tlab texts FILE --language en`) gives the words that must not appear. The
participant really clicks and types: welcome, consent, the instructions, a refused answer (0) and
the corrected one (1), the debrief with its completion code; the database then holds the
corrected answer (1) and the refused reply. Uses the helpers of serve_browser_test.py.

    tests/study/browser/serve_browser_language_test.py --tlab build/bin/tlab
"""
import subprocess
import sys
import tomllib
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import serve_browser_test as base  # noqa: E402
from serve_browser_test import By, Keys, check  # noqa: E402

base.EXPERIMENT_ID = "online-de"


def table(tlab, experiment, *options):
    """The [text] table `tlab texts` prints, flattened to dotted keys."""
    out = subprocess.run([tlab, "texts", experiment, *options], capture_output=True, text=True, timeout=60, check=True).stdout
    flat = {}

    def walk(t, prefix):
        for key, value in t.items():
            if isinstance(value, dict):
                walk(value, prefix + key + ".")
            else:
                flat[prefix + key] = value
    walk(tomllib.loads(out)["text"], "")
    return flat


def body(p):
    return p.driver.find_element(By.TAG_NAME, "body").text


def no_english(p, de, en, keys, name):
    """None of the English texts of `keys` (where German differs) is on the screen."""
    text = body(p)
    for key in keys:
        if en[key] != de[key]:
            check(en[key] not in text, f"{name}: the English {key} {en[key]!r} is shown: {text!r}")


def german_session(tlab, experiment, p, server):
    de, en = table(tlab, experiment), table(tlab, experiment, "--language", "en")
    check(de["button.continue"] == "Weiter geht's", f"the [text] override in tlab texts: {de['button.continue']!r}")
    check(de["button.submit"] != en["button.submit"], "tlab texts printed English for a German file")
    p.driver.get(server.link("teilnehmer-1"))
    s = p.next_screen(-1)
    check(p.driver.execute_script("return document.documentElement.lang;") == "de", "the page's lang attribute")
    check(s["kind"] == "message" and p.find("#continue").text == "Weiter geht's", f"the welcome's button: {p.find('#continue').text!r}")
    p.screenshot("de-welcome")
    p.find("#continue").click()
    s = p.next_screen(s["seq"])
    check(s["kind"] == "consent", f"consent expected, got {s}")
    check(p.find("#accept").text == de["defaults.consent_accept"] and p.find("#decline").text == de["defaults.consent_decline"],
          f"the consent buttons: {p.find('#accept').text!r}, {p.find('#decline').text!r}")
    p.screenshot("de-consent")
    p.find("#accept").click()
    s = p.next_screen(s["seq"])
    check(s["kind"] == "message" and p.find("#screen h1").text == de["title.instructions"], f"the instructions' title: {p.find('#screen h1').text!r}")
    intro = p.find("#screen p.text").text
    expected = de["intro.trials.one"].replace("{n}", "1")
    check(expected in intro and "5 Minuten" in intro, f"the instructions say: {intro!r}")
    no_english(p, de, en, ["intro.trials.one", "title.instructions"], "instructions")
    p.screenshot("de-instructions")
    p.find("#continue").click()
    s = p.next_screen(s["seq"])
    check(s["kind"] == "trial", f"the trial expected, got {s}")
    p.trial_ready()
    check(p.find("#hint").text == de["answer.layer-number"], f"the hint: {p.find('#hint').text!r}")
    check(p.find("#screen .progress").text == de["trial.progress_test"].replace("{index}", "1").replace("{total}", "1"),
          f"the progress: {p.find('#screen .progress').text!r}")
    check(p.find("#submit").text == de["button.submit"], f"the submit button: {p.find('#submit').text!r}")
    p.type_number(0)  # refused: the page says so in German
    error = p.until(lambda: [e for e in p.finds("#screen .error") if e.text], "the refused answer's message")[0]
    # The task's question and the reason of the refusal are the table's German words too.
    check(p.find("#screen h1.question").text == de["question.layer_index"], f"the question: {p.find('#screen h1.question').text!r}")
    reason = de["refusal.whole_number_min"].replace("{min}", "1")
    check(error.text == de["trial.refused"] + " " + reason, f"the refusal says: {error.text!r}")
    p.screenshot("de-trial-refused")
    no_english(p, de, en, ["answer.layer-number", "button.submit", "trial.refused", "question.layer_index", "refusal.whole_number_min"], "trial")
    box = p.find("#answer")
    box.send_keys(Keys.CONTROL, "a")
    box.send_keys("1", Keys.ENTER)
    s = p.next_screen(s["seq"])
    check(s["kind"] == "end", f"the debrief expected, got {s}")
    text = body(p)
    check(de["defaults.debrief_text"] in text and de["end.completion_code"] in text and p.find("#completion-code").text == "DE42",
          f"the debrief: {text!r}")
    no_english(p, de, en, ["defaults.debrief_text", "end.completion_code"], "debrief")
    p.screenshot("de-debrief")
    # Arriving again: the "already completed" page is German too.
    p.driver.get(server.link("teilnehmer-1"))
    p.until(lambda: de["arrival.completed_title"] in body(p), "the German 'already completed' page")
    check(de["end.completion_code"] in body(p), f"the 'already completed' page: {body(p)!r}")
    p.screenshot("de-already-completed")


def check_stored(tlab, server, db, work):
    """The refused 0 is an event, the corrected 1 the trial's answer."""
    server.stop()
    result = subprocess.run([tlab, "export", db, "--csv", str(work / "csv")], capture_output=True, text=True, timeout=120)
    check(result.returncode == 0, f"tlab export failed: {result.stderr}")
    trials = base.read_csv(work / "csv", "trials.csv")
    check([(t["participant"], t["raw_answer"], t["answered"]) for t in trials] == [("teilnehmer-1", "1", "1")],
          f"the stored trial: {trials}")
    refused = [e for e in base.read_csv(work / "csv", "events.csv") if e["kind"] == "refused-reply"]
    check(len(refused) == 1, f"refused replies (expected the 0): {refused}")


def german(args, p, server, db, work):
    german_session(args.tlab, args.experiment, p, server)
    check_stored(args.tlab, server, db, work)


def main():
    args = base.parse_arguments(__doc__.split("\n")[0], "online_de.toml")
    return base.run_in_browser(args, lambda p, server, db, work: german(args, p, server, db, work))


if __name__ == "__main__":
    sys.exit(main())
