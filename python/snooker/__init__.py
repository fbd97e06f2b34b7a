"""The snooker engine from Python: event-driven shots with the thesis's frictional impacts.

Units are SI (m, s, rad, m/s, rad/s) in the table frame, z up; see the project's README.

    >>> import snooker
    >>> shot = snooker.simulate({"balls": [{"id": "cue", "pos": [1.0, 0.8]},
    ...                                    {"id": "red", "pos": [2.0, 0.9]}],
    ...                          "cue": {"ball": "cue", "speed": 2.0, "aim": 0.1}})
    >>> shot.positions([0.0, shot.duration]).shape
    (2, 2, 3)

Scenes are given as a path to a scene file, TOML text, or a dict with the scene file's keys.
Bad scenes raise ``ValueError`` with the command line's message; a valid scene that the engine
could not simulate raises ``SimulationError``.
"""

from __future__ import annotations

import json
import math
import numbers
import os
from typing import Any, Iterable, Optional, Sequence, Union

import numpy as np

from . import _snooker
from ._snooker import CannotPot, SimulationError

__all__ = [
    "Scene",
    "Shot",
    "SimulationError",
    "CannotPot",
    "scene",
    "simulate",
    "simulate_many",
    "plan",
    "impact_ball_ball",
    "impact_cushion",
]

Scene = _snooker.Scene
SceneLike = Union[str, "os.PathLike[str]", dict, "_snooker.Scene"]


def scene(source: SceneLike, name: str = "scene") -> "_snooker.Scene":
    """Reads and checks a scene.

    ``source`` is a path (``str`` or ``os.PathLike``) to a scene file, TOML text (a ``str``
    containing a newline or ``=``), a dict with the scene file's keys (NumPy arrays and
    numbers welcome as values), or a scene already read. ``name`` names TOML text and dicts
    in error messages. Raises ``ValueError`` naming the file, key and reason.
    """
    if isinstance(source, _snooker.Scene):
        return source
    if isinstance(source, dict):
        bad = _not_json(source, "")
        if bad is not None:
            raise ValueError(f"{name}: {bad}")
        return _snooker.parse_json(json.dumps(source, allow_nan=False, default=_plain), name)
    if isinstance(source, os.PathLike):
        return _snooker.load(os.fspath(source))
    if isinstance(source, str):
        if "\n" in source or "=" in source:
            return _snooker.parse_toml(source, name)
        return _snooker.load(source)
    raise ValueError(
        f"{name}: a scene is a path, TOML text or a dict, not {type(source).__name__}"
    )


def _not_json(value: object, key: str) -> Optional[str]:
    """Why ``value`` (at ``key``) cannot be a scene's JSON, in the scene parser's words, or None."""
    at = f"key `{key}`: " if key else ""
    if isinstance(value, dict):
        for k, v in value.items():
            if not isinstance(k, str):
                return f"{at}not a scene: keys are strings, not {type(k).__name__}"
            bad = _not_json(v, f"{key}.{k}" if key else k)
            if bad is not None:
                return bad
        return None
    if isinstance(value, (list, tuple, np.ndarray)):
        for i, v in enumerate(value):
            # An array's element is reported at the array's key, as the parser does.
            inner = f"{key}[{i}]" if isinstance(v, (dict, list, tuple, np.ndarray)) else key
            bad = _not_json(v, inner)
            if bad is not None:
                return bad
        return None
    if isinstance(value, numbers.Real) and not math.isfinite(value):
        shown = "NaN" if math.isnan(value) else ("inf" if value > 0 else "-inf")
        return f"{at}must be a finite number, got {shown}"
    if value is None or isinstance(value, (str, bool, numbers.Real)):
        return None
    return f"{at}not a scene: {type(value).__name__} is not a number, string, list or table"


def _plain(value: object) -> object:
    """NumPy arrays and scalars as the JSON numbers and lists they hold (``json.dumps``)."""
    if isinstance(value, np.ndarray):
        return value.tolist()
    if isinstance(value, numbers.Integral):
        return int(value)
    if isinstance(value, numbers.Real):
        return float(value)
    raise TypeError(f"{type(value).__name__} is not a number, string, list or table")


class Shot:
    """A simulated shot: its events, final states and pots as in ``snooker simulate --json``,
    and the exact trajectory at any times."""

    def __init__(self, native: "_snooker.Shot"):
        self._native = native
        self._doc: Optional[dict] = None

    @property
    def result(self) -> dict:
        """The whole result document (formats.md, "Result"): scene, events, final, duration,
        pots, off_table, models, params, strike, units."""
        if self._doc is None:
            self._doc = json.loads(self._native.result_json())
        return self._doc

    @property
    def events(self) -> list:
        """The events in time order, each a dict (t, kind, balls, after, ...)."""
        return self.result["events"]

    @property
    def final(self) -> dict:
        """Every ball's final state by id: pos, vel, spin (lists), motion (as in the result
        document, without reading it whole)."""
        return {
            b: {"pos": list(p), "vel": list(v), "spin": list(w), "motion": m}
            for b, p, v, w, m in self._native.final_states()
        }

    @property
    def pots(self) -> list:
        """The balls potted, in time order: dicts with ball, pocket and t (s)."""
        return [{"ball": b, "pocket": p, "t": t} for b, p, t in self._native.pots()]

    @property
    def duration(self) -> float:
        """Simulated duration, s."""
        return self._native.duration

    @property
    def ball_ids(self) -> list:
        """The balls' ids, in the order of the positions' second axis."""
        return self._native.ball_ids

    def positions(self, times: Iterable[float]) -> np.ndarray:
        """Every ball's position (m) at each time (s, within [0, duration]): an array of shape
        (len(times), number of balls, 3), sampled from the exact trajectory."""
        t = [float(x) for x in np.asarray(times, dtype=float).ravel()]
        raw = self._native.positions(t)
        return np.frombuffer(raw, dtype=np.float64).reshape(len(t), len(self.ball_ids), 3)

    def __repr__(self) -> str:
        return (
            f"<Shot {self.result['scene']!r}: {len(self.events)} events, "
            f"{self.duration:.3f} s, pots {[p['ball'] for p in self.pots]}>"
        )


def simulate(source: SceneLike) -> Shot:
    """Simulates a scene (path, TOML text, dict or ``Scene``) to its end, the GIL released."""
    return Shot(_snooker.simulate(scene(source)))


def simulate_many(
    scenes: Sequence[SceneLike],
    threads: Optional[int] = None,
    errors: str = "raise",
) -> list:
    """Simulates many scenes on ``threads`` threads (all cores by default), the GIL released,
    the results in input order and bit-identical to one-by-one runs whatever the thread count.

    Every scene is read first (a bad one raises ``ValueError`` naming its index before any is
    simulated). A scene the engine could not simulate raises its ``SimulationError`` with
    ``errors="raise"``; with ``errors="return"`` the error takes the shot's place in the list.
    """
    if errors not in ("raise", "return"):
        raise ValueError(f'errors: "raise" or "return", not {errors!r}')
    if threads is not None and (not isinstance(threads, int) or threads < 1):
        raise ValueError(f"threads: a positive number of threads, not {threads!r}")
    read = []
    for i, s in enumerate(scenes):
        read.append(scene(s, name=f"scenes[{i}]"))
    out = []
    for r in _snooker.simulate_many(read, threads):
        if isinstance(r, SimulationError):
            if errors == "raise":
                raise r
            out.append(r)
        else:
            out.append(Shot(r))
    return out


def plan(
    source: SceneLike,
    pot: str,
    pocket: str,
    cue_to: Sequence[float],
    tolerance: float = 0.001,
    noise: Union[None, str, float, dict] = None,
    bounds: Optional[dict] = None,
    samples: int = 256,
    alternatives: int = 3,
    seed: int = 1,
    cue_ball: str = "cue",
) -> dict:
    """Plans a shot as ``snooker plan`` does (thesis chapter 7): the strike that pots ``pot``
    in ``pocket`` and leaves the cue ball nearest ``cue_to`` (x, y in m), ranked by its pot
    probability under execution noise. Returns the plan document (formats.md, "Plan").

    ``noise``: the execution noise: ``"standard"`` (the default: the computational pool
    tournaments' noise, aim 0.125 deg, elevation 0.1 deg, speed 0.075 m/s, side and height
    0.5 mm), ``0`` (none), or a dict of standard deviations changing the standard noise, e.g.
    ``{"aim": 0.002, "speed": 0.04}`` (keys ``aim``, ``elevation`` rad, ``speed`` m/s,
    ``side``, ``height`` m; ``offset`` sets both side and height; before, ``speed`` was a
    fraction of the cue speed: the old ``speed=F`` at cue speed V is ``F*V``); ``bounds``: intervals, e.g. ``{"speed": (0.3, 6.0)}``
    (keys ``speed`` m/s, ``elevation`` rad, ``side`` and ``height`` m). Bad requests raise
    ``ValueError`` naming the argument (``noise['aim']``, ``cue_to``); a ball that cannot be
    potted raises ``CannotPot``.
    """

    x, y = (float(c) for c in cue_to)
    text = _snooker.plan(
        scene(source),
        pot,
        pocket,
        [x, y],
        float(tolerance),
        _noise(noise),
        {k: (float(lo), float(hi)) for k, (lo, hi) in (bounds or {}).items()},
        int(samples),
        int(alternatives),
        int(seed),
        cue_ball,
    )
    return json.loads(text)


def _noise(noise) -> dict:
    """The noise argument as the extension takes it: standard deviations by name, changing
    the standard noise."""
    if noise is None or (isinstance(noise, str) and noise == "standard"):
        return {}
    if isinstance(noise, str):
        raise ValueError(f"noise: expected 'standard', 0 or a dict, got {noise!r}")
    if isinstance(noise, dict):
        return {str(k): float(v) for k, v in noise.items()}
    if float(noise) == 0.0:
        return {k: 0.0 for k in ("aim", "elevation", "speed", "side", "height")}
    raise ValueError(f"noise: expected 'standard', 0 or a dict, got {noise!r}")


def _impact(native, speed, angle, topspin, sidespin, params: Optional[dict]) -> dict:
    """Calls a native impact report with parameter overrides by name."""
    overrides = {str(k): float(v) for k, v in (params or {}).items()}
    text = native(float(speed), float(angle), float(topspin), float(sidespin), overrides)
    return json.loads(text)


def impact_ball_ball(
    speed: float,
    cut: float = 0.0,
    topspin: float = 0.0,
    sidespin: float = 0.0,
    params: Optional[dict] = None,
) -> dict:
    """One ball-ball impact of the thesis's frictional model, as ``snooker impact ball-ball
    --json``: a cue ball moving along +x at ``speed`` (m/s) with ``topspin`` and ``sidespin``
    (units of V/R; 1 = rolling) meets a resting object ball at ``cut`` degrees (0 = full
    ball). ``params`` overrides parameters by name (e.g. ``{"mu_ball": 0.06}``). Returns the
    report: each ball just after the impact and once its slip has ended, and the impulse."""
    return _impact(_snooker.impact_ball_ball, speed, cut, topspin, sidespin, params)


def impact_cushion(
    speed: float,
    angle: float = 90.0,
    topspin: float = 0.0,
    sidespin: float = 0.0,
    params: Optional[dict] = None,
) -> dict:
    """One cushion impact of the thesis's model, as ``snooker impact cushion --json``: a ball
    at ``speed`` (m/s), ``angle`` degrees from the cushion line (90 = perpendicular), with
    ``topspin`` and ``sidespin`` (units of V/R). Returns the report (the ball after the impact
    and after its slip, its rebound angle, the impulse)."""
    return _impact(_snooker.impact_cushion, speed, angle, topspin, sidespin, params)
