"""The typed API over the library (docs/guide/python.md): simulate, compare, study, report, engines, engine_settings."""

from __future__ import annotations

import contextlib
import decimal
import fractions
import json
import math
import numbers
import os
import pathlib
import re
import shutil
import sys
import tempfile
from typing import (Any, Callable, Dict, Iterator, List, Literal, Mapping, Optional, Sequence, Tuple,
                    TypeVar, Union, overload)

import numpy as np
import numpy.typing as npt

from . import _core, cli
from ._errors import Error, InputError, SimulationError
from ._results import (Comparison, DataFrame, ReportResult, ResponseComparison, Simulation, StudyResult,
                       comparison_from, failed_comparison, response_comparisons_from, simulation_from)

# What the functions take. A number: a Python, NumPy, Fraction or Decimal one. A path: a str or os.PathLike.
Number = Union[float, int, np.floating, np.integer, fractions.Fraction, decimal.Decimal]
Path = Union[str, "os.PathLike[str]"]
# A ground motion given as samples: (dt [s], accelerations [g]) at a uniform step from t = 0, or (times [s],
# accelerations [g]) with strictly increasing times; each a NumPy array or a sequence of numbers.
Samples = Union[npt.ArrayLike, Sequence[float]]
Record = Union[Path, Tuple[float, Samples], Tuple[Samples, Samples]]
# An engine's knobs: {name: value}, or a list of "name=value" strings as vssw.cli takes them.
Knobs = Union[Mapping[str, Union[Number, str]], Sequence[str]]
# progress=: True (a bar), False or None (nothing), or a callable (done, total, what).
Progress = Union[bool, None, Callable[[int, int, str], Any]]
# What compare returns when the call does not say which (the overloads below narrow it for a type checker).
AnyComparison = Union[Comparison, List[Comparison], ResponseComparison, List[ResponseComparison]]
_T = TypeVar("_T")

_DENSITY = 1800.0  # kg/m^3, brick masonry (analytic/wall.hpp kDefaultDensity)
_GRAVITY = 9.81  # m/s^2 (analytic/wall.hpp kDefaultGravity)


def _is_number(value):
    """A Python, NumPy, Fraction or Decimal number (each taken as the nearest float), not a bool."""
    return not isinstance(value, bool) and isinstance(value, (numbers.Real, decimal.Decimal))


def _number(name, value, optional=False):
    """A float from a number (_is_number); InputError naming the parameter otherwise, and for NaN even where the
    value would be ignored (as the command line refuses NaN in every option)."""
    if value is None and optional:
        return None
    if not _is_number(value):
        raise InputError(f"{name}: a number is expected, got {type(value).__name__} {value!r}",
                         _core.EXIT_BAD_INPUT)
    if math.isnan(value):
        raise InputError(f"{name}: NaN is not a number vssw takes", _core.EXIT_BAD_INPUT)
    return float(value)


def _names(name, value):
    """A list of names (a list, or a comma-separated str) as the command line's list options take them: none empty,
    none repeated, and the list not empty; InputError naming the parameter and the item otherwise."""
    items = value.split(",") if isinstance(value, str) else list(value)
    for item in items:
        if not isinstance(item, str) or "\x00" in item:
            raise InputError(f"{name}: names are expected, got {type(item).__name__} {item!r}", _core.EXIT_BAD_INPUT)
    if not items:
        raise InputError(f"{name}: an empty list; name at least one", _core.EXIT_BAD_INPUT)
    for i, item in enumerate(items):
        if item == "":
            raise InputError(f"{name} has an empty item in {value!r}", _core.EXIT_BAD_INPUT)
        if item in items[:i]:
            raise InputError(f"{name} names {item!r} more than once", _core.EXIT_BAD_INPUT)
    return items


def _integer(name, value):
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise InputError(f"{name}: a whole number is expected, got {type(value).__name__} {value!r}",
                         _core.EXIT_BAD_INPUT)
    return int(value)


def _word(name, value, default):
    """A choice as the library reads it ("exact", "eq19", ...); an impact law may also be a number (e = 0.6)."""
    if value is None:
        return default
    if _is_number(value):
        return repr(_number(name, value))
    if not isinstance(value, str) or value == "" or "\x00" in value:
        raise InputError(f"{name}: a word is expected, got {type(value).__name__} {value!r}", _core.EXIT_BAD_INPUT)
    return value


def _knobs(settings):
    """An engine's settings as {name: float}: a dict, or a list of "name=value" strings (as vssw.cli takes them)."""
    if settings is None:
        return {}
    if isinstance(settings, (list, tuple)):
        pairs = {}
        for item in settings:
            name, sep, value = str(item).partition("=")
            if not sep or not name:
                raise InputError(f"settings: 'name=value' is expected, got {item!r}", _core.EXIT_BAD_INPUT)
            pairs[name] = value
        settings = pairs
    if not isinstance(settings, dict):
        raise InputError(f"settings: a dict {{name: value}} is expected, got {type(settings).__name__}",
                         _core.EXIT_BAD_INPUT)
    out = {}
    for name, value in settings.items():
        number: Any = value
        if isinstance(value, str):
            try:
                number = float(value)
            except ValueError:
                raise InputError(f"settings[{name!r}]: {value!r} is not a number", _core.EXIT_BAD_INPUT) from None
        out[str(name)] = _number(f"settings[{name!r}]", number)
    return out


def _wall(model, height, thickness, hinge, xi, density, g, assumptions=None, kinematics=None, impact=None,
          roller=None, overburden_eccentricity=0.0, corner_radius=0.0, diaphragm_period=0.0, diaphragm_damping=None):
    """The wall and the analytic model's assumptions: a named set (default "mechanism", as every command's), any of
    kinematics, impact, roller overriding one part of it."""
    if diaphragm_damping is not None and diaphragm_period == 0.0:
        raise InputError(f"diaphragm_damping {diaphragm_damping!r} without diaphragm_period: a rigid top support has "
                         "no damping to take (give the diaphragm's period > 0)", _core.EXIT_BAD_INPUT)
    return _core.WallArgs(
        model=_word("model", model, "vssw"), height=_number("height", height),
        thickness=_number("thickness", thickness), hinge=_number("hinge", hinge, optional=True),
        xi=_number("xi", xi), density=_number("density", density), g=_number("g", g),
        assumptions=_word("assumptions", assumptions, _core.DEFAULT_ASSUMPTIONS),
        kinematics=_word("kinematics", kinematics, None), impact=_word("impact", impact, None),
        roller=_word("roller", roller, None),
        overburden_eccentricity=_number("overburden_eccentricity", overburden_eccentricity),
        corner_radius=_number("corner_radius", corner_radius),
        diaphragm_period=_number("diaphragm_period", diaphragm_period),
        diaphragm_damping=_core.DEFAULT_DIAPHRAGM_DAMPING if diaphragm_damping is None
        else _number("diaphragm_damping", diaphragm_damping))


def _samples(what: str, values: Any) -> List[float]:
    """A one-dimensional sequence of finite numbers as floats; InputError naming `what` otherwise."""
    try:
        array = np.asarray(values, dtype=np.float64)
    except (TypeError, ValueError):
        raise InputError(f"{what}: numbers are expected, got {type(values).__name__}", _core.EXIT_BAD_INPUT) from None
    if array.ndim != 1:
        raise InputError(f"{what}: a one-dimensional sequence of numbers is expected, got shape {array.shape}",
                         _core.EXIT_BAD_INPUT)
    bad = np.flatnonzero(~np.isfinite(array))
    if bad.size:
        raise InputError(f"{what}: sample {bad[0]} is {array[bad[0]]}, not a finite number", _core.EXIT_BAD_INPUT)
    return [float(x) for x in array]


# A record given as samples, as a study or the program names it in its outputs.
_ARRAY_RECORD_NAME = "array"


def _record_samples(record: Tuple[Any, ...]) -> Tuple[List[float], List[float]]:
    """record=(dt, values) or (t, values): the times [s] and the accelerations [g], checked (InputError naming record
    and what is wrong). The times of (dt, values) are i * dt, as the program computes those of a record at a step."""
    if len(record) != 2:
        raise InputError(f"record: (dt, values) or (t, values) is expected, a tuple of {len(record)} items given",
                         _core.EXIT_BAD_INPUT)
    first, values = record
    accelerations = _samples("record's values [g]", values)
    if len(accelerations) < 2:
        raise InputError(f"record's values: {len(accelerations)} sample(s), a record needs at least 2",
                         _core.EXIT_BAD_INPUT)
    if _is_number(first):
        dt = _number("record's dt [s]", first)
        if not (math.isfinite(dt) and dt > 0.0):
            raise InputError(f"record's dt: must be a positive finite step in s, got {dt!r}", _core.EXIT_BAD_INPUT)
        times = (np.arange(len(accelerations), dtype=np.float64) * dt).tolist()
        return times, accelerations
    times = _samples("record's t [s]", first)
    if len(times) != len(accelerations):
        raise InputError(f"record: {len(times)} times but {len(accelerations)} values", _core.EXIT_BAD_INPUT)
    if times[0] < 0.0:
        raise InputError(f"record's t: must start at 0 or later, got {times[0]!r}", _core.EXIT_BAD_INPUT)
    for i in range(1, len(times)):
        if not times[i] > times[i - 1]:
            raise InputError(f"record's t: must increase strictly, but t[{i}] = {times[i]!r} follows "
                             f"t[{i - 1}] = {times[i - 1]!r}", _core.EXIT_BAD_INPUT)
    return times, accelerations


def _record(record: Optional[Record]) -> Tuple[Optional[str], Optional[Tuple[List[float], List[float]]]]:
    """The record as the library takes it: (a file's path, None), or ("array", (times, accelerations [g])) for one
    given as samples; (None, None) without a record."""
    if record is None:
        return None, None
    if isinstance(record, (tuple, list)):
        return _ARRAY_RECORD_NAME, _record_samples(tuple(record))
    if not isinstance(record, (str, os.PathLike)):
        raise InputError(f"record: a file's path, (dt, values) or (t, values) is expected, got "
                         f"{type(record).__name__}", _core.EXIT_BAD_INPUT)
    return _record_path(record), None


def _record_path(record: Path) -> str:
    """A record path as given when it exists from the current directory; else the shipped data's file of that name
    ("data/records/x.at2" or "records/x.at2" from the data folder of this build or installation)."""
    path = pathlib.Path(os.fspath(record))
    if path.exists() or path.is_absolute():
        return str(path)
    data = pathlib.Path(_core.data_dir())
    for candidate in [data.parent / path, data / path]:
        if candidate.exists():
            return str(candidate)
    return str(path)  # the library names it in its message


def simulate(engine: str = "analytic", *, height: Number, thickness: Number, hinge: Optional[Number] = None,
             model: str = "vssw", xi: Number = 0.0, density: Number = _DENSITY, g: Number = _GRAVITY,
             theta0: Number = 0.0, t_end: Optional[Number] = None, record: Optional[Record] = None,
             scale: Optional[Number] = None, pga: Optional[Number] = None, pulse: Optional[str] = None,
             amplitude: Optional[Number] = None, pulse_period: Optional[Number] = None,
             duration: Optional[Number] = None, dt: Optional[Number] = None, sample_dt: Optional[Number] = None,
             iterations: Optional[int] = None, settings: Optional[Knobs] = None, assumptions: Optional[str] = None,
             kinematics: Optional[str] = None, impact: Union[str, Number, None] = None, roller: Optional[str] = None,
             friction: Optional[Number] = None, stop_at_rest: bool = True, run_budget: Optional[Number] = None,
             overburden_eccentricity: Number = 0.0, corner_radius: Number = 0.0, diaphragm_period: Number = 0.0,
             diaphragm_damping: Optional[Number] = None) -> Simulation:
    """One backend's run of one wall: its trajectory as NumPy arrays (a vssw.Simulation).

    engine: "analytic" (the two-block model, this project's own DOP853 integration) or an engine of this build
        (vssw.engines(): "bullet", "ode", "simbody", "siconos", "box2d", "dart", "mujoco", ...), in any letter case
        ("ODE", "Simbody-Rigid"); the result names it as vssw.engines() does. An engine run is a child process with a
        CPU budget (a library that crashes fails the run, never Python).
    The wall:
        height, thickness: full height 2h and full thickness 2b [m].
        hinge: the hinge's height ratio h1/h in (0, 1) (required for model="vssw"; ignored for a parapet).
        model: "vssw" (two blocks with a top roller, the paper's) or "parapet" (one block, Housner's).
        xi: overburden N/W on the top (0: none). density [kg/m^3] (default 1800). g [m/s^2] (default 9.81).
        overburden_eccentricity: where N acts on the (upper) block's top face, e/b in [-1, 1] (0: the centre, the
            paper's; +1: the corner on the side the wall tips to when theta1 > 0).
        corner_radius: r/b of every block corner in [0, 0.5] (0: the paper's sharp blocks). Engines only for the
            motion: the analytic model refuses a rounded wall (its pivots roll); its threshold is Eq. (12r).
        diaphragm_period [s], diaphragm_damping: a VSSW's top roller carried by a diaphragm of that period and damping
            ratio (default 0.05) under the ground motion (0: rigid, the paper's Eq. 9). Engines that move their roller
            only (ODE, Box2D, DART, Bullet); the analytic model fails such a run under a ground motion (Eq. 9e).
    How it starts and what shakes it (one of a release and a ground motion, or both):
        theta0: release from rest at theta0 * alpha1 (a fraction of alpha1, a parapet's alpha; -1 < theta0 < 1;
            the sign is the side: positive tips the wall towards +x).
        record: a ground-motion file (PEER AT2, two columns time/acceleration, or a CSV with those first) in g
            unless its header says otherwise; a relative path is read from the current directory, else from the
            shipped data ("data/records/northridge1994-rinaldi-228.at2"). Or the samples themselves: (dt, values),
            accelerations [g] at a uniform step dt [s] from t = 0, or (t, values), times [s] strictly increasing from
            0 or later and accelerations [g]; NumPy arrays or sequences, every number finite. Between samples the
            acceleration is linear, as a file's. scale: a factor on it, or pga: its peak ground acceleration [g] (not
            both).
        pulse: "sine", "cosine", "ricker" or "harmonic", with amplitude [g] and pulse_period [s] (duration [s]:
            harmonic only); pga replaces the amplitude.
        t_end: end of the run [s]. Default: a release alone runs long enough for 8 impacts of the analytic model
            (as `vssw compare` runs it); a ground motion runs its duration + 10 s.
        stop_at_rest: end the run once the wall is at rest and the shaking can no longer lift it (default True).
    The backend's settings:
        dt: an engine's step [s], default each engine's own (vssw.engine_settings(engine) lists it: 1 ms for ODE,
            ...); Simbody's integrator chooses its own steps, and its dt is the interval it reports at. Not for the
            analytic model (an InputError), whose integrator chooses its steps to its tolerance (settings={"rtol"}).
        sample_dt: one time grid for every backend [s]: the arrays hold the samples at t = k * sample_dt, t exactly
            that (the analytic model's output interval; an engine's every sample_dt / dt-th step, which must be a
            whole number). A run that ends at rest or overturned between two times of the grid ends at the last one
            before. None: the analytic model every 1e-4 s, an engine every step.
        iterations: solver iterations (Bullet, ODE; default the engine's own).
        settings: the engine's knobs, {name: value} (vssw.engine_settings(engine) lists each with its default,
            unit, range, meaning and the walls it is for), e.g. {"erp": 0.2} for ODE. A knob the engine does not know is an InputError.
        assumptions (analytic only): the model's assumptions as a named set, the same default as every command's:
            "mechanism" (the default: the exact kinematics of Eq. 2, the whole mechanism's plastic impact, a roller
            that can only push; what the engines realise and are compared against) or "paper" (the paper as
            printed: Eq. 3, Eq. 19, a bilateral roller).
        kinematics, impact, roller (analytic only): override one part of the set: "exact" (Eq. 2) or "paper"
            (Eq. 3); "eq19", "whole-mechanism" or a number e in [0, 1]; "bilateral" or "unilateral".
        friction: Coulomb friction of the engines' contacts at the base and the hinge (default None: 2, where nothing
            slides and a slide fails the run). Given, sliding is measured (Simulation.slip) rather than a failure,
            and the analytic model warns where it would slide (it needs more friction than given).
        run_budget: CPU seconds one engine run may take (default 30 s + 1 ms per step).
    Raises InputError (a ValueError) naming a bad value, SimulationError (a RuntimeError) when the run fails."""
    record_file, record_samples = _record(record)
    result = _with_python_names(lambda: _core.simulate(
        engine=_engine(engine),
        wall=_wall(model, height, thickness, hinge, xi, density, g, assumptions, kinematics, impact, roller,
                   overburden_eccentricity, corner_radius, diaphragm_period, diaphragm_damping),
        theta0=_number("theta0", theta0), t_end=_number("t_end", t_end, True), dt=_number("dt", dt, True),
        sample_dt=_number("sample_dt", sample_dt, True), iterations=_integer("iterations", iterations),
        knobs=_knobs(settings), record=record_file, record_samples=record_samples, scale=_number("scale", scale, True),
        pga=_number("pga", pga, True), pulse=None if pulse is None else _word("pulse", pulse, None),
        amplitude=_number("amplitude", amplitude, True), pulse_period=_number("pulse_period", pulse_period, True),
        duration=_number("duration", duration, True), stop_at_rest=bool(stop_at_rest),
        friction=_number("friction", friction, True), run_budget=_number("run_budget", run_budget, True)))
    return simulation_from(result, height=float(height), thickness=float(thickness))


def _progress(progress):
    """progress as given; TypeError unless True, False, None or a callable (checked before anything runs)."""
    if not (progress is None or isinstance(progress, bool) or callable(progress)):
        raise TypeError(f"progress: True, False, None or a callable is expected, got {type(progress).__name__} "
                        f"{progress!r}")
    return progress


class _Bar:
    """progress=True: a tqdm bar where tqdm is installed, else a line on stderr rewritten in place; a callable: called
    as progress(done, total, what); False or None: nothing."""

    def __init__(self, progress, description):
        _progress(progress)
        self.user = progress if callable(progress) else None
        self.bar = None
        self.line = bool(progress) and self.user is None
        self.description = description
        if self.line:
            try:
                from tqdm.auto import tqdm  # type: ignore[import]

                self.bar = tqdm(total=0, desc=description, leave=False)
                self.line = False
            except ImportError:
                pass

    def __call__(self, done, total, what):
        if self.user is not None:
            self.user(done, total, what)
        elif self.bar is not None:
            self.bar.total = total
            self.bar.n = done
            self.bar.set_postfix_str(what[:40], refresh=False)
            self.bar.refresh()
        elif self.line:
            sys.stderr.write(f"\r{self.description} [{done}/{total}] {what}"[:79].ljust(79))
            sys.stderr.flush()

    def close(self):
        if self.bar is not None:
            self.bar.close()
        elif self.line:
            sys.stderr.write("\r" + " " * 79 + "\r")
            sys.stderr.flush()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


def _engine_list(engine: Union[str, Sequence[str]]) -> Tuple[List[str], bool]:
    """The engines named, in their canonical names (_engine), and whether several were asked for (a list or a
    comma-separated str: a list comes back); a name given twice, in any spelling, refused."""
    if isinstance(engine, str):
        if engine == "all":
            return list(_core.default_compared_engines()), True
        if "," not in engine:
            return [_engine(engine)], False
        names = _names("engine", ",".join(e.strip() for e in engine.split(",")))
    elif isinstance(engine, (list, tuple)):
        names = _names("engine", engine)
    else:
        raise InputError(f"engine: a name or a list of names is expected, got {type(engine).__name__}",
                         _core.EXIT_BAD_INPUT)
    return _names("engine", [_engine(name) for name in names]), True


def _engine(name: Any) -> str:
    """An engine's canonical name (vssw.engines()'s) from its name in any letter case, with '_' for '-' or its display
    name ("ODE", "Simbody-Rigid", "MuJoCo"), as the library reads every list of engines; InputError otherwise,
    suggesting the nearest backend's name."""
    word = _word("engine", name, None)
    canonical = _core.canonical_engine(word)
    if canonical is None:
        raise InputError(f"engine '{word}' is not one of this build's{_core.engine_name_hint(word)}: "
                         f"{', '.join(_core.available_engines())}", _core.EXIT_BAD_INPUT)
    return canonical


# The library's messages about a wall or a ground motion name the command line's options (--pga, --roller): the
# Python functions' parameters are these.
_OPTION_NAMES = {f"--{name.replace('_', '-')}": name
                 for name in ["record", "scale", "pga", "pulse", "amplitude", "pulse_period", "duration", "model",
                              "height", "thickness", "hinge", "xi", "density", "g", "assumptions", "kinematics", "impact",
                              "roller", "overburden_eccentricity", "corner_radius", "diaphragm_period",
                              "diaphragm_damping", "friction"]}


def _with_python_names(call):
    """call(), an InputError's message naming the parameters as Python takes them (pga, not --pga)."""
    try:
        return call()
    except InputError as e:
        message = str(e.args[0]) if e.args else str(e)
        # A whole option only ("--g", not the start of "--gnuplot"); one the Python functions do not take stays.
        renamed = re.sub(r"--[a-z][a-z-]*\b", lambda m: _OPTION_NAMES.get(m.group(0), m.group(0)), message)
        if renamed == message:
            raise
        raise InputError(renamed, _core.EXIT_BAD_INPUT) from None


# What compare returns, for a type checker. In free vibration: "all" or a list of names a list, one name one
# Comparison (a comma-separated str gives a list too: pass a list for a checker to know it). Under a ground motion
# (record= or pulse=): any of the four, as the implementation's type says.
@overload
def compare(engine: Union[Literal["all"], List[str], Tuple[str, ...]], *,  # type: ignore[misc]
            record: None = ..., pulse: None = ...,
            height: Number, thickness: Number, hinge: Optional[Number] = ..., model: str = ...,
            xi: Number = ..., density: Number = ..., g: Number = ..., theta0: Optional[Number] = ...,
            scale: Optional[Number] = ..., pga: Optional[Number] = ..., amplitude: Optional[Number] = ...,
            pulse_period: Optional[Number] = ..., duration: Optional[Number] = ..., assumptions: Optional[str] = ...,
            kinematics: Optional[str] = ..., impact: Union[str, Number, None] = ..., roller: Optional[str] = ...,
            dt: Optional[Number] = ..., iterations: Optional[int] = ..., settings: Optional[Knobs] = ...,
            run_budget: Optional[Number] = ..., progress: Progress = ..., overburden_eccentricity: Number = ...
            ) -> List[Comparison]: ...
@overload
def compare(engine: str, *, record: None = ..., pulse: None = ...,
            height: Number, thickness: Number, hinge: Optional[Number] = ..., model: str = ...,
            xi: Number = ..., density: Number = ..., g: Number = ..., theta0: Optional[Number] = ...,
            scale: Optional[Number] = ..., pga: Optional[Number] = ..., amplitude: Optional[Number] = ...,
            pulse_period: Optional[Number] = ..., duration: Optional[Number] = ..., assumptions: Optional[str] = ...,
            kinematics: Optional[str] = ..., impact: Union[str, Number, None] = ..., roller: Optional[str] = ...,
            dt: Optional[Number] = ..., iterations: Optional[int] = ..., settings: Optional[Knobs] = ...,
            run_budget: Optional[Number] = ..., progress: Progress = ..., overburden_eccentricity: Number = ...
            ) -> Comparison: ...
@overload
def compare(engine: Union[str, Sequence[str]], *, record: Optional[Record] = ..., pulse: Optional[str] = ...,
            height: Number, thickness: Number, hinge: Optional[Number] = ..., model: str = ...,
            xi: Number = ..., density: Number = ..., g: Number = ..., theta0: Optional[Number] = ...,
            scale: Optional[Number] = ..., pga: Optional[Number] = ..., amplitude: Optional[Number] = ...,
            pulse_period: Optional[Number] = ..., duration: Optional[Number] = ..., assumptions: Optional[str] = ...,
            kinematics: Optional[str] = ..., impact: Union[str, Number, None] = ..., roller: Optional[str] = ...,
            dt: Optional[Number] = ..., iterations: Optional[int] = ..., settings: Optional[Knobs] = ...,
            run_budget: Optional[Number] = ..., progress: Progress = ..., overburden_eccentricity: Number = ...
            ) -> AnyComparison: ...
def compare(engine: Union[str, Sequence[str]], *, height: Number, thickness: Number, hinge: Optional[Number] = None,
            model: str = "vssw", xi: Number = 0.0, density: Number = _DENSITY, g: Number = _GRAVITY,
            theta0: Optional[Number] = None, record: Optional[Record] = None, scale: Optional[Number] = None,
            pga: Optional[Number] = None, pulse: Optional[str] = None, amplitude: Optional[Number] = None,
            pulse_period: Optional[Number] = None, duration: Optional[Number] = None,
            assumptions: Optional[str] = None, kinematics: Optional[str] = None,
            impact: Union[str, Number, None] = None, roller: Optional[str] = None, dt: Optional[Number] = None,
            iterations: Optional[int] = None, settings: Optional[Knobs] = None, run_budget: Optional[Number] = None,
            progress: Progress = False, overburden_eccentricity: Number = 0.0
            ) -> AnyComparison:
    """Engines against the analytic model on the metrics the project holds them to (`vssw compare`, over the
    library): the threshold acceleration [g] (the smallest constant ground acceleration that lifts the wall off
    rest, by bisection on simulations to 1e-4), the period [s] (4 x the time from the release at theta0 to the first
    impact) and the restitution (theta1' after / before the first impact). Each is measured from both trajectories by
    the same code; targets 0.5 %, 0.5 %, 2 %.

    engine: a backend name in any letter case (returns one vssw.Comparison), a list of names or "all" (every engine
        of this build but the analytic model and simbody-rigid; returns a list of Comparison, one whose engine failed
        carrying its `error` and NaN metrics).
    height, thickness [m], hinge (h1/h), model ("vssw" | "parapet"), xi (N/W), density [kg/m^3], g [m/s^2],
        overburden_eccentricity (e/b): the wall, as vssw.simulate.
    theta0: release for the period and restitution, a fraction of alpha1 (a parapet's alpha) from 0.01 to below 1
        (default 0.5).
    record (a file or (dt, values) or (t, values), with scale or pga) or pulse (with amplitude, pulse_period,
        duration), as vssw.simulate takes them:
        instead, the engines and the analytic model from rest under that ground motion (`vssw compare --record`):
        returns a vssw.ResponseComparison (a list of them for several engines): each run's peak |theta1| / alpha1, its
        time and overturning, and peak_ratio. Not with theta0. A single run's peak is no verdict: judge engines
        under records on an ensemble (vssw.study, vssw.report).
    assumptions: the analytic reference's assumptions, "mechanism" (the default) or "paper", as vssw.simulate takes
        them; kinematics, impact, roller override one part. The engines' settings do not reach it.
    dt [s], iterations, settings ({knob: value}): every engine's step, solver iterations and knobs (dt not with
        the analytic model, which takes no fixed step).
    run_budget: CPU seconds one engine run may take.
    progress: True shows a bar over the engines (tqdm when installed, else a line on stderr); a callable is called
        as progress(done, total, engine).
    A metric that could not be measured is NaN with its reason in `failures` (`vssw compare` exits 3 then).
    Raises InputError naming a bad value before any engine runs; SimulationError when the one engine asked fails."""
    _progress(progress)
    names, several = _engine_list(engine)
    wall = _wall(model, height, thickness, hinge, xi, density, g, assumptions, kinematics, impact, roller,
                 overburden_eccentricity)
    motion = dict(scale=scale, pga=pga, amplitude=amplitude, pulse_period=pulse_period, duration=duration)
    if record is None and pulse is None:
        given = [name for name, value in motion.items() if value is not None]
        if given:
            raise InputError(f"{', '.join(given)}: a ground motion's, given without record= or pulse=",
                             _core.EXIT_BAD_INPUT)
    else:
        if theta0 is not None:
            raise InputError("theta0 is a release for the free vibration; with record= or pulse= the wall starts "
                             "from rest", _core.EXIT_BAD_INPUT)
        if "analytic" in names:
            raise InputError("engine 'analytic': the analytic model is the reference every engine is compared with; "
                             "name engines only", _core.EXIT_BAD_INPUT)
        record_file, record_samples = _record(record)
        with _Bar(progress, "compare") as bar:
            bar(0, 1, ", ".join(names))
            result = _with_python_names(lambda: _core.compare_response(
                engines=names, wall=wall, record=record_file, record_samples=record_samples,
                scale=_number("scale", scale, True),
                pga=_number("pga", pga, True), pulse=None if pulse is None else _word("pulse", pulse, None),
                amplitude=_number("amplitude", amplitude, True),
                pulse_period=_number("pulse_period", pulse_period, True),
                duration=_number("duration", duration, True), dt=_number("dt", dt, True),
                iterations=_integer("iterations", iterations), knobs=_knobs(settings),
                run_budget=_number("run_budget", run_budget, True)))
            bar(1, 1, "done")
        comparisons = response_comparisons_from(result)
        status = comparisons[0].engine.status
        if not several and status != "ok":  # one engine: its failure is the call's, as in the free vibration
            raise SimulationError(f"{names[0]}: {status.partition('failed: ')[2] or status}",
                                  _core.EXIT_SIMULATION_FAILED)
        return comparisons if several else comparisons[0]
    theta0 = 0.5 if theta0 is None else theta0
    arguments = dict(wall=wall, theta0=_number("theta0", theta0), dt=_number("dt", dt, True),
                     iterations=_integer("iterations", iterations), knobs=_knobs(settings),
                     run_budget=_number("run_budget", run_budget, True))
    results = []
    with _Bar(progress, "compare") as bar:
        for i, name in enumerate(names):
            bar(i, len(names), name)
            try:
                results.append(comparison_from(_with_python_names(lambda: _core.compare(engine=name, **arguments))))
            except SimulationError as e:
                if not several:
                    raise
                results.append(failed_comparison(name, str(e)))
        bar(len(names), len(names), "done")
    return results if several else results[0]


def engines() -> List[str]:
    """The backends of this build, in their canonical names: "analytic" first, then each engine found at configure
    time."""
    return list(_core.available_engines())


def _default_number(text):
    """A setting's default as the library writes it ("0.001", "inf", "none") as a number, None where it has none."""
    try:
        return float(text)
    except ValueError:
        return None


def engine_settings(engine: str) -> List[Dict[str, Any]]:
    """Every setting of one backend (its name in any letter case): a list of {name, default, unit, meaning, min,
    max, walls}. default is a float, or None where the setting has no default (it is off unless given); min and max
    are the range a value may take, both included (-inf/inf when unbounded); walls is "any", or "vssw" ("parapet")
    for a setting of that wall only, any other value than its default being refused for the other kind. dt (an
    engine's step) and iterations are given as simulate's dt and iterations, the analytic model's sample_dt (its
    output interval) as simulate's sample_dt, every other one in settings={name: value}."""
    name = _engine(engine)
    settings: List[Dict[str, Any]] = _core.engine_settings(name)
    for s in settings:
        s["default"] = _default_number(s["default"])
        if name == "analytic" and s["name"] == "dt":  # no step of its own: its dt is its output interval
            s["name"] = "sample_dt"
    return settings


def data_dir() -> pathlib.Path:
    """The shipped data folder (records in records/, Table 1) this build or installation reads."""
    return pathlib.Path(_core.data_dir())


def _read_csv(path):
    import pandas as pd  # type: ignore[import]

    # round_trip: the 17 digits the files hold read back to the same doubles (pandas' default may be 1 ulp off).
    return pd.read_csv(path, float_precision="round_trip")


@contextlib.contextmanager
def _folder(out, prefix):
    """The command's folder: `out` as given, or a temporary one removed when the call ends, whether it succeeded (what
    it holds has been read into the result by then) or failed: no folder is left behind unless one is asked for."""
    if out is not None:
        yield pathlib.Path(os.fspath(out))
        return
    folder = pathlib.Path(tempfile.mkdtemp(prefix=prefix))
    try:
        yield folder
    finally:
        shutil.rmtree(folder, ignore_errors=True)


def _run_command(args, progress, description):
    with _Bar(progress, description) as bar:
        code, out, err = _core.run_with_progress([str(a) for a in args], bar if progress else None)
    if code != _core.EXIT_OK:
        raise cli._EXCEPTIONS.get(code, Error)(cli._message(err), code, err)
    return out


def study(file: Union[Path, Dict[str, Any]], out: Optional[Path] = None, *, threads: Optional[int] = None,
          shard: Optional[str] = None, resume: bool = False, force: bool = False, strict: bool = False,
          plots: Optional[bool] = None, gnuplot: Optional[Path] = None, run_budget: Optional[Number] = None,
          progress: Progress = False) -> StudyResult:
    """Runs a study (`vssw study`, docs/studies in the README): walls x assumptions x excitations x engines.

    file: a study file (.toml or .json) or a dict of its keys (a relative record `file` in it is read from the
        current directory; a record there may be its samples, (dt, values) or (t, values) as a tuple, or
        {"name": NAME, "samples": (dt, values)}).
    out: the study folder to write (created if missing). None: a temporary folder, removed once its results are read
        (StudyResult.folder is then None), without plots unless plots=True.
    threads: worker threads (default: the available cores). shard: "K/N", run every N-th case from the K-th.
    resume: finish an interrupted study in `out`. force: run a study of more than 10000 tasks. strict: raise
        SimulationError when any row failed. plots: write the gnuplot plots (default: with `out` given).
    gnuplot: the gnuplot program. run_budget: CPU seconds one engine run may take.
    progress: True shows a bar over the tasks (tqdm when installed, else a line on stderr); a callable is called as
        progress(done, total, what).
    Returns a vssw.StudyResult: results (results.csv as a pandas DataFrame), folder, summary (the JSON summary)."""
    _progress(progress)
    with _folder(out, "vssw-study-") as folder, tempfile.TemporaryDirectory(prefix="vssw-study-file-") as scratch:
        from_dict = isinstance(file, dict)
        path = cli._study_file_of(file, scratch) if isinstance(file, dict) else os.fspath(file)
        options = dict(threads=threads, shard=shard, resume=resume, force=force, strict=strict,
                       no_plots=not (plots if plots is not None else out is not None), gnuplot=gnuplot,
                       run_budget=run_budget)
        args = ["study", cli._text("file", path), f"--out={folder}", *cli._arguments(options), "--json"]
        with cli._errors_name_the_dict(path) if from_dict else contextlib.nullcontext():
            summary = json.loads(_run_command(args, progress, "study"))
        return StudyResult(results=_read_csv(folder / "results.csv"), folder=folder if out is not None else None,
                           summary=summary)


def _joined(name, names):
    """A list of names (_names) as one comma-separated option value; None: the option left out."""
    return None if names is None else ",".join(_names(name, names))


def report(out: Optional[Path] = None, *, suite: Path = "default", engines: Union[str, Sequence[str], None] = None,
           cases: Union[str, Sequence[str], None] = None, threads: Optional[int] = None, plots: Optional[bool] = None,
           earthquake: Optional[Path] = None, bench: Optional[Path] = None, gnuplot: Optional[Path] = None,
           data: Optional[Path] = None, run_budget: Optional[Number] = None, progress: Progress = False
           ) -> ReportResult:
    """Runs the validation suite and writes its report (`vssw report`): every case for the analytic model and each
    engine, the metrics against the references and targets, the plots.

    out: the report folder (created if missing). None: a temporary folder, removed once its tables are read
        (ReportResult.folder, markdown and html are then None), without plots unless plots=True.
    suite: "default", "full" or a suite file. engines: a list of engines, in any letter case (default every engine
        of this build but simbody-rigid). cases: only these case ids (a list). threads: worker threads (default the
        available cores).
    earthquake: "default", "none" or a study file of kind "ensemble" (default: "default", "none" with cases).
    bench: a finished `vssw bench --out DIR` folder whose section ends the report. gnuplot: the gnuplot program.
    data: the records' folder. run_budget: CPU seconds one engine run may take.
    progress: True shows a bar over the (case, engine) tasks; a callable is called as progress(done, total, what).
    Returns a vssw.ReportResult: metrics (metrics.csv), failures (failures.csv), rows (results.json's rows with
    targets), matrix (the verdicts at a glance), earthquake (the verdicts under records, None without that part),
    each a pandas DataFrame, and the folder, report.md and report.html paths."""
    import pandas as pd  # type: ignore[import]

    _progress(progress)
    options = dict(suite=suite, engines=_joined("engines", engines), cases=_joined("cases", cases),
                   threads=threads, no_plots=not (plots if plots is not None else out is not None),
                   earthquake=earthquake, bench=bench, gnuplot=gnuplot, data=data, run_budget=run_budget)
    with _folder(out, "vssw-report-") as folder:
        summary = _run_command(["report", f"--out={folder}", *cli._arguments(options)], progress, "report")
        with open(folder / "results.json", encoding="utf-8") as f:
            results = json.load(f)
        kept = folder if out is not None else None
        return ReportResult(metrics=_read_csv(folder / "metrics.csv"), failures=_read_csv(folder / "failures.csv"),
                            rows=pd.DataFrame(results["rows"]), folder=kept,
                            markdown=kept / "report.md" if kept else None, html=kept / "report.html" if kept else None,
                            summary=summary, matrix=pd.DataFrame(results["matrix"]),
                            earthquake=_earthquake_table(results["earthquake"]))


def _earthquake_table(part):
    """results.json's earthquake verdicts as a DataFrame, one row per engine (None when no earthquake part ran)."""
    import pandas as pd  # type: ignore[import]

    if part is None:
        return None
    rows = []
    for e in part["engines"]:
        a, f = e["overturning_agreement"], e["fragility_median_ratio"]
        rows.append(dict(engine=e["engine"], overturning_agreement=a["value"], overturning_agreement_lo=a["lo"],
                         overturning_agreement_hi=a["hi"], runs=a["n"], overturning_pass=a["pass"],
                         fragility_median_ratio=f["value"], fragility_median_ratio_lo=f["lo"],
                         fragility_median_ratio_hi=f["hi"], fragility_pass=f["pass"], fragility_note=f["note"],
                         peak_ratio_median=e["peak_ratio"]["median"], inside_band=e["inside_band"]["inside"],
                         band_runs=e["inside_band"]["runs"]))
    return pd.DataFrame(rows)
