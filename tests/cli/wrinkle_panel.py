"""A flat garment panel as `tapeline dress` writes one (OBJ, positions in mm, pattern coordinates
in mm, grain along +y): n x n cells of `cell` mm, pulled 3 % across and shortened 5 % along the
warp, optionally raised by a wave along the warp of 1.1 times the wavelength the buckling law
predicts for the fabric with the tension term over 300 mm (or of --wavelength mm).

usage: wrinkle_panel.py OUT.obj N CELL [--wave FABRIC.json | --wavelength MM]
"""
import json
import math
import sys


def main(argv):
    path, n, cell = argv[1], int(argv[2]), float(argv[3])
    lam = None
    if len(argv) > 5 and argv[4] == "--wave":
        f = json.load(open(argv[5]))
        T, B, q = f["stretch_weft_n_m"] * 0.03, f["bending_un_m"] * 1e-6, math.pi / 0.3
        lam = 1.1 * 2 * math.pi * (B / (T * q * q)) ** 0.25 * 1e3
    elif len(argv) > 5 and argv[4] == "--wavelength":
        lam = float(argv[5])
    with open(path, "w") as o:
        o.write("g panel\n# grain 0 1\n")
        for j in range(n + 1):
            for i in range(n + 1):
                u, v = cell * i, cell * j
                h = 2 * math.sin(2 * math.pi * 0.95 * v / lam) if lam else 0
                o.write("v %.9g %.9g %.9g\n" % (1.03 * u, 0.95 * v, h))
        for j in range(n + 1):
            for i in range(n + 1):
                o.write("vt %g %g\n" % (cell * i, cell * j))
        for j in range(n):
            for i in range(n):
                a, b = j * (n + 1) + i + 1, j * (n + 1) + i + 2
                c, d = (j + 1) * (n + 1) + i + 2, (j + 1) * (n + 1) + i + 1
                o.write("f %d/%d %d/%d %d/%d\nf %d/%d %d/%d %d/%d\n" % (a, a, b, b, c, c, a, a, c, c, d, d))


if __name__ == "__main__":
    main(sys.argv)
