"""Type stubs of the native module (built from the Rust crates by maturin)."""

from os import PathLike
from typing import Dict, List, Optional, Sequence, Tuple, Union

class SimulationError(RuntimeError):
    """A valid scene that the engine could not simulate to its end."""

class CannotPot(RuntimeError):
    """No strike within the bounds pots the ball without a foul."""

class Scene:
    """A scene read and checked (the cue strike applied)."""
    @property
    def name(self) -> str: ...
    @property
    def ball_ids(self) -> List[str]: ...

class Shot:
    """A simulated shot (wrapped by ``snooker.Shot``)."""
    def result_json(self) -> str: ...
    @property
    def ball_ids(self) -> List[str]: ...
    @property
    def duration(self) -> float: ...
    def positions(self, times: Sequence[float]) -> bytes: ...
    def pots(self) -> List[Tuple[str, str, float]]: ...
    def final_states(
        self,
    ) -> List[Tuple[str, List[float], List[float], List[float], str]]: ...

def load(path: Union[str, PathLike[str]]) -> Scene: ...
def parse_toml(text: str, file: str) -> Scene: ...
def parse_json(text: str, file: str) -> Scene: ...
def simulate(scene: Scene) -> Shot: ...
def simulate_many(
    scenes: Sequence[Scene], threads: Optional[int] = None
) -> List[Union[Shot, SimulationError]]: ...
def plan(
    scene: Scene,
    pot: str,
    pocket: str,
    cue_to: Sequence[float],
    tolerance: float = 0.001,
    noise: Optional[Dict[str, float]] = None,
    bounds: Optional[Dict[str, Tuple[float, float]]] = None,
    samples: int = 256,
    alternatives: int = 3,
    seed: int = 1,
    cue_ball: str = "cue",
) -> str: ...
def impact_ball_ball(
    speed: float,
    cut: float = 0.0,
    topspin: float = 0.0,
    sidespin: float = 0.0,
    params: Dict[str, float] = {},
) -> str: ...
def impact_cushion(
    speed: float,
    angle: float = 90.0,
    topspin: float = 0.0,
    sidespin: float = 0.0,
    params: Dict[str, float] = {},
) -> str: ...
