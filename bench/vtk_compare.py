#!/usr/bin/env python3
"""tlab's exact `constant` style against VTK's order-independent transparency on the same mesh,
view and image size, in one run on one GL (issues #19, #29: the peer a visualization user picks).

Run by hand, not in CI (it times things). Needs Debian's python3-vtk9 and an X display for VTK's
render window (Debian's VTK has no headless EGL window), e.g.:

    xvfb-run -a -s "-screen 0 1280x1024x24" /usr/bin/python3 bench/vtk_compare.py \
        [--mesh FILE.gltf|FILE.off|torus ...] [--camera "eye=... target=... up=... fovy=..."] [--size 512] [--rounds 3]

(Debian's python3, where python3-vtk9 installs the vtk module.)

Any glTF or GLB file (every mesh in it, placed by its nodes) or OFF mesh (bench/bench_meshes.py
says where public ones come from; an OFF file is converted to glTF first, so both programs read
the same file), or `torus`, a torus of --triangles triangles (the default); --mesh may be
repeated, and each round then times every mesh in turn. The camera is the same
eye/target/up/fovy for both; without --camera it is fitted to the mesh's vertices (as VTK reads
them) as tlab fits it (from +z, or --view-from X,Y,Z). A bad file or option is one line on stderr
naming it, and exit code 1 (2 for an option). Every layer
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


def mesh_positions(path):
    """Every vertex of a glTF or GLB file as VTK reads it (all meshes, placed by their nodes), for
    the fitted camera; bench_meshes.MeshError where VTK finds none (a broken or empty file)."""
    import vtk
    vtk.vtkObject.GlobalWarningDisplayOff()  # a broken file: our one line, not VTK's pages
    reader = vtk.vtkGLTFReader()
    reader.SetFileName(path)
    reader.Update()
    geometry = vtk.vtkCompositeDataGeometryFilter()
    geometry.SetInputConnection(reader.GetOutputPort())
    geometry.Update()
    points = geometry.GetOutput().GetPoints()
    if points is None or points.GetNumberOfPoints() == 0 or geometry.GetOutput().GetNumberOfPolys() == 0:
        raise bench_meshes.MeshError(f"{path}: VTK's glTF reader found no triangles in it (a broken or empty glTF file?)")
    return [points.GetPoint(i) for i in range(points.GetNumberOfPoints())]


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
    camera = a.camera or fitted_camera(mesh_positions(path), direction=a.view_from)
    return path, what, camera


def run_tlab(exe, args, mesh):
    """tlab's stdout; bench_meshes.MeshError with tlab's own one-line message where it fails."""
    done = subprocess.run([exe] + args, capture_output=True, text=True)
    if done.returncode != 0:
        why = (done.stderr.strip().splitlines() or [f"exit code {done.returncode}"])[-1]
        command = " ".join(args[:2] if args[0] == "bench" else args[:1])
        raise bench_meshes.MeshError(f"{mesh}: tlab {command} failed: {why}")
    return done.stdout


def tlab_frame(a, mesh, camera, exe):
    out = run_tlab(exe, ["bench", "render", "--scene", mesh, "--camera", camera, "--style", "constant",
                         "--set", f"alpha={a.opacity}", "--size", f"{a.size}x{a.size}", "--frames", str(a.frames),
                         "--gl", a.gl, "--json"], a.labels[mesh])
    tlab = json.loads(out)
    return tlab["rows"][0], tlab["gl"]


def parse_camera(text):
    """'eye=X,Y,Z target=X,Y,Z up=X,Y,Z fovy=DEG' (near=, far= allowed) as a dict; ValueError naming
    what is wrong."""
    camera = {}
    for item in text.split():
        k, _, v = item.partition("=")
        try:
            camera[k] = [float(x) for x in v.split(",")] if "," in v else float(v)
        except ValueError:
            raise ValueError(f"'{item}' is not KEY=NUMBER or KEY=X,Y,Z") from None
    for k, n in (("eye", 3), ("target", 3), ("up", 3), ("fovy", None)):
        if k not in camera:
            raise ValueError(f"no {k}=")
        if n and (not isinstance(camera[k], list) or len(camera[k]) != n):
            raise ValueError(f"{k}= needs {n} numbers")
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
    ap = bench_meshes.OneLineParser(description=__doc__.splitlines()[0])
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
    check_options(ap, a)
    try:
        run(a)
    except (bench_meshes.MeshError, OSError) as e:
        print(f"vtk_compare.py: error: {bench_meshes.error_line(e)}", file=sys.stderr)
        return 1


def check_options(ap, a):
    """Every option that would fail later, refused before anything runs (one line, exit 2)."""
    for name in ("triangles", "size", "frames", "rounds"):
        if getattr(a, name) < 1:
            ap.error(f"--{name} must be at least 1")
    if not 0 < a.opacity <= 1:
        ap.error("--opacity must be in (0, 1]")
    unknown = [m for m in a.modes.split(",") if m not in ("dual-peeling", "weighted-oit")]
    if unknown:
        ap.error(f"--modes: '{unknown[0]}' is not dual-peeling or weighted-oit")
    try:
        if a.camera:
            parse_camera(a.camera)
    except ValueError as e:
        ap.error(f"--camera: {e}")
    try:
        a.view_from = [float(x) for x in a.view_from.split(",")]
        if len(a.view_from) != 3 or math.hypot(*a.view_from) == 0:
            raise ValueError
    except ValueError:
        ap.error("--view-from: a direction X,Y,Z (not all 0) expected")
    for name in a.mesh or []:
        if name != "torus" and not os.path.isfile(name):
            ap.error(f"--mesh {name}: no such file")
        if name != "torus" and not name.lower().endswith((".gltf", ".glb", ".off")):
            ap.error(f"--mesh {name}: a .gltf, .glb or .off file (or torus) expected")
    for option, exe in (("--tlab", a.tlab), ("--baseline", a.baseline)):
        if exe and not os.access(exe, os.X_OK):
            ap.error(f"{option} {exe}: not an executable (build tlab first, or give {option})")


def run(a):
    with tempfile.TemporaryDirectory() as tmp:
        names = a.mesh or ["torus"]
        meshes = [prepare_mesh(a, name, tmp) for name in names]
        a.labels = {mesh: "the generated torus" if name == "torus" else name for (mesh, _, _), name in zip(meshes, names)}
        for mesh, what, camera in meshes:
            print(f"mesh: {what}; camera: {camera}")
        best = {mesh: {} for mesh, _, _ in meshes}
        fragments, loads = {}, []
        for r in range(a.rounds):
            for mesh, _, camera in meshes:
                time_round(a, r, mesh, camera, best[mesh], fragments)
                loads.append(os.getloadavg()[0])
        for mesh, _, camera in meshes if a.images else []:
            run_tlab(a.tlab, ["render", mesh, "--camera", camera, "--style", "constant", "--set", f"alpha={a.opacity}",
                              "--size", f"{a.size}x{a.size}", "--gl", a.gl,
                              "-o", os.path.join(a.images, f"{os.path.basename(mesh)}-tlab.png")], a.labels[mesh])
        print_table(a, meshes, best, fragments, loads)


if __name__ == "__main__":
    sys.exit(main())
