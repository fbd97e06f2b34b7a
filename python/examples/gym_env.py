"""A Gymnasium-style environment on the snooker engine: how an AI user plugs in.

Observation: every ball's (x, y) on the table (m; a pocketed ball at (-1, -1)), as a float32
array of shape (balls, 2). Action: the strike, [speed m/s, aim rad, side offset m, height
offset m, elevation rad]: finite real numbers (a bool or complex action is refused), clipped
to the bounds. Reward: +1 per object ball potted, -1 if the cue ball is potted (it is then
respotted on the brown spot, or the nearest free place behind it). An episode is
`max_shots` shots from a random position of `reds` reds (0 to 15); it ends early when every
red is down. A step before the first `reset` raises `ResetNeeded` (Gymnasium's;
`RuntimeError` without Gymnasium).

Runs with or without gymnasium installed (with it, the class is a `gymnasium.Env` with its
spaces). Try it: `python examples/gym_env.py` plays random strikes.
"""

from __future__ import annotations

import math
import numbers

import numpy as np

import snooker

try:  # Gymnasium is optional: the environment follows its API either way.
    import gymnasium as gym
    from gymnasium import spaces

    Base = gym.Env
    #: Raised by a step before the first reset, as Gymnasium's own wrappers raise it.
    ResetNeeded = gym.error.ResetNeeded
except ImportError:  # pragma: no cover
    gym = spaces = None
    Base = object
    ResetNeeded = RuntimeError

LENGTH, WIDTH, R = 3.569, 1.778, 0.02625
BROWN_SPOT = (0.737, 0.889)
#: Bounds of the action (speed, aim, side, height, elevation): the engine's strike limits
#: within a miscue-safe offset (0.8 of the 0.5 R limit) and a level-to-steep cue.
ACTION_LOW = np.array([0.1, -math.pi, -0.0105, -0.0105, 0.0])
ACTION_HIGH = np.array([8.0, math.pi, 0.0105, 0.0105, 1.2])


def real_action(action, size: int, what: str) -> np.ndarray:
    """``action`` as ``size`` finite real numbers (float64): anything else raises ``ValueError``
    saying ``what`` is expected. A single number would otherwise be broadcast to every
    component, a NaN has no place in the bounds, and bools or complex numbers are not the
    action space's numbers (NumPy would read True as 1 and drop an imaginary part)."""
    try:
        raw = np.asarray(action)
        a = raw.astype(np.float64) if raw.dtype.kind in "iuf" else None
    except (TypeError, ValueError):
        a = None
    if a is None or a.shape != (size,) or not np.all(np.isfinite(a)):
        raise ValueError(f"action: {what}, got {action!r}")
    return a


def checked(action) -> np.ndarray:
    """``action`` as an array of the action's shape, finite (it is then clipped to the bounds):
    anything else raises ``ValueError`` (``real_action``)."""
    return real_action(action, ACTION_LOW.size,
                       f"{ACTION_LOW.size} finite numbers (speed, aim, side, height, elevation)")


def free_place(balls: dict) -> tuple:
    """Where the potted cue ball goes back: the brown spot, or if a ball is there the nearest
    free point behind it on the table's long axis, then anywhere free (scanning the table):
    never onto another ball."""
    def free(p):
        return all(math.dist(p, q) > 2 * R + 1e-6 for q in balls.values())
    x0, y0 = BROWN_SPOT
    line = [(x0 - k * R, y0) for k in range(int((x0 - 2 * R) / R))]
    grid = [(x, y) for x in np.arange(2 * R, LENGTH - 2 * R, R)
            for y in np.arange(2 * R, WIDTH - 2 * R, R)]
    return next((float(x), float(y)) for x, y in line + grid if free((x, y)))


def whole(value, name: str, low: int, high: int) -> int:
    """``value`` as an ``int`` in [``low``, ``high``]: a Python or NumPy int (not a bool, not a
    float), refused naming the argument (``TypeError`` for the type, ``ValueError`` for the
    range)."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Integral):
        raise TypeError(f"{name}: a whole number, not {value!r}")
    if not low <= int(value) <= high:
        raise ValueError(f"{name}: must lie in [{low}, {high}], got {int(value)}")
    return int(value)


class SnookerEnv(Base):
    """Pot the reds with the cue ball, one strike per step."""

    metadata = {"render_modes": []}

    def __init__(self, reds: int = 3, max_shots: int = 10):
        # At most the 15 reds of snooker, as Frame.open_table racks; at least one shot.
        self.reds = whole(reds, "reds", 0, 15)
        self.max_shots = whole(max_shots, "max_shots", 1, 2**63 - 1)
        self.ids = ["cue"] + [f"red{i + 1}" for i in range(reds)]
        if spaces is not None:
            self.observation_space = spaces.Box(-1.0, LENGTH, (len(self.ids), 2), np.float32)
            self.action_space = spaces.Box(ACTION_LOW, ACTION_HIGH, dtype=np.float64)
        self.rng = np.random.default_rng()
        self.balls: dict = {}
        self.shots = 0

    def _obs(self) -> np.ndarray:
        return np.array([self.balls.get(i, (-1.0, -1.0)) for i in self.ids], np.float32)

    def reset(self, seed=None, options=None):
        if gym is not None:
            # Gymnasium's own seeding (env.np_random), as its env checker requires.
            super().reset(seed=seed)
            self.rng = self.np_random
        elif seed is not None:
            self.rng = np.random.default_rng(seed)
        self.balls, self.shots = {}, 0
        for ball in self.ids:
            while True:
                p = (self.rng.uniform(0.2, LENGTH - 0.2), self.rng.uniform(0.2, WIDTH - 0.2))
                if all(math.dist(p, q) > 3 * R for q in self.balls.values()):
                    self.balls[ball] = p
                    break
        return self._obs(), {}

    def step(self, action):
        if not self.balls:
            raise ResetNeeded("step: call reset() first (the table is empty until then)")
        speed, aim, side, height, elevation = np.clip(checked(action), ACTION_LOW, ACTION_HIGH)
        scene = {
            "balls": [{"id": b, "pos": list(p)} for b, p in self.balls.items()],
            "cue": {"ball": "cue", "speed": float(speed), "aim": float(aim),
                    "offset": [float(side), float(height)], "elevation": float(elevation)},
        }
        shot = snooker.simulate(scene)
        self.shots += 1
        final = shot.final
        potted = {p.ball for p in shot.pots}
        off = {b for b, s in final.items() if s.motion == "off_table"}
        reward = float(len(potted - {"cue"})) - float("cue" in potted)
        self.balls = {b: tuple(s.pos[:2]) for b, s in final.items()
                      if b not in potted and b not in off}
        if "cue" not in self.balls:
            self.balls["cue"] = free_place(self.balls)
        terminated = len(self.balls) == 1
        truncated = self.shots >= self.max_shots
        info = {"events": len(shot.events), "potted": sorted(potted)}
        return self._obs(), reward, terminated, truncated, info


if __name__ == "__main__":
    env = SnookerEnv()
    obs, _ = env.reset(seed=1)
    total, done = 0.0, False
    while not done:
        action = env.rng.uniform(ACTION_LOW, ACTION_HIGH)
        action[4] = 0.0
        obs, reward, terminated, truncated, info = env.step(action)
        total += reward
        done = terminated or truncated
        print(f"shot {env.shots}: reward {reward:+.0f}, potted {info['potted']}")
    print(f"episode reward {total:+.0f}")
