#!/usr/bin/env python3
"""Midpoint (1-to-4) subdivision of a triangle OBJ: every edge gets its midpoint, every triangle
becomes four. The surface is unchanged (unlike Loop subdivision, which smooths and shrinks it),
so a body measured before and after must give the same values; only the vertex count grows
(13,380 -> 53,514 vertices for the MakeHuman bodies). Standard library only.

usage: subdivide_obj.py IN.obj OUT.obj [levels]
"""
import os
import sys


def read_obj(path):
    points, tris = [], []
    with open(path) as f:
        for line in f:
            w = line.split()
            if not w:
                continue
            if w[0] == "v":
                points.append(tuple(float(x) for x in w[1:4]))
            elif w[0] == "f":
                ids = [int(x.split("/")[0]) for x in w[1:]]
                ids = [i - 1 if i > 0 else len(points) + i for i in ids]
                for k in range(1, len(ids) - 1):
                    tris.append((ids[0], ids[k], ids[k + 1]))
    return points, tris


def subdivide(points, tris):
    points = list(points)
    mid = {}

    def m(a, b):
        key = (a, b) if a < b else (b, a)
        if key not in mid:
            pa, pb = points[a], points[b]
            mid[key] = len(points)
            points.append(tuple(0.5 * (x + y) for x, y in zip(pa, pb)))
        return mid[key]

    out = []
    for a, b, c in tris:
        ab, bc, ca = m(a, b), m(b, c), m(c, a)
        out += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
    return points, out


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__.strip().splitlines()[-1])
    points, tris = read_obj(sys.argv[1])
    for _ in range(int(sys.argv[3]) if len(sys.argv) == 4 else 1):
        points, tris = subdivide(points, tris)
    tmp = sys.argv[2] + ".tmp"
    with open(tmp, "w") as f:
        f.write("# %s, midpoint-subdivided\n" % os.path.basename(sys.argv[1]))
        f.writelines("v %.7g %.7g %.7g\n" % p for p in points)
        f.writelines("f %d %d %d\n" % (a + 1, b + 1, c + 1) for a, b, c in tris)
    os.replace(tmp, sys.argv[2])
    print("%s: %d vertices, %d triangles" % (sys.argv[2], len(points), len(tris)))


if __name__ == "__main__":
    main()
