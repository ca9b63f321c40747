#!/usr/bin/env python3
"""Writes meshes/pebble_3d.obj: a rounded pebble, the superellipsoid
|x/a|^p + |y/b|^p + |z/c|^p = 1 (a, b, c = 1.2, 0.8, 0.5; p = 3), as the
icosahedron split twice (320 triangles, 162 vertices) projected radially
onto it. A closed surface for Mesh/Source = surface
(parameters/squashed_pebble_3d.prm)."""
import math, os

a, b, c, p = 1.2, 0.8, 0.5, 3.0
t = (1 + math.sqrt(5)) / 2
v = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
     (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
f = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9),
     (5, 11, 4), (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2),
     (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10),
     (8, 6, 7), (9, 8, 1)]
unit = lambda x: tuple(xi / math.sqrt(sum(y * y for y in x)) for xi in x)
v = [unit(x) for x in v]
for level in range(2):
    middle, finer = {}, []
    def mid(i, j):
        key = (min(i, j), max(i, j))
        if key not in middle:
            v.append(unit(tuple((v[i][k] + v[j][k]) / 2 for k in range(3))))
            middle[key] = len(v) - 1
        return middle[key]
    for (i, j, k) in f:
        ij, jk, ki = mid(i, j), mid(j, k), mid(k, i)
        finer += [(i, ij, ki), (ij, j, jk), (ki, jk, k), (ij, jk, ki)]
    f = finer


def onto_pebble(d):
    # the radius r with |r dx / a|^p + |r dy / b|^p + |r dz / c|^p = 1
    s = sum(abs(di / ai) ** p for di, ai in zip(d, (a, b, c)))
    r = s ** (-1 / p)
    return tuple(r * di for di in d)


v = [onto_pebble(x) for x in v]
out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "pebble_3d.obj")
with open(out, "w") as file:
    file.write("# A rounded pebble: written by meshes/pebble_3d.py\n")
    for x in v:
        file.write("v %.10f %.10f %.10f\n" % x)
    for (i, j, k) in f:
        file.write("f %d %d %d\n" % (i + 1, j + 1, k + 1))
print("%d vertices, %d triangles, z from %.10f to %.10f" %
      (len(v), len(f), min(x[2] for x in v), max(x[2] for x in v)))
