#!/usr/bin/env python3
"""The tables of docs/playing.md from the benchmarks' JSON lines (`--out` of the open_table and
frames benches of the player crate): works on a run still going or cut short, and says how many
layouts or frames each row holds.

    python3 scripts/playing_tables.py OPEN_TABLE.jsonl [...] [--frames FRAMES.jsonl [...]]

The open-table rows: mean break, clearances (15 reds and the 6 colours in one visit, with a
Wilson 95 % interval), highest break, pot success per attempted pot, strokes per visit, median
and mean decision time. The frames row: frames the player won with a Wilson 95 % interval.
"""

import json
import math
import statistics
import sys


def wilson(k: int, n: int) -> tuple:
    """Wilson's 95 % score interval of k successes in n trials."""
    if n == 0:
        return (0.0, 1.0)
    z = 1.959963984540054
    p = k / n
    centre = (p + z * z / (2 * n)) / (1 + z * z / n)
    half = z / (1 + z * z / n) * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n))
    return (max(0.0, centre - half), min(1.0, centre + half))


def read(paths, key):
    """The lines of `paths`, one per (noise, key): a layout or frame run twice (the runs are
    deterministic: the same line) counts once."""
    rows = {}
    for p in paths:
        with open(p) as f:
            for line in f:
                if line.strip():
                    r = json.loads(line)
                    rows.setdefault((r["noise"], r[key]), r)
    return list(rows.values())


def open_table(rows):
    print("| noise | layouts | mean break | clearances (95 % interval) | highest | pots / attempts "
          "| strokes per visit | median decision | mean decision | effort |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for noise in sorted({r["noise"] for r in rows}):
        rs = sorted((r for r in rows if r["noise"] == noise), key=lambda r: r["seed"])
        n = len(rs)
        breaks = [r["break"] for r in rs]
        clear = sum(r["cleared"] for r in rs)
        lo, hi = wilson(clear, n)
        pots, att = sum(r["pots"] for r in rs), sum(r["attempts"] for r in rs)
        times = [t for r in rs for t in r["decision_times"]]
        efforts = sorted({r["effort"] for r in rs})
        print(f"| {noise:g} x standard | {n} (seeds {rs[0]['seed']}-{rs[-1]['seed']}) "
              f"| {statistics.mean(breaks):.1f} | {100 * clear / n:.0f} % ({clear}; "
              f"{100 * lo:.0f}-{100 * hi:.0f} %) | {max(breaks)} "
              f"| {100 * pots / max(att, 1):.1f} % ({pots}/{att}) "
              f"| {sum(r['strokes'] for r in rs) / n:.1f} | {statistics.median(times):.2f} s "
              f"| {statistics.mean(times):.2f} s | {','.join(map(str, efforts))} |")


def frames(rows):
    print("| noise | frames | player won (95 % interval) | mean score, player - greedy "
          "| strokes per frame | capped |")
    print("|---|---|---|---|---|---|")
    for noise in sorted({r["noise"] for r in rows}):
        rs = [r for r in rows if r["noise"] == noise]
        n = len(rs)
        won = sum(r["player_won"] for r in rs)
        lo, hi = wilson(won, n)
        me = [r["scores"][r["player_side"]] for r in rs]
        them = [r["scores"][1 - r["player_side"]] for r in rs]
        print(f"| {noise:g} x standard | {n} | {100 * won / n:.0f} % ({won}; {100 * lo:.0f}-"
              f"{100 * hi:.0f} %) | {statistics.mean(me):.1f} - {statistics.mean(them):.1f} "
              f"| {sum(r['strokes'] for r in rs) / n:.0f} | {sum(r['capped'] for r in rs)} |")


def main(argv):
    if "--frames" in argv:
        i = argv.index("--frames")
        ot, fr = argv[:i], argv[i + 1:]
    else:
        ot, fr = argv, []
    if ot:
        open_table(read(ot, "seed"))
    if fr:
        print()
        frames(read(fr, "frame"))


if __name__ == "__main__":
    main(sys.argv[1:])
