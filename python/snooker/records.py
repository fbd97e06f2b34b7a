"""The documents the engine returns, as objects with attributes: a shot's result (formats.md,
"Result"), a plan ("Plan") and an impact report (``snooker impact --json``).

The extension module hands these over as the Rust crates' typed values converted to Python
(no JSON text in between); each class here is built from that conversion with ``from_dict``
and gives the document back, key for key as the command line writes it, with ``to_dict``.
Units are SI (m, s, rad, m/s, rad/s) in the table frame, z up.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from typing import Any, Dict, List, Optional, Tuple

__all__ = [
    "BallState",
    "Event",
    "Pot",
    "OffTable",
    "StrikeReport",
    "ShotResult",
    "Strike",
    "Route",
    "Robustness",
    "PlannedShot",
    "Plan",
    "MotionSummary",
    "BallAfter",
    "ImpactInput",
    "ImpactReport",
    "Considered",
    "Stroke",
    "Decision",
]

Vec3 = Tuple[float, float, float]


def _document(value: Any) -> Any:
    """A record as its document: dataclasses as dicts in field order, an optional field left
    out where it is None (the documents omit those keys), tuples as lists."""
    if dataclasses.is_dataclass(value):
        out = {}
        for f in dataclasses.fields(value):
            v = getattr(value, f.name)
            if v is None and f.metadata.get("optional"):
                continue
            out[f.metadata.get("key", f.name)] = _document(v)
        return out
    if isinstance(value, dict):
        return {k: _document(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_document(v) for v in value]
    return value


def _optional(**kw: Any) -> Any:
    """A field the document leaves out when it has no value."""
    return dataclasses.field(default=None, metadata={"optional": True, **kw})


class _Record:
    """What every record shares: the document back, key for key."""

    def to_dict(self) -> dict:
        """The document as the command line writes it (JSON-ready: dicts, lists, numbers)."""
        return _document(self)


@dataclass(frozen=True)
class BallState(_Record):
    """A ball's state: centre ``pos`` (m), velocity ``vel`` (m/s), angular velocity ``spin``
    (rad/s) and ``motion`` (``sliding``, ``rolling``, ``spinning``, ``stationary``,
    ``airborne``, ``pocketed``, ``off_table``)."""

    pos: Vec3
    vel: Vec3
    spin: Vec3
    motion: str

    @classmethod
    def from_dict(cls, d: dict) -> "BallState":
        """The record of its JSON document (the inverse of ``to_dict``)."""
        return cls(tuple(d["pos"]), tuple(d["vel"]), tuple(d["spin"]), d["motion"])


def _states(d: dict) -> Dict[str, BallState]:
    return {k: BallState.from_dict(v) for k, v in d.items()}


@dataclass(frozen=True)
class Event(_Record):
    """One event: time ``t`` (s), ``kind`` (``ball_ball``, ``ball_cushion``, ``ball_pocket``,
    ``ball_off_table``, ``slide_to_roll``, ...), the ``balls`` involved by id and their states
    just ``after``; ``pocket`` (a pot), ``cushion`` (the nose, jaw or facing met or flown
    over), ``normal_speed`` (m/s, impacts) and ``beyond_rigid_limit`` (cushion impacts) where
    they apply, else None."""

    t: float
    kind: str
    balls: Tuple[str, ...]
    after: Dict[str, BallState]
    pocket: Optional[str] = _optional()
    cushion: Optional[str] = _optional()
    normal_speed: Optional[float] = _optional()
    beyond_rigid_limit: Optional[bool] = _optional()

    @classmethod
    def from_dict(cls, d: dict) -> "Event":
        """The record of its JSON document (the inverse of ``to_dict``)."""
        return cls(
            d["t"],
            d["kind"],
            tuple(d["balls"]),
            _states(d["after"]),
            d.get("pocket"),
            d.get("cushion"),
            d.get("normal_speed"),
            d.get("beyond_rigid_limit"),
        )


@dataclass(frozen=True)
class Pot(_Record):
    """A pot: the ``ball``, the ``pocket`` and the time ``t`` (s)."""

    ball: str
    pocket: str
    t: float


@dataclass(frozen=True)
class OffTable(_Record):
    """A ball forced off the table: the ``ball``, the ``cushion`` it flew over, the time ``t``."""

    ball: str
    cushion: str
    t: float


@dataclass(frozen=True)
class StrikeReport(_Record):
    """The cue strike: the ``ball`` struck, ``cue_speed`` (m/s), the ``contact`` point relative
    to the centre (m), its ``contact_offset`` from the cue's axis (m), the ``squirt`` angle
    (rad, + left of the heading), the ``speed_ratio`` (ball / cue), the ball's state
    ``after``, and the cloth's friction impulse during the strike, ``cloth_friction`` (N s;
    None unless the ``mu_strike_cloth`` parameter gave one)."""

    ball: str
    cue_speed: float
    contact: Vec3
    contact_offset: float
    squirt: float
    speed_ratio: float
    after: BallState
    cloth_friction: Optional[Vec3] = _optional()

    @classmethod
    def from_dict(cls, d: dict) -> "StrikeReport":
        """The record of its JSON document (the inverse of ``to_dict``)."""
        return cls(
            d["ball"],
            d["cue_speed"],
            tuple(d["contact"]),
            d["contact_offset"],
            d["squirt"],
            d["speed_ratio"],
            BallState.from_dict(d["after"]),
            tuple(d["cloth_friction"]) if "cloth_friction" in d else None,
        )


@dataclass(frozen=True)
class ShotResult(_Record):
    """The result of a shot (formats.md, "Result", with its extensions): the ``scene``'s name,
    the ``events`` in time order, every ball's ``final`` state by id, the ``duration`` (s), the
    ``ending`` (``at_rest``, or ``horizon``: stopped at the scene's horizon with balls still
    moving), the ``pots`` and the balls ``off_table`` in time order, the impact ``models`` and every
    parameter (``params``, by name), the cue ``strike`` if there was one, and a reminder of the
    ``units``."""

    scene: str
    events: List[Event]
    final: Dict[str, BallState]
    duration: float
    ending: str
    pots: List[Pot]
    off_table: List[OffTable]
    models: Dict[str, str]
    params: Dict[str, float]
    strike: Optional[StrikeReport] = _optional()
    units: str = ""

    @classmethod
    def from_dict(cls, d: dict) -> "ShotResult":
        """The record of its JSON document (the inverse of ``to_dict``)."""
        return cls(
            d["scene"],
            [Event.from_dict(e) for e in d["events"]],
            _states(d["final"]),
            d["duration"],
            d.get("ending", "at_rest"),
            [Pot(**p) for p in d["pots"]],
            [OffTable(**o) for o in d["off_table"]],
            dict(d["models"]),
            dict(d["params"]),
            StrikeReport.from_dict(d["strike"]) if d.get("strike") else None,
            d["units"],
        )


@dataclass(frozen=True)
class Strike(_Record):
    """A strike as a scene file's ``[cue]`` gives it: the ``ball`` struck, cue ``speed``
    (m/s), heading ``aim`` (rad), ``offset`` of the cue's axis [side, height] (m) and
    ``elevation`` (rad)."""

    ball: str
    speed: float
    aim: float
    offset: Tuple[float, float]
    elevation: float

    @classmethod
    def from_dict(cls, d: dict) -> "Strike":
        """The record of its JSON document (the inverse of ``to_dict``)."""
        return cls(d["ball"], d["speed"], d["aim"], tuple(d["offset"]), d["elevation"])


@dataclass(frozen=True)
class Route(_Record):
    """The shot's route: the ``kind`` of pot (``direct``, ``double``, ``plant``, ``kiss``),
    what it goes ``via`` (the ball planted through or kissed, or the double's cushions), the
    ``cushions`` the cue ball meets after its first ball and its ``spin`` (``screw``, ``stun``
    or ``follow``)."""

    kind: str
    via: List[str]
    cushions: List[str]
    spin: str


@dataclass(frozen=True)
class Robustness(_Record):
    """A shot under execution noise: the ``noise`` (standard deviations, by name), the
    ``samples`` simulated, the ``pot_probability``, the mean of the cue ball's ends
    ``cue_final_mean`` (m) and their spread ``cue_final_spread`` (m, root mean square)."""

    noise: Dict[str, float]
    samples: int
    pot_probability: float
    cue_final_mean: Tuple[float, float]
    cue_final_spread: float

    @classmethod
    def from_dict(cls, d: dict) -> "Robustness":
        """The record of its JSON document (the inverse of ``to_dict``)."""
        return cls(
            dict(d["noise"]),
            d["samples"],
            d["pot_probability"],
            tuple(d["cue_final_mean"]),
            d["cue_final_spread"],
        )


@dataclass(frozen=True)
class PlannedShot(_Record):
    """One planned shot: its ``strike``, whether it pots (``potted``, without noise), where the
    cue ball stops (``cue_final``, m), its ``distance`` from the target (m), its ``route`` and
    its ``robustness`` under noise."""

    strike: Strike
    potted: bool
    cue_final: Tuple[float, float]
    distance: float
    route: Route
    robustness: Robustness

    @classmethod
    def from_dict(cls, d: dict) -> "PlannedShot":
        """The record of its JSON document (the inverse of ``to_dict``)."""
        return cls(
            Strike.from_dict(d["strike"]),
            d["potted"],
            tuple(d["cue_final"]),
            d["distance"],
            Route(
                d["route"]["kind"],
                list(d["route"]["via"]),
                list(d["route"]["cushions"]),
                d["route"]["spin"],
            ),
            Robustness.from_dict(d["robustness"]),
        )


@dataclass(frozen=True)
class Plan(_Record):
    """A plan (formats.md, "Plan"): the ``scene``, the ball to ``pot``, the ``pocket``, the
    cue ball's ``target`` (m) and ``tolerance`` (m), whether it was ``reached``, the ``best``
    shot and the ``alternatives``, the ``shots_simulated`` and the ``wall_time`` (s)."""

    scene: str
    pot: str
    pocket: str
    target: Tuple[float, float]
    tolerance: float
    reached: bool
    best: PlannedShot
    alternatives: List[PlannedShot]
    shots_simulated: int
    wall_time: float

    @classmethod
    def from_dict(cls, d: dict) -> "Plan":
        """The record of its JSON document (the inverse of ``to_dict``)."""
        return cls(
            d["scene"],
            d["pot"],
            d["pocket"],
            tuple(d["target"]),
            d["tolerance"],
            d["reached"],
            PlannedShot.from_dict(d["best"]),
            [PlannedShot.from_dict(a) for a in d["alternatives"]],
            d["shots_simulated"],
            d["wall_time"],
        )


@dataclass(frozen=True)
class MotionSummary(_Record):
    """A ball's motion in the impact report's terms: horizontal ``speed`` (m/s), heading
    ``direction_deg`` (degrees from the incoming path or the cushion line), ``vertical_speed``
    (m/s), ``spin`` (rad/s), its vertical part ``sidespin`` and the ``motion``."""

    speed: float
    direction_deg: float
    vertical_speed: float
    spin: Vec3
    sidespin: float
    motion: str

    @classmethod
    def from_dict(cls, d: dict) -> "MotionSummary":
        """The record of its JSON document (the inverse of ``to_dict``)."""
        return cls(
            d["speed"],
            d["direction_deg"],
            d["vertical_speed"],
            tuple(d["spin"]),
            d["sidespin"],
            d["motion"],
        )


@dataclass(frozen=True)
class BallAfter(_Record):
    """One ball after an impact: just ``after_impact``, once its slip has ended
    (``after_slip``), its hop (``hop_height``, ``hop_length``, m), the
    ``distance_to_end_of_slip`` (m) and, off a cushion, the ``rebound_angle_deg``."""

    after_impact: MotionSummary
    after_slip: MotionSummary
    hop_height: float
    hop_length: float
    distance_to_end_of_slip: float
    rebound_angle_deg: Optional[float] = _optional()

    @classmethod
    def from_dict(cls, d: dict) -> "BallAfter":
        """The record of its JSON document (the inverse of ``to_dict``)."""
        return cls(
            MotionSummary.from_dict(d["after_impact"]),
            MotionSummary.from_dict(d["after_slip"]),
            d["hop_height"],
            d["hop_length"],
            d["distance_to_end_of_slip"],
            d.get("rebound_angle_deg"),
        )


@dataclass(frozen=True)
class ImpactInput(_Record):
    """The impact asked for: ``setup`` (``ball-ball`` or ``cushion``), ``speed`` (m/s),
    ``angle_deg``, spins in units of V/R and the frictions and restitutions used."""

    setup: str
    speed: float
    angle_deg: float
    topspin_v_over_r: float
    sidespin_v_over_r: float
    mu_ball: float
    e_ball: float
    mu_cushion: float
    e_cushion: float
    mu_slide: float


@dataclass(frozen=True)
class ImpactReport(_Record):
    """The report of one impact (``snooker impact --json``): the ``input``, the balls after it
    (``cue_ball`` and ``object_ball`` for ball-ball, ``ball`` for a cushion), the normal
    ``impulse`` (N s), the cushion's ``normal_speed`` (m/s) and the ``units``."""

    input: ImpactInput
    cue_ball: Optional[BallAfter] = _optional()
    object_ball: Optional[BallAfter] = _optional()
    ball: Optional[BallAfter] = _optional()
    impulse: float = 0.0
    normal_speed: Optional[float] = _optional()
    units: str = ""

    @classmethod
    def from_dict(cls, d: dict) -> "ImpactReport":
        """The record of its JSON document (the inverse of ``to_dict``)."""
        def ball(key: str) -> Optional[BallAfter]:
            return BallAfter.from_dict(d[key]) if key in d else None

        return cls(
            ImpactInput(**d["input"]),
            ball("cue_ball"),
            ball("object_ball"),
            ball("ball"),
            d["impulse"],
            d.get("normal_speed"),
            d["units"],
        )


@dataclass(frozen=True)
class Considered(_Record):
    """A stroke the player considered (formats.md, "Play log", ``plan``): the ball to ``pot``
    and the ``pocket`` (``""`` for a safety), the ``kind`` (``direct``, ``double``, ``plant``,
    ``kiss`` or ``safety``), its ``pot_probability`` under the noise, where the cue ball stops
    played exactly (``cue_to``, m), the ``ball`` the cue ball is sent at first, what the pot
    goes ``via`` (the ball planted through or kissed, the double's cushions), its expected
    ``value`` in points and the noise ``samples`` simulated for it."""

    pot: str
    pocket: str
    kind: str
    pot_probability: float
    cue_to: Tuple[float, float]
    ball: str
    via: List[str]
    value: float
    samples: int

    @classmethod
    def from_dict(cls, d: dict) -> "Considered":
        """The record of its JSON document (the inverse of ``to_dict``)."""
        return cls(
            d["pot"],
            d["pocket"],
            d["kind"],
            d["pot_probability"],
            tuple(d["cue_to"]),
            d["ball"],
            list(d["via"]),
            d["value"],
            d["samples"],
        )


@dataclass(frozen=True)
class Stroke(_Record):
    """One stroke played (a line of the play log, formats.md "Play log"): its number
    (``stroke``), the ``player`` at the table (0 or 1), the ``frame`` before it as frame TOML
    (the cue ball placed and the nomination made: ``snooker.frame(stroke.frame)`` reads it),
    the colour ``nominated`` (``""`` for none), the strike ``intended`` and the one
    ``executed`` (intended + execution noise), the ``plan`` chosen and the ``alternatives``
    considered, the ``referee``'s result of the executed strike (a dict, formats.md "Referee
    result" without ``shot``), the ``decision_time`` (s), the ``agent`` and the
    ``shots_simulated`` to decide."""

    stroke: int
    player: int
    frame: str
    nominated: str
    intended: Strike
    executed: Strike
    plan: Considered
    alternatives: List[Considered]
    referee: Dict[str, Any]
    decision_time: float
    agent: str
    shots_simulated: int

    @property
    def points(self) -> int:
        """Points the stroke scored (0 for a foul)."""
        return int(self.referee["points"])

    @property
    def foul(self) -> Optional[str]:
        """The foul's reason, None for a legal stroke."""
        f = self.referee.get("foul")
        return f["reason"] if isinstance(f, dict) else f

    @classmethod
    def from_dict(cls, d: dict) -> "Stroke":
        """The record of its JSON document (the inverse of ``to_dict``)."""
        plan = dict(d["plan"])
        alternatives = plan.pop("alternatives", [])
        return cls(
            d["stroke"],
            d["player"],
            d["frame"],
            d["nominated"],
            Strike.from_dict(d["intended"]),
            Strike.from_dict(d["executed"]),
            Considered.from_dict(plan),
            [Considered.from_dict(a) for a in alternatives],
            dict(d["referee"]),
            d["decision_time"],
            d["agent"],
            d["shots_simulated"],
        )

    def to_dict(self) -> dict:
        """The play log's line (the alternatives inside ``plan``, as the log writes them)."""
        d = _document(self)
        alternatives = d.pop("alternatives")
        d["plan"]["alternatives"] = alternatives
        order = ["stroke", "player", "frame", "nominated", "intended", "executed", "plan",
                 "referee", "decision_time", "agent", "shots_simulated"]
        return {k: d[k] for k in order}


@dataclass(frozen=True)
class Decision(_Record):
    """One stroke chosen (``snooker.choose``): where the cue ball in hand goes (``cue_ball``,
    m, None when not in hand), the colour ``nominated`` (None for none), the ``strike`` meant,
    the ``plan`` and the ``alternatives``, and the ``shots_simulated`` to decide."""

    cue_ball: Optional[Tuple[float, float]]
    nominated: Optional[str]
    strike: Strike
    plan: Considered
    alternatives: List[Considered]
    shots_simulated: int

    @classmethod
    def from_dict(cls, d: dict) -> "Decision":
        """The record of its JSON document (the inverse of ``to_dict``)."""
        return cls(
            tuple(d["cue_ball"]) if d["cue_ball"] is not None else None,
            d["nominated"],
            Strike.from_dict(d["strike"]),
            Considered.from_dict(d["plan"]),
            [Considered.from_dict(a) for a in d["alternatives"]],
            d["shots_simulated"],
        )
