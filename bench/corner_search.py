#!/usr/bin/python3
"""--corners best against the natural corner choice, on the shipped boundary examples
and on every CAD part of a folder, at the default size (the bounding-box diagonal /
25) or at the diagonal / --divisor (CAD parts; the boundaries keep their counts):
worst and mean scaled Jacobian, faces where another corner set won, and the time of
each run (whole process) with its ratio to the natural run, from one run of each on
this machine.

    /usr/bin/python3 bench/corner_search.py [--tquad build/bin/tquad]
        [--cad-dir ../shared/data/cad] [--divisor 25] [--markdown]

Prints one line per input; with --markdown, a table for bench/MEASURED.md.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CAD_EXTENSIONS = (".step", ".stp", ".brep", ".brp", ".iges", ".igs")


def run(tquad, path, best, out_dir, size=None):
    args = [tquad, "mesh", path, "-o", os.path.join(out_dir, "out.vtu"), "--report", "json"]
    if size is not None:
        args += ["--size", repr(size)]
    if best:
        args += ["--corners", "best"]
    if path.endswith(CAD_EXTENSIONS):
        args += ["--keep-going"]
    start = time.perf_counter()
    done = subprocess.run(args, capture_output=True, text=True)
    seconds = time.perf_counter() - start
    if done.returncode != 0:
        return {"error": done.stderr.strip().splitlines()[-1] if done.stderr.strip() else f"exit {done.returncode}"}
    report = json.loads(done.stdout)
    sj = report["quality"]["scaled_jacobian"]
    searches = [f["corner_search"] for f in report["faces"] if "corner_search" in f]
    return {"min": sj["min"], "mean": sj["avg"], "quads": report["quads"], "seconds": seconds,
            "edge_size": report.get("edge_size"),
            "searched": len(searches), "changed": sum(1 for s in searches if s["changed"]),
            "worse_faces": sum(1 for s in searches if s["chosen"]["min"] < s["natural"]["min"] - 1e-12),
            "refused": len(report.get("refused_faces", []))}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--tquad", default=os.path.join(REPO, "build", "bin", "tquad"))
    parser.add_argument("--cad-dir", default=os.path.join(REPO, "..", "shared", "data", "cad"))
    parser.add_argument("--divisor", type=float, default=25.0,
                        help="CAD parts at the bounding-box diagonal / this (default 25, tquad's default size)")
    parser.add_argument("--markdown", action="store_true")
    args = parser.parse_args()
    inputs = sorted(os.path.join(REPO, "resources", "boundaries", f)
                    for f in os.listdir(os.path.join(REPO, "resources", "boundaries")) if f.endswith(".json"))
    if os.path.isdir(args.cad_dir):
        inputs += sorted((os.path.join(args.cad_dir, f) for f in os.listdir(args.cad_dir)
                          if f.lower().endswith(CAD_EXTENSIONS)), key=lambda p: os.path.basename(p).lower())
    else:
        print(f"no CAD folder at {args.cad_dir}: boundary examples only", file=sys.stderr)
    if args.markdown:
        print("| input | natural: SJ min / mean | best: SJ min / mean | faces searched, won by other corners "
              "| faces worse | quads natural / best | time best / natural |")
        print("|---|---|---|---|---:|---|---:|")
    with tempfile.TemporaryDirectory() as out_dir:
        for path in inputs:
            size = None
            if args.divisor != 25 and path.endswith(CAD_EXTENSIONS):
                default = run(args.tquad, path, False, out_dir)  # its edge_size is the diagonal / 25
                if "error" not in default:
                    size = default["edge_size"] * 25 / args.divisor
            natural = run(args.tquad, path, False, out_dir, size)
            best = run(args.tquad, path, True, out_dir, size)
            name = os.path.basename(path)
            if "error" in natural or "error" in best:
                print(f"{name}: natural {natural.get('error', 'ok')}; best {best.get('error', 'ok')}")
                continue
            ratio = best["seconds"] / natural["seconds"]
            if args.markdown:
                print(f"| {name} | {natural['min']:.3f} / {natural['mean']:.3f} | {best['min']:.3f} / {best['mean']:.3f} "
                      f"| {best['searched']}, {best['changed']} | {best['worse_faces']} "
                      f"| {natural['quads']} / {best['quads']} | {ratio:.1f} |")
            else:
                print(f"{name:38s} natural {natural['min']:.3f}/{natural['mean']:.3f}  best {best['min']:.3f}/"
                      f"{best['mean']:.3f}  searched {best['searched']} changed {best['changed']} "
                      f"worse {best['worse_faces']}  time x{ratio:.1f}")


if __name__ == "__main__":
    main()
