#!/usr/bin/python3
"""Generated machined parts through tquad: refused faces, degenerate quads, cracks.

Writes the parts of seeds FIRST..LAST with build/bin/generated_parts (OpenCASCADE's
booleans, fillets and chamfers: tests/occ/generated_parts.h) and meshes each with
`tquad mesh --keep-going` at the diagonal / 25 and the other divisors asked for,
one process per part and size. Prints, per size, the refused faces by code with
their reasons, the parts with a degenerate quad (a corner at 0 or 180 degrees), the
worst scaled Jacobian, and the parts meshed whole whose mesh has an edge not in two
quads (a crack: every generated part is a closed solid).

    /usr/bin/python3 bench/generated_parts.py [--tquad build/bin/tquad]
        [--generator build/bin/generated_parts] [--seeds 1 200] [--divisors 25 50]
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
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        crashed = subprocess.run([args.generator, folder, str(args.seeds[0]), str(args.seeds[1])],
                                 capture_output=True, text=True, check=True).stdout.split("\n")
        parts = sorted((f for f in os.listdir(folder) if f.endswith(".brep")), key=lambda f: int(f[5:-5]))
        print(f"seeds {args.seeds[0]} to {args.seeds[1]}: {len(parts)} parts built, "
              f"{sum(1 for line in crashed if line)} crashed in OpenCASCADE")
        out = os.path.join(folder, "mesh.vtu")
        for divisor in args.divisors:
            faces, refused, degenerate, cracked, failed, worst = 0, [], [], [], [], 1.0
            for part in parts:
                path = os.path.join(folder, part)
                plain, error = run(args.tquad, path, out, ["--no-smooth"])
                report = None
                if plain:
                    report, error = run(args.tquad, path, out, ["--size", repr(plain["edge_size"] * 25 / divisor)])
                if report is None:
                    failed.append((part, error))
                    continue
                faces += len(report["faces"]) + len(report["refused_faces"])
                refused += [(part, f["code"], f["reason"]) for f in report["refused_faces"]]
                quality = report["quality"]
                worst = min(worst, quality["scaled_jacobian"]["min"])
                if quality["degenerate"] > 0:
                    degenerate.append(part)
                if not report["refused_faces"] and open_edges(out) > 0:
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
