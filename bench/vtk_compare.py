#!/usr/bin/env python3
"""tlab's exact `constant` style against VTK's order-independent transparency on the same glTF
mesh, view and image size, in one run on one GL (issue #19: the peer a visualization user picks).

Run by hand, not in CI (it times things). Needs Debian's python3-vtk9 and an X display for VTK's
render window (Debian's VTK has no headless EGL window), e.g.:

    xvfb-run -a -s "-screen 0 1280x1024x24" /usr/bin/python3 bench/vtk_compare.py [--mesh FILE.gltf] [--size 512]

(Debian's python3, where python3-vtk9 installs the vtk module.)

Without --mesh it writes a torus of --triangles triangles as glTF (positions, normals, indices) so
both programs read the same file. The camera is the same eye/target/up/fovy for both; every layer
has the same opacity (tlab: constant alpha; VTK: actor opacity). Prints per-frame ms (median over
--frames after a warm-up) for tlab constant, VTK dual depth peeling and VTK weighted-average OIT,
and the ratio tlab / VTK dual peeling."""
import argparse
import base64
import json
import math
import os
import statistics
import struct
import subprocess
import sys
import tempfile
import time


def torus_gltf(path, triangles, major=1.0, minor=0.4):
    """A torus as a glTF 2.0 file with an embedded buffer: u x v quads, two triangles each."""
    v = max(3, int(math.sqrt(triangles / 2 / 2.5)))
    u = max(3, int(triangles / 2 / v))
    pos, nrm, idx = [], [], []
    for i in range(u):
        a = 2 * math.pi * i / u
        for j in range(v):
            b = 2 * math.pi * j / v
            c = (math.cos(b), math.sin(b))
            pos += [(major + minor * c[0]) * math.cos(a), minor * c[1], (major + minor * c[0]) * math.sin(a)]
            nrm += [c[0] * math.cos(a), c[1], c[0] * math.sin(a)]
    for i in range(u):
        for j in range(v):
            p0, p1 = i * v + j, ((i + 1) % u) * v + j
            p2, p3 = ((i + 1) % u) * v + (j + 1) % v, i * v + (j + 1) % v
            idx += [p0, p2, p1, p0, p3, p2]
    blob = struct.pack(f"<{len(pos)}f", *pos) + struct.pack(f"<{len(nrm)}f", *nrm) + struct.pack(f"<{len(idx)}I", *idx)
    n, fb = len(pos) // 3, len(pos) * 4
    doc = {
        "asset": {"version": "2.0", "generator": "tlab bench/vtk_compare.py"},
        "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2}]}],
        "buffers": [{"byteLength": len(blob), "uri": "data:application/octet-stream;base64," + base64.b64encode(blob).decode()}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": fb, "target": 34962},
                        {"buffer": 0, "byteOffset": fb, "byteLength": fb, "target": 34962},
                        {"buffer": 0, "byteOffset": 2 * fb, "byteLength": len(idx) * 4, "target": 34963}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": n, "type": "VEC3",
             "min": [min(pos[k::3]) for k in range(3)], "max": [max(pos[k::3]) for k in range(3)]},
            {"bufferView": 1, "componentType": 5126, "count": n, "type": "VEC3"},
            {"bufferView": 2, "componentType": 5125, "count": len(idx), "type": "SCALAR"}],
    }
    with open(path, "w") as f:
        json.dump(doc, f)
    return len(idx) // 3


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


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--tlab", default=os.path.join(os.path.dirname(__file__), "..", "build", "bin", "tlab"))
    ap.add_argument("--mesh", help="a glTF mesh (default: a generated torus)")
    ap.add_argument("--triangles", type=int, default=100000)
    ap.add_argument("--size", type=int, default=512)
    ap.add_argument("--frames", type=int, default=5)
    ap.add_argument("--opacity", type=float, default=0.3)
    ap.add_argument("--camera", default="eye=0,2.2,2.6 target=0,0,0 up=0,1,0 fovy=40")
    ap.add_argument("--gl", default="auto", help="tlab's --gl")
    ap.add_argument("--images", help="also write tlab.png and vtk-MODE.png of the view into this folder")
    a = ap.parse_args()
    camera = {}
    for item in a.camera.split():
        k, v = item.split("=")
        camera[k] = [float(x) for x in v.split(",")] if "," in v else float(v)
    with tempfile.TemporaryDirectory() as tmp:
        mesh = a.mesh
        if not mesh:
            mesh = os.path.join(tmp, "torus.gltf")
            n = torus_gltf(mesh, a.triangles)
            print(f"mesh: generated torus, {n} triangles")
        out = subprocess.run([a.tlab, "bench", "render", "--scene", mesh, "--camera", a.camera, "--style", "constant",
                              "--set", f"alpha={a.opacity}", "--size", f"{a.size}x{a.size}", "--frames", str(a.frames),
                              "--gl", a.gl, "--json"], check=True, capture_output=True, text=True).stdout
        tlab = json.loads(out)
        row = tlab["rows"][0]
        print(f"tlab constant ({tlab['gl']['backend']}, {tlab['gl']['renderer']}): {row['frame_ms']:.1f} ms/frame, "
              f"{row['fragments']} fragments, passes {row['pass_ms']}")
        if a.images:
            os.makedirs(a.images, exist_ok=True)
            subprocess.run([a.tlab, "render", mesh, "--camera", a.camera, "--style", "constant", "--set", f"alpha={a.opacity}",
                            "--size", f"{a.size}x{a.size}", "--gl", a.gl, "-o", os.path.join(a.images, "tlab.png")],
                           check=True, capture_output=True)
        results = {}
        for mode in ("dual-peeling", "weighted-oit"):
            png = os.path.join(a.images, f"vtk-{mode}.png") if a.images else None
            ms, renderer = vtk_frame_ms(mesh, a.size, camera, a.opacity, a.frames, mode, png)
            results[mode] = ms
            print(f"VTK {mode} ({renderer}): {ms:.1f} ms/frame")
        print(f"ratio tlab constant / VTK dual peeling = {row['frame_ms'] / results['dual-peeling']:.2f} "
              f"(goal <= 0.5), at {a.size}x{a.size}, median of {a.frames} frames, load {os.getloadavg()[0]:.1f}")


if __name__ == "__main__":
    sys.exit(main())
