#!/usr/bin/python3
"""Writes scenes/dome.stl, the skin of scenes/dome_stl.json: a closed binary STL (mm, outward normals).

The dome is a paraboloid over the disc r <= 10 mm, z = 3 - 2 (r / 10)^2 (3 mm thick at the centre, 1 mm at
the rim), standing on a vertical side wall with its base on z = 0. Its top is tessellated on rings 0.5 mm
apart up to r = 5 mm (where the sensors are) and 1 mm apart beyond, each ring with points as far apart as
its rings, so a facet sags at most z'' s^2 / 8 = 0.04 * 1 / 8 = 5 um below the paraboloid (1.25 um inside
r = 5); the flat base needs no resolution and is tessellated 2.5 mm apart. The output is the same bytes on
every run.
Usage: make_dome_stl.py [OUT]   (default: dome.stl beside this script)"""
import math
import os
import struct
import sys

RIM, H_CENTRE, H_RIM = 10.0, 3.0, 1.0
TOP_RADII = [0.5 * i for i in range(11)] + [6.0, 7.0, 8.0, 9.0, RIM]
BASE_RADII = [0.0, 2.5, 5.0, 7.5, RIM]


def top_z(r):
    return H_CENTRE - (H_CENTRE - H_RIM) * (r / RIM) ** 2


def ring(r, spacing):
    """Points (x, y, r) on the circle of radius r, about `spacing` apart; the centre is one point."""
    if r == 0:
        return [(0.0, 0.0, 0.0)]
    m = max(6, round(2 * math.pi * r / spacing))
    return [(r * math.cos(2 * math.pi * j / m), r * math.sin(2 * math.pi * j / m), r) for j in range(m)]


def rings(radii, rim_spacing):
    """Rings at the given radii, each spaced like its gap to the previous ring, the rim like the top's rim."""
    out = [ring(0.0, 1.0)]
    for r0, r1 in zip(radii, radii[1:]):
        out.append(ring(r1, rim_spacing if r1 == RIM else r1 - r0))
    return out


def zip_rings(inner, outer):
    """Triangles (counter-clockwise seen from +z) joining two rings by advancing the lagging angle."""
    if len(inner) == 1:
        return [(inner[0], outer[j], outer[(j + 1) % len(outer)]) for j in range(len(outer))]
    tris, a, b, ni, no = [], 0, 0, len(inner), len(outer)
    while a < ni or b < no:
        next_a, next_b = (a + 1) / ni, (b + 1) / no
        if b >= no or (a < ni and next_a <= next_b):
            tris.append((inner[a % ni], outer[b % no], inner[(a + 1) % ni]))
            a += 1
        else:
            tris.append((inner[a % ni], outer[b % no], outer[(b + 1) % no]))
            b += 1
    return tris


def normal(p, q, s):
    u = [q[k] - p[k] for k in range(3)]
    w = [s[k] - p[k] for k in range(3)]
    n = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]]
    m = math.sqrt(sum(x * x for x in n))
    return [x / m for x in n]


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "dome.stl")
    top, base = rings(TOP_RADII, 1.0), rings(BASE_RADII, 1.0)
    tris = []
    for inner, outer in zip(top, top[1:]):  # top, normal up
        tris += [[(p[0], p[1], top_z(p[2])) for p in t] for t in zip_rings(inner, outer)]
    for inner, outer in zip(base, base[1:]):  # base, normal down
        tris += [[(p[0], p[1], 0.0) for p in (a, c, b)] for a, b, c in zip_rings(inner, outer)]
    rim = top[-1]
    for j in range(len(rim)):  # side wall, counter-clockwise rim x up = outward
        p, q = rim[j], rim[(j + 1) % len(rim)]
        lo_p, lo_q, hi_p, hi_q = (p[0], p[1], 0.0), (q[0], q[1], 0.0), (p[0], p[1], H_RIM), (q[0], q[1], H_RIM)
        tris += [[lo_p, lo_q, hi_q], [lo_p, hi_q, hi_p]]
    with open(out, "wb") as f:
        f.write(b"skinfem dome: z = 3 - 2 (r/10)^2 over r <= 10 mm, side wall to z = 0".ljust(80, b" "))
        f.write(struct.pack("<I", len(tris)))
        for t in tris:
            f.write(struct.pack("<3f", *normal(*t)))
            for p in t:
                f.write(struct.pack("<3f", *p))
            f.write(b"\0\0")


if __name__ == "__main__":
    main()
