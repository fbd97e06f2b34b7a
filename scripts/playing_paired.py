#!/usr/bin/env python3
"""Two players on the same open tables, layout by layout: the paired difference of their breaks
with a 95 % interval (normal, from the differences' standard deviation), their mean breaks,
pot success and clearances. The input is the open_table bench's JSON lines (`--out`); a layout
is the pair (noise, seed), and only layouts both sides played count.

    python3 scripts/playing_paired.py BEFORE.jsonl[,MORE.jsonl] AFTER.jsonl[,MORE.jsonl] [--noise K]

A visit's break varies by about 20 points over layouts, so 100 layouts resolve about +-5 points
and 200 about +-4 (docs/playing.md, "The second round").
"""

import json
import math
import sys


def read(paths: str, noise: float) -> dict:
    """Seed -> line of the comma-separated files `paths` at `noise` (first line wins)."""
    out = {}
    for p in paths.split(","):
        with open(p) as f:
            for line in f:
                if line.strip():
                    r = json.loads(line)
                    if r["noise"] == noise:
                        out.setdefault(r["seed"], r)
    return out


def main(argv: list) -> int:
    noise = 1.0
    args = []
    i = 0
    while i < len(argv):
        if argv[i] == "--noise":
            noise = float(argv[i + 1])
            i += 2
        else:
            args.append(argv[i])
            i += 1
    if len(args) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    a, b = read(args[0], noise), read(args[1], noise)
    seeds = sorted(set(a) & set(b))
    n = len(seeds)
    if n < 2:
        print(f"only {n} layouts played by both: nothing to compare", file=sys.stderr)
        return 1
    d = [b[s]["break"] - a[s]["break"] for s in seeds]
    mean = sum(d) / n
    sd = math.sqrt(sum((x - mean) ** 2 for x in d) / (n - 1))
    half = 1.959963984540054 * sd / math.sqrt(n)

    def summary(r):
        pots = sum(r[s]["pots"] for s in seeds)
        att = sum(r[s]["attempts"] for s in seeds)
        brk = sum(r[s]["break"] for s in seeds) / n
        clear = sum(bool(r[s]["cleared"]) for s in seeds)
        return brk, pots / max(att, 1), clear

    (ba, pa, ca), (bb, pb, cb) = summary(a), summary(b)
    print(f"layouts {n} (seeds {seeds[0]}-{seeds[-1]}), noise {noise:g} x standard")
    print(f"mean break {ba:.1f} -> {bb:.1f}: paired difference {mean:+.1f} +- {half:.1f} (95 %)")
    print(f"pot success {pa:.3f} -> {pb:.3f}; clearances {ca} -> {cb}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
