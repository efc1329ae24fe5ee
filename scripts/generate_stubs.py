#!/usr/bin/python3
"""Writes mesh_shape's signature in src/python/tquad/__init__.pyi from the options
schema (src/core/mesh_option_schema.cpp), so the stub cannot drift from it.

Usage: PYTHONPATH=build/python scripts/generate_stubs.py [--check]
--check: exit 1, changing nothing, when the stub differs from what would be written
(tests/python/test_stubs.py does the same check).
"""
import os
import re
import sys

STUB = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "src", "python", "tquad", "__init__.pyi")
_DEF = re.compile(r"^def mesh_shape\(.*?-> Mesh: \.\.\.\n", re.S | re.M)


def mesh_shape_stub(schema) -> str:
    """The stub's def of mesh_shape: the input, then every option as a keyword."""
    parameters = ["brep_text_or_path: str", "*"]
    parameters += ["%s: %s = ..." % (row["name"], row["type"]) for row in schema]
    head = "def mesh_shape("
    lines, line = [], head
    for i, parameter in enumerate(parameters):
        piece = parameter + (", " if i + 1 < len(parameters) else ") -> Mesh: ...")
        if line.strip() and line != head and len(line + piece.rstrip()) > 100:
            lines.append(line.rstrip())
            line = " " * len(head)
        line += piece
    return "\n".join(lines + [line]) + "\n"


def stub_with_schema(text: str, schema) -> str:
    if not _DEF.search(text):
        raise ValueError("no 'def mesh_shape(...) -> Mesh: ...' in " + STUB)
    return _DEF.sub(lambda _: mesh_shape_stub(schema), text, count=1)


def main() -> int:
    import tquad
    with open(STUB) as f:
        text = f.read()
    wanted = stub_with_schema(text, tquad.mesh_option_schema())
    if "--check" in sys.argv[1:]:
        if wanted != text:
            print("%s: mesh_shape differs from the options schema; run %s" % (STUB, sys.argv[0]))
            return 1
        return 0
    if wanted != text:
        with open(STUB, "w") as f:
            f.write(wanted)
    return 0


if __name__ == "__main__":
    sys.exit(main())
