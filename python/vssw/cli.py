"""vssw.cli: the vssw program's commands from Python, options as keyword arguments, results as the commands' JSON
(plain dicts). This was the whole package before the typed API (vssw.simulate, vssw.compare, vssw.study,
vssw.report: docs/guide/python.md); it is kept unchanged for the scripts written against it. vssw.wall, vssw.free,
vssw.history, vssw.run and vssw.help are still these functions; the dict-returning compare and study are here.

Every function runs the `vssw` program's command of the same name in this process (no subprocess, no binary on
PATH) with its keyword arguments as the command's options, and returns the command's JSON as plain Python objects:

    wall(**options)      `vssw wall`: the closed forms of a VSSW and of the parapet of the same size
    free(**options)      `vssw free`: free vibration from rest at theta0 * alpha1
    history(**options)   `vssw history`: response to a record or a pulse; trace=True adds the time history
    compare(**options)   `vssw compare`: engines against the analytic model
    study(file, **kw)    `vssw study`: a study file (or a dict of its keys); its results.csv as a pandas DataFrame
    run(command, ...)    any command with --json, e.g. run("check", bounds="bounds/ci.toml")
    help(command)        the command's --help text: every option, unit and default
    export_scene(engine, path, **wall)   `vssw scene`: the scene an engine runs, in its own format (MJCF, URDF)

Options: `name=value` is `--name value` with underscores as dashes (pulse_period=0.5 is --pulse-period 0.5); True
is a bare flag and False or None leaves the option out; a list or tuple repeats the option (engine=["ode",
"bullet"]); a dict is NAME=VALUE pairs (set={"slide_limit": 0.1} is --set slide_limit=0.1). Keys of the results are
the JSON keys the README lists ("The vssw program"). Relative paths (records, study files) are read from the current
directory, as the program reads them.

Errors raise exceptions carrying the program's one-line message: bad input (exit code 2) InputError, a ValueError;
a failed simulation (3) SimulationError, a RuntimeError; a bound out in `check` (1) BoundsError. All three derive
from vssw.Error and keep the exit code, the program's stderr and, where the command printed one, its JSON (result).
"""

from __future__ import annotations

import contextlib as _contextlib
import decimal as _decimal
import json as _json
import math as _math
import numbers as _numbers
import os as _os
import tempfile as _tempfile
from typing import Any as _Any
from typing import Dict as _Dict
from typing import Iterator as _Iterator
from typing import Optional as _Optional
from typing import Union as _Union

from . import _core, _study_records
from ._errors import BoundsError, Error, InputError, SimulationError

# help() is left out of __all__: `from vssw import *` must not hide the built-in help.
__all__ = ["wall", "free", "history", "compare", "study", "run", "export_scene", "Error", "InputError",
           "SimulationError", "BoundsError"]

_EXCEPTIONS = {_core.EXIT_BAD_INPUT: InputError, _core.EXIT_SIMULATION_FAILED: SimulationError,
               _core.EXIT_OUT_OF_BOUNDS: BoundsError}
# The prefixes of the program's error line (cli/cli.cpp); the exception's message is the line without them.
_PREFIXES = ("vssw: error: ", "vssw: simulation failed: ", "vssw: check failed: ")


def _bad_value(name, why):
    return InputError(f"{name}: {why}", _core.EXIT_BAD_INPUT, "")


def _text(name, text):
    """A string as one argument. Refused: an empty one (the program would read an empty number as 0) and one with a
    NUL character (the C argument would end there: "4\x00junk" was read as 4)."""
    if isinstance(text, bytes):
        raise _bad_value(name, f"a number, a string or a path is expected, got bytes {text!r}")
    if text == "":
        raise _bad_value(name, "an empty value; give a value, or None to leave the option out")
    if "\x00" in text:
        raise _bad_value(name, f"a value with a NUL character: {text!r}")
    return text


def _value_text(name, value):
    """One option value as the program reads it: floats in full precision (repr round-trips), NaN and infinities
    as the words the program refuses by name."""
    if isinstance(value, (str, _os.PathLike)):
        return _text(name, _os.fspath(value))
    if isinstance(value, bool):  # a bare flag is True at the top level only (_arguments); here it would become 1
        raise _bad_value(name, f"{value} is not a value (True and False turn a flag on and off)")
    if isinstance(value, _numbers.Integral):
        return str(int(value))
    if isinstance(value, _numbers.Real):  # NumPy floats too: float() first, so that repr is "0.4", not "np.float64(0.4)"
        return repr(float(value))  # "nan", "inf", "-inf" for those: the words the program refuses by name
    raise InputError(f"{name}: a number, a string or a path is expected, got {type(value).__name__} {value!r}",
                     _core.EXIT_BAD_INPUT, "")


def _arguments(options):
    """Keyword arguments as command-line arguments, in the order given."""
    args = []
    for name, value in options.items():
        flag = "--" + name.replace("_", "-")
        if value is None or value is False:
            continue
        if value is True:
            args.append(flag)
        elif isinstance(value, dict):
            args += [f"{flag}={_text(name, str(key))}={_value_text(f'{name}[{key!r}]', v)}" for key, v in value.items()]
        elif isinstance(value, (list, tuple)):
            args += [f"{flag}={_value_text(name, v)}" for v in value]
        else:
            # --name=value, one argument: a value starting with '-' (a negative number) stays a value, and no value
            # can be taken for the next option. (True for an option that needs a value gives the bare --name, which
            # the program refuses by name: "--height needs a value".)
            args.append(f"{flag}={_value_text(name, value)}")
    return args


def _message(stderr):
    """The program's error line without its 'vssw: error: ' prefix (the last such line: a command may have warned
    before)."""
    lines = [line for line in stderr.splitlines() if line.startswith("vssw: ")]
    line = lines[-1] if lines else stderr.strip()
    for prefix in _PREFIXES:
        if line.startswith(prefix):
            return line[len(prefix):]
    return line


_HELP = ("--help", "-h")


def _call(args):
    """Runs `vssw ARGS --json` in this process; returns the parsed JSON or raises the exit code's exception. With
    --help (help=True) the help text is returned instead: it is the answer asked for, not an error."""
    if any(a in _HELP for a in args):
        code, out, err = _core.run([str(a) for a in args])
        if code == _core.EXIT_OK:
            return out
        raise _EXCEPTIONS.get(code, Error)(_message(err), code, err)
    code, out, err = _core.run([str(a) for a in args] + ["--json"])
    result = None
    if out.strip():
        try:
            result = _json.loads(out)
        except ValueError:
            pass  # no JSON: the exception below carries the error line
    if code == _core.EXIT_OK:
        if result is None:
            raise Error(f"vssw {args[0]} printed no JSON", code, err)
        return result
    raise _EXCEPTIONS.get(code, Error)(_message(err), code, err, result)


def _reserved(options, names):
    for name in names:
        if name in options:
            raise InputError(f"'{name}' is set by the vssw module itself; it cannot be given", _core.EXIT_BAD_INPUT,
                             "")


def run(command: _Union[str, "_os.PathLike[str]"], *positional: _Union[str, "_os.PathLike[str]"],
        **options: _Any) -> _Any:
    """Any vssw command with --json, e.g. run("check", bounds="bounds/ci.toml") or
    run("study", "merge", "s1", "s2", out="s"). Positional arguments are passed as they are, before the options.
    Returns the parsed JSON; run("--help") and help=True return the help text."""
    _reserved(options, ["json"])
    words = [_text("command", _os.fspath(command))]
    words += [_text(f"positional argument {i + 1}", _os.fspath(p)) for i, p in enumerate(positional)]
    return _call([*words, *_arguments(options)])


def _commands():
    """The program's commands, read from its --help (the lines of its Subcommands section)."""
    _, text, _ = _core.run(["--help"])
    listed = text.split("Subcommands:", 1)[-1].splitlines()
    return [line.split()[0] for line in listed if line.startswith("  ") and line.split()]


def help(command: _Optional[str] = None) -> str:  # noqa: A001 (the module's own help, as `vssw COMMAND --help`)
    """The --help text of a command (every option with its unit and default), or of the program."""
    commands = _commands() if command is not None else []
    if command is not None and command not in commands:
        # `vssw NAME --help` with a name that is no command prints the program's help: refuse it here instead.
        message = f"'{command}' is not a command; the commands are {', '.join(commands)}"
        raise InputError(message, _core.EXIT_BAD_INPUT, "")
    code, out, err = _core.run(([command] if command else []) + ["--help"])
    if code != _core.EXIT_OK:
        raise InputError(_message(err), code, err)
    return out


def wall(**options: _Any) -> _Dict[str, _Any]:
    """`vssw wall`: the closed forms (Eqs. 12, 15, 19, 21, 22, 26; Housner's parapet). Options: height, thickness,
    hinge (required), xi, density, g. Returns the JSON: alpha1, alpha2, R1, R2, threshold_g, restitution, A, P,
    theta_lim, period_half_A, collapse_angle, ..., parapet {alpha, R, threshold_g, restitution, p}."""
    return run("wall", **options)


def free(trace: bool = False, **options: _Any) -> _Dict[str, _Any]:
    """`vssw free`: free vibration released from rest at theta0 (a fraction of alpha1, a parapet's alpha). Options:
    height, thickness, hinge, theta0 (required), model, assumptions ("mechanism", the default, or "paper"),
    kinematics, impact, roller (each overriding one part of the set), xi, density, g, rtol, output_dt, csv, strict (True:
    SimulationError when the model's own assumptions fail along the run, i.e. any warning). Returns the
    JSON: impacts [{t, theta_dot_before, theta_dot_after}], peaks, peak_times, stop_time, falls, warnings, roller,
    ...; with trace=True also "trace", as for history(). engine="mujoco" (any engine of vssw.engines()) runs the
    wall in that engine instead of the analytic model, with its settings dt, iterations, set (a dict {knob: value});
    its trace has the columns t, theta1_over_alpha1, theta_dot_over_ref, theta2_over_alpha1, top_dy, E_over_Vr, ag_g,
    contacts, and the analytic model's options (assumptions, kinematics, impact, roller, rtol, strict) raise
    InputError with it."""
    return _with_trace("free", trace, options)


def _read_trace(path):
    """The CSV the program wrote (a header of column names, then numbers) as {column: 1-D float array}."""
    import numpy as np

    with open(path, encoding="utf-8") as f:
        header = f.readline().strip().split(",")
        data = np.loadtxt(f, delimiter=",", ndmin=2)
    if data.size == 0:
        data = np.empty((0, len(header)))
    return {name: data[:, i].copy() for i, name in enumerate(header)}


def history(trace: bool = False, **options: _Any) -> _Dict[str, _Any]:
    """`vssw history`: the response from rest to a record (record=FILE, with scale= or pga=) or a pulse (pulse=
    "sine"|"cosine"|"ricker"|"harmonic", amplitude=, pulse_period=). Other options as `free` (no theta0), and
    output_dt, t_end, csv (a file to write the time history to). record may also be the samples, (dt, values) or
    (t, values) in s and g as vssw.simulate takes them (written to a temporary two-column file, removed afterwards).
    Returns the JSON; with trace=True also "trace":
    the time history as NumPy arrays keyed by the CSV's columns (t, theta1_over_alpha1, theta_dot_over_ref,
    E_over_Vr, ED_over_Vr, ag_g), read from csv= when given, else from a temporary file. engine= runs an engine
    instead, as for free() (its trace's columns are free()'s with an engine)."""
    return _with_trace("history", trace, options)


def export_scene(engine: str, path: _Union[str, "_os.PathLike[str]"], **options: _Any) -> _Dict[str, _Any]:
    """`vssw scene`: write the scene `engine` runs for a wall to `path` in the engine's own file format (MJCF for
    "mujoco", URDF of the blocks for "dart"; an engine without one raises InputError), without running it. Options: height, thickness, hinge
    (required), model, xi, density, g, friction, theta0 (the release as a fraction of alpha1, default 0), dt,
    iterations, set. The file is written under a temporary name and renamed onto `path`. Returns the JSON: engine,
    version, format, path, model, theta0, dt."""
    _reserved(options, ["out"])
    return run("scene", engine=engine, out=_os.fspath(path), **options)


@_contextlib.contextmanager
def _record_file(options: _Dict[str, _Any]) -> _Iterator[_Dict[str, _Any]]:
    """The options with record=(dt, values) or (t, values) written to a temporary two-column file (times [s] and
    accelerations [g], 17 digits: read back to the same doubles) named in record=; removed when the call ends."""
    record = options.get("record")
    if not isinstance(record, (tuple, list)):
        yield options
        return
    from ._api import _record_samples

    times, values = _record_samples(tuple(record))
    with _tempfile.TemporaryDirectory(prefix="vssw-record-") as folder:
        path = _os.path.join(folder, "record.txt")
        _study_records.write_two_columns(path, times, values)
        yield {**options, "record": path}


def _with_trace(command, trace, options):
    """The command's JSON; with trace, its --csv time history too (from csv= when given, else a temporary file)."""
    with _record_file(options) as given:
        return _with_trace_of(command, trace, given)


def _with_trace_of(command, trace, options):
    if not trace:
        return run(command, **options)
    if options.get("csv"):
        result = run(command, **options)
        result["trace"] = _read_trace(_os.fspath(options["csv"]))
        return result
    with _tempfile.TemporaryDirectory(prefix="vssw-trace-") as folder:
        path = _os.path.join(folder, "trace.csv")
        result = run(command, **{**options, "csv": path})
        result["trace"] = _read_trace(path)
    return result


def compare(**options: _Any) -> _Dict[str, _Any]:
    """`vssw compare`: engine (a name, a list of names or "all"; required) against the analytic model, on the wall
    of height, thickness, hinge (and xi, density, g, model, assumptions, kinematics, impact, roller): threshold, period (theta0),
    restitution; or, with record= or pulse=, the response from rest. Engine options: dt, iterations, set (a dict
    {knob: value} or a list of "knob=value"), run_budget (CPU seconds one engine run may take; each runs in a child
    process, so an engine library that crashes or passes its budget raises SimulationError, never ends Python). Returns the JSON (one engine: {engine, threshold {analytic, engine,
    rel_error, ...}, period, restitution, ...}; several: {comparisons, engine_failures, wall_time_s}). A metric that
    could not be measured raises SimulationError with the JSON as its `result`. record may be (dt, values) or (t,
    values), as for history()."""
    with _record_file(options) as given:
        return run("compare", **given)


def _pandas():
    """pandas when it imports, else None (pandas is optional: study() then returns a list of dicts)."""
    try:
        import pandas  # type: ignore[import]
    except ImportError:
        return None
    return pandas


def _study_value(where, value):
    """A study dict's value as JSON holds it, checked where the file written from it could not say which key was
    wrong: NaN, infinities, a NUL or a lone surrogate in a string, a type JSON has no value for. Fraction and Decimal
    are numbers (the nearest float), as the typed API takes them. InputError naming the key (study['walls']...)."""
    if value is None or isinstance(value, bool):
        return value
    if isinstance(value, str):
        if "\x00" in value:
            raise _bad_value(where, f"a string with a NUL character: {value!r}")
        try:
            value.encode("utf-8")
        except UnicodeEncodeError:
            raise _bad_value(where, f"a string that is not valid Unicode (a lone surrogate): {value!r}") from None
        return value
    if isinstance(value, _numbers.Integral):
        return int(value)
    if isinstance(value, (_numbers.Real, _decimal.Decimal)):
        if not _math.isfinite(value):
            raise _bad_value(where, f"{value!r} is not a finite number")
        return float(value)
    if isinstance(value, dict):
        return {_study_value(f"{where} key", key): _study_value(f"{where}[{key!r}]", item)
                for key, item in value.items()}
    if isinstance(value, (list, tuple)):
        return [_study_value(f"{where}[{i}]", item) for i, item in enumerate(value)]
    raise _bad_value(where, f"a {type(value).__name__} is not a value a study file holds: {value!r}")


def _study_file_of(spec, folder):
    """A study given as a dict, checked (_study_value) and written as study.json into `folder` (its records given as
    samples written beside it: _study_records); its path."""
    spec = _study_value("study", {**_study_records.with_record_files(spec, folder), "name": spec.get("name", "study")})
    path = _os.path.join(folder, _study_records.STUDY_FILE)
    with open(path, "w", encoding="utf-8") as f:
        _json.dump(spec, f, allow_nan=False)
    return path


@_contextlib.contextmanager
def _errors_name_the_dict(path):
    """An InputError about a study given as a dict (written to `path`, a temporary file) names the dict, not the file:
    "study dict: wall.thickness: ..." rather than "study file /tmp/.../study.json: wall.thickness: ..."."""
    try:
        yield
    except InputError as e:
        message = str(e.args[0]) if e.args else str(e)
        renamed = message.replace(f"study file {path}", "study dict").replace(str(path), "the study dict")
        if renamed == message:
            raise
        raise InputError(renamed, e.code, e.stderr, e.result) from None


def study(file: _Union[str, "_os.PathLike[str]", _Dict[str, _Any]], out: _Union[str, "_os.PathLike[str]", None] = None,
          **options: _Any) -> _Any:
    """`vssw study`: `file` is a study file (.toml or .json, README "Studies") or a dict of its keys (a relative
    record `file` in it is read from the current directory; a record there may be its samples, as vssw.study takes
    them). Writes the study folder into `out` (plots and prose
    included); without `out`, into a temporary folder removed afterwards, with no plots. Other options: threads,
    shard ("K/N"), resume, force, strict, no_plots, gnuplot, run_budget. Returns results.csv as a pandas DataFrame (its
    `attrs["summary"]` the command's JSON summary) when pandas imports, else the rows of results.json as a list of
    dicts (the same columns; empty values None)."""
    _reserved(options, ["json"])
    # Two folders: the study file's (with the records given as samples, any name) and the results' when out is None.
    with _tempfile.TemporaryDirectory(prefix="vssw-study-") as scratch, \
            _tempfile.TemporaryDirectory(prefix="vssw-study-out-") as temporary_out:
        from_dict = isinstance(file, dict)
        path = _study_file_of(file, scratch) if isinstance(file, dict) else _os.fspath(file)
        folder = _os.fspath(out) if out is not None else _os.path.join(temporary_out, "out")
        if out is None:
            options.setdefault("no_plots", True)
        with _errors_name_the_dict(path) if from_dict else _contextlib.nullcontext():
            summary = run("study", path, out=folder, **options)
        pandas = _pandas()
        if pandas is not None:
            # round_trip: pandas' default parser can be 1 ulp off the 17 digits written (measured on periods).
            frame = pandas.read_csv(_os.path.join(folder, "results.csv"), float_precision="round_trip")
            frame.attrs["summary"] = summary
            return frame
        with open(_os.path.join(folder, "results.json"), encoding="utf-8") as f:
            return _json.load(f)["rows"]

