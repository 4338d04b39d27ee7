#!/usr/bin/env python3
"""Public meshes for tlab's benchmarks, written as glTF 2.0 files (positions, per-vertex normals,
indices) that both `tlab` and VTK read (bench/vtk_compare.py). Nothing here is committed: the
meshes come from Debian packages, or are generated.

    python3 bench/bench_meshes.py off FILE.off OUT.gltf
        any OFF mesh, e.g. the Stanford bunny, fandisk (CAD) or the elephant from Debian's
        libcgal-demo (/usr/share/doc/libcgal-dev/data.tar.gz: data/meshes/bunny00.off, ...)
    python3 bench/bench_meshes.py teapot fg_teapot_data.h OUT.gltf [--steps N]
        Newell's teapot (28 bicubic Bezier patches, 269 control points), read from the original
        control points quoted in freeglut's source (Debian source package freeglut,
        src/fg_teapot_data.h), each patch tessellated into N x N quads
    python3 bench/bench_meshes.py torus OUT.gltf [--triangles N]
        the torus bench/vtk_compare.py generates without --mesh
    python3 bench/bench_meshes.py stack OUT.gltf [--layers 16] [--grid 32]
        a deep stack: --layers parallel squares (2 x 2, facing +z, evenly spaced in z over [-1, 1]),
        each --grid x --grid quads, so a view from +z sees --layers layers over most of the picture

Vertex normals are the area-weighted averages of the faces around each vertex (after welding
vertices that share a position, so patch seams and the teapot's poles are smooth)."""
import argparse
import base64
import json
import math
import re
import struct
import sys


def weld(positions, triangles, digits=6):
    """Merges vertices with the same rounded position; drops triangles that become degenerate."""
    key_of, out, remap = {}, [], []
    for p in positions:
        k = tuple(round(c, digits) for c in p)
        if k not in key_of:
            key_of[k] = len(out)
            out.append(p)
        remap.append(key_of[k])
    tris = []
    for t in triangles:
        a, b, c = (remap[i] for i in t)
        if a != b and b != c and a != c:
            tris.append((a, b, c))
    return out, tris


def vertex_normals(positions, triangles):
    """Area-weighted face normals summed at each vertex, normalised."""
    acc = [[0.0, 0.0, 0.0] for _ in positions]
    for a, b, c in triangles:
        pa, pb, pc = positions[a], positions[b], positions[c]
        u = [pb[k] - pa[k] for k in range(3)]
        v = [pc[k] - pa[k] for k in range(3)]
        n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
        for i in (a, b, c):
            for k in range(3):
                acc[i][k] += n[k]
    out = []
    for n in acc:
        length = math.sqrt(n[0] ** 2 + n[1] ** 2 + n[2] ** 2)
        out.append([x / length for x in n] if length > 0 else [0.0, 0.0, 1.0])
    return out


def write_gltf(path, positions, triangles, normals=None, generator="tlab bench/bench_meshes.py"):
    """A glTF 2.0 file with one embedded buffer; returns the triangle count."""
    if normals is None:
        normals = vertex_normals(positions, triangles)
    pos = [c for p in positions for c in p]
    nrm = [c for n in normals for c in n]
    idx = [i for t in triangles for i in t]
    blob = struct.pack(f"<{len(pos)}f", *pos) + struct.pack(f"<{len(nrm)}f", *nrm) + struct.pack(f"<{len(idx)}I", *idx)
    n, fb = len(positions), len(pos) * 4
    doc = {
        "asset": {"version": "2.0", "generator": generator},
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
    return len(triangles)


def read_off(path):
    """An OFF file: vertices and polygons (fanned into triangles)."""
    with open(path) as f:
        words = [w for line in f for w in line.split("#", 1)[0].split()]
    if not words or not words[0].endswith("OFF"):
        raise ValueError(f"{path}: not an OFF file")
    nv, nf = int(words[1]), int(words[2])
    at = 4
    positions = []
    for _ in range(nv):
        positions.append([float(x) for x in words[at:at + 3]])
        at += 3
    triangles = []
    for _ in range(nf):
        k = int(words[at])
        poly = [int(x) for x in words[at + 1:at + 1 + k]]
        at += 1 + k
        triangles += [(poly[0], poly[i], poly[i + 1]) for i in range(1, k - 1)]
    return positions, triangles


def read_teapot_patches(header):
    """The first object of the Schneider archive quoted in fg_teapot_data.h: Newell's teapot."""
    text = open(header).read()
    start = text.index("Martin Newell's teapot")
    lines = text[start:].splitlines()[1:]
    nv, _, npatch, _ = (int(x) for x in lines[0].split())
    points, patches, row = {}, [], 1
    while len(points) < nv:
        parts = lines[row].split()
        row += 1
        if parts:
            points[int(parts[0])] = [float(x) for x in parts[1:4]]
    numbers = []
    while len(patches) < npatch:
        numbers += [int(x) for x in re.findall(r"-?\d+", lines[row])]
        row += 1
        while len(numbers) >= 16:
            patches.append([abs(i) for i in numbers[:16]])
            numbers = numbers[16:]
    return [[points[i] for i in p] for p in patches]


def bezier_patch(cp, steps):
    """(steps+1)^2 points of a bicubic Bezier patch with control points cp[4*i + j]."""
    def bernstein(t):
        s = 1 - t
        return (s * s * s, 3 * t * s * s, 3 * t * t * s, t * t * t)
    grid = []
    for a in range(steps + 1):
        bu = bernstein(a / steps)
        for b in range(steps + 1):
            bv = bernstein(b / steps)
            grid.append([sum(bu[i] * bv[j] * cp[4 * i + j][k] for i in range(4) for j in range(4)) for k in range(3)])
    return grid


def teapot(header, steps):
    positions, triangles = [], []
    for cp in read_teapot_patches(header):
        base = len(positions)
        positions += bezier_patch(cp, steps)
        for a in range(steps):
            for b in range(steps):
                p0 = base + a * (steps + 1) + b
                p1, p2, p3 = p0 + 1, p0 + steps + 2, p0 + steps + 1
                triangles += [(p0, p1, p2), (p0, p2, p3)]
    return positions, triangles


def torus(triangles, major=1.0, minor=0.4):
    """u x v quads, two triangles each, with analytic normals (the torus vtk_compare.py generates)."""
    v = max(3, int(math.sqrt(triangles / 2 / 2.5)))
    u = max(3, int(triangles / 2 / v))
    pos, nrm, tris = [], [], []
    for i in range(u):
        a = 2 * math.pi * i / u
        for j in range(v):
            b = 2 * math.pi * j / v
            c = (math.cos(b), math.sin(b))
            pos.append([(major + minor * c[0]) * math.cos(a), minor * c[1], (major + minor * c[0]) * math.sin(a)])
            nrm.append([c[0] * math.cos(a), c[1], c[0] * math.sin(a)])
    for i in range(u):
        for j in range(v):
            p0, p1 = i * v + j, ((i + 1) % u) * v + j
            p2, p3 = ((i + 1) % u) * v + (j + 1) % v, i * v + (j + 1) % v
            tris += [(p0, p2, p1), (p0, p3, p2)]
    return pos, nrm, tris


def stack(layers, grid):
    """`layers` squares of grid x grid quads each, at z evenly spaced over [-1, 1]."""
    pos, nrm, tris = [], [], []
    for layer in range(layers):
        z = -1.0 + 2.0 * layer / max(1, layers - 1)
        base = len(pos)
        for i in range(grid + 1):
            for j in range(grid + 1):
                pos.append([-1.0 + 2.0 * j / grid, -1.0 + 2.0 * i / grid, z])
                nrm.append([0.0, 0.0, 1.0])
        for i in range(grid):
            for j in range(grid):
                p0 = base + i * (grid + 1) + j
                tris += [(p0, p0 + 1, p0 + grid + 2), (p0, p0 + grid + 2, p0 + grid + 1)]
    return pos, nrm, tris


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = ap.add_subparsers(dest="kind", required=True)
    o = sub.add_parser("off")
    o.add_argument("input")
    o.add_argument("output")
    t = sub.add_parser("teapot")
    t.add_argument("header", help="freeglut's src/fg_teapot_data.h")
    t.add_argument("output")
    t.add_argument("--steps", type=int, default=6)
    r = sub.add_parser("torus")
    r.add_argument("output")
    r.add_argument("--triangles", type=int, default=100000)
    k = sub.add_parser("stack")
    k.add_argument("output")
    k.add_argument("--layers", type=int, default=16)
    k.add_argument("--grid", type=int, default=32)
    a = ap.parse_args()
    if a.kind in ("torus", "stack"):
        pos, nrm, tris = torus(a.triangles) if a.kind == "torus" else stack(a.layers, a.grid)
        n = write_gltf(a.output, pos, tris, nrm)
    else:
        pos, tris = read_off(a.input) if a.kind == "off" else teapot(a.header, a.steps)
        pos, tris = weld(pos, tris)
        n = write_gltf(a.output, pos, tris)
    print(f"{a.output}: {n} triangles")


if __name__ == "__main__":
    sys.exit(main())
