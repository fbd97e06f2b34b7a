#!/usr/bin/env python3
"""Aggregates the part logs of a long fuzz run (fuzz --from K --scenes N, one log per part:
the harness's stdout) into the book's Robustness page (docs/robustness.md): the run's line, its
endings by kind and its coverage table, written between the markers <!-- fuzz-report --> and
<!-- /fuzz-report -->. Usage: scripts/fuzz_report.py LOG_DIR [COMMIT]"""
import collections
import glob
import os
import re
import sys

ENDINGS = ['at rest', 'rejected', 'still moving at max_time', 'event cap', 'stuck at an instant',
           'impact failed', 'non-finite', 'panic']
LABELS = {'still moving at max_time': 'still moving when cut (30 s)',
          'event cap': 'event cap (cut at 5,000)',
          'rejected': 'rejected with a message naming the file'}

kinds = []            # in the order the logs list them
phys = collections.Counter()
other = collections.Counter()
reasons = collections.Counter()
coverage = collections.defaultdict(lambda: collections.Counter())
features = []
n = fails = 0
seed = None
parts = sorted(glob.glob(os.path.join(sys.argv[1], 'part-*.log')))
for f in parts:
    lines = open(f).read().splitlines()
    if not lines:
        continue
    m = re.match(r'seed (\d+): scenes (\d+)\.\.(\d+) \((\d+) scenes\), (\d+) failing', lines[0])
    if not m:
        continue
    seed = m.group(1)
    n += int(m.group(4))
    fails += int(m.group(5))
    mode = 'endings'
    for line in lines[1:]:
        if line.startswith('coverage:'):
            mode = 'coverage-head'
            continue
        if line.startswith('near-frictionless'):
            mode = 'reasons'
            continue
        if mode == 'endings':
            m4 = re.match(r'^(\S+)\s+(' + '|'.join(ENDINGS) + r')\s+(\d+)\s+(\d+)$', line)
            if m4:
                k = (m4.group(1), m4.group(2))
                if m4.group(1) not in kinds:
                    kinds.append(m4.group(1))
                phys[k] += int(m4.group(3))
                other[k] += int(m4.group(4))
        elif mode == 'coverage-head':
            features = line.split()[2:]
            mode = 'coverage'
        elif mode == 'coverage':
            cells = line.split()
            if len(cells) == len(features) + 2:
                row = coverage[cells[0]]
                row['scenes'] += int(cells[1])
                for name, v in zip(features, cells[2:]):
                    row[name] += int(v)
        elif mode == 'reasons':
            m3 = re.match(r'^\s+(still moving at max_time|event cap)\s+(.+?)\s+(\d+)$', line)
            if m3:
                reasons[(m3.group(1), m3.group(2))] += int(m3.group(3))

c = lambda v: f"{v:,}"
endings = "| kind | ending | physical cloth | near-frictionless cloth |\n|---|---|---|---|\n"
for kind in kinds:
    for e in ENDINGS:
        if phys[(kind, e)] or other[(kind, e)]:
            label = LABELS.get(e, e)
            if kind == 'hostile' and e == 'at rest':
                label = 'at rest (a corruption that left a valid scene)'
            endings += f"| {kind} | {label} | {c(phys[(kind, e)])} | {c(other[(kind, e)])} |\n"

cov = "| kind | scenes | " + " | ".join(f"`{f}`" for f in features) + " |\n"
cov += "|---|---|" + "---|" * len(features) + "\n"
total = collections.Counter()
for kind in kinds:
    row = coverage[kind]
    total.update(row)
    cov += f"| {kind} | {c(row['scenes'])} | " + " | ".join(c(row[f]) for f in features) + " |\n"
cov += f"| all | {c(total['scenes'])} | " + " | ".join(c(total[f]) for f in features) + " |\n"

M, E = 'still moving at max_time', 'event cap'
why = lambda e, w: c(reasons[(e, w)])
done = n >= 1000000
commit = f", at commit {sys.argv[2]}" if len(sys.argv) > 2 else ""
head = (f"**The run of 10⁶ scenes** (seed {seed}{commit}, in parts of 50,000 with `--from`; "
        "`scripts/fuzz_report.py LOG_DIR COMMIT` writes this part of the page from the parts' "
        "logs): "
        + (f"**{fails} {'failure' if fails == 1 else 'failures'}** in {c(n)} scenes." if done
           else f"under way; the first {c(n)} scenes have **{fails} failures**.")
        + " Their endings:\n\n")
unfinished = sum(phys[(k, e)] for k in kinds for e in (M, E))
broken = sum(phys[(k, e)] + other[(k, e)] for k in kinds
             for e in ('stuck at an instant', 'impact failed', 'non-finite', 'panic'))
clean = ("No shot on a physical cloth needed the event cap or ran out of time. " if unfinished == 0
         else f"{c(unfinished)} shots on a physical cloth did not finish. ")
clean += ("No scene was stuck at an instant, no impact failed, nothing non-finite, no panic, every "
          "scene deterministic. " if broken == 0 and fails == 0 else "")
body = ("\n" + clean + "Why the cloth of each shot that did not finish was near-frictionless (the first reason "
        f"that applies): a sliding deceleration below 0.05 g0, {why(M, 'sliding deceleration < 0.05 g0')} "
        f"still moving and {why(E, 'sliding deceleration < 0.05 g0')} at the cap; a rolling deceleration "
        f"below 0.005 g0, {why(M, 'rolling deceleration < 0.005 g0')} and {why(E, 'rolling deceleration < 0.005 g0')}; "
        f"sidespin decay below 5 rad/s², {why(M, 'sidespin decay < 5 rad/s^2')} and {why(E, 'sidespin decay < 5 rad/s^2')}; "
        f"tilt and nap above half the rolling resistance, {why(M, 'tilt and nap > half the rolling resistance')} "
        f"and {why(E, 'tilt and nap > half the rolling resistance')}.\n\n"
        "Coverage: how many scenes of each kind reached each event kind, and each class of issue 21 "
        "(`cushion_in_air`: a cushion, jaw or facing met by a ball in the air; `pot_from_air`; "
        "`over_jaw`, `over_pocket_back`: a ball leaving the table there; `micro_collision`: an "
        "impact approaching at 2 mm/s or less; `steep_cue`: a strike at 60° or steeper; "
        "`offset_beyond_r_plus_r`: a strike with an offset coordinate beyond R + r, valid only "
        "with a steep cue; `strike_cloth_friction`, where the run has it: a strike the cloth's "
        "friction acted on, `mu_strike_cloth` set and the cue inclined; `strike_jump` and `bounce`, "
        "where the run has them: a strike that made the ball jump and a landing that bounced, "
        "`e_bed` set):\n\n")
page = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'docs', 'robustness.md')
s = open(page).read()
i = s.index('<!-- fuzz-report -->') + len('<!-- fuzz-report -->')
j = s.index('<!-- /fuzz-report -->')
s = s[:i] + '\n' + head + endings + body + cov + s[j:]
open(page, 'w').write(s)
print(n, fails, seed)
