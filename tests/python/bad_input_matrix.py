"""The bad-input matrix: what a careless or hostile user can give TemplateQuad, each
input run through the command line and, where it has one, the Python module.

Every case names what it checks and the parts its one-line message must hold. The
command line must exit with the case's status (2 for bad input) and leave no output
and no temporary file behind; the Python module must raise ValueError with the same
parts, and the interpreter must live on. test_bad_input_matrix.py runs the matrix;
run as a program it prints the table of docs/cli.md ("Bad-input matrix") from a
fresh run:

    /usr/bin/python3 tests/python/bad_input_matrix.py build/bin/tquad

(with PYTHONPATH holding the built tquad package for the Python column).
"""
import json
import math
import os
import resource
import subprocess
import sys
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable, List, Optional, Sequence, Tuple

import numpy as np

REPO = Path(__file__).resolve().parents[2]
SHAPES = REPO / "resources" / "shapes"

# A square of 4 x 4 segments: the good boundary the bad ones are edits of.
GOOD_POINTS = [(i, 0.0) for i in range(4)] + [(4.0, i) for i in range(4)] + \
              [(4.0 - i, 4.0) for i in range(4)] + [(0.0, 4.0 - i) for i in range(4)]
GOOD_CORNERS = [0, 4, 8, 12]


@dataclass
class Prepared:
    """A case made concrete in a folder: the input, extra CLI arguments, the output."""
    input: str
    args: List[str] = field(default_factory=list)
    output: str = "out.vtu"
    file_size_limit: Optional[int] = None  # bytes (RLIMIT_FSIZE), for a full disk


@dataclass
class Case:
    name: str                                   # the words of docs/cli.md's table
    prepare: Optional[Callable[[Path], Prepared]]  # None: a Python-only case
    expect: Sequence[str]                       # parts of the message
    python: Optional[Callable[[object, Prepared], object]] = None  # same input via tquad
    exit_status: int = 2
    python_expect: Optional[Sequence[str]] = None  # parts of Python's message, if not `expect`


def _write(folder: Path, name: str, text) -> str:
    path = folder / name
    path.write_bytes(text if isinstance(text, bytes) else text.encode())
    return str(path)


def _boundary(folder: Path, name: str, points, corners) -> str:
    return _write(folder, name, json.dumps({"points": [list(p) for p in points], "corners": corners}))


def _edited_example(name: str, old: str, new: str) -> str:
    text = (SHAPES / name).read_text()
    if old not in text:
        raise AssertionError(f"{old!r} is not in {name}")
    return text.replace(old, new, 1)


def _odd_points():
    points = list(GOOD_POINTS)
    del points[1]  # 15 segments
    return points, [0, 3, 7, 11]


def _touching_points():
    # A non-planar loop whose point 10 comes back onto point 2.
    points = [(0, 0, 0), (1, 0, 0), (2, 0, 0), (3, 0, 1), (4, 0, 0), (4, 1, 0), (4, 2, 0), (4, 3, 0),
              (3, 3, 0), (2.5, 2, 0.5), (2, 0, 0), (1, 3, 0), (0, 3, 0), (0, 2, 0), (0, 1, 0), (0, 0.5, 0)]
    return points, [0, 4, 8, 12]


def _rounding_apart_points():
    # Point 2 one unit in the last place from point 1 (a fuzzed loop like it once gave
    # a T3 split a NaN centre).
    points = list(GOOD_POINTS)
    points[2] = (math.nextafter(1.0, 2.0), 0.0)
    return points, GOOD_CORNERS


def _huge_points():
    points = [(x * 1e300, y * 1e300) for x, y in GOOD_POINTS]
    return points, GOOD_CORNERS


def _self_crossing_points():
    points = list(GOOD_POINTS)
    points[14] = (6.0, 2.0)  # the left side pushed through the right one
    return points, GOOD_CORNERS


def _boundary_case(name: str, make, expect: Sequence[str], python_call=None) -> Case:
    points, corners = make()

    def prepare(folder: Path) -> Prepared:
        return Prepared(_boundary(folder, "loop.json", points, corners))

    def via_python(tquad, prepared: Prepared):
        return tquad.mesh_boundary(points, corners)

    return Case(name, prepare, expect, python_call or via_python)


def _shape_file(name: str, text_or_bytes, args: Sequence[str] = ()) -> Callable[[Path], Prepared]:
    def prepare(folder: Path) -> Prepared:
        return Prepared(_write(folder, name, text_or_bytes), list(args))
    return prepare


def _example(name: str, args: Sequence[str] = (), output: str = "out.vtu",
             file_size_limit: Optional[int] = None) -> Callable[[Path], Prepared]:
    def prepare(folder: Path) -> Prepared:
        return Prepared(str(SHAPES / name), list(args), output, file_size_limit)
    return prepare


def _mesh_file(tquad, prepared: Prepared, **options):
    return tquad.mesh_shape(prepared.input, **options)


def _symlink(folder: Path, name: str, target: str) -> str:
    (folder / name).symlink_to(target)
    return str(folder / name)


def _folder_output(folder: Path) -> str:
    (folder / "taken.vtu").mkdir()
    return "taken.vtu"


def _read_only_output(folder: Path) -> str:
    # As root, permissions do not stop a write; /proc refuses new files to anyone.
    if os.geteuid() == 0:
        return "/proc/tquad-out.vtu"
    locked = folder / "locked"
    locked.mkdir()
    locked.chmod(0o555)
    return str(locked / "out.vtu")


def cases() -> List[Case]:
    """The matrix, in the order of docs/cli.md's table."""
    step = (SHAPES / "plate_with_hole.step").read_text()
    return [
        # Boundary files.
        Case("empty boundary file", lambda d: Prepared(_write(d, "empty.json", "")), ["empty.json", "empty"],
             lambda tquad, p: tquad.mesh_boundary([], []), python_expect=["N x 3"]),
        Case("boundary of no points (crashed the command and the interpreter)",
             lambda d: Prepared(_boundary(d, "none.json", [], [])), ["none.json", "0 points"],
             lambda tquad, p: tquad.mesh_boundary(np.zeros((0, 3)), []), python_expect=["0 points"]),
        Case("boundary file that is not JSON", lambda d: Prepared(_write(d, "garbage.json", "{points: ]")),
             ["garbage.json", "invalid JSON"]),
        _boundary_case("odd number of boundary segments", _odd_points, ["15 segments, an odd number"]),
        _boundary_case("one corner", lambda: (GOOD_POINTS, [0]), ["corner"]),
        _boundary_case("corner index out of range", lambda: (GOOD_POINTS, [0, 4, 8, 99]), ["99"]),
        _boundary_case("self-intersecting boundary", _self_crossing_points, ["cross"]),
        _boundary_case("coordinates near 1e308", _huge_points, ["point 1", "beyond 1e12"]),
        _boundary_case("non-planar loop that touches itself", _touching_points, ["points 2 and 10 coincide"]),
        _boundary_case("two points one rounding apart", _rounding_apart_points,
                       ["segment 1 from point 1 to point 2 is 2.22e-16 long", "coincide but for rounding"]),
        Case("NaN coordinate (Python; JSON has no NaN)", None, ["point 0"],
             lambda tquad, p: tquad.mesh_boundary([(float("nan"), 0.0)] + GOOD_POINTS[1:], GOOD_CORNERS)),
        Case("huge --t5-cut-edges", lambda d: Prepared(_boundary(d, "loop.json", GOOD_POINTS, GOOD_CORNERS),
                                                       ["--t5-cut-edges", "2000000000"]),
             ["T5 cut edges", "1e8"],
             lambda tquad, p: tquad.mesh_boundary(GOOD_POINTS, GOOD_CORNERS, t5_cut_edges=2000000000)),
        Case("mesh over --max-quads", lambda d: Prepared(_boundary(d, "loop.json", GOOD_POINTS, GOOD_CORNERS),
                                                         ["--max-quads", "10"]),
             ["16 quads", "limit of 10"],
             lambda tquad, p: tquad.mesh_boundary(GOOD_POINTS, GOOD_CORNERS, max_quads=10)),
        # CAD files.
        Case("empty STEP file", _shape_file("empty.step", ""), ["empty.step", "is empty"], _mesh_file),
        Case("empty BREP file", _shape_file("empty.brep", ""), ["empty.brep", "is empty"], _mesh_file),
        Case("garbage BREP file", _shape_file("garbage.brep", b"\x00\xffnot a shape\n" * 50),
             ["garbage.brep", "not a BREP file"], _mesh_file),
        Case("STEP file cut in half", _shape_file("half.step", step[:len(step) // 2]), ["cut short"], _mesh_file),
        Case("STEP reference left dangling (crashes OpenCASCADE's reader)",
             _shape_file("dangling.step", _edited_example("plate_with_hole.step", "#138 = LINE(", "#178 = LINE(")),
             ["is damaged", "crashed"], _mesh_file),
        Case("STEP face whose type name is damaged (OpenCASCADE transfers the shell without it)",
             _shape_file("lost_face.step", _edited_example("plate_with_hole.step", "#114 = ADVANCED_FACE(",
                                                           "#114 = ADVANCE2_FACE(")),
             ["lost_face.step", "is damaged: shell #16 lost its face 2 of 4"], _mesh_file),
        Case("STEP line that does not parse (OpenCASCADE drops it and transfers the rest)",
             _shape_file("bad_syntax.step", _edited_example("plate_with_hole.step", "#50 = VECTOR('',#51,1.);",
                                                            "#50 = VECTOR('',#51,1.)B")),
             ["bad_syntax.step", "is damaged: Undefined Parsing: Line 64"], _mesh_file),
        Case("STEP point coordinate that does not parse (OpenCASCADE reads the point without it)",
             _shape_file("bad_point.step", _edited_example("plate_with_hole.step",
                                                           "#25 = CARTESIAN_POINT('',(100.,0.,0.));",
                                                           "#25 = CARTESIAN_POINT('',(100.,0.,O.));")),
             ["bad_point.step", "is damaged: entity #25 (CARTESIAN_POINT) did not read"], _mesh_file),
        Case("STEP length unit whose prefix is damaged (OpenCASCADE reads millimetres as metres)",
             _shape_file("bad_unit.step", _edited_example("plate_with_hole.step", "SI_UNIT(.MILLI.,.METRE.)",
                                                          "SI_UNIT(.MILLX.,.METRE.)")),
             ["bad_unit.step", "is damaged: entity #270 (", "did not read (Enumeration si_prefix"], _mesh_file),
        Case("BREP curve count 99999 (OpenCASCADE's reader looped on a failed stream)",
             _shape_file("endless.brep", _edited_example("filleted_bracket.brep",
                                                         "Ed\n 1e-07 1 1 0\n1  4 0 3.14159265358",
                                                         "Ed\n 1e-07 1 1 0\n99999  4 0 3.14159265358"),
                         ["--read-timeout", "20"]),
             ["endless.brep", "is damaged"], lambda tquad, p: _mesh_file(tquad, p, read_timeout=20)),
        Case("BREP section count 10^9 in a 3 kB file",
             _shape_file("huge_count.brep", _edited_example("filleted_bracket.brep", "\nCurves 15\n",
                                                            "\nCurves 1000000000\n")),
             ["huge_count.brep", "Curves declares 1000000000 entries"], _mesh_file),
        Case("BREP number damaged by one byte (a plane's origin)",
             _shape_file("bad_number.brep", _edited_example("filleted_bracket.brep", "\nSurfaces 8\n1 ",
                                                            "\nSurfaces 8\n1 0\xef")),
             ["face 0", "geometry invalid"], _mesh_file),
        Case("/dev/zero as input", lambda d: Prepared("/dev/zero"), ["/dev/zero", "not a regular file"],
             _mesh_file),
        Case("/dev/zero named as a STEP file", lambda d: Prepared(_symlink(d, "zero.step", "/dev/zero")),
             ["zero.step", "not a regular file"], _mesh_file),
        Case("a folder as input", lambda d: Prepared(str(d)), ["not a regular file"], _mesh_file),
        Case("unknown input extension", _shape_file("part.xyz", "solid"), ["part.xyz"], _mesh_file),
        Case("missing input file", lambda d: Prepared(str(d / "absent.step")), ["absent.step", "cannot open"],
             _mesh_file),
        # Sizes and options on a good part.
        Case("size 1e-7 on a 100 mm plate", _example("plate_with_hole.brep", ["--size", "1e-7"]),
             ["edge 0 would need 1e+09 segments", "the size is too small"],
             lambda tquad, p: _mesh_file(tquad, p, size=1e-7)),
        Case("faces together over --max-quads, each under it, the area estimate under it too",
             _example("filleted_bracket.brep", ["--size", "2", "--max-quads", "1600"]),
             ["the faces together have more quads", "limit of 1600"],
             lambda tquad, p: _mesh_file(tquad, p, size=2.0, max_quads=1600)),
        Case("area estimate between one and two times --max-quads (before meshing)",
             _example("open_box.brep", ["--size", "1", "--max-quads", "2000"]),
             ["about 4e+03 quads", "limit of 2000"],
             lambda tquad, p: _mesh_file(tquad, p, size=1.0, max_quads=2000)),
        Case("size 1e-4 on a 40 mm box (area estimate, before meshing)", _example("open_box.brep", ["--size", "1e-4"]),
             ["about 4e+11 quads", "limit of 100000000"], lambda tquad, p: _mesh_file(tquad, p, size=1e-4)),
        Case("size NaN", _example("plate_with_hole.brep", ["--size", "nan"]), ["size"],
             lambda tquad, p: _mesh_file(tquad, p, size=float("nan"))),
        Case("negative size", _example("plate_with_hole.brep", ["--size", "-1"]), ["size"],
             lambda tquad, p: _mesh_file(tquad, p, size=-1.0)),
        Case("--faces 0-999999999", _example("plate_with_hole.brep", ["--faces", "0-999999999"]), ["face"],
             lambda tquad, p: _mesh_file(tquad, p, faces=[999999999])),
        Case("corner vertex that does not exist", _example("plate_with_hole.brep", ["--corners", "0:9,10"]),
             ["face 0", "vertex 9 does not exist"], lambda tquad, p: _mesh_file(tquad, p, corners={0: [9, 10]})),
        Case("NaN read timeout (Python; the CLI's range check is CLI11's)", None, ["read_timeout"],
             lambda tquad, p: tquad.mesh_shape(str(SHAPES / "plate_with_hole.brep"), read_timeout=float("nan"))),
        # Output locations.
        Case("unknown output extension", _example("plate_with_hole.brep", output="out.xyz"),
             ["unknown output format"]),
        Case("output folder missing", _example("plate_with_hole.brep", output="no_such_folder/out.vtu"),
             ["no_such_folder"]),
        Case("output is an existing folder", lambda d: Prepared(str(SHAPES / "plate_with_hole.brep"),
                                                                output=_folder_output(d)),
             ["not a regular file"]),
        Case("output is /dev/null", _example("plate_with_hole.brep", output="/dev/null"),
             ["/dev/null", "unknown output format"]),
        Case("output is a device named like a mesh file",
             lambda d: Prepared(str(SHAPES / "plate_with_hole.brep"), output=_symlink(d, "null.vtu", "/dev/null")),
             ["null.vtu", "not a regular file"]),
        Case("read-only output location", lambda d: Prepared(str(SHAPES / "plate_with_hole.brep"),
                                                             output=_read_only_output(d)),
             ["cannot create a file next to", "out.vtu"]),
        Case("output location full (a 4 KiB file-size limit)",
             _example("filleted_bracket.brep", file_size_limit=4096), ["cannot write", "nothing was written"]),
        Case("output is the input", lambda d: Prepared(_write(d, "same.json", json.dumps(
            {"points": [list(p) for p in GOOD_POINTS], "corners": GOOD_CORNERS})), output="same.json"),
             ["the output file is the input file"]),
        # Shells that are not closed solids: meshed, not refused.
        Case("open shell (a box without its top)", _example("open_box.brep"), [],
             _mesh_file, exit_status=0),
        Case("non-manifold shell (three faces on one edge)", _example("three_fins.brep"), [],
             _mesh_file, exit_status=0),
    ]


def _files(folder: Path) -> List[str]:
    return sorted(str(p.relative_to(folder)) for p in folder.rglob("*"))


@dataclass
class CliResult:
    status: int
    message: str   # stderr, one line expected
    left: List[str]  # files the run added to the folder


def run_cli(tquad_exe: str, case: Case, folder: Path) -> CliResult:
    prepared = case.prepare(folder)
    before = _files(folder)
    limit = prepared.file_size_limit

    def limit_file_size():
        if limit is not None:
            resource.setrlimit(resource.RLIMIT_FSIZE, (limit, limit))

    output = prepared.output if os.path.isabs(prepared.output) else str(folder / prepared.output)
    run = subprocess.run([tquad_exe, "mesh", prepared.input, "-o", output] + prepared.args,
                         capture_output=True, text=True, timeout=120, preexec_fn=limit_file_size, cwd=folder)
    after = _files(folder)
    left = [f for f in after if f not in before and not (run.returncode == 0 and folder / f == Path(output))]
    return CliResult(run.returncode, run.stderr.strip(), left)


def run_python(tquad, case: Case, folder: Path) -> Tuple[Optional[str], object]:
    """(the ValueError's message or None, the result when there was none)."""
    prepared = case.prepare(folder) if case.prepare else None
    try:
        return None, case.python(tquad, prepared)
    except ValueError as error:
        return str(error), None


def _shortened(message: str, folder: str) -> str:
    """The message as docs/cli.md shows it: no prefix, no machine's folders."""
    message = message.replace("tquad: error: ", "", 1).replace(str(SHAPES) + "/", "")
    return message.replace(folder + "/", "").replace(folder, "FOLDER").replace("|", "\\|")


def markdown_table(tquad_exe: str, tquad) -> str:
    import tempfile
    lines = ["| input | exit | message (CLI) | Python |", "|---|---|---|---|"]
    for case in cases():
        with tempfile.TemporaryDirectory() as cli_dir, tempfile.TemporaryDirectory() as py_dir:
            if case.prepare is None:
                status, message = "n/a", "n/a"
            else:
                cli = run_cli(tquad_exe, case, Path(cli_dir))
                status = str(cli.status)
                message = "(meshed)" if cli.status == 0 else "`" + _shortened(cli.message, cli_dir) + "`"
            if case.python is None:
                python = "n/a"
            else:
                error, result = run_python(tquad, case, Path(py_dir))
                python = "ValueError" if error else f"mesh of {len(result.quads)} quads"
            lines.append(f"| {case.name} | {status} | {message} | {python} |")
    return "\n".join(lines)


if __name__ == "__main__":
    import tquad as tquad_module
    print(markdown_table(sys.argv[1], tquad_module))
