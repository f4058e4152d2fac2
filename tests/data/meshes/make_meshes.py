#!/usr/bin/env python3
"""Writes the small mesh files the mesh tests read (run from this folder; output is committed).

The unit cube [0,1]^3 has its faces counter-clockwise seen from outside (outward); variants
flip faces, drop faces, nest or move cubes. Expected results are in tests/meshes/*_test.cpp.
"""
import struct

V = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
# 0-based quads, outward: bottom, top, front (y=0), back (y=1), left (x=0), right (x=1)
QUADS = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (2, 3, 7, 6), (0, 4, 7, 3), (1, 2, 6, 5)]
NORMALS = [(0, 0, -1), (0, 0, 1), (0, -1, 0), (0, 1, 0), (-1, 0, 0), (1, 0, 0)]


def tris(quads):
    return [t for q in quads for t in ((q[0], q[1], q[2]), (q[0], q[2], q[3]))]


def rev(faces):
    return [tuple(reversed(f)) for f in faces]


def fmt(x):
    return ("%g" % x)


def obj(name, verts, faces, header=""):
    with open(name, "w", newline="\n") as f:
        f.write(header)
        for v in verts:
            f.write("v %s\n" % " ".join(fmt(c) for c in v))
        for face in faces:
            f.write("f %s\n" % " ".join(str(i + 1) for i in face))


def off(name, verts, faces):
    with open(name, "w", newline="\n") as f:
        f.write("OFF\n# unit cube\n%d %d 0\n" % (len(verts), len(faces)))
        for v in verts:
            f.write("%s\n" % " ".join(fmt(c) for c in v))
        for face in faces:
            f.write("%d %s\n" % (len(face), " ".join(str(i) for i in face)))


def ply_ascii(name, verts, faces):
    with open(name, "w", newline="\n") as f:
        f.write("ply\nformat ascii 1.0\ncomment unit cube\nelement vertex %d\n" % len(verts))
        f.write("property float x\nproperty float y\nproperty float z\n")
        f.write("element face %d\nproperty list uchar int vertex_indices\nend_header\n" % len(faces))
        for v in verts:
            f.write("%s\n" % " ".join(fmt(c) for c in v))
        for face in faces:
            f.write("%d %s\n" % (len(face), " ".join(str(i) for i in face)))


def ply_binary(name, verts, faces, big_endian):
    e = ">" if big_endian else "<"
    with open(name, "wb") as f:
        f.write(("ply\nformat %s 1.0\nelement vertex %d\n" %
                 ("binary_big_endian" if big_endian else "binary_little_endian", len(verts))).encode())
        f.write(b"property double x\nproperty double y\nproperty double z\n")
        f.write(("element face %d\nproperty list uchar uint vertex_indices\nend_header\n" % len(faces)).encode())
        for v in verts:
            f.write(struct.pack(e + "3d", *v))
        for face in faces:
            f.write(struct.pack(e + "B%dI" % len(face), len(face), *face))


def stl_ascii(name, verts, triangles):
    with open(name, "w", newline="\n") as f:
        f.write("solid cube\n")
        for t in triangles:
            f.write("  facet normal 0 0 0\n    outer loop\n")
            for i in t:
                f.write("      vertex %s\n" % " ".join(fmt(c) for c in verts[i]))
            f.write("    endloop\n  endfacet\n")
        f.write("endsolid cube\n")


def stl_binary(name, verts, triangles, header=b"binary unit cube"):
    with open(name, "wb") as f:
        f.write(header.ljust(80, b"\0"))
        f.write(struct.pack("<I", len(triangles)))
        for t in triangles:
            f.write(struct.pack("<3f", 0, 0, 0))
            for i in t:
                f.write(struct.pack("<3f", *verts[i]))
            f.write(b"\0\0")


def moved(verts, d):
    return [tuple(c + d for c in v) for v in verts]


def scaled(verts, s, d):
    return [tuple(c * s + d for c in v) for v in verts]


obj("cube.obj", V, QUADS)
obj("cube_upper.OBJ", V, QUADS)
off("cube.off", V, QUADS)
ply_ascii("cube_ascii.ply", V, QUADS)
ply_binary("cube_binary_le.ply", V, QUADS, False)
ply_binary("cube_binary_be.ply", V, QUADS, True)
stl_ascii("cube_ascii.stl", V, tris(QUADS))
stl_binary("cube_binary.stl", V, tris(QUADS))
# A binary STL whose free-text header starts with "solid", as many exporters write.
stl_binary("cube_binary_solid_header.stl", V, tris(QUADS), b"solid cube written by a CAD exporter")

obj("open_box.obj", V, QUADS[:1] + QUADS[2:])  # no top
obj("cube_one_face_flipped.obj", V, QUADS[:1] + rev(QUADS[1:2]) + QUADS[2:])
off("cube_inside_out.off", V, rev(QUADS))
stl_ascii("cube_inside_out.stl", V, rev(tris(QUADS)))
# Outer cube [0,3]^3 and inner cube [1,2]^3, both written outward: a hollow solid.
obj("hollow_cube.obj", scaled(V, 3, 0) + scaled(V, 1, 1), QUADS + [tuple(i + 8 for i in q) for q in QUADS])
# Two separate cubes, the second written inside-out.
ply_ascii("two_cubes_one_inverted.ply", V + moved(V, 2), QUADS + rev([tuple(i + 8 for i in q) for q in QUADS]))
# A 2x2 grid of quads in the plane z=0, and one hexagon.
grid = [(x, y, 0) for y in range(3) for x in range(3)]
obj("grid_quads.obj", grid, [(y * 3 + x, y * 3 + x + 1, y * 3 + x + 4, y * 3 + x + 3) for y in range(2) for x in range(2)])
off("hexagon.off", [(1, 0, 0), (0.5, 0.866, 0), (-0.5, 0.866, 0), (-1, 0, 0), (-0.5, -0.866, 0), (0.5, -0.866, 0)],
    [(0, 1, 2, 3, 4, 5)])
# The cube plus a triangle of zero area on three new collinear points.
obj("cube_with_degenerate.obj", V + [(2, 0, 0), (3, 0, 0), (4, 0, 0)], QUADS + [(8, 9, 10)])

# Cube with per-face normals and texture coordinates (v/vt/vn).
with open("cube_normals_uvs.obj", "w", newline="\n") as f:
    for v in V:
        f.write("v %s\n" % " ".join(fmt(c) for c in v))
    for uv in [(0, 0), (1, 0), (1, 1), (0, 1)]:
        f.write("vt %s\n" % " ".join(fmt(c) for c in uv))
    for n in NORMALS:
        f.write("vn %s\n" % " ".join(fmt(2 * c) for c in n))  # not unit length on purpose
    for k, q in enumerate(QUADS):
        f.write("f %s\n" % " ".join("%d/%d/%d" % (i + 1, j + 1, k + 1) for j, i in enumerate(q)))
# Same cube, normals on three faces only: the file's normals cannot be used.
with open("cube_partial_normals.obj", "w", newline="\n") as f:
    for v in V:
        f.write("v %s\n" % " ".join(fmt(c) for c in v))
    for n in NORMALS:
        f.write("vn %s\n" % " ".join(fmt(c) for c in n))
    for k, q in enumerate(QUADS):
        f.write("f %s\n" % " ".join(("%d//%d" % (i + 1, k + 1)) if k < 3 else str(i + 1) for i in q))
# UTF-8 byte-order mark, tabs between corners, a polyline, relative (negative) indices.
with open("cube_tabs_polyline_relative.obj", "w", newline="\n") as f:
    f.write("\ufeff# cube with quirks\n")
    for v in V:
        f.write("v\t%s\n" % "\t".join(fmt(c) for c in v))
    f.write("l 1 2 3\n")
    for q in QUADS:
        f.write("f\t%s\n" % "\t".join(str(i - 8) for i in q))
