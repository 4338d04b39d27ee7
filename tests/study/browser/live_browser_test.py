#!/usr/bin/env python3
"""Live views online in a real browser (headless Chromium driven by Selenium, the harness of
serve_browser_test.py): tests/study/data/live_online.toml's walk trial is walked by real arrow keys
and looked around by real pointer drags, its orbit trial (the dynamic style's lens following the
cursor) orbited by drags. Every frame the page displayed is hashed here from its decoded pixels
(the <img> drawn on a canvas: SHA-256 of "WxH:" and its RGBA bytes) and must be a "frame" event the
server stored for that trial with the same SHA-256; the stored frames are numbered from 0, begin
with the start view and name the input that moved them; the answers are stored; and `tlab replay`
renders every logged frame of both trials again from the database alone: "N of N frames identical".
With an experiment whose [online] frames = "jpeg" (live_online_jpeg.toml) the page shows JPEG
frames: each displayed picture has the frame's size and pixels near, not equal to, the logged ones
(lossy), every stored frame says "encoding": "jpeg quality=Q", and replay still finds N of N.

    tests/study/browser/live_browser_test.py --tlab build/bin/tlab
"""
import json
import re
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import serve_browser_test as base  # noqa: E402
from serve_browser_test import ActionChains, Keys, check  # noqa: E402

base.EXPERIMENT_ID = "live-online"

# The pixels of the picture on show, as the page decoded them: framePixelsSha256's "WxH:" + RGBA,
# with the stage's record of the frame read in the same task as the pixels. A frame that is
# replacing the picture (data-swapping: its pixels may be on show before the record is) is waited
# for: CI once read frame 6's pixels against frame 5's record.
DISPLAYED_SHA256 = """
const done = arguments[arguments.length - 1];
const stage = document.getElementById('stage');
const read = () => {
  if (stage.dataset.swapping) { setTimeout(read, 10); return; }
  const img = document.querySelector('#stage img');
  const c = document.createElement('canvas');
  c.width = img.naturalWidth; c.height = img.naturalHeight;
  const g = c.getContext('2d', { colorSpace: 'srgb' });
  g.drawImage(img, 0, 0);
  const rgba = g.getImageData(0, 0, c.width, c.height).data;
  const shown = { index: Number(stage.dataset.frameIndex), width: img.naturalWidth, height: img.naturalHeight,
                  logged: stage.dataset.frameSha256 };
  const head = new TextEncoder().encode(c.width + 'x' + c.height + ':');
  const bytes = new Uint8Array(head.length + rgba.length);
  bytes.set(head); bytes.set(rgba, head.length);
  crypto.subtle.digest('SHA-256', bytes).then((d) => done(Object.assign(shown, {
    sha: Array.from(new Uint8Array(d), (b) => b.toString(16).padStart(2, '0')).join('') })));
};
read();
"""


def frames_shown(p):
    return int(p.find("#stage").get_attribute("data-frames") or "0")


LOSSY = False  # [online] frames = "jpeg": the page shows JPEGs of the logged pixels


def displayed(p):
    """The frame on show: its index and the SHA-256 of its pixels (the page's record of it, with JPEG frames)."""
    d = p.driver.execute_async_script(DISPLAYED_SHA256)
    if LOSSY:  # a picture of the frame's size, not exactly the logged pixels
        check(re.fullmatch(r"[0-9a-f]{64}", d["logged"] or "") and d["sha"] != d["logged"] and d["width"] == 192 and d["height"] == 192,
              f"frame {d['index']}: the page shows a {d['width']}x{d['height']} JPEG of pixels {d['sha']}, logged {d['logged']}")
        return d["index"], d["logged"]
    check(d["sha"] == d["logged"], f"frame {d['index']}: the page shows pixels of SHA-256 {d['sha']}, the server logged {d['logged']}")
    return d["index"], d["sha"]


def after_input(p, before, what):
    """Waits for a frame after `before` frames and for no request in flight; returns the frame shown."""
    p.until(lambda: frames_shown(p) > before, f"a new frame after {what}")
    return displayed(p)


def drag(p, dx, dy):
    img = p.find("#stage img")
    actions = ActionChains(p.driver).move_to_element(img).click_and_hold()
    for step in range(1, 5):
        actions.move_by_offset(dx // 4, dy // 4).pause(0.05)
    actions.release().perform()


def explore(p, navigation):
    """The start view, a drag, arrow keys (walking) or a cursor move over the lens (orbiting)."""
    p.until(lambda: frames_shown(p) >= 1, "the start view")
    seen = [displayed(p)]
    p.screenshot(f"trial-{navigation}-start")
    n = frames_shown(p)
    drag(p, 60, -20)
    seen.append(after_input(p, n, "a drag"))
    p.screenshot(f"trial-{navigation}-dragged")
    n = frames_shown(p)
    if navigation == "walk":
        ActionChains(p.driver).send_keys(Keys.ARROW_UP, Keys.ARROW_UP, Keys.ARROW_UP, Keys.ARROW_RIGHT).perform()
        seen.append(after_input(p, n, "the arrow keys"))
        p.screenshot("trial-walk-walked")
    else:
        img = p.find("#stage img")
        ActionChains(p.driver).move_to_element_with_offset(img, -30, 20).pause(0.1).move_to_element_with_offset(img, 25, -25).perform()
        seen.append(after_input(p, n, "the cursor over the picture"))
        p.screenshot("trial-orbit-lens")
    check(len({sha for _, sha in seen}) == len(seen), f"{navigation}: the input did not change the picture: {seen}")
    return seen


def walk(p, server):
    shown = {}

    def answer(seq):
        live = p.driver.execute_script("return current.live;")
        check(live is not None and "live" in p.find("#stage").get_attribute("class"), f"the trial is not live: {live}")
        shown["walk" if live["navigation"] == "walk" else "orbit"] = explore(p, live["navigation"])
        check(live["lens"] == (live["navigation"] == "orbit"), f"the lens follows the cursor only in the orbit trial's style: {live}")
        words = p.find("#navigation").text  # how to move, from the text table
        check(("arrow keys walk" in words) == (live["navigation"] == "walk") and ("lens follows" in words) == live["lens"],
              f"the {live['navigation']} trial says how to move: {words!r}")
        # A refused answer (more than the 1,000,000 a count may be), then the corrected one.
        p.type_number(2000000, select_all=True)
        error = p.until(lambda: [e for e in p.finds("#screen .error") if e.text], "the refused answer's message")[0]
        check("from 0 to 1000000" in error.text, f"the refusal in the live trial says: {error.text!r}")
        check(p.state()["seq"] == seq, "the refused answer left the live trial")
        p.screenshot(f"trial-{live['navigation']}-refused")
        p.type_number(2, select_all=True)

    base.walk_trials(p, server, answer)
    p.screenshot("end")
    return shown


def check_stored(tlab, db, folder, shown):
    result = subprocess.run([tlab, "export", db, "--csv", str(folder)], capture_output=True, text=True, timeout=120)
    check(result.returncode == 0, f"tlab export failed: {result.stderr}")
    trials = base.read_csv(folder, "trials.csv")
    check(len(trials) == 2 and all(t["answered"] == "1" and t["raw_answer"] == "2" for t in trials), f"the trials: {trials}")
    task_of = {t["sequence"]: t["task_id"] for t in trials}
    events = [e for e in base.read_csv(folder, "events.csv") if e["kind"] == "frame"]
    by_task = {}
    for e in events:
        check(e["trial_sequence"] in task_of, f"a frame event outside the trials: {e}")
        by_task.setdefault(task_of[e["trial_sequence"]], []).append(json.loads(e["detail"]))
    check(set(by_task) == {"walk", "orbit"}, f"frame events of the tasks {list(by_task)} (expected walk and orbit)")
    for task, frames in by_task.items():
        frames.sort(key=lambda f: f["index"])
        check([f["index"] for f in frames] == list(range(len(frames))), f"{task}: frame indices {[f['index'] for f in frames]}")
        check(frames[0]["input"] == "start", f"{task}: the first frame is {frames[0]}")
        for f in frames:
            check(re.fullmatch(r"[0-9a-f]{64}", f["sha256"]) and f["camera"].startswith("eye="), f"{task}: a frame event {f}")
            check(f.get("encoding", "").startswith("jpeg quality=") if LOSSY else f.get("encoding") == "png", f"{task}: the frame's encoding {f}")
        inputs = " ".join(f["input"] for f in frames)
        if task == "walk":
            check("drag" in inputs and "key" in inputs and "point" not in inputs and all("lens" not in f for f in frames), f"the walk trial's frames: {inputs}")
        else:
            check("drag" in inputs and "point" in inputs and all("lens" in f for f in frames if "point" in f["input"]),
                  f"the orbit trial's frames: {[(f['input'], f.get('lens')) for f in frames]}")
        stored = {f["index"]: f["sha256"] for f in frames}
        for index, sha in shown[task]:  # every picture the page displayed is a stored frame of its trial
            check(stored.get(index) == sha, f"{task}: the page displayed frame {index} with pixels {sha}, stored: {stored.get(index)}")
    print(f"frames stored: { {t: len(f) for t, f in by_task.items()} }; displayed and matched: { {t: len(v) for t, v in shown.items()} }")
    # Replay of each browser trial: every frame rendered again here and compared with its logged hash.
    for sequence, task in task_of.items():
        n = len(by_task[task])
        replay = subprocess.run([tlab, "replay", db, "--participant", base.PARTICIPANT, "--trial", sequence],
                                capture_output=True, text=True, timeout=300)
        print(f"tlab replay --trial {sequence} ({task}): {replay.stdout.strip().splitlines()[-1:] or replay.stderr.strip()}")
        check(replay.returncode == 0 and f"{n} of {n} frames identical" in replay.stdout,
              f"{task}: tlab replay of the browser trial: exit {replay.returncode}\n{replay.stdout}\n{replay.stderr}")


def session(args, p, server, db, work):
    shown = walk(p, server)
    check(set(shown) == {"walk", "orbit"}, f"live trials shown: {list(shown)}")
    server.stop()
    check_stored(args.tlab, db, work / "csv", shown)


def main():
    global LOSSY
    args = base.parse_arguments(__doc__.split("\n")[0], "live_online.toml")
    LOSSY = 'frames = "jpeg"' in Path(args.experiment).read_text()
    return base.run_in_browser(args, lambda p, server, db, work: session(args, p, server, db, work))


if __name__ == "__main__":
    sys.exit(main())
