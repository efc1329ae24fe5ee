"""Part families built with FreeCAD's Part module, run inside freecadcmd by
bench/generated_parts.py --source freecad: FOLDER, FIRST, LAST and FORMATS are set
before this text runs. Seed s writes FOLDER/part_<s>.<format> for each format
(brep, step, igs): the same part through OpenCASCADE's writers and readers.

Families, by seed: a block, cylinder or turned profile with holes, bosses, a slot, a
spherical dimple, fillets and chamfers; a turned shaft with O-ring grooves (torus
cuts), a bore, a countersink and a milled flat; a flange with a hub and a bolt
circle; a loft from a rectangle to a circle, bored; a filleted box shelled open
(makeThickness) and drilled; an L-bracket with a rib, holes and fillets; a bent
sheet (an open shell) with holes. A step that fails or leaves an invalid shape is
skipped."""
import math
import os
import random

import Part
from FreeCAD import Vector as V


def kept(step, shape):
    try:
        out = step(shape)
        if out.isValid() and len(out.Faces) > 0 and (out.ShapeType == "Shell" or out.Volume > 1e-3 * shape.Volume):
            return out
    except Exception:  # the step is skipped
        pass
    return shape


def machined_block(r):
    L, W, H = r.uniform(40, 120), r.uniform(30, 90), r.uniform(5, 30)
    s = Part.makeBox(L, W, H) if r.random() < 0.6 else Part.makeCylinder(W / 2, 2 * H, V(L / 2, W / 2, 0))
    b = s.BoundBox
    for _ in range(r.randint(0, 5)):
        rad = r.uniform(1.5, min(b.XLength, b.YLength) / 6)
        x, y = r.uniform(b.XMin + rad, b.XMax - rad), r.uniform(b.YMin + rad, b.YMax - rad)
        depth = b.ZLength * (2 if r.random() < 0.7 else r.uniform(0.3, 0.8))
        s = kept(lambda t: t.cut(Part.makeCylinder(rad, depth + 1, V(x, y, b.ZMax - depth))), s)
    if r.random() < 0.3:
        c = V(r.uniform(b.XMin, b.XMax), r.uniform(b.YMin, b.YMax), b.ZMax)
        s = kept(lambda t: t.cut(Part.makeSphere(r.uniform(3, 12), c)), s)
    if r.random() < 0.6:
        edges = [e for e in s.Edges if r.random() < 0.3]
        if edges:
            s = kept(lambda t: t.makeFillet(r.uniform(0.5, 4), edges), s)
    return s


def shaft(r):
    R, L = r.uniform(8, 20), r.uniform(40, 120)
    s = Part.makeCylinder(R, L)
    for _ in range(r.randint(1, 3)):
        z, rr = r.uniform(5, L - 5), r.uniform(0.8, 2.5)
        s = kept(lambda t: t.cut(Part.makeTorus(R, rr, V(0, 0, z))), s)
    rb = r.uniform(2, R / 2)
    s = kept(lambda t: t.cut(Part.makeCylinder(rb, L + 2, V(0, 0, -1))), s)
    s = kept(lambda t: t.cut(Part.makeCone(rb * 2, rb, rb, V(0, 0, L - rb + 0.001))), s)
    if r.random() < 0.5:
        s = kept(lambda t: t.cut(Part.makeBox(2 * R, 2 * R, L / 2, V(R - r.uniform(1, R / 3), -R, L / 4))), s)
    return s


def flange(r):
    R, H = r.uniform(20, 50), r.uniform(4, 12)
    s = Part.makeCylinder(R, H).fuse(Part.makeCylinder(R / 2, H * 3)).removeSplitter()
    s = kept(lambda t: t.cut(Part.makeCylinder(R / 4, H * 4, V(0, 0, -1))), s)
    n, rb = r.randint(3, 8), r.uniform(1.5, R / 8)
    for k in range(n):
        a = 2 * math.pi * k / n
        s = kept(lambda t: t.cut(Part.makeCylinder(rb, H + 2, V(0.75 * R * math.cos(a), 0.75 * R * math.sin(a), -1))), s)
    return s


def loft(r):
    w, h, L = r.uniform(20, 50), r.uniform(10, 30), r.uniform(30, 80)
    rect = Part.makePolygon([V(-w / 2, -h / 2, 0), V(w / 2, -h / 2, 0), V(w / 2, h / 2, 0), V(-w / 2, h / 2, 0),
                             V(-w / 2, -h / 2, 0)])
    circle = Part.Wire(Part.makeCircle(min(w, h) * r.uniform(0.3, 0.6), V(r.uniform(-3, 3), 0, L)))
    s = Part.makeLoft([rect, circle], True)
    return kept(lambda t: t.cut(Part.makeCylinder(min(w, h) / 6, L + 2, V(0, 0, -1))), s)


def shelled_box(r):
    L, W, H = r.uniform(40, 100), r.uniform(30, 70), r.uniform(15, 40)
    b = Part.makeBox(L, W, H)
    b = kept(lambda t: t.makeFillet(r.uniform(2, 6), [e for e in t.Edges if abs(e.Vertexes[0].Z - e.Vertexes[-1].Z) > 1e-6]), b)
    top = [f for f in b.Faces if abs(f.CenterOfMass.z - H) < 1e-6]
    s = kept(lambda t: t.makeThickness(top, -r.uniform(1.5, 4), 1e-3), b)
    for _ in range(r.randint(0, 3)):
        x, y = r.uniform(8, L - 8), r.uniform(8, W - 8)
        s = kept(lambda t: t.cut(Part.makeCylinder(r.uniform(1.5, 4), 10, V(x, y, -1))), s)
    return s


def bracket(r):
    L, W, T = r.uniform(40, 100), r.uniform(20, 50), r.uniform(3, 8)
    profile = Part.makePolygon([V(0, 0, 0), V(L, 0, 0), V(L, 0, T), V(T, 0, T), V(T, 0, L * 0.6), V(0, 0, L * 0.6),
                                V(0, 0, 0)])
    s = Part.Face(profile).extrude(V(0, W, 0))
    rib = Part.makePolygon([V(T, W / 2 - T / 2, T), V(L * 0.5, W / 2 - T / 2, T), V(T, W / 2 - T / 2, L * 0.4),
                            V(T, W / 2 - T / 2, T)])
    s = kept(lambda t: t.fuse(Part.Face(rib).extrude(V(0, T, 0))).removeSplitter(), s)
    for _ in range(r.randint(1, 4)):
        x, y = r.uniform(T + 5, L - 5), r.uniform(5, W - 5)
        s = kept(lambda t: t.cut(Part.makeCylinder(r.uniform(1.5, 4), T + 2, V(x, y, -1))), s)
    if r.random() < 0.7:
        s = kept(lambda t: t.makeFillet(r.uniform(0.5, T * 0.8), [e for e in t.Edges if r.random() < 0.3]), s)
    return s


def sheet(r):
    points, x, z, a = [V(0, 0, 0)], 0.0, 0.0, 0.0
    for k in range(r.randint(2, 5)):
        length = r.uniform(15, 50)
        a += r.choice([-1, 1]) * r.uniform(30, 100) * math.pi / 180 if k else 0
        x, z = x + length * math.cos(a), z + length * math.sin(a)
        points.append(V(x, 0, z))
    width = r.uniform(20, 60)
    s = Part.makePolygon(points).extrude(V(0, width, 0))
    for _ in range(r.randint(0, 6)):
        k = r.randint(0, len(points) - 2)
        p, q = points[k], points[k + 1]
        d = q - p
        n = V(-d.z, 0, d.x)
        n.normalize()
        c = p + d * r.uniform(0.2, 0.8) + V(0, r.uniform(6, width - 6), 0)
        s = kept(lambda t: t.cut(Part.makeCylinder(r.uniform(1.5, 5), 20, c - n * 10, n)), s)
    return s


FAMILIES = [machined_block, shaft, flange, loft, shelled_box, bracket, sheet]

for seed in range(FIRST, LAST + 1):
    dice = random.Random(seed)
    part = FAMILIES[seed % len(FAMILIES)](dice)
    base = os.path.join(FOLDER, "part_%d" % seed)
    for form in FORMATS:
        {"brep": part.exportBrep, "step": part.exportStep, "igs": part.exportIges}[form](base + "." + form)
