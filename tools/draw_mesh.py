#!/usr/bin/python3
"""Draw a planar quad mesh to PNG: quads in grey, cuts between patches in blue, quads
with an inverted corner filled red.

    python3 tools/draw_mesh.py mesh.json out.png   (JSON: nodes, quads, optional cuts)
"""
import json
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.collections import PolyCollection, LineCollection


def corner_turns(poly):
    out = []
    for i in range(4):
        a, b, c = poly[i - 1], poly[i], poly[(i + 1) % 4]
        u = (c[0] - b[0], c[1] - b[1])
        v = (a[0] - b[0], a[1] - b[1])
        out.append(u[0] * v[1] - u[1] * v[0])
    return out


def main(source, target):
    data = json.load(open(source))
    nodes = [(p[0], p[1]) for p in data["nodes"]]
    polys = [[nodes[i] for i in q] for q in data.get("quads", [])]
    bad = [p for p in polys if min(corner_turns(p)) <= 0]
    fig, ax = plt.subplots(figsize=(10, 10))
    ax.add_collection(PolyCollection(polys, facecolors="#f4f4f4", edgecolors="#555", linewidths=0.4))
    if bad:
        ax.add_collection(PolyCollection(bad, facecolors="#e33", edgecolors="#900", linewidths=0.8))
    cuts = [[nodes[i] for i in c] for c in data.get("cuts", [])]
    ax.add_collection(LineCollection(cuts, colors="#1560bd", linewidths=1.2))
    ax.autoscale()
    ax.set_aspect("equal")
    ax.set_title("%s: %d quads, %d inverted" % (data.get("description", source), len(polys), len(bad)), fontsize=9)
    ax.axis("off")
    fig.savefig(target, dpi=110, bbox_inches="tight")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
