"""A Gymnasium environment that plays real frames of snooker: one step is one stroke, judged
by the rules (WPBSA, as the `snooker referee` command judges them).

Observation (a dict): ``balls``, every ball's (x, y) in m in a fixed order (the cue ball, red1
to red15, yellow to black), (-1, -1) for a ball not on the table (potted, or the cue ball in
hand); ``on``, the ball on (0 red, 1 any colour, 2-7 yellow to black); ``ball_in_hand`` and
``free_ball`` (0 or 1). When the frame ends, the last observation shows the balls where its
last stroke left them; a step after it raises ``ResetNeeded``.

Action: eight numbers in [-1, 1] (the normalised space Gymnasium recommends), mapped
linearly onto [speed 0.2-8 m/s, aim -pi-pi rad, side offset, height offset (within 0.8 of the
miscue limit, 0.5 R), elevation 0-0.5 rad, nomination 0-6, u 0-1, v 0-1] (``physical``).
``nomination`` picks among the colours the player may nominate (when one must be nominated;
with a free ball the first choice, 0, declines it and plays the ball on: ``nomination_choices``);
(u, v) place the cue ball in hand in the D (radius sqrt(u) of the D's, at angle v of the half
circle), moved to the nearest valid place if it touches a ball.

Reward: the points the player at the table scored, less the points of a foul. Episode: a whole
frame (``episode="frame"``: one agent plays both players) or one visit (``episode="visit"``:
it ends when the turn passes); truncated after ``max_strokes`` strokes. ``reds`` (0 to 15) and
``max_strokes`` (at least 1) are checked by the constructor (``reds`` is for
``start="open"``: the break-off racks 15); a step before the first ``reset``
raises Gymnasium's ``ResetNeeded``.

Try it: ``python python/examples/frame_env.py`` (from the repository's root) plays a frame of random strokes.
"""

from __future__ import annotations

import math

import gymnasium as gym
import numpy as np
from gymnasium import spaces

import snooker
# The scene environment's checks of a whole-number argument and of an action's numbers.
from gym_env import real_action, whole

IDS = ["cue"] + [f"red{i}" for i in range(1, 16)] + [
    "yellow", "green", "brown", "blue", "pink", "black"]
ON = ["red", "colour", "yellow", "green", "brown", "blue", "pink", "black"]
#: Offsets stay within 0.8 of the miscue limit (0.5 R, thesis eq. 7.7).
OFFSET_MAX = 0.8 * 0.5 * 0.0262
ACTION_LOW = np.array([0.2, -math.pi, -OFFSET_MAX, -OFFSET_MAX, 0.0, 0.0, 0.0, 0.0])
ACTION_HIGH = np.array([8.0, math.pi, OFFSET_MAX, OFFSET_MAX, 0.5, 6.0, 1.0, 1.0])


def nomination_choices(frame) -> list:
    """What the action's ``nomination`` picks from on ``frame``: nothing when no nomination is
    needed; the colours that may be nominated with a colour on; with a free ball, None (the
    free ball declined, WPBSA Section 3 Rule 12(b)) and then those colours."""
    noms = frame.legal_nominations
    if not noms or frame.nominated is not None:
        return []
    if frame.free_ball:
        return [None] + noms
    return noms if frame.on == "colour" else []


class SnookerFrameEnv(gym.Env):
    """Frames of snooker, one stroke per step, under the real rules."""

    metadata = {"render_modes": []}

    def __init__(self, reds: int = 15, start: str = "open", episode: str = "frame",
                 max_strokes: int = 200):
        if start not in ("open", "break_off"):
            raise ValueError(f'start: "open" or "break_off", not {start!r}')
        if episode not in ("frame", "visit"):
            raise ValueError(f'episode: "frame" or "visit", not {episode!r}')
        # Checked here, not at the first reset: Frame.open_table racks 0 to 15 reds.
        self.reds = whole(reds, "reds", 0, 15)
        if start == "break_off" and self.reds != 15:
            raise ValueError(f"reds: the break-off racks 15 reds (reds is for start=\"open\"), "
                             f"got {self.reds}")
        self.max_strokes = whole(max_strokes, "max_strokes", 1, 2**63 - 1)
        self.start, self.episode = start, episode
        self.observation_space = spaces.Dict({
            "balls": spaces.Box(-1.0, 4.0, (len(IDS), 2), np.float32),
            "on": spaces.Discrete(len(ON)),
            "ball_in_hand": spaces.Discrete(2),
            "free_ball": spaces.Discrete(2),
        })
        self.action_space = spaces.Box(-1.0, 1.0, (len(ACTION_LOW),), dtype=np.float64)
        self.frame: snooker.Frame = snooker.Frame.break_off()
        #: The last observation once the frame is over (the balls as its last stroke left
        #: them); None while it goes on.
        self.final: dict | None = None
        self.strokes = 0
        #: Whether reset has been called: a step before it raises Gymnasium's ResetNeeded.
        self.started = False

    def _obs(self) -> dict:
        if self.final is not None:
            return self.final
        f = self.frame
        return self._observe(f, f.balls, f.ball_in_hand, f.free_ball)

    @staticmethod
    def _observe(f, balls: dict, ball_in_hand: bool, free_ball: bool) -> dict:
        """The observation of frame ``f``'s balls at ``balls`` (x, y by id; a ball missing is
        off the table); the cue ball in hand is off the table wherever the frame keeps it."""
        # The frame's own ids may differ from IDS (a file's): map by kind, reds in order.
        slots = {}
        reds = iter(range(1, 16))
        for ball_id, kind in f.kinds.items():
            slot = f"red{next(reds)}" if kind == "red" else kind
            if ball_id in balls and not (kind == "cue" and ball_in_hand):
                slots[slot] = balls[ball_id][:2]
        pos = np.array([slots.get(i, (-1.0, -1.0)) for i in IDS], np.float32)
        return {
            "balls": pos,
            "on": ON.index(f.on),
            "ball_in_hand": int(ball_in_hand),
            "free_ball": int(free_ball),
        }

    def reset(self, seed=None, options=None):
        super().reset(seed=seed)
        if self.start == "break_off":
            self.frame = snooker.Frame.break_off()
        else:
            self.frame = snooker.Frame.open_table(self.reds, int(self.np_random.integers(2**63)))
        self.strokes = 0
        self.final = None
        self.started = True
        return self._obs(), {}

    def _choices(self, action) -> tuple:
        """The nomination and the cue ball's place the action asks for, as the frame allows."""
        f = self.frame
        nominated = None
        choices = nomination_choices(f)
        if choices:
            nominated = choices[min(int(action[5]), len(choices) - 1)]
        cue_ball = None
        if f.ball_in_hand:
            (cx, cy), radius = f.the_d
            r = radius * math.sqrt(action[6])
            angle = math.pi / 2 + math.pi * action[7]
            cue_ball = f.nearest_placement((cx + r * math.cos(angle), cy + r * math.sin(angle)))
        return nominated, cue_ball

    @staticmethod
    def physical(action) -> np.ndarray:
        """The action in its physical units (see the module's docs): eight finite real
        numbers, clipped to [-1, 1]; any other shape, a NaN, an infinity, a bool or a complex
        number raises ``ValueError`` (``real_action``)."""
        a = real_action(action, ACTION_LOW.size, f"{ACTION_LOW.size} finite numbers in [-1, 1]")
        a = np.clip(a, -1.0, 1.0)
        return ACTION_LOW + (a + 1.0) / 2.0 * (ACTION_HIGH - ACTION_LOW)

    def step(self, action):
        if not self.started:
            raise gym.error.ResetNeeded("step: call reset() first")
        if self.final is not None:
            raise gym.error.ResetNeeded("step: the frame is over; call reset()")
        a = self.physical(action)
        speed, aim, side, height, elevation = (float(x) for x in a[:5])
        nominated, cue_ball = self._choices(a)
        strike = {"speed": speed, "aim": aim, "offset": [side, height], "elevation": elevation}
        frame = self.frame
        if frame.free_ball and nominated is None:
            frame = frame.with_nomination(None)  # the free ball declined
        try:
            verdict, after = frame.play(strike, nominated=nominated, cue_ball=cue_ball)
        except ValueError:
            # A strike the cue cannot play (the tip would go through the cloth): level and
            # central instead.
            strike.update(offset=[0.0, 0.0], elevation=0.0)
            verdict, after = frame.play(strike, nominated=nominated, cue_ball=cue_ball)
        player = self.frame.to_play
        self.strokes += 1
        reward = float(verdict.points) - float(verdict.foul_points)
        terminated = verdict.frame_over
        if after is not None:
            self.frame = after
            if self.episode == "visit" and after.to_play != player:
                terminated = True
        else:
            # The frame is over: the last observation shows where its last stroke left the
            # balls (the frame itself has no next position to show).
            left = {b: s.pos for b, s in verdict.shot.final.items()
                    if s.motion not in ("pocketed", "off_table")}
            self.final = self._observe(frame, left, False, False)
        truncated = not terminated and self.strokes >= self.max_strokes
        info = {
            "player": player,
            "foul": verdict.foul,
            "potted": verdict.potted,
            "points": verdict.points,
            "scores": verdict.scores,
            "winner": verdict.winner,
        }
        return self._obs(), reward, terminated, truncated, info


if __name__ == "__main__":
    env = SnookerFrameEnv(reds=6)
    obs, _ = env.reset(seed=1)
    done = False
    while not done:
        obs, reward, terminated, truncated, info = env.step(env.action_space.sample())
        done = terminated or truncated
        print(f"stroke {env.strokes}: player {info['player']} {info['foul'] or 'legal'}, "
              f"potted {info['potted']}, reward {reward:+.0f}, scores {info['scores']}")
    print("winner:", info["winner"])
