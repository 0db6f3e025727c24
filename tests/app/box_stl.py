#!/usr/bin/python3
"""Writes a closed box, 16 x 16 x 3 mm with its base on z = 0 and outward normals, for the command-line
tests. Usage: box_stl.py OUT [options]; the format follows OUT's extension (.stl ASCII, .obj, .off).
  --open       drop the last two triangles (an open surface)
  --overlap    add a second box shifted by (4, 4, 0): closed and manifold, but self-intersecting
  --edge       add a second box shifted by (16, 16, 0): the two share one vertical edge (non-manifold)
  --mixed      every third triangle written inward (orientations mixed)
  --inward     every triangle written inward
  --unshared   (.obj, .off) every triangle with its own three points, repeated coordinates
  --scale S    every coordinate times S"""
import sys

S = float(sys.argv[sys.argv.index("--scale") + 1]) if "--scale" in sys.argv else 1.0
L, H = 8.0 * S, 3.0 * S
V = [(-L, -L, 0), (L, -L, 0), (L, L, 0), (-L, L, 0), (-L, -L, H), (L, -L, H), (L, L, H), (-L, L, H)]
QUADS = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]


def triangles(shift):
    for q in QUADS:
        for tri in ((q[0], q[1], q[2]), (q[0], q[2], q[3])):
            yield [tuple(V[i][k] + shift[k] for k in range(3)) for i in tri]


def facet(a, b, c):
    u = [b[k] - a[k] for k in range(3)]
    w = [c[k] - a[k] for k in range(3)]
    n = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]]
    m = sum(x * x for x in n) ** 0.5
    lines = [" facet normal %g %g %g" % tuple(x / m for x in n), "  outer loop"]
    lines += ["   vertex %g %g %g" % p for p in (a, b, c)]
    return lines + ["  endloop", " endfacet"]


tris = list(triangles((0, 0, 0)))
if "--open" in sys.argv:
    tris = tris[:-2]
if "--overlap" in sys.argv:
    tris += list(triangles((4, 4, 0)))
if "--edge" in sys.argv:
    tris += list(triangles((16, 16, 0)))
if "--inward" in sys.argv:
    tris = [[t[0], t[2], t[1]] for t in tris]
if "--mixed" in sys.argv:
    tris = [[t[0], t[2], t[1]] if i % 3 == 0 else t for i, t in enumerate(tris)]
out = sys.argv[1]
if out.endswith(".stl"):
    lines = ["solid box"] + [line for t in tris for line in facet(*t)] + ["endsolid box"]
else:
    points, index = [], {}
    faces = []
    for t in tris:
        face = []
        for p in t:
            if "--unshared" in sys.argv or p not in index:
                index[p] = len(points)
                points.append(p)
            face.append(index[p])
        faces.append(face)
    if out.endswith(".obj"):
        lines = ["v %g %g %g" % p for p in points] + ["f %d %d %d" % tuple(i + 1 for i in f) for f in faces]
    else:
        lines = ["OFF", "%d %d 0" % (len(points), len(faces))] + ["%g %g %g" % p for p in points]
        lines += ["3 %d %d %d" % tuple(f) for f in faces]
open(out, "w").write("\n".join(lines) + "\n")
