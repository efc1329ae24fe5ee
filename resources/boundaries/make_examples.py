#!/usr/bin/python3
"""Writes the example boundary files of this folder (stdlib only).

Each file is a `tquad mesh` input: {"points": [[x, y, z], ...], "corners": [i, ...]},
a closed loop of points in order (counter-clockwise seen from +z for the planar ones)
and the indices of the corner points. Run from anywhere:
    /usr/bin/python3 resources/boundaries/make_examples.py
"""
import json
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))


def polyline(corner_points, counts):
    """Straight sides between consecutive corner points, counts[i] uniform segments on
    side i. Returns the loop points (each corner once) and the corner indices."""
    points, corners = [], []
    k = len(corner_points)
    for i in range(k):
        a, b = corner_points[i], corner_points[(i + 1) % k]
        corners.append(len(points))
        for j in range(counts[i]):
            t = j / counts[i]
            points.append([a[d] + t * (b[d] - a[d]) for d in range(3)])
    return points, corners


def plate_t2():
    # A 3 x 2 rectangle; opposite sides 12/16 and 20/10 differ: template T2.
    return polyline([(0, 0, 0), (3, 0, 0), (3, 2, 0), (0, 2, 0)], [12, 20, 16, 10])


def triangle_t4():
    # Equilateral triangle with counts (10, 10, 4), the paper's Table 1 case 9(g): T4.
    h = math.sqrt(3) / 2
    return polyline([(0, 0, 0), (1, 0, 0), (0.5, h, 0)], [10, 10, 4])


def disk_t5():
    # Unit circle, two curves of 20 segments each (upper and lower half): T5.
    n = 40
    points = [[math.cos(2 * math.pi * i / n), math.sin(2 * math.pi * i / n), 0.0] for i in range(n)]
    return points, [0, n // 2]


def sphere_octant_t3():
    # A curved 3D patch: the octant x, y, z >= 0 of the unit sphere, bounded by three
    # quarter great circles with 12, 8 and 8 segments (template T3).
    counts = [12, 8, 8]
    arcs = [((1, 0, 0), (0, 1, 0)), ((0, 1, 0), (0, 0, 1)), ((0, 0, 1), (1, 0, 0))]
    points, corners = [], []
    for (a, b), count in zip(arcs, counts):
        corners.append(len(points))
        for j in range(count):
            t = (math.pi / 2) * j / count
            points.append([math.cos(t) * a[d] + math.sin(t) * b[d] for d in range(3)])
    return points, corners


def write(name, loop):
    points, corners = loop
    path = os.path.join(HERE, name)
    with open(path, "w") as f:
        f.write('{"points": [\n')
        f.write(",\n".join("[%s]" % ", ".join(repr(float(c)) for c in p) for p in points))
        f.write('\n],\n"corners": %s}\n' % json.dumps(corners))
    print("wrote", path, len(points), "points, corners", corners)


if __name__ == "__main__":
    write("plate_t2.json", plate_t2())
    write("triangle_t4.json", triangle_t4())
    write("disk_t5.json", disk_t5())
    write("sphere_octant_t3.json", sphere_octant_t3())
