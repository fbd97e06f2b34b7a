"""The project's player as a baseline agent in the Gymnasium environment of
``examples/frame_env.py``: a yardstick for a learned agent.

``PlayerAgent(env)`` turns ``snooker.choose`` (the player's decision: candidate pots of every
kind planned by the planner, sampled under the execution noise it expects, valued by points
and position; a safety when no pot is worth its risk; the cue ball in hand placed in the D)
into the environment's normalised action (``frame_env.physical`` inverted): speed, aim,
offsets, elevation, the nomination's index and the place in the D. It reads the frame from
the environment (``env.frame``): the observation drops what the player needs (spins are
zero between strokes, but the ids and the nomination's choices are the frame's). The
environment plays the action as given, without execution noise: ``noise`` is what the player
expects when it chooses (the standard noise by default, so it prefers strokes that forgive
an error), not noise added to the stroke.

Try it: ``python examples/player_agent.py`` plays visits on open tables with the player and
with random actions and prints the points of each.
"""

from __future__ import annotations

import math

import numpy as np

import snooker
from frame_env import ACTION_HIGH, ACTION_LOW, SnookerFrameEnv, nomination_choices


class PlayerAgent:
    """The player as an agent of ``SnookerFrameEnv``: ``agent(obs)`` is the action."""

    def __init__(self, env: SnookerFrameEnv, noise="standard", effort: int = 1000,
                 seed: int = 1):
        self.env, self.noise, self.effort, self.seed = env, noise, effort, seed
        self.strokes = 0
        #: The last decision (``snooker.Decision``), for a look at what was planned.
        self.decision = None

    def __call__(self, obs=None) -> np.ndarray:
        frame = self.env.frame
        self.strokes += 1
        d = snooker.choose(frame, noise=self.noise, seed=self.seed, stroke=self.strokes,
                           effort=self.effort)
        self.decision = d
        return action_of(frame, d)


def action_of(frame, d) -> np.ndarray:
    """The environment's normalised action for decision ``d`` on ``frame``."""
    s = d.strike
    aim = math.remainder(s.aim, 2.0 * math.pi)
    nomination = 0.0
    choices = nomination_choices(frame)
    if choices:
        nomination = choices.index(d.nominated) + 0.5
    u, v = 0.0, 0.5
    if d.cue_ball is not None:
        (cx, cy), radius = frame.the_d
        dx, dy = d.cue_ball[0] - cx, d.cue_ball[1] - cy
        u = min((math.hypot(dx, dy) / radius) ** 2, 1.0)
        angle = math.atan2(dy, dx)
        if angle < 0.0:
            angle += 2.0 * math.pi
        v = (angle - math.pi / 2.0) / math.pi
    physical = np.array([s.speed, aim, s.offset[0], s.offset[1], s.elevation, nomination, u, v])
    a = 2.0 * (physical - ACTION_LOW) / (ACTION_HIGH - ACTION_LOW) - 1.0
    return np.clip(a, -1.0, 1.0)


def visit_points(env: SnookerFrameEnv, agent, seed: int) -> float:
    """Points of one visit from ``env.reset(seed=seed)`` played by ``agent``."""
    obs, _ = env.reset(seed=seed)
    total, done = 0.0, False
    while not done:
        obs, reward, terminated, truncated, _ = env.step(agent(obs))
        total += reward
        done = terminated or truncated
    return total


if __name__ == "__main__":
    env = SnookerFrameEnv(reds=6, episode="visit")
    player = PlayerAgent(env, effort=1000)
    env.action_space.seed(1)
    for seed in range(1, 6):
        p = visit_points(env, player, seed)
        r = visit_points(env, lambda obs: env.action_space.sample(), seed)
        print(f"open table {seed}: the player {p:+.0f}, random actions {r:+.0f}")
