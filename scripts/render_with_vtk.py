#!/usr/bin/env python3
"""Draws a scene exported by `tlab scene export SCENE -o scene.glb` with VTK, from the camera in
the file, at the image size in the file: another renderer's picture of tlab's view (issue #28).

    xvfb-run -a /usr/bin/python3 scripts/render_with_vtk.py scene.glb out.png [--shift DX,DY,DZ] [--flip]

Debian's python3-vtk9 needs an X display for its render window (hence xvfb-run). --shift moves
the eye and the focal point by a world-space offset and --flip writes the image upside down: the
two mistakes tlab's alignment check must catch.

The camera follows the README's conventions: the camera node's world matrix places the eye at
its origin looking down its -Z axis with +Y up; yfov is the vertical field of view in radians;
aspectRatio = width / height; the image's row 0 is the top."""
import argparse
import json
import math
import struct
import sys


def read_glb_json(path):
    with open(path, "rb") as f:
        data = f.read()
    if data[:4] != b"glTF":
        with open(path) as f:
            return json.load(f)
    length, kind = struct.unpack_from("<II", data, 12)
    if kind != 0x4E4F534A:  # "JSON"
        raise SystemExit(f"{path}: the first GLB chunk is not JSON")
    return json.loads(data[20:20 + length])


def tlab_camera(doc):
    """Eye, focal point, up, vertical angle (degrees), near, far and image size from the file."""
    for node in doc["nodes"]:
        if "camera" not in node:
            continue
        m = node.get("matrix", [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1])  # column-major
        eye = m[12:15]
        forward = [-m[8], -m[9], -m[10]]
        up = m[4:7]
        p = doc["cameras"][node["camera"]]["perspective"]
        size = doc["scenes"][doc.get("scene", 0)]["extras"]["tlab_image_size"]
        return eye, forward, up, math.degrees(p["yfov"]), p["znear"], p.get("zfar", p["znear"] * 1e4), size
    raise SystemExit("no camera node in the file (export it with tlab scene export)")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("scene")
    ap.add_argument("png")
    ap.add_argument("--shift", default="0,0,0", help="move the camera by DX,DY,DZ (world units)")
    ap.add_argument("--flip", action="store_true", help="write the picture upside down")
    a = ap.parse_args()
    import vtk
    doc = read_glb_json(a.scene)
    eye, forward, up, fovy, near, far, (width, height) = tlab_camera(doc)
    shift = [float(v) for v in a.shift.split(",")]
    eye = [e + s for e, s in zip(eye, shift)]
    reader = vtk.vtkGLTFReader()
    reader.SetFileName(a.scene)
    reader.Update()
    geometry = vtk.vtkCompositeDataGeometryFilter()
    geometry.SetInputConnection(reader.GetOutputPort())
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputConnection(geometry.GetOutputPort())
    mapper.ScalarVisibilityOff()
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(0.85, 0.55, 0.25)
    actor.GetProperty().BackfaceCullingOff()
    ren = vtk.vtkRenderer()
    ren.AddActor(actor)
    ren.SetBackground(1, 1, 1)
    win = vtk.vtkRenderWindow()
    win.SetOffScreenRendering(1)
    win.SetMultiSamples(0)
    win.AddRenderer(ren)
    win.SetSize(width, height)
    cam = ren.GetActiveCamera()
    cam.SetPosition(*eye)
    cam.SetFocalPoint(*[e + f for e, f in zip(eye, forward)])
    cam.SetViewUp(*up)
    cam.SetViewAngle(fovy)  # vertical, as tlab's fovy
    cam.SetClippingRange(near, far)
    win.Render()
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(win)
    grab.ReadFrontBufferOff()
    grab.Update()
    image = grab.GetOutput()
    if a.flip:
        flip = vtk.vtkImageFlip()
        flip.SetFilteredAxis(1)
        flip.SetInputData(image)
        flip.Update()
        image = flip.GetOutput()
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(a.png)
    writer.SetInputData(image)
    writer.Write()
    print(f"wrote {a.png} ({width}x{height}) eye {eye} fovy {fovy:.3f}")


if __name__ == "__main__":
    sys.exit(main())
