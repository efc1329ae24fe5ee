#!/usr/bin/python3
"""Generated machined parts through tquad: refused faces, degenerate quads, cracks.

Writes the parts of seeds FIRST..LAST with build/bin/generated_parts (OpenCASCADE's
booleans, fillets and chamfers: tests/occ/generated_parts.h), or with --source
freecad FreeCAD's Part module (bench/freecad_part_families.py: shafts, flanges,
lofts, shelled boxes, brackets, sheets; --formats writes each as BREP, STEP and/or
IGES, through OpenCASCADE's writers and readers), and meshes each with
`tquad mesh --keep-going` at the diagonal / 25 and the other divisors asked for,
one process per part and size. Prints, per size, the refused faces by code with
their reasons, the parts with a degenerate quad (a corner at 0 or 180 degrees), the
worst scaled Jacobian, and, for the occ parts (closed solids all), those meshed whole
whose mesh has an edge not in two quads (a crack).

    /usr/bin/python3 bench/generated_parts.py [--tquad build/bin/tquad]
        [--generator build/bin/generated_parts] [--seeds 1 200] [--divisors 25 50]
        [--source occ|freecad] [--formats brep step igs] [--sew]
"""
import argparse
import collections
import json
import os
import subprocess
import sys
import tempfile

import meshio

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(REPO, "bench"))
from freecad_script import run_in_freecad  # noqa: E402


def run(tquad, path, out, extra):
    done = subprocess.run([tquad, "mesh", path, "-o", out, "--report", "json", "--keep-going"] + extra,
                          capture_output=True, text=True)
    if done.returncode != 0:
        return None, done.stderr.strip().splitlines()[-1] if done.stderr.strip() else f"exit {done.returncode}"
    return json.loads(done.stdout), None


def open_edges(vtu):
    uses = collections.Counter()
    for quad in meshio.read(vtu).cells_dict["quad"]:
        for i in range(4):
            uses[tuple(sorted((quad[i], quad[(i + 1) % 4])))] += 1
    return sum(1 for n in uses.values() if n != 2)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--tquad", default=os.path.join(REPO, "build", "bin", "tquad"))
    parser.add_argument("--generator", default=os.path.join(REPO, "build", "bin", "generated_parts"))
    parser.add_argument("--seeds", type=int, nargs=2, default=[1, 200], metavar=("FIRST", "LAST"))
    parser.add_argument("--divisors", type=int, nargs="+", default=[25, 50])
    parser.add_argument("--source", choices=["occ", "freecad"], default="occ")
    parser.add_argument("--formats", nargs="+", choices=["brep", "step", "igs"], default=["brep"])
    parser.add_argument("--sew", action="store_true", help="mesh with --sew (IGES trimmed surfaces)")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        if args.source == "occ":
            crashed = subprocess.run([args.generator, folder, str(args.seeds[0]), str(args.seeds[1])],
                                     capture_output=True, text=True, check=True).stdout.split("\n")
            print(f"seeds {args.seeds[0]} to {args.seeds[1]}: {sum(1 for line in crashed if line)} crashed in OpenCASCADE")
        else:
            with open(os.path.join(REPO, "bench", "freecad_part_families.py")) as f:
                families = f.read()
            done = run_in_freecad(f"FOLDER = {folder!r}\nFIRST = {args.seeds[0]}\nLAST = {args.seeds[1]}\n"
                                  f"FORMATS = {args.formats!r}\n" + families)
            if done.returncode != 0:
                print(done.stdout[-2000:], done.stderr[-2000:], file=sys.stderr)
                return 1
        parts = sorted((f for f in os.listdir(folder) if f.startswith("part_")),
                       key=lambda f: (int(f[5:].split(".")[0]), f))
        print(f"{len(parts)} parts ({args.source}, {' '.join(args.formats) if args.source == 'freecad' else 'brep'})")
        out = os.path.join(folder, "mesh.vtu")
        for divisor in args.divisors:
            faces, refused, degenerate, cracked, failed, worst = 0, [], [], [], [], 1.0
            for part in parts:
                path = os.path.join(folder, part)
                sew = ["--sew"] if args.sew else []
                plain, error = run(args.tquad, path, out, ["--no-smooth"] + sew)
                report = None
                if plain:
                    report, error = run(args.tquad, path, out, ["--size", repr(plain["edge_size"] * 25 / divisor)] + sew)
                if report is None:
                    failed.append((part, error))
                    continue
                faces += len(report["faces"]) + len(report["refused_faces"])
                refused += [(part, f["code"], f["reason"]) for f in report["refused_faces"]]
                quality = report["quality"]
                worst = min(worst, quality["scaled_jacobian"]["min"])
                if quality["degenerate"] > 0:
                    degenerate.append(part)
                # (the occ parts are closed solids; FreeCAD's families include open sheets)
                if args.source == "occ" and not report["refused_faces"] and open_edges(out) > 0:
                    cracked.append(part)
            codes = collections.Counter(code for _, code, _ in refused)
            print(f"D/{divisor}: {faces} faces, {len(refused)} refused {dict(codes)}, "
                  f"{len(degenerate)} parts with a degenerate quad, worst scaled Jacobian {worst:.3f}, "
                  f"{len(cracked)} meshed whole with a crack, {len(failed)} runs failed", flush=True)
            for part, code, reason in refused:
                print(f"  {part}: {code}: {reason}")
            for part in cracked:
                print(f"  {part}: an edge not in two quads")
            for part, error in failed:
                print(f"  {part}: tquad failed: {error}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
