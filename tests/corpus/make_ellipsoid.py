#!/usr/bin/python3
"""Writes N points of the ellipsoid x^2/1 + y^2/0.8^2 + z^2/0.6^2 = 1 as .xyz, sampled uniformly
in the longitude and the polar angle, so ten times denser near the poles than at the equator
(as a scan is denser where it looks straight at the surface): make_ellipsoid.py OUT N"""
import math
import random
import sys

out, n = sys.argv[1], int(sys.argv[2])
rng = random.Random(22)
with open(out, "w") as f:
    for _ in range(n):
        theta, phi = rng.uniform(0, math.pi), rng.uniform(0, 2 * math.pi)
        f.write("%.9f %.9f %.9f\n" % (math.sin(theta) * math.cos(phi),
                                      0.8 * math.sin(theta) * math.sin(phi),
                                      0.6 * math.cos(theta)))
