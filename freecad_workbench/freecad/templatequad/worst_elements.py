"""The worst elements of a mesh: which, where, and when to warn (pure functions, tested
headless; view_provider.show_worst draws them, the task panel and the command call it).

Preferences (User parameter:BaseApp/Preferences/Mod/TemplateQuad):
    WorstElements     how many of the worst elements are shown (default 10)
    WarnBelowQuality  the task panel warns when the worst element's scaled Jacobian is
                      under this (default 0.1)
"""
import bisect
from typing import List, Sequence, Tuple

PREFERENCES = "User parameter:BaseApp/Preferences/Mod/TemplateQuad"
DEFAULT_COUNT = 10
DEFAULT_WARN_BELOW = 0.1


def preferences() -> Tuple[int, float]:
    """(how many to show, the quality to warn under), from FreeCAD's preferences."""
    import FreeCAD

    group = FreeCAD.ParamGet(PREFERENCES)
    count = group.GetInt("WorstElements", DEFAULT_COUNT)
    warn = group.GetFloat("WarnBelowQuality", DEFAULT_WARN_BELOW)
    return max(1, count), warn


def worst_elements(quality: Sequence[float], count: int) -> List[Tuple[int, float]]:
    """worst_elements(): the `count` lowest values of `quality` (one per element, in
    element order) as (element id from 1, value), worst first; ties by element id."""
    import numpy

    values = numpy.asarray(quality, dtype=float)
    order = numpy.argsort(values, kind="stable")[:max(0, count)]
    return [(int(j) + 1, float(values[j])) for j in order]


def owner_of(element_id: int, owners: Sequence[int]) -> int:
    """owner_of(): the 0-based shape element (face, or solid of a 3D mesh) whose
    elements include element_id; `owners` is the mesh object's ElementOwners, flat
    (owner, first element 0-based, count) triples in element order; -1 if none."""
    triples = [owners[k:k + 3] for k in range(0, len(owners) - 2, 3)]
    firsts = [t[1] for t in triples]
    k = bisect.bisect_right(firsts, element_id - 1) - 1
    if k >= 0 and element_id - 1 < triples[k][1] + triples[k][2]:
        return triples[k][0]
    return -1


def worst_lines(worst, owners: Sequence[int], owner_kind: str) -> List[str]:
    """One line per worst element: its id, scaled Jacobian and FreeCAD's name of its
    face (or solid)."""
    lines = []
    for element, value in worst:
        owner = owner_of(element, owners)
        where = f" on {owner_kind}{owner + 1}" if owner >= 0 else ""
        lines.append(f"element {element}{where}: scaled Jacobian {value:.3f}")
    return lines


def quality_warning(worst_value: float, owner_name: str, warn_below: float) -> str:
    """The task panel's warning when the worst element is under warn_below ("" else)."""
    if worst_value >= warn_below:
        return ""
    where = f" on {owner_name}" if owner_name else ""
    return (f"The worst element{where} has a scaled Jacobian of {worst_value:.3f}, under "
            f"{warn_below:g}: stresses next to it are unreliable. 'Show worst' shows where.")
