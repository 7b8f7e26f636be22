"""The typed API's results: small dataclasses with attributes, NumPy arrays for trajectories, pandas DataFrames for
tables (docs/guide/python.md)."""

from __future__ import annotations

import dataclasses
import math
import pathlib
import warnings
from typing import Any, Dict, List, Optional, Tuple

import numpy as np
import numpy.typing as npt

Array = npt.NDArray[np.float64]
# A pandas DataFrame: Any to a type checker, as Debian's pandas ships no type information (and pandas is optional at
# run time: the package imports it only where a table is made).
DataFrame = Any


@dataclasses.dataclass(frozen=True)
class Impact:
    """One impact of a trajectory: theta1 changing sign (compare/metrics.hpp, the code `vssw compare` measures with).

    t: crossing time [s], theta1 interpolated linearly between the samples either side.
    theta_dot_before, theta_dot_after: theta1' either side [rad/s], extrapolated to t (NaN when not resolved).
    ratio: theta_dot_after / theta_dot_before (the restitution of this impact; NaN when not resolved).
    resolved: each side's flight had samples enough to extrapolate from."""

    t: float
    theta_dot_before: float
    theta_dot_after: float
    ratio: float
    resolved: bool


@dataclasses.dataclass(frozen=True)
class Simulation:
    """One backend's run of one wall (vssw.simulate). Arrays are NumPy float64, one value per sample:

    t [s]; theta1 [rad] (the lower body's rotation, positive clockwise: tipping towards +x); theta1_dot [rad/s];
    theta2 [rad] (the upper body's, negative while theta1 > 0; equal to theta1 for a parapet); top_dy [m] (the top
    face's rise); kinetic, potential [J] (per metre of wall for the analytic model, for the scene's depth for the
    engines); contacts (contact points in use; 0 for the analytic model); ground_acceleration [m/s^2] (a_h at each
    sample, along +x).

    Also: engine, version (of its library), settings (as used: dt (the engine's step; None for the analytic model,
    which takes none), iterations, sample_dt (the output interval: the analytic model's always, an engine's when
    asked), knobs), alpha1 [rad] (the angle rotations are measured in: alpha1 of a VSSW's lower block, alpha of a
    parapet), alpha [rad] (the whole wall's slenderness atan(b/h), a study's `alpha`; alpha1 for a parapet), height,
    thickness [m] (2h, 2b), theta0 [rad] (the release), t_end [s] (asked; the run may stop earlier at rest),
    overturned, at_rest_at_end, steps (engine or integrator steps), warnings (the analytic model's own assumptions
    failing along the run), impacts (list of Impact), peaks (list of (t [s], theta1 [rad]) turning points), period
    [s] (4 x release to first impact; None without a release or an impact), max_abs_theta1 [rad] (the largest
    sample of the whole run; impacts, peaks, period and max_abs_theta1 are read off the run's samples: an engine's
    every step, the analytic model's at its output interval, which sample_dt sets), peak_rotation [alpha1] and
    peak_time [s] (the run's peak as a study and the report measure it: the located turning point of the analytic
    model, the collapse angle and the overturning when it overturned), assumptions
    (analytic: "mechanism", "paper" or "custom"; None for an engine), kinematics (analytic: "exact" or "paper"; None
    for an engine or a parapet), ground_motion (its name, None in free
    vibration), slip (an engine run's sliding when friction was given, a Slip; else None), geometry (the wall as the model built it:
    {model ("vssw" or "parapet"), b, h1, h2 [m] (half dimensions; h2 None for a parapet, h1 its h), alpha1, alpha2
    [rad], xi, N [N/m], overburden_eccentricity (e/b), corner_radius (r/b)}: what plot() and animate() draw)."""

    engine: str
    version: str
    t: Array
    theta1: Array
    theta1_dot: Array
    theta2: Array
    top_dy: Array
    kinetic: Array
    potential: Array
    contacts: npt.NDArray[np.int32]
    ground_acceleration: Array
    settings: Dict[str, Any]
    alpha1: float
    alpha: float
    height: float
    thickness: float
    theta0: float
    t_end: float
    overturned: bool
    at_rest_at_end: bool
    steps: int
    warnings: List[str]
    impacts: List[Impact]
    peaks: List[Tuple[float, float]]
    period: Optional[float]
    max_abs_theta1: float
    peak_rotation: float
    peak_time: float
    assumptions: Optional[str]
    kinematics: Optional[str]
    ground_motion: Optional[str]
    slip: Optional[Slip] = None
    geometry: Optional[Dict[str, Any]] = None

    @property
    def theta1_over_alpha1(self) -> Array:
        """theta1 / alpha1: the rotation in units of the reference angle (1 is the corner over the pivot at rest)."""
        return self.theta1 / self.alpha1

    @property
    def theta1_over_alpha(self) -> Array:
        """Deprecated: theta1_over_alpha1 (alpha now means the whole wall's slenderness, as in a study's results)."""
        warnings.warn("Simulation.theta1_over_alpha is theta1 / alpha1: use Simulation.theta1_over_alpha1 (alpha is "
                      "now the whole wall's slenderness atan(b/h), as in a study's results)", FutureWarning,
                      stacklevel=2)
        return self.theta1_over_alpha1

    @property
    def energy(self) -> Array:
        """kinetic + potential [J]."""
        return self.kinetic + self.potential

    @property
    def restitution(self) -> Optional[float]:
        """theta1' after / before the first impact when it is resolved, else None (what `vssw compare` measures)."""
        if self.impacts and self.impacts[0].resolved:
            return self.impacts[0].ratio
        return None

    def plot(self, ax: Any = None, quantities: Optional[Any] = None) -> Any:
        """theta1 and theta2 against time (and the top's rise and the energy where the run has them) on matplotlib
        axes: vssw._plot.plot_simulation. Returns the Figure."""
        from ._plot import plot_simulation

        return plot_simulation(self, ax=ax, quantities=quantities)

    def animate(self, path: Optional[Any] = None, fps: float = 25, speed: float = 1.0,
                t_start: Optional[float] = None, t_stop: Optional[float] = None) -> Any:
        """The two blocks and the roller moving as the run did, as a matplotlib Animation; written to path (.gif,
        or .mp4 where ffmpeg is installed) when one is given: vssw._animation.animate_simulation."""
        from ._animation import animate_simulation

        return animate_simulation(self, path=path, fps=fps, speed=speed, t_start=t_start, t_stop=t_stop)

    def to_dataframe(self) -> DataFrame:
        """The arrays as a pandas DataFrame, one column each."""
        import pandas as pd  # type: ignore[import]

        return pd.DataFrame({name: getattr(self, name) for name in _ARRAYS})

    def __repr__(self) -> str:
        return (f"Simulation(engine={self.engine!r}, samples={len(self.t)}, t_end={self.t_end:g} s, "
                f"max |theta1|/alpha1={self.max_abs_theta1 / self.alpha1:.4g}, overturned={self.overturned}, "
                f"period={self.period!r})")


_ARRAYS = ["t", "theta1", "theta1_dot", "theta2", "top_dy", "kinetic", "potential", "contacts", "ground_acceleration"]


@dataclasses.dataclass(frozen=True)
class SlipAt:
    """An engine's sliding at one contact (the base or the hinge), as `vssw compare --friction --json` writes it:
    largest_b, residual_b (the largest and the last slide, in half-thicknesses b), largest_m, residual_m (in m)."""

    largest_b: float
    largest_m: float
    residual_b: float
    residual_m: float


# The keys Simulation.slip had as a flat dict: each read through Slip[key], with a warning, as before.
_FLAT_SLIP_KEYS = {"base_largest": ("base", "largest_m"), "base_residual": ("base", "residual_m"),
                   "hinge_largest": ("hinge", "largest_m"), "hinge_residual": ("hinge", "residual_m")}


@dataclasses.dataclass(frozen=True)
class Slip:
    """An engine run's sliding when friction was given (Simulation.slip), in the structure of `vssw compare
    --friction --json`'s slip: base, hinge (each a SlipAt; hinge None for a parapet), slid_before_rocking,
    slid_off (the reason the run ended off its support, or None); besides, b [m], t_first_slip and t_first_lift [s, or
    None]."""

    base: SlipAt
    hinge: Optional[SlipAt]
    slid_before_rocking: bool
    slid_off: Optional[str]
    b: float
    t_first_slip: Optional[float]
    t_first_lift: Optional[float]

    def __getitem__(self, key: str) -> Any:
        """Deprecated: the flat dict's keys (slip["base_largest"] [m], ...), read from the fields."""
        warnings.warn(f"Simulation.slip[{key!r}] is deprecated: Simulation.slip is a Slip, as `vssw compare --json` "
                      "writes it (slip.base.largest_m, slip.hinge.residual_m, slip.b, ...)", FutureWarning,
                      stacklevel=2)
        if key in _FLAT_SLIP_KEYS:
            where, name = _FLAT_SLIP_KEYS[key]
            at = getattr(self, where)
            return 0.0 if at is None else getattr(at, name)
        return getattr(self, key)


def slip_from(d: Optional[Dict[str, Any]]) -> Optional[Slip]:
    """The Slip of `vssw compare --friction --json`'s slip as _core gives it (with b); its tolerance_b left out."""
    if d is None:
        return None
    return Slip(base=SlipAt(**d["base"]), hinge=None if d["hinge"] is None else SlipAt(**d["hinge"]),
                slid_before_rocking=d["slid_before_rocking"], slid_off=d["slid_off"], b=d["b"],
                t_first_slip=d["t_first_slip"], t_first_lift=d["t_first_lift"])


def simulation_from(d: Dict[str, Any], height: float, thickness: float) -> Simulation:
    fields = {f.name for f in dataclasses.fields(Simulation)}
    values = {k: v for k, v in d.items() if k in fields}
    values["impacts"] = [Impact(**i) for i in d["impacts"]]
    values["peaks"] = [tuple(p) for p in d["peaks"]]
    values["slip"] = slip_from(d["slip"])
    return Simulation(height=height, thickness=thickness, **values)


@dataclasses.dataclass(frozen=True)
class Metric:
    """One metric of an engine against the analytic model (vssw.compare).

    value: the engine's; reference: the analytic model's (both measured from their trajectories by the same code);
    rel_error: value / reference - 1 (NaN when either is missing); target: the accuracy asked of an engine
    (threshold and period 0.5 %, restitution 2 %: compare/targets.hpp); within_target: |rel_error| <= target."""

    value: float
    reference: float
    rel_error: float
    target: float

    @property
    def within_target(self) -> bool:
        return not math.isnan(self.rel_error) and abs(self.rel_error) <= self.target


@dataclasses.dataclass(frozen=True)
class ClosedForms:
    """The closed forms beside the measured values: threshold_g (Eq. 12 / 17) [g], restitution (Eq. 19 / Housner's
    e), restitution_whole_mechanism (the whole mechanism's plastic impact), period_linearised (Eq. 22 / Housner's at
    theta0 [s]; NaN where it does not apply: an overburden, theta0 beyond A)."""

    threshold_g: float
    restitution: float
    restitution_whole_mechanism: float
    period_linearised: float


@dataclasses.dataclass(frozen=True)
class Comparison:
    """One engine against the analytic model (vssw.compare): threshold [g], period [s], restitution and
    restitution_amplitude (from the peaks either side of the first impact), each a Metric; closed_forms; theta0 (the
    release, a fraction of alpha1); settings (the engine's, as used); threshold_trials and impacts ((analytic, engine)
    simulations of the threshold search, impacts in the free vibrations); failures (why a metric is NaN, one line
    each); analytic_warnings (the analytic model's own assumptions failing along its free vibration); error (several
    engines asked: the engine's failure, its metrics then NaN; None otherwise)."""

    engine: str
    version: str
    threshold: Metric
    period: Metric
    restitution: Metric
    restitution_amplitude: Metric
    closed_forms: ClosedForms
    theta0: float
    settings: Dict[str, Any]
    threshold_trials: Tuple[int, int]
    impacts: Tuple[int, int]
    failures: List[str]
    analytic_warnings: List[str]
    error: Optional[str] = None

    @property
    def metrics(self) -> Dict[str, Metric]:
        """{"threshold": Metric, "period": ..., "restitution": ..., "restitution_amplitude": ...}."""
        return {name: getattr(self, name) for name in ["threshold", "period", "restitution", "restitution_amplitude"]}

    @property
    def within_targets(self) -> bool:
        """Threshold, period and restitution all within their targets."""
        return all(getattr(self, m).within_target for m in ["threshold", "period", "restitution"])

    def to_dataframe(self) -> DataFrame:
        """One row per metric: engine, metric, value, reference, rel_error, target, within_target."""
        import pandas as pd  # type: ignore[import]

        return pd.DataFrame([dict(engine=self.engine, metric=name, value=m.value, reference=m.reference,
                                  rel_error=m.rel_error, target=m.target, within_target=m.within_target)
                             for name, m in self.metrics.items()])


def _pair(counts: Any) -> Tuple[int, int]:
    analytic, engine = counts
    return int(analytic), int(engine)


def comparison_from(d: Dict[str, Any]) -> Comparison:
    return Comparison(
        engine=d["engine"], version=d["version"],
        threshold=Metric(**d["threshold"]), period=Metric(**d["period"]), restitution=Metric(**d["restitution"]),
        restitution_amplitude=Metric(**d["restitution_amplitude"]), closed_forms=ClosedForms(**d["closed_forms"]),
        theta0=d["theta0"], settings=d["settings"], threshold_trials=_pair(d["threshold_trials"]),
        impacts=_pair(d["impacts"]), failures=list(d["failures"]), analytic_warnings=list(d["analytic_warnings"]))


def failed_comparison(engine: str, message: str) -> Comparison:
    nan = float("nan")
    missing = Metric(nan, nan, nan, nan)
    return Comparison(engine=engine, version="", threshold=missing, period=missing, restitution=missing,
                      restitution_amplitude=missing, closed_forms=ClosedForms(nan, nan, nan, nan), theta0=nan,
                      settings={}, threshold_trials=(0, 0), impacts=(0, 0), failures=[message],
                      analytic_warnings=[], error=message)


@dataclasses.dataclass(frozen=True)
class ResponseRun:
    """One backend's run from rest under the ground motion (vssw.compare with record= or pulse=): engine, version,
    settings (as a study writes them: "" at the engine's defaults), peak (max |theta1| / alpha1), peak_time [s],
    overturned (None when the run failed), t_overturn [s] (NaN when standing), status ("ok" or "failed: reason"),
    warnings (the analytic model's own assumptions failing along the run, "; "-joined)."""

    engine: str
    version: str
    settings: str
    peak: float
    peak_time: float
    overturned: Optional[bool]
    t_overturn: float
    status: str
    warnings: str


@dataclasses.dataclass(frozen=True)
class ResponseComparison:
    """An engine against the analytic model from rest under one ground motion (vssw.compare with record= or pulse=):
    engine and reference (each a ResponseRun), ground_motion (what shook the wall, in words). A single run's peak is
    not a verdict: under a record it switches branch for a 1 % change of the scale (docs/earthquakes.md); judge an
    engine on an ensemble (vssw.study with kind "ensemble", or vssw.report's earthquake part)."""

    engine: ResponseRun
    reference: ResponseRun
    ground_motion: str

    @property
    def peak_ratio(self) -> float:
        """engine peak / reference peak (NaN when either run failed)."""
        return self.engine.peak / self.reference.peak if self.reference.peak else float("nan")

    @property
    def overturning_agrees(self) -> Optional[bool]:
        """Both overturned or both stood (None when a run failed)."""
        if self.engine.overturned is None or self.reference.overturned is None:
            return None
        return self.engine.overturned == self.reference.overturned


def response_comparisons_from(d: Dict[str, Any]) -> List[ResponseComparison]:
    reference = ResponseRun(**d["reference"])
    return [ResponseComparison(engine=ResponseRun(**r), reference=reference, ground_motion=d["ground_motion"])
            for r in d["runs"]]


@dataclasses.dataclass(frozen=True)
class StudyResult:
    """A study's outputs (vssw.study): results (results.csv as a DataFrame, read to the last bit), folder (the study
    folder: results.csv, results.json, manifest.json, study.md, plots/; None when no `out` was given, the temporary
    folder removed), summary (the command's JSON summary)."""

    results: DataFrame
    folder: Optional[pathlib.Path]
    summary: Dict[str, Any]

    def __repr__(self) -> str:
        return f"StudyResult(folder={str(self.folder)!r}, rows={len(self.results)})"


@dataclasses.dataclass(frozen=True)
class ReportResult:
    """A validation report's outputs (vssw.report): metrics (metrics.csv: case_id, engine, metric, unit, reference,
    analytic, engine_value, error), failures (failures.csv: case_id, engine, message), rows (results.json's rows,
    with target and within_target, as a DataFrame), folder, markdown (report.md), html (report.html) (these three
    None when no `out` was given, the temporary folder removed), summary (the
    command's printed summary, one line per engine), matrix (the engine x metric matrix at a glance: engine, metric,
    worst_error, case_id, target, pass, ...), earthquake (one row per engine under the record ensemble:
    overturning_agreement with its lo, hi, runs and pass; fragility_median_ratio with its lo, hi, pass and note;
    peak_ratio_median; inside_band of band_runs; None when the report ran no earthquake part)."""

    metrics: DataFrame
    failures: DataFrame
    rows: DataFrame
    folder: Optional[pathlib.Path]
    markdown: Optional[pathlib.Path]
    html: Optional[pathlib.Path]
    summary: str
    matrix: Optional[DataFrame] = None
    earthquake: Optional[DataFrame] = None

    def __repr__(self) -> str:
        return f"ReportResult(folder={str(self.folder)!r}, metrics={len(self.metrics)} rows)"
