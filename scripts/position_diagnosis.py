#!/usr/bin/env python3
"""Sums up the position-play diagnosis of `player/examples/attempts.rs` (one JSON line per
stroke): where the pot success per attempt is lost.

    python3 scripts/position_diagnosis.py LINES.jsonl [MORE.jsonl ...]

For the attempted pots it prints the pot success beside the chances the player worked with:
the sampled chance of the pot chosen (what the search expected), the closed-form chance of
that pot from where the cue ball lay, the closed-form chance of the best pot from there, and,
for the pots that followed a pot, the best pot's closed-form chance from where the previous
stroke meant to leave the cue ball. The steps between them say how much each link loses:
planned position -> position reached (the cue ball's end spread), position reached -> pot
chosen (the valuation's choice), expected -> potted (the estimate's optimism).
"""
import json
import math
import sys


def mean(v):
    return sum(v) / len(v) if v else float("nan")


def wilson(k, n, z=1.96):
    if n == 0:
        return (float("nan"), float("nan"))
    p = k / n
    d = 1 + z * z / n
    c = (p + z * z / (2 * n)) / d
    h = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / d
    return (c - h, c + h)


def row(name, rows):
    n = len(rows)
    k = sum(r["potted"] for r in rows)
    lo, hi = wilson(k, n)
    return (
        f"| {name} | {n} | {100 * k / max(n, 1):.1f} % ({100 * lo:.0f}-{100 * hi:.0f}) | "
        f"{mean([r['sampled'] for r in rows]):.3f} | "
        f"{mean([r['closed_chance'] for r in rows if r['closed_chance'] is not None]):.3f} | "
        f"{mean([r['best_chance_here'] for r in rows]):.3f} | "
        f"{mean([r['from']['planned_best_chance'] for r in rows if r['from']]):.3f} |"
    )


def main():
    lines = []
    for path in sys.argv[1:]:
        with open(path) as f:
            lines += [json.loads(l) for l in f if l.strip()]
    pots = [l for l in lines if l["kind"] != "safety"]
    seeds = sorted({l["seed"] for l in lines})
    visits = {}
    for l in lines:
        visits.setdefault(l["seed"], 0)
        visits[l["seed"]] += l["points"]
    print(f"{len(seeds)} visits (seeds {seeds[0]}-{seeds[-1]}), {len(lines)} strokes, "
          f"{len(pots)} pots attempted, mean break {mean(list(visits.values())):.1f}")
    print()
    print("| attempts | n | potted (95 %) | sampled chance | closed-form chance of the pot | "
          "best closed-form chance there | best closed-form chance at the planned end |")
    print("|---|---|---|---|---|---|---|")
    print(row("all", pots))
    print(row("in hand", [p for p in pots if p["in_hand"]]))
    print(row("after a pot", [p for p in pots if p["from"]]))
    print(row("direct", [p for p in pots if p["kind"] == "direct"]))
    print(row("not direct", [p for p in pots if p["kind"] != "direct"]))
    print(row("on a red", [p for p in pots if p["on"] == "red"]))
    print(row("on a colour", [p for p in pots if p["on"] != "red"]))
    after = [p for p in pots if p["from"]]
    print()
    print("By the sampled chance of the pot chosen:")
    print("| sampled | n | potted | mean sampled |")
    print("|---|---|---|---|")
    for lo, hi in [(0, 0.7), (0.7, 0.8), (0.8, 0.9), (0.9, 0.95), (0.95, 1.01)]:
        r = [p for p in pots if lo <= p["sampled"] < hi]
        if r:
            print(f"| {lo:.2f}-{min(hi, 1):.2f} | {len(r)} | "
                  f"{100 * mean([x['potted'] for x in r]):.0f} % | {mean([x['sampled'] for x in r]):.3f} |")
    misses = [p for p in pots if not p["potted"]]
    low = [p for p in misses if p["sampled"] < 0.7]
    print(f"- misses: {len(misses)}, of them {len(low)} at a sampled chance below 0.7")
    print()
    print("The position the pots after a pot came from:")
    e = sorted(p["from"]["end_error"] for p in after)
    if e:
        print(f"- the cue ball's end from the planned end: median {1000 * e[len(e) // 2]:.0f} mm, "
              f"mean {1000 * mean(e):.0f} mm, 90th percentile {1000 * e[int(0.9 * len(e))]:.0f} mm")
    for name, cond in [
        ("cue ball ran into another ball", lambda f: f["cue_balls_hit_after_first"] > 0),
        ("cue ball path > 1.5 m", lambda f: f["cue_path"] > 1.5),
        ("cue ball off >= 2 cushions", lambda f: f["cue_cushions"] >= 2),
        ("end error > 150 mm", lambda f: f["end_error"] > 0.15),
        ("the pot chosen is the planned one", lambda f: f["same_pot_as_planned"]),
    ]:
        yes = [p for p in after if cond(p["from"])]
        no = [p for p in after if not cond(p["from"])]
        print(f"- {name}: {len(yes)} of {len(after)}; potted {100 * mean([p['potted'] for p in yes]):.0f} % "
              f"(else {100 * mean([p['potted'] for p in no]):.0f} %), sampled {mean([p['sampled'] for p in yes]):.3f} "
              f"(else {mean([p['sampled'] for p in no]):.3f}), planned best {mean([p['from']['planned_best_chance'] for p in yes]):.3f}, "
              f"best there {mean([p['best_chance_here'] for p in yes]):.3f}")
    if after and "meant_balls_hit_after_first" in after[0]["from"]:
        played = [p for p in after if p["from"]["cue_balls_hit_after_first"] > 0]
        meant = [p for p in played if p["from"]["meant_balls_hit_after_first"] > 0]
        meant_only = [p for p in after if p["from"]["meant_balls_hit_after_first"] > 0
                      and p["from"]["cue_balls_hit_after_first"] == 0]
        print(f"- of the {len(played)} positions after the cue ball ran into a ball, the stroke "
              f"as meant did so too in {len(meant)}; the stroke as meant ran into a ball but the "
              f"one played did not in {len(meant_only)}")
        print()
        print("| the stroke before | positions | best closed-form chance at the planned end | "
              "end error, median | sampled chance of the pot chosen | potted |")
        print("|---|---|---|---|---|---|")
        kinds = [
            ("meant to run into a ball", lambda f: f["meant_balls_hit_after_first"] > 0),
            ("ran into a ball, not meant", lambda f: f["meant_balls_hit_after_first"] == 0
             and f["cue_balls_hit_after_first"] > 0),
            ("ran into no ball", lambda f: f["meant_balls_hit_after_first"] == 0
             and f["cue_balls_hit_after_first"] == 0),
        ]
        for name, cond in kinds:
            r = [p for p in after if cond(p["from"])]
            if not r:
                continue
            e = sorted(p["from"]["end_error"] for p in r)
            k = sum(p["potted"] for p in r)
            print(f"| {name} | {len(r)} | {mean([p['from']['planned_best_chance'] for p in r]):.3f} | "
                  f"{1000 * e[len(e) // 2]:.0f} mm | {mean([p['sampled'] for p in r]):.3f} | "
                  f"{100 * k / len(r):.1f} % ({k}/{len(r)}) |")
        # Predicted spread along the way (the valuer's model: 2 L sd / v) against the error.
        ratio = sorted(p["from"]["end_error"] / max(1e-9, 2 * p["from"]["meant_path"] * 0.075
                                                     / p["from"]["speed"]) for p in after
                       if p["from"]["meant_path"] > 0)
        if ratio:
            print(f"- the end error over the valuer's spread along the way (2 L sd / v): median "
                  f"{ratio[len(ratio) // 2]:.2f}, 90th percentile {ratio[int(0.9 * len(ratio))]:.2f}")
    # Where the chance was lost, pot by pot after a pot: planned best -> best reached ->
    # sampled chosen -> potted.
    if after:
        pb = mean([p["from"]["planned_best_chance"] for p in after])
        br = mean([p["best_chance_here"] for p in after])
        sc = mean([p["sampled"] for p in after])
        po = mean([p["potted"] for p in after])
        print()
        print(f"Chain over the {len(after)} pots after a pot: best chance at the planned end {pb:.3f} "
              f"-> best chance where the cue ball stopped {br:.3f} -> sampled chance of the pot chosen "
              f"{sc:.3f} -> potted {po:.3f}")


main()
