#!/usr/bin/python3
"""What the smoothing costs and gives on every CAD part of a folder: the meshing time
(every candidate route of each face) and the smoothing time after it, from the JSON
report's face_seconds, one thread, the least of --repeat runs (times on a shared
machine vary by tens of percent); and the scaled Jacobian min / mean with and
without smoothing (--no-smooth), at the default size (the bounding-box diagonal / 25)
and at the finer sizes asked for.

    /usr/bin/python3 bench/smoothing_cost.py [--tquad build/bin/tquad]
        [--cad-dir ../shared/data/cad] [--divisors 25 100] [--repeat 3] [--markdown]

Prints one line per part and size; with --markdown, a table for bench/MEASURED.md.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CAD_EXTENSIONS = (".step", ".stp", ".brep", ".brp", ".iges", ".igs")


def report(tquad, path, out_dir, extra):
    args = [tquad, "mesh", path, "-o", os.path.join(out_dir, "out.vtu"), "--report", "json", "--keep-going",
            "--threads", "1"] + extra
    done = subprocess.run(args, capture_output=True, text=True)
    if done.returncode != 0:
        raise RuntimeError(done.stderr.strip().splitlines()[-1] if done.stderr.strip() else f"exit {done.returncode}")
    return json.loads(done.stdout)


def measure(tquad, path, size, repeat, out_dir):
    sized = [] if size is None else ["--size", repr(size)]
    raw = report(tquad, path, out_dir, sized + ["--no-smooth"])
    runs = [report(tquad, path, out_dir, sized) for _ in range(repeat)]
    meshing = min(r["face_seconds"]["meshing"] for r in runs)
    smoothing = min(r["face_seconds"]["smoothing"] for r in runs)
    before, after = raw["quality"]["scaled_jacobian"], runs[0]["quality"]["scaled_jacobian"]
    return {"quads": runs[0]["quads"], "edge_size": runs[0]["edge_size"], "meshing": meshing,
            "smoothing": smoothing, "ratio": smoothing / meshing if meshing > 0 else float("inf"),
            "before": (before["min"], before["avg"]), "after": (after["min"], after["avg"]),
            "inverted": runs[0]["quality"]["inverted"]}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--tquad", default=os.path.join(REPO, "build", "bin", "tquad"))
    parser.add_argument("--cad-dir", default=os.path.join(REPO, "..", "shared", "data", "cad"))
    parser.add_argument("--divisors", type=int, nargs="+", default=[25, 100])
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--markdown", action="store_true")
    args = parser.parse_args()
    if not os.path.isdir(args.cad_dir):
        print(f"no CAD folder at {args.cad_dir}", file=sys.stderr)
        return 2
    parts = sorted((f for f in os.listdir(args.cad_dir) if f.lower().endswith(CAD_EXTENSIONS)), key=str.lower)
    if args.markdown:
        print("| part | size | quads | SJ min / mean, not smoothed | smoothed | meshing | smoothing | ratio |")
        print("|---|---|---:|---|---|---:|---:|---:|")
    with tempfile.TemporaryDirectory() as out_dir:
        for part in parts:
            path = os.path.join(args.cad_dir, part)
            default = report(args.tquad, path, out_dir, ["--no-smooth"])["edge_size"]  # the diagonal / 25
            for divisor in args.divisors:
                size = None if divisor == 25 else default * 25 / divisor
                try:
                    m = measure(args.tquad, path, size, args.repeat, out_dir)
                except RuntimeError as error:
                    print(f"{part} D/{divisor}: failed: {error}", flush=True)
                    continue
                if args.markdown:
                    print(f"| {part} | D/{divisor} | {m['quads']:,} | {m['before'][0]:.3f} / {m['before'][1]:.3f} "
                          f"| {m['after'][0]:.3f} / {m['after'][1]:.3f} | {m['meshing'] * 1e3:.1f} ms "
                          f"| {m['smoothing'] * 1e3:.1f} ms | {m['ratio']:.2f} |", flush=True)
                else:
                    print(f"{part:36s} D/{divisor:<4d} quads {m['quads']:7d} min/mean {m['before'][0]:.3f}/"
                          f"{m['before'][1]:.3f} -> {m['after'][0]:.3f}/{m['after'][1]:.3f} inverted {m['inverted']} "
                          f"meshing {m['meshing']:.4f} s smoothing {m['smoothing']:.4f} s ratio {m['ratio']:.2f}",
                          flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
