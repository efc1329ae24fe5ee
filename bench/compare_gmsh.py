#!/usr/bin/python3
"""Side-by-side speed and memory: TemplateQuad's bench_templates against Gmsh 4.8.

Run with Debian's /usr/bin/python3 (it has python3-gmsh):

    /usr/bin/python3 bench/compare_gmsh.py [--bench build/bin/bench_templates]

Cases, all on the same W x H rectangle with evenly spaced boundary points:
  (a) ours, equal opposite counts (one mapped grid) and unequal counts (templates);
  (b) Gmsh transfinite quads (setTransfiniteSurface + setRecombine), equal counts;
  (c) Gmsh's all-quad unstructured route (frontal-Delaunay + full-quad recombination)
      for unequal counts, at a smaller size because it is slow; ours runs the same
      small case for the ratio.
Gmsh time covers gmsh.model.mesh.generate(2) only. Each Gmsh case runs in its own
process (this script re-invoked with --gmsh-case) so its peak RSS is its own: the
reported memory is ru_maxrss after meshing minus the RSS just before generate(2).
Nothing here asserts a speed; the numbers are printed as measured.
"""

import argparse
import json
import os
import resource
import subprocess
import sys
import time

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def parse_counts(text):
    counts = [int(c) for c in text.split(",")]
    if len(counts) != 4 or min(counts) < 1 or sum(counts) % 2:
        raise argparse.ArgumentTypeError("need four positive counts with an even sum")
    return counts


def current_rss_bytes():
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")


def peak_rss_bytes():
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024  # KiB on Linux


# ---------------------------------------------------------------- gmsh child process

def gmsh_case(spec):
    """Meshes one case in this process and prints one JSON line."""
    import gmsh
    from gmsh_rectangle import quiet_single_thread, rectangle

    counts, width, height = spec["counts"], spec["width"], spec["height"]
    gmsh.initialize([], False)
    try:
        quiet_single_thread(gmsh)
        lines, surface = rectangle(gmsh, width, height, counts)
        if spec["route"] == "transfinite":
            gmsh.model.mesh.setTransfiniteSurface(surface)
        else:
            gmsh.option.setNumber("Mesh.Algorithm", 6)  # frontal-Delaunay (8 crashes in 4.8)
            gmsh.option.setNumber("Mesh.RecombinationAlgorithm", spec["recombination"])
        gmsh.model.mesh.setRecombine(2, surface)

        times = []
        rss_before = current_rss_bytes()
        for i in range(spec["runs"]):
            if i:
                gmsh.model.mesh.clear()
            start = time.perf_counter()
            gmsh.model.mesh.generate(2)
            times.append(time.perf_counter() - start)
        peak = peak_rss_bytes()

        quads = triangles = 0
        types, tags, _ = gmsh.model.mesh.getElements(2)
        for etype, etags in zip(types, tags):
            if etype == 3:
                quads += len(etags)
            elif etype == 2:
                triangles += len(etags)
        node_tags, _, _ = gmsh.model.mesh.getNodes()
        boundary = [len(gmsh.model.mesh.getElements(1, line)[1][0]) for line in lines]
    finally:
        gmsh.finalize()
    print(json.dumps({
        "quads": quads, "triangles": triangles, "nodes": len(node_tags),
        "boundary_segments": boundary, "times_s": times, "best_s": min(times),
        "rss_before_bytes": rss_before, "peak_rss_bytes": peak,
    }))


# ---------------------------------------------------------------- parent

def run_ours(bench, counts, args):
    cmd = [bench, "--json", "--runs", str(args.runs), "--counts", ",".join(map(str, counts)),
           "--width", repr(args.width), "--height", repr(args.height)]
    out = subprocess.run(cmd, check=True, capture_output=True, text=True, timeout=300)
    r = json.loads(out.stdout.strip().splitlines()[-1])
    return {"mesher": "TemplateQuad " + r["template_tree"], "counts": counts,
            "quads": r["quads"], "other": 0, "best_s": r["best_s"], "first_s": r["first_s"],
            "median_s": r["median_s"], "bytes_per_quad": r["bytes_per_quad"]}


def run_gmsh(counts, route, runs, args, recombination=2, timeout=240):
    spec = {"counts": counts, "width": args.width, "height": args.height, "route": route,
            "runs": runs, "recombination": recombination}
    names = {1: "Blossom", 2: "simple full-quad", 3: "Blossom full-quad"}
    label = ("Gmsh transfinite" if route == "transfinite"
             else "Gmsh frontal-Delaunay + " + names.get(recombination, str(recombination)))
    row = {"mesher": label, "counts": counts}
    try:
        out = subprocess.run([sys.executable, os.path.abspath(__file__), "--gmsh-case",
                              json.dumps(spec)], capture_output=True, text=True,
                             timeout=timeout)
    except subprocess.TimeoutExpired:
        row["error"] = "timeout after %d s" % timeout
        return row
    lines = [l for l in out.stdout.splitlines() if l.startswith("{")]
    if out.returncode != 0 or not lines:
        row["error"] = "exit %d: %s" % (out.returncode, out.stderr.strip()[-300:])
        return row
    r = json.loads(lines[-1])
    row.update({"quads": r["quads"], "other": r["triangles"], "best_s": r["best_s"],
                "first_s": r["times_s"][0],
                "median_s": sorted(r["times_s"])[len(r["times_s"]) // 2],
                "bytes_per_quad": (r["peak_rss_bytes"] - r["rss_before_bytes"])
                / max(r["quads"], 1),
                "boundary": r["boundary_segments"]})
    return row


def fmt_row(case, row, reference=None):
    counts = ",".join(map(str, row["counts"]))
    if "error" in row:
        return "| %s | %s | %s | - | - | - | - | - | - | %s |" % (
            case, row["mesher"], counts, "", row["error"])
    qps = row["quads"] / row["best_s"]
    ratio = "-"
    if reference is not None and "error" not in reference:
        ratio = "%.1fx" % (qps / (reference["quads"] / reference["best_s"]))
    note = ""
    if "boundary" in row and row["boundary"] != row["counts"]:
        note = "boundary segments %s" % ",".join(map(str, row["boundary"]))
    rate = "%.2f M" % (qps / 1e6) if qps >= 1e6 else "%.0f" % qps
    return "| %s | %s | %s | %d | %d | %.4f | %.4f | %s | %.1f | %s | %s |" % (
        case, row["mesher"], counts, row["quads"], row["other"], row["first_s"], row["best_s"],
        rate,
        row["bytes_per_quad"], ratio, note)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--bench", default=os.path.join(REPO, "build", "bin", "bench_templates"),
                        help="bench_templates binary (default: build/bin/ under the repo root)")
    parser.add_argument("--equal", type=parse_counts, default=[1200, 1000, 1200, 1000])
    parser.add_argument("--unequal", type=parse_counts, default=[1000, 1200, 1400, 1300])
    parser.add_argument("--small-unequal", type=parse_counts, default=[300, 360, 420, 390],
                        help="counts for Gmsh's slow unstructured all-quad route")
    parser.add_argument("--runs", type=int, default=5, help="runs of each fast case")
    parser.add_argument("--width", type=float, default=1.0)
    parser.add_argument("--height", type=float, default=0.8)
    parser.add_argument("--recombination", type=int, default=2,
                        help="Mesh.RecombinationAlgorithm for case (c) (1 Blossom, 2, 3)")
    parser.add_argument("--skip-unstructured", action="store_true")
    parser.add_argument("--gmsh-case", help=argparse.SUPPRESS)
    args = parser.parse_args()

    if args.gmsh_case:
        gmsh_case(json.loads(args.gmsh_case))
        return
    if not os.access(args.bench, os.X_OK):
        sys.exit("bench binary not found: %s (build the bench_templates target or pass --bench)"
                 % args.bench)

    start = time.perf_counter()
    ours_equal = run_ours(args.bench, args.equal, args)
    ours_unequal = run_ours(args.bench, args.unequal, args)
    gmsh_tf = run_gmsh(args.equal, "transfinite", args.runs, args)
    rows = [("a equal", ours_equal, gmsh_tf), ("a unequal", ours_unequal, gmsh_tf),
            ("b equal", gmsh_tf, None)]
    if not args.skip_unstructured:
        ours_small = run_ours(args.bench, args.small_unequal, args)
        gmsh_un = run_gmsh(args.small_unequal, "unstructured", 1, args,
                           recombination=args.recombination)
        rows += [("c small unequal", ours_small, gmsh_un), ("c small unequal", gmsh_un, None)]

    print("Rectangle %g x %g, single thread, %d runs per fast case (best time); Gmsh times "
          "cover generate(2) only; memory = peak RSS minus RSS before meshing.\n"
          % (args.width, args.height, args.runs))
    print("| case | mesher | counts | quads | triangles | first s | best s | quads/s (best) "
          "| bytes/quad | ours/gmsh speed | note |")
    print("|---|---|---|---:|---:|---:|---:|---:|---:|---:|---|")
    for case, row, reference in rows:
        print(fmt_row(case, row, reference))
    print("\nRatio: quads/s (best) of ours over the Gmsh row of the same case letter; 'a unequal'"
          " is compared with Gmsh transfinite on the equal counts, which that route needs.\n"
          "Every run of ours maps fresh pages (a cold call); Gmsh's repeated runs reuse its"
          " process heap, so its best time may be warm.")
    print("total script time %.1f s" % (time.perf_counter() - start))


if __name__ == "__main__":
    main()
