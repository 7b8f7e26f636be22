# The compiled module's interface (python/core.cpp), for type checkers: the package's typed functions call these.
from typing import Any, Callable, Dict, List, Mapping, Optional, Sequence, Tuple

VERSION: str
COMMIT: str
EXIT_OK: int
EXIT_OUT_OF_BOUNDS: int
EXIT_BAD_INPUT: int
EXIT_SIMULATION_FAILED: int
DEFAULT_ASSUMPTIONS: str
DEFAULT_DIAPHRAGM_DAMPING: float

RecordSamples = Optional[Tuple[Sequence[float], Sequence[float]]]

class WallArgs:
    def __init__(self, model: str, height: float, thickness: float, hinge: Optional[float], xi: float,
                 density: float, g: float, assumptions: str, kinematics: Optional[str], impact: Optional[str],
                 roller: Optional[str], overburden_eccentricity: float = ..., corner_radius: float = ...,
                 diaphragm_period: float = ..., diaphragm_damping: float = ...) -> None: ...

def run(args: Sequence[str]) -> Tuple[int, str, str]: ...
def run_with_progress(args: Sequence[str],
                      progress: Optional[Callable[[int, int, str], Any]]) -> Tuple[int, str, str]: ...
def simulate(engine: str, wall: WallArgs, theta0: float, t_end: Optional[float], dt: Optional[float],
             sample_dt: Optional[float], iterations: Optional[int], knobs: Mapping[str, float],
             record: Optional[str], record_samples: RecordSamples, scale: Optional[float], pga: Optional[float],
             pulse: Optional[str], amplitude: Optional[float], pulse_period: Optional[float],
             duration: Optional[float], stop_at_rest: bool, friction: Optional[float],
             run_budget: Optional[float]) -> Dict[str, Any]: ...
def compare(engine: str, wall: WallArgs, theta0: float, dt: Optional[float], iterations: Optional[int],
            knobs: Mapping[str, float], run_budget: Optional[float]) -> Dict[str, Any]: ...
def compare_response(engines: Sequence[str], wall: WallArgs, record: Optional[str], record_samples: RecordSamples,
                     scale: Optional[float], pga: Optional[float], pulse: Optional[str], amplitude: Optional[float],
                     pulse_period: Optional[float], duration: Optional[float], dt: Optional[float],
                     iterations: Optional[int], knobs: Mapping[str, float],
                     run_budget: Optional[float]) -> Dict[str, Any]: ...
def engine_settings(engine: str) -> List[Dict[str, Any]]: ...
def available_engines() -> List[str]: ...
def canonical_engine(name: str) -> Optional[str]: ...
def engine_name_hint(name: str) -> str: ...
def default_compared_engines() -> List[str]: ...
def data_dir() -> str: ...
