"""The planar rectangle the Gmsh benches mesh (compare_gmsh.py, sweep.py), in one place.

Imported inside their Gmsh child processes, after ``gmsh.initialize``.
"""


def quiet_single_thread(gmsh) -> None:
    """No terminal output, errors raised instead of aborting the process (Gmsh's
    default), one thread (the comparisons are single-threaded)."""
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.option.setNumber("General.AbortOnError", 0)
    gmsh.option.setNumber("General.NumThreads", 1)


def rectangle(gmsh, width, height, segments):
    """A width x height rectangle in z = 0 whose sides (bottom, right, top, left) get
    the given segment counts; returns (its four lines, its surface)."""
    gmsh.model.add("rect")
    geo = gmsh.model.geo
    corners = [(0, 0), (width, 0), (width, height), (0, height)]
    points = [geo.addPoint(x, y, 0) for x, y in corners]
    lines = [geo.addLine(points[i], points[(i + 1) % 4]) for i in range(4)]
    surface = geo.addPlaneSurface([geo.addCurveLoop(lines)])
    geo.synchronize()
    for line, n in zip(lines, segments):
        gmsh.model.mesh.setTransfiniteCurve(line, n + 1)  # nodes = segments + 1
    return lines, surface
