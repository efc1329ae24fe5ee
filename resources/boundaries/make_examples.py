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


def arc_side(points, corners, centre, radius, start, end, count):
    """Appends an arc of `count` segments (start angle included, end excluded)."""
    corners.append(len(points))
    for j in range(count):
        t = start + (end - start) * j / count
        points.append([centre[0] + radius * math.cos(t), centre[1] + radius * math.sin(t), 0.0])


def straight_side(points, corners, a, b, count):
    corners.append(len(points))
    for j in range(count):
        t = j / count
        points.append([a[d] + t * (b[d] - a[d]) for d in range(2)] + [0.0])


def paper_example3():
    # Stand-in for the paper's example 3 (Figure 9; its exact shape is only drawn):
    # four natural curves and 34 boundary edges, as Table 3's rows (116 nodes, 98
    # quads). Three straight sides of a 10 x 6 quadrilateral and a top side bulging
    # out as an arc; counts 10, 6, 10, 8.
    points, corners = [], []
    straight_side(points, corners, (0, 0), (10, 0), 10)
    straight_side(points, corners, (10, 0), (10, 4), 6)
    # The arc through (10, 4) and (0, 6) with its centre below them.
    a, b = (10.0, 4.0), (0.0, 6.0)
    mid = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
    chord = (b[0] - a[0], b[1] - a[1])
    length = math.hypot(*chord)
    normal = (chord[1] / length, -chord[0] / length)  # points into the region
    centre = (mid[0] + 8.0 * normal[0], mid[1] + 8.0 * normal[1])
    radius = math.hypot(a[0] - centre[0], a[1] - centre[1])
    start = math.atan2(a[1] - centre[1], a[0] - centre[0])
    end = math.atan2(b[1] - centre[1], b[0] - centre[0])
    arc_side(points, corners, centre, radius, start, end, 10)
    straight_side(points, corners, (0, 6), (0, 0), 8)
    return points, corners


def paper_example4():
    # Stand-in for the paper's example 4 (Figure 10): three natural curves and 24
    # boundary edges (Table 3: 63 nodes, 50 quads). A quarter disk of radius 1: two
    # radii and the arc, 8 segments each.
    points, corners = [], []
    straight_side(points, corners, (0, 0), (1, 0), 8)
    arc_side(points, corners, (0, 0), 1.0, 0.0, math.pi / 2, 8)
    straight_side(points, corners, (0, 1), (0, 0), 8)
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
    write("paper_example3_t1.json", paper_example3())
    write("paper_example4_t3.json", paper_example4())
