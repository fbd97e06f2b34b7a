"""The snooker engine from Python: event-driven shots with the thesis's frictional impacts.

Units are SI (m, s, rad, m/s, rad/s) in the table frame, z up; see the project's book (docs/physics.md).

    >>> import snooker
    >>> shot = snooker.simulate({"balls": [{"id": "cue", "pos": [1.0, 0.8]},
    ...                                    {"id": "red", "pos": [2.0, 0.9]}],
    ...                          "cue": {"ball": "cue", "speed": 2.0, "aim": 0.1}})
    >>> shot.positions([0.0, shot.duration]).shape
    (2, 2, 3)

Scenes are given as a path to a scene file, TOML text, or a dict with the scene file's keys.
Bad scenes raise ``ValueError`` with the command line's message; a valid scene that the engine
could not simulate raises ``SimulationError``.

Snooker by the rules: ``snooker.Frame`` is a frame between strokes (the balls at rest, the ball
on, the scores, whose turn), ``frame.play(strike)`` simulates a stroke and judges it:

    >>> frame = snooker.Frame.break_off()
    >>> verdict, after = frame.play({"speed": 7.0, "aim": 0.0465})
    >>> verdict.foul is None or verdict.foul in ("first_hit_not_on", "cue_ball_potted")
    True
"""

from __future__ import annotations

import math
import numbers
import os
from typing import Any, Dict, Iterable, List, Optional, Sequence, Union

import numpy as np

from . import _snooker
from ._snooker import CannotPot, SimulationError
from .records import (
    BallState,
    Considered,
    Decision,
    Event,
    ImpactReport,
    OffTable,
    Plan,
    PlannedShot,
    Pot,
    ShotResult,
    Stroke,
)

__all__ = [
    "Scene",
    "Shot",
    "ShotResult",
    "Event",
    "BallState",
    "Pot",
    "OffTable",
    "Plan",
    "PlannedShot",
    "ImpactReport",
    "Frame",
    "Verdict",
    "frame",
    "SimulationError",
    "CannotPot",
    "scene",
    "simulate",
    "simulate_many",
    "plan",
    "play",
    "choose",
    "Stroke",
    "Decision",
    "Considered",
    "impact_ball_ball",
    "impact_cushion",
    "MAX_THREADS",
]

#: Most threads ``simulate_many`` starts, as ``snooker batch``.
MAX_THREADS: int = _snooker.MAX_THREADS

Scene = _snooker.Scene
SceneLike = Union[str, "os.PathLike[str]", dict, "_snooker.Scene"]
#: A frame of snooker between strokes (see ``frame``); ``Frame.break_off()``,
#: ``Frame.open_table(reds, seed)``, ``Frame.load(path)``, ``Frame.from_dict(d)``.
Frame = _snooker.Frame
#: The referee's verdict on a stroke (``Frame.play``).
Verdict = _snooker.Verdict
FrameLike = Union[str, "os.PathLike[str]", dict, "_snooker.Frame"]


def _is_text(source: str) -> bool:
    """Whether a ``str`` source is TOML text rather than a path: it has a newline, or a ``=``
    (a key) and names no file (sweep folders such as ``speed=2/`` are paths)."""
    return "\n" in source or ("=" in source and not os.path.isfile(source))


def scene(source: SceneLike, name: str = "scene") -> "_snooker.Scene":
    """Reads and checks a scene.

    ``source`` is a path (``str`` or ``os.PathLike``) to a scene file, TOML text (a ``str``
    containing a newline, or a ``=`` and naming no file: ``"runs/speed=2/s.toml"`` is a
    path), a dict with the scene file's keys (NumPy arrays and
    numbers welcome as values), or a scene already read. ``name`` names TOML text and dicts
    in error messages. Raises ``ValueError`` naming the file, key and reason.
    """
    if isinstance(source, _snooker.Scene):
        return source
    if isinstance(source, dict):
        return _snooker.parse_dict(_plain(source), name)
    if isinstance(source, os.PathLike):
        return _snooker.load(os.fspath(source))
    if isinstance(source, str):
        if _is_text(source):
            return _snooker.parse_toml(source, name)
        return _snooker.load(source)
    raise ValueError(
        f"{name}: a scene is a path, TOML text or a dict, not {type(source).__name__}"
    )


def frame(source: FrameLike, name: str = "frame") -> "_snooker.Frame":
    """Reads and checks a frame of snooker (formats.md, "Frame": a scene plus a ``[frame]``
    table): a path to a frame file, TOML text (as ``scene`` tells them apart), a dict with the
    file's keys, or a frame already read. Its ``[cue]``, if any, is not part of the frame (pass
    the strike to ``play``). Raises ``ValueError`` naming the file, key and reason."""
    if isinstance(source, _snooker.Frame):
        return source
    if isinstance(source, dict):
        return _snooker.Frame.from_dict(_plain(source), name)
    if isinstance(source, os.PathLike):
        return _snooker.Frame.load(os.fspath(source))
    if isinstance(source, str):
        if _is_text(source):
            return _snooker.Frame.from_toml(source, name)
        return _snooker.Frame.load(source)
    raise ValueError(
        f"{name}: a frame is a path, TOML text or a dict, not {type(source).__name__}"
    )


def _plain(value: Any) -> Any:
    """``value`` with NumPy arrays and scalars as the lists and numbers they hold (what the
    scene crate reads), everything else as it is: a conversion, not a check (the scene crate
    checks every value and names the key at fault)."""
    if isinstance(value, dict):
        return {k: _plain(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    if isinstance(value, np.ndarray):
        return _plain(value.tolist())
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    if isinstance(value, numbers.Integral):
        return int(value)
    if isinstance(value, numbers.Real):
        return float(value)
    if isinstance(value, (set, frozenset)):
        # Unordered, so never a scene's array: handed on as an opaque object the scene crate
        # refuses at its key ("'set' object is not an instance of 'Sequence'").
        return _Unordered()
    return value


#: An opaque stand-in for a set (its name is what the scene crate's message shows).
_Unordered = type("set", (), {"__doc__": "A set in a dict scene: not a sequence."})


class Shot:
    """A simulated shot: its result document (``result``: events, final states, pots, as
    ``snooker simulate --json`` writes them, as objects) and the exact trajectory at any
    times."""

    def __init__(self, native: "_snooker.Shot"):
        self._native = native
        self._result: Optional[ShotResult] = None

    @property
    def result(self) -> ShotResult:
        """The whole result document (formats.md, "Result"): scene, events, final, duration,
        pots, off_table, models, params, strike, units; ``result.to_dict()`` is the JSON
        document."""
        if self._result is None:
            self._result = ShotResult.from_dict(self._native.result())
        return self._result

    @property
    def events(self) -> List[Event]:
        """The events in time order."""
        return self.result.events

    @property
    def final(self) -> Dict[str, BallState]:
        """Every ball's final state by id (without building the whole result document)."""
        return {
            b: BallState(tuple(p), tuple(v), tuple(w), m)
            for b, p, v, w, m in self._native.final_states()
        }

    @property
    def pots(self) -> List[Pot]:
        """The balls potted, in time order."""
        return [Pot(b, p, t) for b, p, t in self._native.pots()]

    @property
    def duration(self) -> float:
        """Simulated duration, s."""
        return self._native.duration

    @property
    def ball_ids(self) -> List[str]:
        """The balls' ids, in the order of the positions' second axis."""
        return self._native.ball_ids

    def positions(self, times: Iterable[float]) -> np.ndarray:
        """Every ball's position (m) at each time (s, within [0, duration]): an array of shape
        (len(times), number of balls, 3), sampled from the exact trajectory. ``times`` is one
        number (the array's first axis then has length 1) or a 1-D sequence or array of
        numbers; anything else (a 2-D array, a bool, a string) raises naming ``times``."""
        t = _times(times)
        raw = self._native.positions(t)
        return np.frombuffer(raw, dtype=np.float64).reshape(len(t), len(self.ball_ids), 3)

    def __repr__(self) -> str:
        return (
            f"<Shot {self._native.scene_name!r}: {self._native.event_count} events, "
            f"{self.duration:.3f} s, pots {[p.ball for p in self.pots]}>"
        )


def _times(times: Any) -> List[float]:
    """``times`` as a list of floats: one number or a 1-D sequence of numbers, refused naming
    the argument (``TypeError`` for the type, ``ValueError`` for the shape: a 2-D array is not
    flattened, which would give positions at times the caller did not ask for in that order).
    Whether each lies within the shot is the extension's check."""
    try:
        a = np.asarray(times)
        bad_type = a.dtype == np.bool_ or not (
            np.issubdtype(a.dtype, np.number) and not np.iscomplexobj(a)
        )
    except (TypeError, ValueError):
        bad_type = True
    if bad_type:
        raise TypeError(f"times: a number or a 1-D sequence of numbers, not {times!r}")
    if a.ndim > 1:
        raise ValueError(
            f"times: a number or a 1-D sequence of numbers, not an array of shape {a.shape}"
        )
    return [float(x) for x in a.astype(float).ravel()]


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

    ``scenes`` is a sequence of scenes (each as ``scene`` takes it); a single scene, a ``str``
    or a dict, raises ``TypeError``. ``threads`` is a whole number (a Python or NumPy int) from
    1 to ``MAX_THREADS`` (1024, as ``snooker batch``); no more threads than scenes are
    started. Every scene is read first (a bad one raises ``ValueError`` naming its index,
    ``scenes[i]``, before any is simulated); an unnamed scene's result is named as
    ``simulate`` names it. A scene the engine could not simulate raises its ``SimulationError`` with
    ``errors="raise"``; with ``errors="return"`` the error takes the shot's place in the list.
    """
    if errors not in ("raise", "return"):
        raise ValueError(f'errors: "raise" or "return", not {errors!r}')
    if isinstance(scenes, (str, bytes, dict, os.PathLike, _snooker.Scene)):
        raise TypeError(
            f"scenes: a sequence of scenes (a list), not one {type(scenes).__name__}: "
            "pass [scene] for one")
    if threads is not None:
        threads = _whole(threads, "threads", 1, MAX_THREADS)
    read = []
    for i, s in enumerate(scenes):
        try:
            read.append(scene(s))
        except (ValueError, TypeError) as e:
            raise type(e)(f"scenes[{i}]: {e}") from None
    if threads is not None:
        # More threads than scenes would only idle, and starting many thousands takes minutes.
        threads = min(threads, max(len(read), 1))
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
    kinds: Optional[Sequence[str]] = None,
) -> Plan:
    """Plans a shot as ``snooker plan`` does (thesis chapter 7): the strike that pots ``pot``
    in ``pocket`` and leaves the cue ball nearest ``cue_to`` (x, y in m), ranked by its pot
    probability under execution noise. Returns the plan (formats.md, "Plan"; ``to_dict()`` is
    the JSON document).

    ``noise``: the execution noise: ``"standard"`` (the default: the computational pool
    tournaments' noise, aim 0.125 deg, elevation 0.1 deg, speed 0.075 m/s, side and height
    0.5 mm), ``"standard*K"`` (every component times K), ``0`` or ``"0"`` (none), or a dict of
    standard deviations changing the standard noise, e.g.
    ``{"aim": 0.002, "speed": 0.04}`` (keys ``aim``, ``elevation`` rad, ``speed`` m/s,
    ``side``, ``height`` m; ``offset`` sets both side and height; before, ``speed`` was a
    fraction of the cue speed: the old ``speed=F`` at cue speed V is ``F*V``); ``bounds``:
    intervals, e.g. ``{"speed": (0.3, 6.0)}`` (keys ``speed`` m/s, ``elevation`` rad, ``side``
    and ``height`` m); ``kinds``: the kinds of pot tried, as ``--kinds`` (``direct``,
    ``double``, ``plant``, ``kiss``; all by default). Bad requests raise ``ValueError`` naming
    the argument (``noise['aim']``, ``cue_to``); a ball that cannot be potted raises
    ``CannotPot``.
    """

    if bounds is not None and not isinstance(bounds, dict):
        raise TypeError(f"bounds: a dict of (low, high) by variable, not {bounds!r}")
    if kinds is not None and (isinstance(kinds, (str, bytes)) or not all(
            isinstance(k, str) for k in kinds)):
        raise TypeError(f"kinds: a list of kind names (direct, double, plant, kiss), not {kinds!r}")
    doc = _snooker.plan(
        scene(source),
        pot,
        pocket,
        _pair(cue_to, "cue_to"),
        _number(tolerance, "tolerance"),
        _noise(noise),
        {str(k): tuple(_pair(v, f"bounds['{k}']")) for k, v in (bounds or {}).items()},
        _whole(samples, "samples", 1),
        _whole(alternatives, "alternatives", 0),
        _whole(seed, "seed", 0),
        cue_ball,
        None if kinds is None else list(kinds),
    )
    return Plan.from_dict(doc)


def play(
    source: FrameLike,
    noise: Union[None, str, float, dict] = None,
    seed: int = 1,
    effort: int = 4000,
    visit: bool = True,
    agent: str = "player",
    opponent: str = "player",
    max_strokes: int = 300,
) -> List[Stroke]:
    """Plays from a frame as ``snooker play`` does: the player chooses every stroke (candidate
    pots of every kind planned by the planner, sampled under the execution noise, valued by
    the points and the position left; a safety when no pot is worth its risk; the cue ball in
    hand placed in the D), the stroke is played with the noise added and judged by the rules,
    until the player at the table misses or fouls (``visit=True``: one break) or the frame
    ends (``visit=False``: ``agent`` for the side to play, ``opponent`` for the other; a frame
    still going after ``max_strokes`` stops there). Returns the strokes (the play log's lines,
    formats.md "Play log", as objects; ``to_dict()`` is the line).

    ``noise`` as for ``plan`` (``"standard"``, ``0`` or a dict of standard deviations); given
    ``seed`` and ``effort`` (the search's budget per stroke in simulated shots) the strokes are
    the same on any machine and any number of threads. Agents: ``"player"`` or ``"greedy"``
    (the likeliest pot, no position play, no safety)."""
    lines = _snooker.play(
        frame(source),
        _noise(noise),
        _whole(seed, "seed", 0),
        _whole(effort, "effort", 1),
        _flag(visit, "visit"),
        str(agent),
        str(opponent),
        _whole(max_strokes, "max_strokes", 1),
    )
    return [Stroke.from_dict(line) for line in lines]


def choose(
    source: FrameLike,
    noise: Union[None, str, float, dict] = None,
    seed: int = 1,
    stroke: int = 1,
    effort: int = 4000,
    agent: str = "player",
) -> Decision:
    """The stroke the player (or ``agent="greedy"``) chooses for a frame, expecting the
    execution ``noise``: where the cue ball in hand goes, the nomination, the strike meant
    (a dict of it is what ``Frame.play`` takes: ``decision.strike.to_dict()``) and what was
    planned. Its random draws come from (``seed``, ``stroke``): the same arguments, the same
    decision."""
    doc = _snooker.choose(
        frame(source),
        _noise(noise),
        _whole(seed, "seed", 0),
        _whole(stroke, "stroke", 0),
        _whole(effort, "effort", 1),
        str(agent),
    )
    return Decision.from_dict(doc)


def _noise(noise) -> dict:
    """The noise argument as the extension takes it: standard deviations by name, changing
    the standard noise. The strings are the command line's whole-noise spellings:
    ``"standard"``, ``"standard*K"`` (every component times K >= 0), ``"0"`` or ``"none"``."""
    if noise is None or (isinstance(noise, str) and noise.strip() == "standard"):
        return {}
    if isinstance(noise, str):
        spec = noise.strip()
        if spec in ("0", "none"):
            return {k: 0.0 for k in _snooker.STANDARD_NOISE}
        if spec.startswith("standard*"):
            try:
                k = float(spec[len("standard*"):])
            except ValueError:
                k = math.nan
            if not (math.isfinite(k) and k >= 0.0):
                raise ValueError(f"noise: expected standard*K with K >= 0, got {noise!r}")
            return {name: k * sd for name, sd in _snooker.STANDARD_NOISE.items()}
        raise ValueError(
            f"noise: expected 'standard', 'standard*K', 0 or a dict, got {noise!r}")
    if isinstance(noise, dict):
        return {str(k): _number(v, f"noise['{k}']") for k, v in noise.items()}
    if isinstance(noise, (bool, np.bool_)) or not isinstance(noise, numbers.Real):
        raise TypeError(f"noise: expected 'standard', 0 or a dict, got {noise!r}")
    if float(noise) == 0.0:
        return {k: 0.0 for k in ("aim", "elevation", "speed", "side", "height")}
    raise ValueError(f"noise: expected 'standard', 0 or a dict, got {noise!r}")


def _flag(value: Any, name: str) -> bool:
    """``value`` as a ``bool``: ``True`` or ``False`` (or NumPy's), refused naming the argument
    with ``TypeError`` (``bool("no")`` would be true)."""
    if not isinstance(value, (bool, np.bool_)):
        raise TypeError(f"{name}: True or False, not {value!r}")
    return bool(value)


def _number(value: Any, name: str) -> float:
    """``value`` as a ``float``: a Python or NumPy int or float (not a bool, not a string,
    which would be read silently as 1 or parsed), refused naming the argument with
    ``TypeError``. Whether it is finite and within range is the extension's check."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
        raise TypeError(f"{name}: a number, not {value!r}")
    return float(value)


def _pair(value: Any, name: str) -> List[float]:
    """``value`` as two floats: a list, tuple or 1-D array of exactly two numbers, refused
    naming the argument (``TypeError`` for the type, ``ValueError`` for the length)."""
    if isinstance(value, np.ndarray) and value.ndim == 1:
        value = value.tolist()
    if not isinstance(value, (list, tuple)):
        raise TypeError(f"{name}: two numbers (a list or tuple), not {value!r}")
    if len(value) != 2:
        raise ValueError(f"{name}: two numbers, got {len(value)}: {value!r}")
    return [_number(v, f"{name}[{i}]") for i, v in enumerate(value)]


#: The largest unsigned 64-bit number: the ceiling of seeds and counts.
_U64 = 2**64 - 1


def _whole(value: Any, name: str, low: int, high: int = _U64) -> int:
    """``value`` as an ``int`` in [``low``, ``high``]: a Python or NumPy int (not a bool, not a
    float, which would be truncated silently), refused naming the argument: ``TypeError`` for
    the type, ``ValueError`` for the range."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Integral):
        raise TypeError(f"{name}: a whole number, not {value!r}")
    if not low <= int(value) <= high:
        raise ValueError(f"{name}: must lie in [{low}, {high}], got {int(value)}")
    return int(value)


def _impact(native, speed, angle, topspin, sidespin, params: Optional[dict]) -> ImpactReport:
    """Calls a native impact report with parameter overrides by name; ``angle`` is the
    argument's (name, value), ``cut`` or ``angle``."""
    if params is not None and not isinstance(params, dict):
        raise TypeError(f"params: a dict of values by parameter name, not {params!r}")
    overrides = {str(k): _number(v, f"params['{k}']") for k, v in (params or {}).items()}
    doc = native(
        _number(speed, "speed"),
        _number(angle[1], angle[0]),
        _number(topspin, "topspin"),
        _number(sidespin, "sidespin"),
        overrides,
    )
    return ImpactReport.from_dict(doc)


def impact_ball_ball(
    speed: float,
    cut: float = 0.0,
    topspin: float = 0.0,
    sidespin: float = 0.0,
    params: Optional[dict] = None,
) -> ImpactReport:
    """One ball-ball impact of the thesis's frictional model, as ``snooker impact ball-ball
    --json``: a cue ball moving along +x at ``speed`` (m/s) with ``topspin`` and ``sidespin``
    (units of V/R; 1 = rolling) meets a resting object ball at ``cut`` degrees (0 = full
    ball). ``params`` overrides parameters by name (e.g. ``{"mu_ball": 0.06}``). Returns the
    report: each ball just after the impact and once its slip has ended, and the impulse."""
    return _impact(_snooker.impact_ball_ball, speed, ("cut", cut), topspin, sidespin, params)


def impact_cushion(
    speed: float,
    angle: float = 90.0,
    topspin: float = 0.0,
    sidespin: float = 0.0,
    params: Optional[dict] = None,
) -> ImpactReport:
    """One cushion impact of the thesis's model, as ``snooker impact cushion --json``: a ball
    at ``speed`` (m/s), ``angle`` degrees from the cushion line (90 = perpendicular), with
    ``topspin`` and ``sidespin`` (units of V/R). Returns the report (the ball after the impact
    and after its slip, its rebound angle, the impulse)."""
    return _impact(_snooker.impact_cushion, speed, ("angle", angle), topspin, sidespin, params)
