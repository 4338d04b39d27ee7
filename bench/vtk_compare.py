#!/usr/bin/env python3
"""tlab's exact `constant` style against VTK's order-independent transparency on the same mesh,
view and image size, in one run on one GL (issues #19, #29: the peer a visualization user picks).

Run by hand, not in CI (it times things). Needs Debian's python3-vtk9 and an X display for VTK's
render window (Debian's VTK has no headless EGL window), e.g.:

    xvfb-run -a -s "-screen 0 1280x1024x24" /usr/bin/python3 bench/vtk_compare.py \
        [--mesh FILE.gltf|FILE.off|torus ...] [--camera "eye=... target=... up=... fovy=..."] [--size 512] [--rounds 3]

(Debian's python3, where python3-vtk9 installs the vtk module.)

Any glTF or OFF mesh (bench/bench_meshes.py says where public ones come from; an OFF file is
converted to glTF first, so both programs read the same file), or `torus`, a torus of --triangles
triangles (the default); --mesh may be repeated, and each round then times every mesh in turn. The camera is the same eye/target/up/fovy for both; without --camera it is
fitted to the mesh's bounding sphere as tlab fits it (from +z, or --view-from X,Y,Z). Every layer
has the same opacity (tlab: constant alpha; VTK: actor opacity). The two programs are timed in
alternation, --rounds times (the machine may be shared: each side's best round counts), each round
the median of --frames frames after a warm-up: tlab constant, VTK dual depth peeling (exact:
unlimited peels, occlusion ratio 0) and VTK weighted-average OIT. Prints every round, then a
table: each mesh's best of each side, the ratio tlab / VTK dual peeling, and the load average."""
import argparse
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bench_meshes  # noqa: E402


def vtk_frame_ms(mesh, size, camera, opacity, frames, mode, png=None):
    import vtk
    reader = vtk.vtkGLTFReader()
    reader.SetFileName(mesh)
    reader.Update()
    geometry = vtk.vtkCompositeDataGeometryFilter()
    geometry.SetInputConnection(reader.GetOutputPort())
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputConnection(geometry.GetOutputPort())
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetOpacity(opacity)
    actor.GetProperty().SetColor(0.9, 0.6, 0.3)
    actor.GetProperty().BackfaceCullingOff()
    ren = vtk.vtkRenderer()
    ren.AddActor(actor)
    ren.SetBackground(1, 1, 1)
    if mode == "dual-peeling":
        ren.SetUseDepthPeeling(1)  # VTK 9 peels two layers per pass (dual depth peeling)
        ren.SetMaximumNumberOfPeels(100)
        ren.SetOcclusionRatio(0.0)  # exact: peel until nothing is left
    else:
        ren.SetUseDepthPeeling(0)  # VTK's default: weighted-average order-independent transparency
    win = vtk.vtkRenderWindow()
    win.SetOffScreenRendering(1)
    win.SetMultiSamples(0)
    win.SetAlphaBitPlanes(1)
    win.AddRenderer(ren)
    win.SetSize(size, size)
    cam = ren.GetActiveCamera()
    cam.SetPosition(*camera["eye"])
    cam.SetFocalPoint(*camera["target"])
    cam.SetViewUp(*camera["up"])
    cam.SetViewAngle(camera["fovy"])
    ren.ResetCameraClippingRange()
    win.Render()
    win.WaitForCompletion()
    times = []
    for _ in range(frames):
        start = time.perf_counter()
        win.Render()
        win.WaitForCompletion()
        times.append((time.perf_counter() - start) * 1000.0)
    if png:  # the picture, to check both programs drew the same view
        grab = vtk.vtkWindowToImageFilter()
        grab.SetInput(win)
        writer = vtk.vtkPNGWriter()
        writer.SetFileName(png)
        writer.SetInputConnection(grab.GetOutputPort())
        writer.Write()
    info = win.ReportCapabilities().splitlines()
    renderer = next((l.split(":", 1)[1].strip() for l in info if "OpenGL renderer string" in l), "?")
    return statistics.median(times), renderer


def fitted_camera(mesh_positions, fovy=40.0, direction=(0.0, 0.0, 1.0)):
    """renderer/scene/camera.cpp fitCamera: the bounding box's centre, radius to the farthest vertex,
    a 5 % margin, seen from `direction`."""
    lo = [min(p[k] for p in mesh_positions) for k in range(3)]
    hi = [max(p[k] for p in mesh_positions) for k in range(3)]
    c = [(lo[k] + hi[k]) / 2 for k in range(3)]
    r = max(math.dist(c, p) for p in mesh_positions)
    d = math.hypot(*direction)
    distance = 1.05 * r / math.sin(math.radians(fovy) / 2)
    eye = [c[k] + direction[k] / d * distance for k in range(3)]
    up = "0,0,-1" if abs(direction[1] / d) > 0.99 else "0,1,0"
    fmt = lambda v: ",".join(f"{x:.6g}" for x in v)
    return f"eye={fmt(eye)} target={fmt(c)} up={up} fovy={fovy:g}"


def gltf_positions(path):
    """The POSITION accessor of a glTF file written by bench_meshes.write_gltf (one embedded buffer)."""
    import base64
    import struct
    doc = json.load(open(path))
    acc = doc["accessors"][doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"]]
    view = doc["bufferViews"][acc["bufferView"]]
    blob = base64.b64decode(doc["buffers"][view["buffer"]]["uri"].split(",", 1)[1])
    start = view.get("byteOffset", 0) + acc.get("byteOffset", 0)
    flat = struct.unpack_from(f"<{3 * acc['count']}f", blob, start)
    return [flat[i:i + 3] for i in range(0, len(flat), 3)]


def prepare_mesh(a, name, tmp):
    """The glTF file both programs read, a description of it, and its camera."""
    if name == "torus":
        path = os.path.join(tmp, "torus.gltf")
        pos, nrm, tris = bench_meshes.torus(a.triangles)
        n = bench_meshes.write_gltf(path, pos, tris, nrm)
        return path, f"generated torus, {n} triangles", a.camera or "eye=0,2.2,2.6 target=0,0,0 up=0,1,0 fovy=40"
    path, what = name, name
    if name.lower().endswith(".off"):
        path = os.path.join(tmp, os.path.splitext(os.path.basename(name))[0] + ".gltf")
        pos, tris = bench_meshes.weld(*bench_meshes.read_off(name))
        n = bench_meshes.write_gltf(path, pos, tris)
        what = f"{name} as glTF, {n} triangles"
    camera = a.camera or fitted_camera(gltf_positions(path), direction=[float(x) for x in a.view_from.split(",")])
    return path, what, camera


def tlab_frame(a, mesh, camera, exe):
    out = subprocess.run([exe, "bench", "render", "--scene", mesh, "--camera", camera, "--style", "constant",
                          "--set", f"alpha={a.opacity}", "--size", f"{a.size}x{a.size}", "--frames", str(a.frames),
                          "--gl", a.gl, "--json"], check=True, capture_output=True, text=True).stdout
    tlab = json.loads(out)
    return tlab["rows"][0], tlab["gl"]


def parse_camera(text):
    camera = {}
    for item in text.split():
        k, v = item.split("=")
        camera[k] = [float(x) for x in v.split(",")] if "," in v else float(v)
    return camera


def time_round(a, r, mesh, camera, best, fragments):
    """One round on one mesh: tlab (and the baseline), then each VTK mode; keeps each side's best."""
    for label, exe in [("tlab", a.tlab)] + ([("baseline", a.baseline)] if a.baseline else []):
        row, gl = tlab_frame(a, mesh, camera, exe)
        best[label] = min(best.get(label, math.inf), row["frame_ms"])
        fragments[mesh] = row["fragments"]
        passes = ", ".join(f"{k} {v:.1f}" for k, v in row["pass_ms"].items())
        print(f"round {r + 1}: {os.path.basename(mesh)}: {label} constant ({gl['backend']}, {gl['renderer']}): "
              f"{row['frame_ms']:.1f} ms/frame, {row['fragments']} fragments ({passes})", flush=True)
    for mode in a.modes.split(","):
        png = os.path.join(a.images, f"{os.path.basename(mesh)}-vtk-{mode}.png") if a.images and r == 0 else None
        if png:
            os.makedirs(a.images, exist_ok=True)
        ms, renderer = vtk_frame_ms(mesh, a.size, parse_camera(camera), a.opacity, a.frames, mode, png)
        best[mode] = min(best.get(mode, math.inf), ms)
        print(f"round {r + 1}: {os.path.basename(mesh)}: VTK {mode} ({renderer}): {ms:.1f} ms/frame", flush=True)


def print_table(a, meshes, best, fragments, loads):
    """Each mesh's best times and the ratios to VTK dual peeling, as a Markdown table."""
    labels = ["tlab"] + (["baseline"] if a.baseline else []) + a.modes.split(",")
    print(f"\nbest of {a.rounds} rounds (median of {a.frames} frames each), {a.size}x{a.size}, "
          f"load average {min(loads):.1f}-{max(loads):.1f}:")
    ratios = [l for l in ("tlab", "baseline") if l in labels] if "dual-peeling" in labels else []
    print("| mesh | fragments | " + " | ".join(f"{l} ms" for l in labels) + "".join(f" | {l} / dual peeling" for l in ratios) + " |")
    print("|---" * (2 + len(labels) + len(ratios)) + "|")
    for mesh, what, _ in meshes:
        b = best[mesh]
        cells = [f"{b[l]:.1f}" for l in labels] + [f"{b[l] / b['dual-peeling']:.2f}" for l in ratios]
        print(f"| {what} | {fragments[mesh]} | " + " | ".join(cells) + " |")
    if ratios:
        print("(goal: tlab / VTK dual peeling <= 0.5)")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--tlab", default=os.path.join(os.path.dirname(__file__), "..", "build", "bin", "tlab"))
    ap.add_argument("--baseline", help="another tlab executable (e.g. a build before a change), timed in the same rounds")
    ap.add_argument("--mesh", action="append", help="a glTF or OFF mesh, or 'torus' (the generated torus); repeat it "
                    "to time several meshes in one run, round by round (default: the torus)")
    ap.add_argument("--triangles", type=int, default=100000)
    ap.add_argument("--size", type=int, default=512)
    ap.add_argument("--frames", type=int, default=5)
    ap.add_argument("--rounds", type=int, default=3, help="alternating rounds; each side's best counts")
    ap.add_argument("--opacity", type=float, default=0.3)
    ap.add_argument("--camera", help="eye=X,Y,Z target=X,Y,Z up=X,Y,Z fovy=DEG for every mesh (default: the torus "
                    "view 'eye=0,2.2,2.6 target=0,0,0 up=0,1,0 fovy=40' for the torus, else fitted)")
    ap.add_argument("--view-from", default="0,0,1", help="direction of the fitted camera")
    ap.add_argument("--modes", default="dual-peeling,weighted-oit", help="VTK modes to time")
    ap.add_argument("--gl", default="auto", help="tlab's --gl")
    ap.add_argument("--images", help="also write MESH-tlab.png and MESH-vtk-MODE.png of each view into this folder")
    a = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        meshes = [prepare_mesh(a, name, tmp) for name in (a.mesh or ["torus"])]
        for mesh, what, camera in meshes:
            print(f"mesh: {what}; camera: {camera}")
        best = {mesh: {} for mesh, _, _ in meshes}
        fragments, loads = {}, []
        for r in range(a.rounds):
            for mesh, _, camera in meshes:
                time_round(a, r, mesh, camera, best[mesh], fragments)
                loads.append(os.getloadavg()[0])
        for mesh, _, camera in meshes if a.images else []:
            subprocess.run([a.tlab, "render", mesh, "--camera", camera, "--style", "constant", "--set", f"alpha={a.opacity}",
                            "--size", f"{a.size}x{a.size}", "--gl", a.gl,
                            "-o", os.path.join(a.images, f"{os.path.basename(mesh)}-tlab.png")], check=True, capture_output=True)
        print_table(a, meshes, best, fragments, loads)


if __name__ == "__main__":
    sys.exit(main())
