#!/usr/bin/env python3
"""Markdown tables from a bench/gpu_table.sh run: every style's ms per frame by scene and size
(tlab bench all --json), constant's and smart's passes, and the memory floor (tlab bench floor
--json). Usage: python3 bench/gpu_table.py OUT_DIR > table.md   (standard library only)"""
import json
import os
import sys


def scene_name(scene):
    """builtin:NAME?params stays as written; a file is named by its base name."""
    return scene if scene.startswith("builtin:") else os.path.splitext(os.path.basename(scene))[0]


def size_name(size):
    w, _, h = size.partition("x")
    return f"{w}²" if w == h else size


def load(path, required=True):
    """The JSON a tlab command wrote; None for an optional one that is missing or broken (its
    command failed, which bench/gpu_table.sh records)."""
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        if required:
            raise SystemExit(f"gpu_table.py: {path}: {e}")
        print(f"gpu_table.py: {path}: {e}; left out", file=sys.stderr)
        return None


def ms(value):
    return f"{value:.2f}" if value < 100 else f"{value:.0f}"


def passes(row):
    """A frame's passes in the order they run (JSON keeps them sorted by name)."""
    order = ["raster", "blend", "fill", "sort", "connect", "solve"]
    named = sorted(row["pass_ms"].items(),
                   key=lambda p: (p[0] == "compose", order.index(p[0]) if p[0] in order else len(order)))
    return ", ".join(f"{name} {ms(t)}" for name, t in named)


def grouped(rows):
    """The styles and the (scene, size) lines in the order they ran, and each row by (scene, size, style)."""
    styles, lines = [], []
    for r in rows:
        if r["style"] not in styles:
            styles.append(r["style"])
        if (r["scene"], r["size"]) not in lines:
            lines.append((r["scene"], r["size"]))
    return styles, lines, {(r["scene"], r["size"], r["style"]): r for r in rows}


class Footnotes:
    """A failed row's cell points to a numbered note with its error, printed after the table."""

    def __init__(self):
        self.notes = []

    def cell(self, scene, size, style, error):
        self.notes.append(f"{scene_name(scene)}, {size}, {style}: {error}")
        return f"failed ({len(self.notes)})"

    def write(self, out):
        out += [f"\n({i}) {n}" for i, n in enumerate(self.notes, 1)]


def style_table(rows, out):
    """One line per scene and size, one column per style: ms per frame and the ratio to the
    reference style (the first), or a footnote with the error."""
    styles, lines, cell = grouped(rows)
    notes = Footnotes()
    out.append("| scene | size | fragments | " + " | ".join(styles) + " |")
    out.append("|---|---|---:|" + "---:|" * len(styles))
    for scene, size in lines:
        fragments = max((cell[(scene, size, s)].get("fragments", 0) for s in styles if (scene, size, s) in cell),
                        default=0)
        cells = []
        for i, s in enumerate(styles):
            r = cell.get((scene, size, s))
            if r is None:
                cells.append("")
            elif "error" in r:
                cells.append(notes.cell(scene, size, s, r["error"]))
            elif i == 0 or not r.get("ratio_to_reference"):
                cells.append(ms(r["frame_ms"]))
            else:
                cells.append(f"{ms(r['frame_ms'])} ({r['ratio_to_reference']:.2f}×)")
        out.append(f"| {scene_name(scene)} | {size_name(size)} | {fragments:,} | " + " | ".join(cells) + " |")
    notes.write(out)


def pass_table(rows, styles, out):
    out.append("| scene | size | " + " | ".join(styles) + " |")
    out.append("|---|---|" + "---|" * len(styles))
    _, lines, cell = grouped(rows)
    for scene, size in lines:
        found = [cell.get((scene, size, s)) for s in styles]
        cells = ["failed" if r is None or "error" in r else passes(r) for r in found]
        out.append(f"| {scene_name(scene)} | {size_name(size)} | " + " | ".join(cells) + " |")


def floor_table(floors, out):
    out.append("| scene | size | style | pass | ms | MB read + written | floor ms at the GL copy | × floor |")
    out.append("|---|---|---|---|---:|---:|---:|---:|")
    notes = Footnotes()
    for size, f in floors:
        for r in f["rows"]:
            if "error" in r:
                failed = notes.cell(r["scene"], size, r["style"], r["error"])
                out.append(f"| {scene_name(r['scene'])} | {size_name(size)} | {r['style']} | {failed} | | | | |")
                continue
            gb = f["gl_copy_bandwidth"]
            mb = (r["bytes_read"] + r["bytes_written"]) / 1e6
            floor_ms = (r["bytes_read"] + r["bytes_written"]) / gb * 1e3 if gb > 0 else 0
            ratio = "—" if r["gl_ratio"] is None else f"{r['gl_ratio']:.1f}"  # nothing to move (a pass skipped)
            out.append(f"| {scene_name(r['scene'])} | {size_name(size)} | {r['style']} | {r['pass']} | {ms(r['ms'])} | "
                       f"{mb:.1f} | {floor_ms:.3f} | {ratio} |")
    notes.write(out)


def main():
    if len(sys.argv) != 2:
        raise SystemExit("usage: python3 bench/gpu_table.py OUT_DIR")
    d = sys.argv[1]
    every = load(os.path.join(d, "all.json"))
    gl = every["gl"]
    out = [f"tlab on **{gl['renderer']}** ({gl['vendor']}, OpenGL {gl['version']}, {gl['backend']})", ""]
    machine = os.path.join(d, "machine.txt")
    if os.path.exists(machine):
        with open(machine) as f:
            out += [f"    {line.rstrip()}" for line in f if line.strip()]
        out.append("")
    rows = every["rows"]
    out.append(f"Every style, ms per frame (median of {every['frames']} frames after a warm-up, the sum of the passes, "
               f"each ended by glFinish; in brackets × {every['reference_style']} on the same scene and size):")
    out.append("")
    style_table(rows, out)
    out += ["", "Passes of constant and smart (ms):", ""]
    pass_table(rows, ["constant", "smart"], out)
    floors = []
    for name in sorted(os.listdir(d)):
        if name.startswith("floor-") and name.endswith(".json"):
            floor = load(os.path.join(d, name), required=False)
            if floor is not None:
                floors.append((name[len("floor-"):-len(".json")], floor))
    floors.sort(key=lambda sf: [int(x) for x in sf[0].split("x")])
    if floors:
        copies = ", ".join(f"{f['gl_copy_bandwidth'] / 1e9:.0f} GB/s ({size_name(s)} run)" for s, f in floors)
        out += ["", f"Memory floor (tlab bench floor): each pass's bytes over this GL's streaming copy, {copies}:", ""]
        floor_table(floors, out)
    print("\n".join(out))


if __name__ == "__main__":
    main()
