#!/usr/bin/python3
"""Random edits of a CAD file, each meshed by tquad: how the command ends on damaged input.

    python3 tools/cad_mutations.py FILE COUNT [--seed S] [--keep DIR] [--tquad PATH]

Each edit is one of: a byte replaced by a printable one, a digit replaced by 9, 0,
99999, -1 or 7, up to 20 bytes deleted, or the file cut at a random point. The edited
file is meshed with `tquad mesh EDITED -o OUT.vtu --keep-going --read-timeout 10`
under a 30 s limit. Outcomes: exit 0 (meshed), exit 2 (refused; the reader's crash or
deadline counted apart), exit 1 (internal failure), a signal (the command itself died)
or the 30 s limit. Files of the last three kinds are kept in DIR for study.
"""
import argparse
import os
import random
import subprocess
import sys
import tempfile

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def edit(data, rng):
    b = bytearray(data)
    kind = rng.choice(["byte", "digit", "delete", "cut"])
    pos = rng.randrange(len(b))
    if kind == "byte":
        b[pos] = rng.randrange(32, 127)
    elif kind == "digit":
        digits = [j for j in range(len(b)) if 48 <= b[j] <= 57]
        pos = rng.choice(digits)
        b[pos:pos + 1] = rng.choice([b"9", b"0", b"99999", b"-1", b"7"])
    elif kind == "delete":
        del b[pos:pos + rng.randrange(1, 21)]
    else:
        b = b[:pos]
    return bytes(b)


def outcome(tquad, path, out):
    try:
        r = subprocess.run([tquad, "mesh", path, "-o", out, "--keep-going", "--read-timeout", "10"],
                           capture_output=True, timeout=30)
    except subprocess.TimeoutExpired:
        return "hang (30 s)"
    err = r.stderr.decode(errors="replace")
    if r.returncode < 0:
        return "killed by signal %d" % -r.returncode
    if r.returncode == 2 and "crashed" in err:
        return "refused: the reader crashed"
    if r.returncode == 2 and "did not finish" in err:
        return "refused: the reader's deadline"
    return {0: "meshed", 1: "internal failure", 2: "refused"}.get(r.returncode, "exit %d" % r.returncode)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("file")
    parser.add_argument("count", type=int)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--keep", default=os.path.join(tempfile.gettempdir(), "cad_mutations"))
    parser.add_argument("--tquad", default=os.path.join(REPO, "build", "bin", "tquad"))
    args = parser.parse_args()
    data = open(args.file, "rb").read()
    ext = os.path.splitext(args.file)[1]
    rng = random.Random(args.seed)
    counts = {}
    with tempfile.TemporaryDirectory() as work:
        for i in range(args.count):
            path = os.path.join(work, "edit%05d%s" % (i, ext))
            with open(path, "wb") as f:
                f.write(edit(data, rng))
            result = outcome(args.tquad, path, os.path.join(work, "out.vtu"))
            counts[result] = counts.get(result, 0) + 1
            if result in ("internal failure", "hang (30 s)") or result.startswith("killed"):
                os.makedirs(args.keep, exist_ok=True)
                kept = os.path.join(args.keep, os.path.basename(path))
                os.replace(path, kept)
                print("%s: %s" % (result, kept), flush=True)
    print("%s, %d edits (seed %d): %s" % (os.path.basename(args.file), args.count, args.seed,
                                          ", ".join("%s %d" % kv for kv in sorted(counts.items()))))
    return 0


if __name__ == "__main__":
    sys.exit(main())
