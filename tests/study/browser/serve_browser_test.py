#!/usr/bin/env python3
"""End-to-end test of `tlab serve` in a real browser (headless Chromium driven by Selenium).

One participant walks a whole session of tests/study/data/online.toml by really clicking: consent,
the information form, a training trial with feedback, one trial of every answer kind (number +
Enter, label hit boxes on the picture, Done, the floor plan, a letter button), the turntable
drag, a page reload in the middle of a trial, a break, the questionnaire and the debrief with
its completion code and link. The database is then checked through `tlab export --csv`, and
the same participant id arriving again is refused as "already completed". Every trial first gets an
answer the server refuses (typed out of range, or clicked and changed on its way to the server);
the page must take the corrected answer, which is the one stored.

A screenshot of every screen goes into --screenshots DIR (or $TLAB_BROWSER_SCREENSHOTS; default:
a temporary folder, printed). Synchronisation is by explicit waits on the page's state
(main#screen's data-kind, data-seq and data-onset attributes), never by sleeping.

    tests/study/browser/serve_browser_test.py --tlab build/bin/tlab
"""
import argparse
import csv
import json
import os
import queue
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

CHROMIUM = "/usr/bin/chromium"
CHROMEDRIVER = "/usr/bin/chromedriver"
SETUP_HINT = "install the browser-test packages (chromium, chromium-driver, python3-selenium) with scripts/setup.sh"


def fail(message):
    print("FAIL: " + message, file=sys.stderr)
    sys.exit(1)


try:
    from selenium import webdriver
    from selenium.common.exceptions import TimeoutException, WebDriverException
    from selenium.webdriver.chrome.service import Service
    from selenium.webdriver.common.action_chains import ActionChains
    from selenium.webdriver.common.by import By
    from selenium.webdriver.common.keys import Keys
    from selenium.webdriver.support.ui import WebDriverWait
except ImportError as error:
    fail(f"Selenium is missing for {sys.executable} ({error}): {SETUP_HINT}")

EXPERIMENT_ID = "online"
PARTICIPANT = "browser-1"
WINDOW = (1280, 900)
PICTURE = 200  # [stimulus] size of online.toml
COMPLETION_CODE = "ONLINE42"
COMPLETION_URL = "https://app.prolific.com/submissions/complete?cc=ONLINE42"
# What the participant types and chooses in the forms, by field id.
FORM_VALUES = {"age": "34", "handedness": "right", "ease": "4", "strategy": "the shading", "comments": "clear pictures"}
WAIT_S = 30  # the longest any screen may take to come


def check(condition, message):
    if not condition:
        raise AssertionError(message)


class Server:
    """`tlab serve` on a free port; the port comes from its "participants:" line."""

    def __init__(self, tlab, experiment, db, log_path):
        self.log = open(log_path, "ab")
        self.process = subprocess.Popen([tlab, "serve", experiment, "--db", db, "--listen", "127.0.0.1:0", "--quiet"],
                                        stdout=subprocess.PIPE, stderr=self.log, text=True)
        lines = queue.Queue()
        threading.Thread(target=self._read, args=(lines,), daemon=True).start()
        self.stdout = []
        deadline = time.monotonic() + 180  # preparing the stimuli: a few seconds here
        self.base = None
        while self.base is None or not any(line.startswith("admin:") for line in self.stdout):
            try:
                line = lines.get(timeout=max(0.1, deadline - time.monotonic()))
            except queue.Empty:
                raise AssertionError(f"tlab serve printed no participants/admin lines in time (stderr: {log_path})")
            if line is None:
                raise AssertionError(f"tlab serve ended early with status {self.process.wait()} (stderr: {log_path}): {''.join(self.stdout)}")
            self.stdout.append(line)
            m = re.match(r"participants: (http://127\.0\.0\.1:(\d+))/s/" + EXPERIMENT_ID + r"\?PROLIFIC_PID=PARTICIPANT-ID$", line.strip())
            if m:
                self.base = m.group(1)

    def _read(self, lines):
        for line in self.process.stdout:
            lines.put(line)
        lines.put(None)

    def link(self, participant):
        return f"{self.base}/s/{EXPERIMENT_ID}?PROLIFIC_PID={participant}"

    def stop(self):
        """SIGTERM: the server stops by itself; its status must be 0."""
        if self.process.poll() is None:
            self.process.send_signal(signal.SIGTERM)
            try:
                status = self.process.wait(timeout=30)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait()
                raise AssertionError("tlab serve did not stop within 30 s of SIGTERM")
            check(status == 0, f"tlab serve exited with status {status} after SIGTERM")
        self.log.close()

    def kill(self):
        if self.process.poll() is None:
            self.process.kill()
            self.process.wait()
        if not self.log.closed:
            self.log.close()


def start_browser(profile):
    for path, package in ((CHROMIUM, "chromium"), (CHROMEDRIVER, "chromium-driver")):
        if not os.access(path, os.X_OK):
            fail(f"{path} is missing (Debian package {package}): {SETUP_HINT}")
    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    for argument in ("--headless=new", f"--window-size={WINDOW[0]},{WINDOW[1]}", "--force-device-scale-factor=1",
                     f"--user-data-dir={profile}", "--no-first-run", "--disable-dev-shm-usage", "--disable-extensions",
                     "--hide-scrollbars", "--lang=en-US"):
        options.add_argument(argument)
    if os.geteuid() == 0:
        options.add_argument("--no-sandbox")  # Chromium refuses to run as root with its sandbox
    try:
        return webdriver.Chrome(service=Service(CHROMEDRIVER), options=options)
    except WebDriverException as error:
        fail(f"headless Chromium did not start ({error.msg}): {SETUP_HINT}")


class Participant:
    """The browser of one participant, with a screenshot of every screen it shows."""

    def __init__(self, driver, shots):
        self.driver = driver
        self.shots = shots
        self.count = 0
        self.wait = WebDriverWait(driver, WAIT_S)

    def screenshot(self, name):
        self.count += 1
        path = self.shots / f"{self.count:02d}-{name}.png"
        check(self.driver.save_screenshot(str(path)), f"could not save {path}")
        return path

    def state(self):
        return self.driver.execute_script(
            "const m = document.getElementById('screen');"
            "return m ? {kind: m.dataset.kind || '', seq: Number(m.dataset.seq || -1), answer: m.dataset.answerKind || '',"
            " onset: m.dataset.onset || ''} : null;")

    def next_screen(self, after_seq):
        """Waits for a screen other than "wait" with a number above after_seq."""
        def ready(_):
            s = self.state()
            return s if s and s["kind"] not in ("", "wait") and s["seq"] > after_seq else False
        try:
            return self.wait.until(ready)
        except TimeoutException:
            raise AssertionError(f"no new screen after screen {after_seq} within {WAIT_S} s (shown: {self.state()})")

    def until(self, condition, what):
        try:
            return self.wait.until(lambda d: condition())
        except TimeoutException:
            raise AssertionError(f"timed out waiting for {what}")

    def find(self, css):
        return self.driver.find_element(By.CSS_SELECTOR, css)

    def finds(self, css):
        return self.driver.find_elements(By.CSS_SELECTOR, css)

    def trial_ready(self):
        """Waits until the trial's picture is painted and its onset stored by the server."""
        self.until(lambda: self.state()["onset"] == "reported", "the trial's onset report")

    def press_at(self, element):
        """A real mouse click at the element's centre (the browser's hit testing decides what is clicked)."""
        ActionChains(self.driver).move_to_element(element).click().perform()

    def type_number(self, number, select_all=False):
        box = self.find("#answer")
        self.until(lambda: self.driver.switch_to.active_element == box, "the answer box to have the focus")
        if select_all:
            box.send_keys(Keys.CONTROL, "a")
        box.send_keys(str(number), Keys.ENTER)


def walk_trials(p, server, answer):
    """Opens the participant's link and walks the session to its end: Continue on every message,
    answer(seq) on every trial once its onset is reported. Returns when the end screen shows."""
    p.driver.get(server.link(PARTICIPANT))
    p.until(lambda: "/p/" in p.driver.current_url, "the redirect to the session page")
    s = p.next_screen(-1)
    while s["kind"] != "end":
        kind, seq = s["kind"], s["seq"]
        if kind == "trial":
            p.trial_ready()
            answer(seq)
        elif kind == "message":
            p.find("#continue").click()
        else:
            raise AssertionError(f"unexpected screen kind {kind!r}")
        s = p.next_screen(seq)


def check_picture_unscaled(p, what):
    """The stimulus is drawn at its rendered size in device pixels: CSS px x devicePixelRatio = image pixels."""
    m = p.driver.execute_script(
        "const i = document.querySelector('#stage img'); const r = i.getBoundingClientRect();"
        "return {w: r.width, h: r.height, dpr: devicePixelRatio, nw: i.naturalWidth, nh: i.naturalHeight,"
        " visible: r.left >= 0 && r.top >= 0 && r.right <= innerWidth && r.bottom <= innerHeight};")
    check(m["nw"] == PICTURE and m["nh"] == PICTURE, f"{what}: the picture is {m['nw']}x{m['nh']}, expected {PICTURE}x{PICTURE}")
    check(abs(m["w"] * m["dpr"] - PICTURE) < 0.01 and abs(m["h"] * m["dpr"] - PICTURE) < 0.01,
          f"{what}: the picture is scaled: {m['w']}x{m['h']} CSS px at devicePixelRatio {m['dpr']}")
    check(m["visible"], f"{what}: the picture is not wholly inside the window")


def check_countdown(p, what):
    clock = p.find("#countdown")
    p.until(lambda: re.fullmatch(r"\d+:\d\d", clock.text), f"{what}: the countdown")
    check(clock.is_displayed() and clock.size["width"] > 0, f"{what}: the countdown is not visible")
    overlap = p.driver.execute_script(
        "const a = document.querySelector('#countdown').getBoundingClientRect();"
        "return Array.from(document.querySelectorAll('#screen h1, #screen .progress')).some((e) => { const b = e.getBoundingClientRect();"
        " return a.left < b.right && b.left < a.right && a.top < b.bottom && b.top < a.bottom; });")
    check(not overlap, f"{what}: the countdown overlaps the question")


def countdown_seconds(p):
    m = re.fullmatch(r"(\d+):(\d\d)", p.find("#countdown").text)
    return int(m.group(1)) * 60 + int(m.group(2)) if m else 10 ** 9


def check_hits_on_labels(p, what):
    """Each label's hit box is centred on the label's pixel in the picture."""
    misplaced = p.driver.execute_script(
        "const s = document.querySelector('#stage img').getBoundingClientRect(); const page = arguments[0]; const out = [];"
        "document.querySelectorAll('#stage .hit').forEach((h) => { const r = h.getBoundingClientRect();"
        " const l = page.labels.find((x) => x.label === h.dataset.label);"
        " const dx = (r.left + r.width / 2) - (s.left + l.x / devicePixelRatio), dy = (r.top + r.height / 2) - (s.top + l.y / devicePixelRatio);"
        " if (Math.hypot(dx, dy) > 1) out.push(h.dataset.label + ' off by ' + dx + ',' + dy);"
        " const top = document.elementFromPoint(r.left + r.width / 2, r.top + r.height / 2);"
        " if (top !== h) out.push(h.dataset.label + ' is covered by ' + (top ? top.tagName + '.' + top.className : 'nothing')); });"
        "return out;", p.driver.execute_script("return current;"))
    check(not misplaced, f"{what}: label hit boxes are not on the labels: {misplaced}")


def check_too_small_notice(p):
    """A window smaller than the picture shows the notice; the full size hides it again."""
    notice = p.find("#toosmall")
    check(not notice.is_displayed(), "the 'window too small' notice is shown in a large window")
    p.driver.set_window_size(520, 300)
    p.until(lambda: notice.is_displayed(), "the 'window too small' notice in a small window")
    check(f"{PICTURE + 40} × {PICTURE + 160} pixels" in notice.text, f"the 'window too small' notice says: {notice.text!r}")
    p.screenshot("window-too-small")
    p.driver.set_window_size(*WINDOW)
    p.until(lambda: not notice.is_displayed(), "the 'window too small' notice to go in a large window")


def drag_turntable(p):
    """Drags the turntable right and up; the view changes (a new picture), and the page sends the views."""
    img = p.find("#stage img")
    before = img.get_attribute("src")
    actions = ActionChains(p.driver).move_to_element(img).click_and_hold()
    for _ in range(10):
        actions.move_by_offset(12, -9)
    actions.release().perform()
    p.until(lambda: img.get_attribute("src") != before, "the turntable to show another view after the drag")
    p.until(lambda: p.driver.execute_script("return document.querySelector('#stage img').complete;"), "the new view to load")


def leaving_asks(p):
    """Whether the page asks before it is left (its beforeunload handler cancels the event)."""
    return p.driver.execute_script("const e = new Event('beforeunload', {cancelable: true}); dispatchEvent(e); return e.defaultPrevented;")


def check_other_browser_refused(server):
    """The participant's link opened in a second browser (another profile: another cookie) while the
    session is live: that page says the session is open elsewhere and gets no screen."""
    profile = Path(tempfile.mkdtemp(prefix="tlab-other-browser-"))
    other = start_browser(profile)
    try:
        other.get(server.link(PARTICIPANT))
        q = Participant(other, Path(tempfile.gettempdir()))
        q.until(lambda: q.find("#problem").is_displayed(), "the other browser's notice")
        text = q.find("#problem-text").text
        check("open in another browser" in text, f"the other browser's notice says: {text!r}")
        check(q.state()["kind"] == "", f"the other browser was shown a screen: {q.state()}")
    finally:
        other.quit()
        shutil.rmtree(profile, ignore_errors=True)


def walk_session(p, server):
    """Walks one participant through the whole session; returns what was answered, by answer kind."""
    answers = {}  # answer kind (training: "training") -> expected raw_answer text
    seen = {}
    reloaded = False
    instructions = 0  # task instruction screens seen
    p.driver.get(server.link(PARTICIPANT))
    p.until(lambda: "/p/" in p.driver.current_url, "the redirect to the session page")
    s = p.next_screen(-1)
    while True:
        kind = s["kind"]
        key = kind + ("-" + s["answer"] if s["answer"] else "")
        seen[key] = seen.get(key, 0) + 1
        name = key if seen[key] == 1 else f"{key}-{seen[key]}"
        if kind == "trial":
            p.trial_ready()
            check_picture_unscaled(p, name)
            check_countdown(p, name)
        p.screenshot(name)
        seq = s["seq"]
        if kind == "message":
            title = p.find("#screen h1").text
            check(not re.search(r"\b(layer|boundary|nearest|count|find|letter)\b", title), f"a task's internal id in the title {title!r}")
            if title in ("Instructions", "Practice"):  # the instructions say how many trials and their limit
                instructions += 1
                text = p.find("#screen p.text").text
                check(re.search(r"There (is 1 (practice )?trial|are \d+ (practice )?trials) of this kind now", text)
                      and "time limit of 5 minutes" in text, f"{title}: the instructions do not say the trials and the time limit: {text!r}")
            if seen[key] == 1:
                check_other_browser_refused(server)
            p.find("#continue").click()
        elif kind == "consent":
            check(p.find("#decline").is_displayed(), "the consent screen has no decline button")
            p.find("#accept").click()
        elif kind == "form":
            if seen[key] == 1:  # the information form sent empty first: refused, said on the page
                p.find("#submit").click()
                error = p.until(lambda: [e for e in p.finds("#screen .error") if e.text], "the form's error message")[0]
                check(error.find_element(By.XPATH, "..").get_attribute("data-field") == "age" and "required" in error.text
                      and "'age'" not in error.text, f"the empty form's error, under the age field in words: {error.text!r}")
                check(p.state()["seq"] == seq, "the refused form was left")
                p.screenshot("form-refused")
            fill_form(p)
            p.find("#submit").click()
        elif kind == "feedback":
            heading = p.find("h1").text
            check(heading in ("Correct", "Not quite"), f"feedback heading: {heading!r}")
            check("The right answer:" in p.find("#screen").text, "the feedback shows no right answer")
            given = p.find("#given").text
            check(given == "Your answer: " + answers["training"], f"the feedback shows {given!r}, the participant answered {answers['training']!r}")
            ActionChains(p.driver).send_keys(Keys.ENTER).perform()  # Enter continues, as the button does
        elif kind == "break":
            go = p.find("#continue")
            check(not go.is_enabled(), "the break's Continue button is enabled before min_seconds")
            check(re.search(r"in \d+ s", p.find("#screen").text), "the break shows no countdown")
            check(re.search(r"\d+ trials? (is|are) left\.", p.find("#screen").text), f"the break does not say what is left: {p.find('#screen').text!r}")
            p.until(go.is_enabled, "the break's Continue button to be enabled")
            p.screenshot("break-over")
            ActionChains(p.driver).send_keys(Keys.ENTER).perform()  # Enter continues once the button is enabled
        elif kind == "end":
            check(instructions == 6, f"{instructions} task instruction screens, expected 6 (the practice, then each task but the practised one)")
            check(not leaving_asks(p), "leaving the debrief asks the participant to stay")
            check(p.find("#completion-code").text == COMPLETION_CODE, "the completion code on the debrief")
            check(p.find("#completion-link").get_attribute("href") == COMPLETION_URL, "the completion link on the debrief")
            # A reload of the debrief (to copy the code) shows it again.
            p.driver.refresh()
            again = p.next_screen(-1)
            check(again["kind"] == "end" and p.find("#completion-code").text == COMPLETION_CODE, f"after reloading the debrief: {again}")
            return answers
        elif kind == "trial":
            answer_kind = s["answer"]
            training = p.driver.execute_script("return current.phase;") == "training"
            if answer_kind == "label" and not reloaded:
                # A reload in the middle of a trial: the same trial comes back (shown a second time),
                # its countdown going on from where it was (once it has dropped below its start).
                start = countdown_seconds(p)
                p.until(lambda: countdown_seconds(p) < start, "the countdown to go down")
                p.driver.refresh()
                again = p.next_screen(-1)
                check(again["seq"] == seq and again["kind"] == "trial", f"after the reload: {again}, expected trial screen {seq}")
                p.trial_ready()
                check_countdown(p, "trial after reload")
                check(countdown_seconds(p) < start, f"the countdown started again after the reload: {p.find('#countdown').text}")
                check_picture_unscaled(p, "trial after reload")
                p.screenshot("trial-label-after-reload")
                reloaded = True
            check(leaving_asks(p), f"{name}: leaving the page during a trial does not ask first (beforeunload)")
            refused = provoke_refusal(p, answer_kind, seq)
            if answer_kind in ("layer-number", "label-set"):
                p.screenshot(f"{name}-refused")
            check(refused, f"{name}: no reason for the refusal on the page")
            answers["training" if training else answer_kind] = answer_trial(p, answer_kind, training)
        else:
            raise AssertionError(f"unexpected screen kind {kind!r}")
        s = p.next_screen(seq)


def fill_form(p):
    for field in p.finds("#screen .field"):
        fid = field.get_attribute("data-field")
        check(fid in FORM_VALUES, f"a form field the test does not know: {fid!r}")
        value = FORM_VALUES[fid]
        radios = field.find_elements(By.CSS_SELECTOR, "input[type=radio]")
        if radios:
            choice = [r for r in radios if r.get_attribute("value") == value]
            check(len(choice) == 1, f"field {fid}: no option {value!r}")
            p.press_at(choice[0])
            check(choice[0].is_selected(), f"field {fid}: the click did not choose {value!r}")
        else:
            field.find_element(By.CSS_SELECTOR, "input").send_keys(value)


def corrupt_next_answer(p, answer):
    """The page's next answer reaches the server as `answer` (a value the server refuses): for the
    widgets where no click can make a refused answer, the refusal is the server's real reply."""
    p.driver.execute_script(
        "const send = window.fetch, bad = JSON.parse(arguments[0]);"
        "window.fetch = (url, options) => { if (options && options.body) { const b = JSON.parse(options.body);"
        " if (b.type === 'answer') { window.fetch = send; b.answer = bad; options = Object.assign({}, options, {body: JSON.stringify(b)}); } }"
        " return send(url, options); };", json.dumps(answer))


def record_replies(p):
    """From now on the replies the page sends (their JSON bodies) are kept, for sent_replies."""
    p.driver.execute_script(
        "window.sentReplies = []; const send = window.fetch;"
        "window.fetch = (url, options) => { if (options && options.body) sentReplies.push(JSON.parse(options.body)); return send(url, options); };")


def sent_replies(p, kind):
    """The replies of type `kind` the page sent since record_replies."""
    return [r for r in p.driver.execute_script("return window.sentReplies || [];") if r.get("type") == kind]


def provoke_refusal(p, answer_kind, seq):
    """A first answer the server refuses (typed, or clicked and changed on its way): the page says
    why and stays on the trial, ready for the corrected answer that answer_trial then gives."""
    if answer_kind == "layer-number":
        p.type_number(0)  # below 1: refused by the server
    elif answer_kind == "count":
        p.type_number(1000001)  # above 1000000: refused by the server
    elif answer_kind == "label":
        corrupt_next_answer(p, "ZZ")
        p.press_at(p.finds("#stage .hit")[0])
    elif answer_kind == "label-set":
        corrupt_next_answer(p, ["ZZ"])
        p.find("#submit").click()
    elif answer_kind == "floor-point":
        corrupt_next_answer(p, {"x": -1, "y": -1})
        p.press_at(p.find("#floor-plan"))
    elif answer_kind == "letter":
        corrupt_next_answer(p, "?")
        p.press_at(p.finds("#screen button.letter")[0])
    else:
        raise AssertionError(f"an answer kind the test does not know: {answer_kind}")
    error = p.until(lambda: [e for e in p.finds("#screen .error") if e.text], f"{answer_kind}: the refused answer's message")[0]
    check(p.state()["seq"] == seq and p.state()["kind"] == "trial", f"{answer_kind}: the trial was left after a refused answer")
    return error.text


def answer_trial(p, answer_kind, training):
    """Answers the trial on show by clicking and typing; returns the expected stored answer text."""
    if answer_kind == "layer-number":
        hint = p.find("#hint").text
        check(hint == "Type the layer number (1 is the front surface) and press Enter.", f"the layer-number hint: {hint!r}")
        number = 1 if training else 2
        p.type_number(number)
        return str(number)
    if answer_kind == "count":
        check("turntable" in p.find("#stage").get_attribute("class"), "the orbit task shows no turntable")
        drag_turntable(p)
        p.screenshot("trial-count-turned")
        check_too_small_notice(p)
        p.type_number(3, select_all=True)
        return "3"
    if answer_kind in ("label", "label-set"):
        check_hits_on_labels(p, answer_kind)
        hits = p.finds("#stage .hit")
        check(len(hits) >= 2, f"{answer_kind}: {len(hits)} labels to click")
        if answer_kind == "label":
            label = hits[-1].get_attribute("data-label")
            p.press_at(hits[-1])
            return label
        chosen = [hits[1], hits[0]]  # stored in the order clicked
        for hit in chosen:
            p.press_at(hit)
            p.until(lambda: "selected" in hit.get_attribute("class"), "a clicked label to be marked")
        p.screenshot("trial-label-set-chosen")
        expected = ",".join(h.get_attribute("data-label") for h in chosen)
        p.find("#submit").click()
        return expected
    if answer_kind == "floor-point":
        plan = p.find("#floor-plan")
        box = p.driver.execute_script(
            "const i = document.getElementById('floor-plan'); const r = i.getBoundingClientRect();"
            "return {left: r.left, top: r.top, border: i.clientLeft, width: i.clientWidth, height: i.clientHeight, plan: current.floor_plan};")
        check(box["width"] == box["plan"]["width"] and box["height"] == box["plan"]["height"], f"the floor plan is scaled: {box}")
        record_replies(p)  # to compare the clicked plan pixel (the store has world coordinates)
        target = (box["width"] // 4, box["height"] * 3 // 4)  # in the plan's pixels
        centre = (plan.size["width"] / 2, plan.size["height"] / 2)  # Selenium's offsets are from the element's centre
        ActionChains(p.driver).move_to_element_with_offset(plan, int(box["border"] + target[0] - centre[0]), int(box["border"] + target[1] - centre[1])).click().perform()
        sent = p.until(lambda: sent_replies(p, "answer"), "the floor-plan answer")
        point = sent[0]["answer"]
        check(abs(point["x"] - target[0]) <= 1.5 and abs(point["y"] - target[1]) <= 1.5, f"clicked the plan at {target}, the page sent {point}")
        return "floor-point"  # world coordinates in the store: checked for their form
    if answer_kind == "letter":
        buttons = p.finds("#screen button.letter")
        check([b.text for b in buttons] == ["C", "K", "R", "X", "Y"], f"letter buttons: {[b.text for b in buttons]}")
        p.press_at(buttons[1])
        return "K"
    raise AssertionError(f"an answer kind the test does not know: {answer_kind}")


def read_csv(folder, name):
    with open(folder / name, newline="") as f:
        return list(csv.DictReader(f))


def check_database(tlab, db, folder, answers):
    result = subprocess.run([tlab, "export", db, "--csv", str(folder)], capture_output=True, text=True, timeout=120)
    check(result.returncode == 0, f"tlab export failed: {result.stderr}")
    trials = [t for t in read_csv(folder, "trials.csv") if t["participant"] == PARTICIPANT]
    check(len(trials) == 7, f"{len(trials)} trial rows, expected 7 (1 training + 6 test)")
    for t in trials:
        phase, kind = t["phase"], t["answer_kind"]
        what = f"trial {t['sequence']} ({phase}, {t['task_id']}, {kind})"
        check(t["responded"] == "1" and t["answered"] == "1", f"{what}: not answered: {t}")
        check(float(t["rt_seconds"]) > 0, f"{what}: rt_seconds {t['rt_seconds']}")
        expected = answers["training" if phase == "training" else kind]
        if kind == "floor-point":
            check(re.fullmatch(r"-?\d+\.\d{4},-?\d+\.\d{4}", t["raw_answer"]), f"{what}: raw_answer {t['raw_answer']!r}")
        else:
            check(t["raw_answer"] == expected, f"{what}: raw_answer {t['raw_answer']!r}, clicked {expected!r}")
        check(t["showings"] == ("2" if kind == "label" else "1"), f"{what}: shown {t['showings']} times")
    events = read_csv(folder, "events.csv")
    onsets = [json.loads(e["detail"]) for e in events if e["kind"] == "onset"]
    check(any(o.get("showing") == 2 and o.get("via") == "browser" for o in onsets), f"no onset with showing 2: {onsets}")
    check(sum(1 for e in events if e["kind"] == "camera") >= 1, "no camera event from the turntable drag")
    refused = [json.loads(e["detail"]) for e in events if e["kind"] == "refused-reply"]
    forms = [r for r in refused if '"form"' in r["body"]]
    answers_refused = [r for r in refused if '"answer"' in r["body"]]
    check(len(forms) == 1 and len(answers_refused) == 7 and len(refused) == 8,
          f"refused replies (expected the empty form and the first answer of each of the 7 trials): {refused}")
    sessions = read_csv(folder, "sessions.csv")
    check(len(sessions) == 1, f"{len(sessions)} sessions")
    session = sessions[0]
    check(session["mode"] == "browser" and session["status"] == "finished", f"the session: {session}")
    check(session["responses"] == "7" and session["onsets"] == "8", f"the session has {session['responses']} responses and {session['onsets']} onsets, expected 7 and 8")
    browser = json.loads(session["display"]).get("browser", {})
    for key in ("device_pixel_ratio", "window_width", "window_height", "screen_width", "refresh_hz", "user_agent"):
        check(key in browser, f"the session's display JSON has no browser field {key}: {session['display']}")
    check(browser["device_pixel_ratio"] == 1 and browser["window_width"] == WINDOW[0], f"the browser's display: {browser}")
    check(browser["refresh_hz"] > 0, f"refresh_hz {browser['refresh_hz']}")
    consent = read_csv(folder, "consent.csv")
    check([c["decision"] for c in consent] == ["accepted"], f"consent rows: {consent}")
    info = {r["field"]: r["value"] for r in read_csv(folder, "participant_info.csv")}
    check(info == {"age": FORM_VALUES["age"], "handedness": FORM_VALUES["handedness"]}, f"participant info: {info}")
    answers_q = {r["item"]: r["answer"] for r in read_csv(folder, "questionnaires.csv")}
    check(answers_q == {k: FORM_VALUES[k] for k in ("ease", "strategy", "comments")}, f"questionnaire: {answers_q}")


def check_refused_again(p, server, name):
    p.driver.get(server.link(PARTICIPANT))
    p.until(lambda: "Already completed" in p.driver.find_element(By.TAG_NAME, "body").text, "the 'already completed' page")
    # The code and the way back to the platform again (the participant may not have copied them).
    check(p.find("#completion-code").text == COMPLETION_CODE, "the completion code on the 'already completed' page")
    check(p.find("#completion-link").get_attribute("href") == COMPLETION_URL, "the completion link on the 'already completed' page")
    p.screenshot(name)


def parse_arguments(description, experiment):
    here = Path(__file__).resolve().parent
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--tlab", default=os.environ.get("TLAB_EXE", str(here.parents[2] / "build" / "bin" / "tlab")))
    parser.add_argument("--experiment", default=str(here.parent / "data" / experiment))
    parser.add_argument("--screenshots", default=os.environ.get("TLAB_BROWSER_SCREENSHOTS", ""))
    args = parser.parse_args()
    if not os.access(args.tlab, os.X_OK):
        fail(f"no tlab binary at {args.tlab} (build it: cmake --build build --target tlab)")
    return args


def run_in_browser(args, body):
    """Starts `tlab serve` on args.experiment and headless Chromium, runs body(participant, server, db,
    work) and reports; the server and the browser always go. Returns the exit status."""
    work = Path(tempfile.mkdtemp(prefix="tlab-browser-"))
    shots = Path(args.screenshots) if args.screenshots else work / "screenshots"
    shots.mkdir(parents=True, exist_ok=True)
    for old in shots.glob("[0-9][0-9]-*.png"):  # an earlier run's
        old.unlink()
    db = str(work / "study.db")
    started = time.monotonic()
    server = driver = p = None
    ok = False
    try:
        server = Server(args.tlab, args.experiment, db, work / "serve.log")
        print(f"tlab serve ready in {time.monotonic() - started:.1f} s at {server.base}")
        driver = start_browser(work / "chromium-profile")
        p = Participant(driver, shots)
        body(p, server, db, work)
        ok = True
        print(f"PASS in {time.monotonic() - started:.1f} s; screenshots in {shots}")
    except Exception as error:  # assertions and WebDriver errors: reported with the screen on show
        print(f"FAIL: {type(error).__name__}: {error}\n(server log: {work / 'serve.log'}; screenshots: {shots})", file=sys.stderr)
        if p:
            try:
                p.screenshot("failure")
            except Exception:
                pass
    finally:
        if driver:
            driver.quit()
        if server:
            server.kill()
        if ok:  # the work folder goes, but for the screenshots when they are in it
            for item in work.iterdir():
                if item != shots:
                    shutil.rmtree(item, ignore_errors=True) if item.is_dir() else item.unlink()
            if shots != work / "screenshots":
                work.rmdir()
    return 0 if ok else 1


def check_admin_page(p, server):
    """The admin page after the session: the finished participant with their answers, the target and progress."""
    link = next(line.split("admin: ", 1)[1].strip() for line in server.stdout if line.startswith("admin:"))
    p.driver.get(link)
    text = p.until(lambda: p.driver.find_element(By.ID, "summary").text, "the admin page's summary")
    check(text.startswith("1 slot assigned, 1 of 1 participant finished (the target)"), f"the admin summary: {text!r}")
    row = [c.text for c in p.driver.find_elements(By.CSS_SELECTOR, "#slots tr:nth-child(2) td")]
    check(row[1:3] == [PARTICIPANT, "finished"] and row[7:10] == ["6", "0", "7/7"], f"the admin row of {PARTICIPANT}: {row}")
    p.screenshot("admin")


def whole_session(args, p, server, db, work):
    answers = walk_session(p, server)
    print(f"session walked: {answers}")
    check_admin_page(p, server)
    check_refused_again(p, server, "already-completed")
    server.stop()
    check_database(args.tlab, db, work / "csv", answers)
    # After a restart the store remembers: the same id is refused again.
    again = Server(args.tlab, args.experiment, db, work / "serve.log")
    try:
        check_refused_again(p, again, "already-completed-after-restart")
        again.stop()
    finally:
        again.kill()


def main():
    args = parse_arguments(__doc__.split("\n")[0], "online.toml")
    return run_in_browser(args, lambda p, server, db, work: whole_session(args, p, server, db, work))


if __name__ == "__main__":
    sys.exit(main())
