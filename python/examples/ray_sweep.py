"""Pot probability over a grid of cue-ball positions under execution noise, on Ray.

A red lies near the top-left pocket (the corner at x = 3.569 m, y = 1.778 m); for every
cue-ball position of a grid, the cue ball is struck at the ghost-ball aim that pots it,
`samples` times with Gaussian errors in aim, speed and tip offset. Each Ray task draws and
simulates the shots of a few positions with `snooker.simulate_many`; the rows (position,
sample, potted, where the cue ball stopped) are gathered into one Parquet file, and the pot
probability per position is printed.

    python examples/ray_sweep.py                      # this machine (ray.init())
    python examples/ray_sweep.py --address auto       # the cluster this node belongs to
    python examples/ray_sweep.py --address ray://head:10001 --nx 40 --ny 20 --samples 256

The same code runs on one machine or a cluster: only `ray.init`'s address changes. The shots
are independent, so the sweep scales with the cores while each task's work outweighs Ray's
per-task cost (about 5 ms here): tasks of 512 shots or more keep it under 5 % (docs/python.md
has the measured shots/s).
"""

from __future__ import annotations

import argparse
import math
import time

import numpy as np

import snooker

# The 12 ft table's playing area (m) and the ball radius: the scene files' defaults.
LENGTH, WIDTH, R = 3.569, 1.778, 0.02625
RED = (3.30, 1.55)
POCKET = "top-left"
POCKET_AT = (LENGTH, WIDTH)


def grid(nx: int, ny: int) -> list:
    """Cue-ball positions: an nx by ny grid over the half of the table nearer the red."""
    xs = np.linspace(1.9, 3.2, nx)
    ys = np.linspace(0.15, 1.45, ny)
    return [(float(x), float(y)) for y in ys for x in xs]


def scenes(positions: list, samples: int, seed: int, first: int = 0,
           noise=(0.002, 0.02, 0.001)) -> list:
    """The shots of the sweep from `positions` (the first being the grid's position number
    `first`), as scene dicts: per position, `samples` strikes at the ghost-ball aim with errors
    of standard deviations noise = (aim rad, speed fraction, offset m). Each position has its
    own generator, seeded by (seed, its number), so that a task can draw its own shots and
    every run draws the same."""
    out = []
    # The ghost ball: where the cue ball's centre must be to send the red to the pocket.
    d = np.subtract(POCKET_AT, RED)
    ghost = np.subtract(RED, 2 * R * d / np.linalg.norm(d))
    for i, (x, y) in enumerate(positions, start=first):
        rng = np.random.default_rng([seed, i])
        aim = math.atan2(ghost[1] - y, ghost[0] - x)
        for k in range(samples):
            e_aim, e_speed = rng.normal(0.0, noise[:2])
            e_side, e_height = rng.normal(0.0, noise[2], 2)
            out.append({
                "name": f"p{i}-s{k}",
                "balls": [{"id": "cue", "pos": [x, y]}, {"id": "red", "pos": list(RED)}],
                "cue": {
                    "ball": "cue",
                    "speed": 2.0 * (1.0 + e_speed),
                    "aim": aim + e_aim,
                    "offset": [e_side, e_height],
                },
            })
    return out


def rows(shots: list) -> list:
    """One row per shot: potted (the red in the pocket, the cue ball not potted) and where the
    cue ball stopped."""
    out = []
    for shot in shots:
        if isinstance(shot, Exception):
            out.append({"potted": False, "cue_x": math.nan, "cue_y": math.nan,
                        "error": str(shot)})
            continue
        pots = {p.ball: p.pocket for p in shot.pots}
        cue = shot.final["cue"].pos
        out.append({"potted": pots.get("red") == POCKET and "cue" not in pots,
                    "cue_x": cue[0], "cue_y": cue[1], "error": None})
    return out


def run_chunk(positions: list, samples: int, seed: int, first: int) -> list:
    """One task's work: it draws its own shots (only their recipe travels) and simulates them
    on one thread (Ray gives each task a core)."""
    chunk = scenes(positions, samples, seed, first)
    return rows(snooker.simulate_many(chunk, threads=1, errors="return"))


def connect(address=None, num_cpus=None) -> None:
    """Starts a local Ray instance (address None) or joins a cluster ("auto", "ray://...")."""
    import sys

    import ray
    from ray import cloudpickle

    # The workers need `snooker` installed, not this file: its functions travel by value.
    if __name__ != "__main__":
        cloudpickle.register_pickle_by_value(sys.modules[__name__])
    ray.init(address=address, num_cpus=num_cpus, ignore_reinit_error=True,
             include_dashboard=False, log_to_driver=False)


def sweep(positions: list, samples: int, seed: int, per_task: int) -> list:
    """Runs the sweep as Ray tasks of `per_task` positions each (Ray connected): the rows in
    the order of `scenes(positions, samples, seed)`."""
    import ray

    task = ray.remote(num_cpus=1)(run_chunk)
    futures = [
        task.remote(positions[i:i + per_task], samples, seed, i)
        for i in range(0, len(positions), per_task)
    ]
    return [row for part in ray.get(futures) for row in part]


def table(positions: list, samples: int, results: list):
    """The rows with their positions, as a pyarrow table."""
    import pyarrow as pa

    cols = {"position": [], "x": [], "y": [], "sample": []}
    for i, (x, y) in enumerate(positions):
        for k in range(samples):
            cols["position"].append(i)
            cols["x"].append(x)
            cols["y"].append(y)
            cols["sample"].append(k)
    for key in ("potted", "cue_x", "cue_y", "error"):
        cols[key] = [r[key] for r in results]
    return pa.table(cols)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--address", default=None, help="Ray cluster address (default: local)")
    ap.add_argument("--nx", type=int, default=12)
    ap.add_argument("--ny", type=int, default=8)
    ap.add_argument("--samples", type=int, default=64)
    ap.add_argument("--per-task", type=int, default=16,
                    help="grid positions per Ray task (times --samples shots)")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--out", default="sweep.parquet")
    args = ap.parse_args()
    import pyarrow.parquet as pq

    positions = grid(args.nx, args.ny)
    connect(args.address)
    sweep(positions[: 2 * args.per_task], args.samples, args.seed, args.per_task)  # warm
    start = time.perf_counter()
    results = sweep(positions, args.samples, args.seed, args.per_task)
    wall = time.perf_counter() - start
    shots = len(results)
    t = table(positions, args.samples, results)
    pq.write_table(t, args.out)
    potted = np.array(t.column("potted").to_pylist()).reshape(len(positions), args.samples)
    print(f"{shots} shots in {wall:.2f} s ({shots / wall:.0f} shots/s), "
          f"{args.per_task * args.samples} per task; written to {args.out}")
    best = int(np.argmax(potted.mean(axis=1)))
    print(f"pot probability: mean {potted.mean():.2f}, best {potted[best].mean():.2f} "
          f"from {positions[best]}")


if __name__ == "__main__":
    main()
