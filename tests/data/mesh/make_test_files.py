#!/usr/bin/env python3
"""Writes the small surface files used by tests/mesh (run from this folder).
Good files: a tetrahedron or unit cube in every format the reader knows.
Bad files: one defect each, for the validation messages."""
import math
import struct

# Unit tetrahedron, faces counter-clockwise seen from outside (volume 1/6).
TV = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
TF = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]
# Unit cube as quads (vertex = x + 2y + 4z), outward (volume 1).
CV = [(x, y, z) for z in (0, 1) for y in (0, 1) for x in (0, 1)]
CQ = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]


def write(name, text):
    with open(name, "w", newline="\n") as f:
        f.write(text)


def off(name, V, F, header="OFF\n"):
    s = header + "%d %d 0\n" % (len(V), len(F))
    s += "".join("%r %r %r\n" % tuple(map(float, v)) for v in V)
    s += "".join("%d %s\n" % (len(f), " ".join(map(str, f))) for f in F)
    write(name, s)


def normal(a, b, c):
    u = [b[i] - a[i] for i in range(3)]
    w = [c[i] - a[i] for i in range(3)]
    n = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]]
    l = math.sqrt(sum(x * x for x in n)) or 1.0
    return [x / l for x in n]


def binary_stl(V, F, header):
    b = header.ljust(80, b" ")[:80] + struct.pack("<I", len(F))
    for f in F:
        p = [V[i] for i in f]
        b += struct.pack("<3f", *normal(*p))
        for q in p:
            b += struct.pack("<3f", *q)
        b += b"\0\0"
    return b


# ---- good files ----
s = "solid tetra made by hand\n"
for f in TF:
    p = [TV[i] for i in f]
    s += "  facet normal %g %g %g\n    outer loop\n" % tuple(normal(*p))
    s += "".join("      vertex %g %g %g\n" % q for q in p)
    s += "    endloop\n  endfacet\n"
s += "endsolid tetra made by hand\n"
write("tetra_ascii.stl", s)
# A binary STL whose header starts with "solid", as some exporters write it.
open("tetra_binary.stl", "wb").write(binary_stl(TV, TF, b"solid but binary"))

obj = "# unit cube, quads, v/vt/vn forms\nmtllib none.mtl\no cube\n"
obj += "".join("v %g %g %g\n" % v for v in CV)
obj += "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\n"
forms = ["%d", "%d/1", "%d//1", "%d/1/1"]
for k, q in enumerate(CQ):
    obj += "f " + " ".join(forms[(k + j) % 4] % (i + 1) for j, i in enumerate(q)) + "\n"
write("cube_quads.obj", obj)

obj = "".join("v %g %g %g 0.5 0.25 1.0\n" % v for v in TV)  # RGB after xyz
obj += "".join("f %d %d %d\n" % tuple(i - 4 for i in f) for f in TF)  # negative (relative) indices
write("tetra_rgb.obj", obj)

s = "OFF\n# unit cube with quad faces and face colours\n8 6 12\n"
s += "".join("%g %g %g\n" % v for v in CV)
s += "".join("4 %d %d %d %d 255 0 0\n" % q for q in CQ)
write("cube.off", s)
off("tetra_off_content.txt", TV, TF)  # OFF content, extension says nothing

ply = "ply\nformat ascii 1.0\ncomment unit tetrahedron\nelement vertex 4\n"
ply += "property float x\nproperty float y\nproperty float z\nproperty float nx\nproperty float ny\nproperty float nz\n"
ply += "element face 4\nproperty list uchar int vertex_indices\nend_header\n"
ply += "".join("%g %g %g 0 0 1\n" % v for v in TV)
ply += "".join("3 %d %d %d\n" % f for f in TF)
write("tetra_ascii.ply", ply)


def binary_ply(order, fmt_name):
    h = ("ply\nformat %s 1.0\nelement vertex 4\nproperty double x\nproperty double y\nproperty double z\n"
         "property uchar red\nproperty uchar green\nproperty uchar blue\n"
         "element face 4\nproperty list uchar uint vertex_indices\nproperty float quality\n"
         "element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n" % fmt_name).encode()
    b = h
    for v in TV:
        b += struct.pack(order + "3d3B", *v, 200, 100, 50)
    for f in TF:
        b += struct.pack(order + "B3If", 3, *f, 0.5)
    b += struct.pack(order + "2i", 0, 1)
    return b


open("tetra_binary_le.ply", "wb").write(binary_ply("<", "binary_little_endian"))
open("tetra_binary_be.ply", "wb").write(binary_ply(">", "binary_big_endian"))

# ---- bad files ----
open("empty.stl", "wb").write(b"")
open("truncated_binary.stl", "wb").write(binary_stl(TV, TF, b"tetra")[:84 + 50 * 2 + 20])
write("truncated.off", "OFF\n4 4 0\n" + "".join("%g %g %g\n" % v for v in TV) + "3 0 2 1\n3 0 1 3\n")
open("truncated_binary_le.ply", "wb").write(binary_ply("<", "binary_little_endian")[:-40])
write("unknown.dat", "this is not a surface\n1 2 3\n")
open("unknown_binary.bin", "wb").write(bytes(range(256)) * 2)
write("nan.obj", "v 0 0 0\nv 1 0 0\nv 0 nan 0\nv 0 0 1\n" + "".join("f %d %d %d\n" % tuple(i + 1 for i in f) for f in TF))
write("inf.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 inf\n" + "".join("3 %d %d %d\n" % f for f in TF))
write("bad_index.off", "OFF\n4 4 0\n" + "".join("%g %g %g\n" % v for v in TV) + "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 7\n")
obj = "".join("v %g %g %g\n" % v for v in CV)
obj += "".join("f %d %d %d %d\n" % tuple(i + 1 for i in q) for q in CQ if q != (4, 5, 7, 6))  # no top
write("open_box.obj", obj)
# Two tetrahedra sharing the edge 0-1 (a rotated copy): edge in four faces.
TB = TV + [(0, -1, 0), (0, 0, -1)]
off("nonmanifold_edge.off", TB, TF + [(0, 4, 1), (0, 1, 5), (0, 5, 4), (1, 4, 5)])
# Two tetrahedra sharing only vertex 0 (point reflection, faces reversed).
TR = TV + [(-1, 0, 0), (0, -1, 0), (0, 0, -1)]
off("nonmanifold_vertex.off", TR, TF + [(0, 4, 5), (0, 6, 4), (0, 5, 6), (4, 6, 5)])
off("flipped_face.off", TV, TF[:3] + [(1, 3, 2)])
off("inward.off", TV, [(f[0], f[2], f[1]) for f in TF])
off("unreferenced_vertex.off", TV + [(5, 5, 5)], TF)
off("two_components.off", TV + [(x + 3, y, z) for (x, y, z) in TV], TF + [tuple(i + 4 for i in f) for f in TF])
# Edge 1-2 split at its midpoint on one side only; the slit closed by the flat face (4, 1, 2).
off("degenerate.off", TV + [(0.5, 0.5, 0)], [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 4, 3), (4, 2, 3), (4, 1, 2)])
off("repeated_vertex.off", TV, TF + [(0, 0, 1)])
# Icosahedron with one vertex pushed through to the far side.
g = (1 + math.sqrt(5)) / 2
IV = [(-1, g, 0), (1, g, 0), (-1, -g, 0), (1, -g, 0), (0, -1, g), (0, 1, g), (0, -1, -g), (0, 1, -g),
      (g, 0, -1), (g, 0, 1), (-g, 0, -1), (-g, 0, 1)]
IF = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2), (10, 7, 6),
      (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10),
      (8, 6, 7), (9, 8, 1)]
IV[0] = tuple(-2 * c for c in IV[0])
off("self_intersecting.off", IV, IF)
