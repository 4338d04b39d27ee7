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


class MeshError(Exception):
    """A mesh file this script cannot read: the message names the file (and line)."""


def read_text(path):
    """A text file's contents; MeshError for one that is not text (a binary file given by mistake)."""
    try:
        with open(path) as f:
            return f.read()
    except UnicodeDecodeError:
        raise MeshError(f"{path}: not a text file") from None


def error_line(e):
    """The one line for a MeshError or an OSError (a file that cannot be read or written)."""
    return f"{e.filename}: {e.strerror}" if isinstance(e, OSError) and e.filename and e.strerror else str(e)


def off_lines(path):
    """(line number, numbers) for each line of an OFF file that holds something, comments dropped."""
    for number, line in enumerate(read_text(path).splitlines(), 1):
        words = line.split("#", 1)[0].split()
        if words:
            yield number, words


def read_off(path):
    """An OFF file (also COFF, NOFF, STOFF ...: a vertex line's first three numbers are its
    position, a face line's extra numbers its colour): vertices and polygons, fanned into triangles."""
    lines = off_lines(path)

    def next_line(what):
        try:
            return next(lines)
        except StopIteration:
            raise MeshError(f"{path}: ends before {what}") from None

    def numbers(number, words, kind, what):
        try:
            return [kind(w) for w in words]
        except ValueError:
            raise MeshError(f"{path}: line {number}: {what} expected, found '{' '.join(words)}'") from None

    number, words = next_line("its header")
    if not words[0].endswith("OFF"):
        raise MeshError(f"{path}: line {number}: not an OFF file (it starts with '{words[0]}', not OFF)")
    if len(words) > 1:  # the counts on the header's line
        counts = words[1:]
    else:
        number, counts = next_line("the vertex and face counts")
    nv, nf = numbers(number, counts[:2], int, "the vertex and face counts") if len(counts) >= 2 else (-1, -1)
    if nv < 0 or nf < 0:
        raise MeshError(f"{path}: line {number}: the vertex and face counts expected, found '{' '.join(counts)}'")
    positions = []
    for i in range(nv):
        number, words = next_line(f"vertex {i + 1} of {nv}")
        if len(words) < 3:
            raise MeshError(f"{path}: line {number}: a vertex (x y z) expected, found '{' '.join(words)}'")
        positions.append(numbers(number, words[:3], float, "a vertex (x y z)"))
    triangles = []
    for i in range(nf):
        number, words = next_line(f"face {i + 1} of {nf}")
        k = numbers(number, words[:1], int, "a face (n i1 ... in)")[0]
        if k < 0 or len(words) < 1 + k:
            raise MeshError(f"{path}: line {number}: a face of {k} vertex indices expected, found '{' '.join(words)}'")
        poly = numbers(number, words[1:1 + k], int, "a face (n i1 ... in)")
        bad = [v for v in poly if not 0 <= v < nv]
        if bad:
            raise MeshError(f"{path}: line {number}: vertex index {bad[0]} out of range (the file has {nv} vertices)")
        triangles += [(poly[0], poly[i], poly[i + 1]) for i in range(1, k - 1)]
    if not triangles:
        raise MeshError(f"{path}: no triangles (faces of three or more vertices)")
    return positions, triangles


def read_teapot_patches(header):
    """The first object of the Schneider archive quoted in fg_teapot_data.h: Newell's teapot (a
    line "Martin Newell's teapot", then one with the counts of points and patches, the numbered
    points, and the patches' 16 point numbers each)."""
    text = read_text(header)
    start = text.find("Martin Newell's teapot")
    if start < 0:
        raise MeshError(f"{header}: no \"Martin Newell's teapot\" (freeglut's src/fg_teapot_data.h has it)")
    first = text.count("\n", 0, start) + 2  # the line number of lines[0]
    lines = text[start:].splitlines()[1:]

    def line(row, what):
        if row >= len(lines):
            raise MeshError(f"{header}: ends before {what}")
        return lines[row]

    def bad(row, what):
        return MeshError(f"{header}: line {first + row}: {what} expected, found '{lines[row].strip()}'")

    try:
        nv, _, npatch, _ = (int(x) for x in line(0, "the counts").split())
    except ValueError:
        raise bad(0, "the counts (points, 0, patches, 0)") from None
    points, patches, row = {}, [], 1
    while len(points) < nv:
        parts = line(row, f"point {len(points) + 1} of {nv}").split()
        if parts:
            try:
                if len(parts) < 4:
                    raise ValueError
                points[int(parts[0])] = [float(x) for x in parts[1:4]]
            except ValueError:
                raise bad(row, "a point (number x y z)") from None
        row += 1
    numbers = []
    while len(patches) < npatch:
        numbers += [int(x) for x in re.findall(r"-?\d+", line(row, f"patch {len(patches) + 1} of {npatch}"))]
        row += 1
        while len(numbers) >= 16:
            patch = [abs(i) for i in numbers[:16]]
            missing = [i for i in patch if i not in points]
            if missing:
                raise MeshError(f"{header}: line {first + row - 1}: patch {len(patches) + 1} names point {missing[0]}, "
                                f"which is not among the {nv} points")
            patches.append(patch)
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


class OneLineParser(argparse.ArgumentParser):
    """Usage errors in one line, as tlab's own."""

    def error(self, message):
        self.exit(2, f"{self.prog}: error: {message} (see --help)\n")


def main():
    ap = OneLineParser(description=__doc__.splitlines()[0])
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
    for name in ("triangles", "layers", "grid", "steps"):
        if getattr(a, name, 1) < 1:
            ap.error(f"--{name} must be at least 1")
    try:
        if a.kind in ("torus", "stack"):
            pos, nrm, tris = torus(a.triangles) if a.kind == "torus" else stack(a.layers, a.grid)
            n = write_gltf(a.output, pos, tris, nrm)
        else:
            pos, tris = read_off(a.input) if a.kind == "off" else teapot(a.header, a.steps)
            pos, tris = weld(pos, tris)
            n = write_gltf(a.output, pos, tris)
    except (MeshError, OSError) as e:
        print(f"bench_meshes.py: error: {error_line(e)}", file=sys.stderr)
        return 1
    print(f"{a.output}: {n} triangles")


if __name__ == "__main__":
    sys.exit(main())
