"""vssw from Python: the rocking of masonry walls (Sorrentino, Masiani & Griffith 2008) and the engines measured
against it, over the library (docs/guide/python.md).

The typed API (keyword arguments with units, results as objects, arrays as NumPy, tables as pandas):

    simulate(engine, height=, thickness=, hinge=, theta0= | record= | pulse=, ...)
        one backend's run: a Simulation with t, theta1, theta1_dot, theta2, top_dy, kinetic, potential arrays
    compare(engine, height=, thickness=, hinge=, theta0=0.5, ...)
        engines against the analytic model: a Comparison with threshold, period, restitution (each a Metric:
        value, reference, rel_error, target, within_target); with record= or pulse= a ResponseComparison (peaks)
    study(file_or_dict, out=None, ...)      a study: StudyResult(results DataFrame, folder, summary)
    report(out=None, suite="default", ...)  the validation report: ReportResult(metrics, failures, rows, folder, ...)
    engines(), engine_settings(engine), data_dir()

The command-line functions (JSON as dicts, vssw.cli): wall, free, history, run, help here as before; the
dict-returning compare and study are vssw.cli.compare and vssw.cli.study.

Errors: InputError (a ValueError) names a bad value; SimulationError (a RuntimeError) a failed run; BoundsError a
bound out in `check`; all derive from Error.
"""

import os as _os


def _locate_installed_files():
    """An installed package (cmake --install) finds its plugins and data from where it lies (_install.py, written at
    install time), unless the environment already names them. In the build tree there is no _install.py: the library
    finds the build's own plugins and the source tree's data."""
    try:
        from . import _install  # type: ignore[attr-defined]
    except ImportError:
        return
    here = _os.path.dirname(_os.path.abspath(__file__))
    plugins = _os.path.normpath(_os.path.join(here, _install.PLUGINS))
    share = _os.path.normpath(_os.path.join(here, _install.SHARE))
    if not _os.environ.get("VSSW_PLUGIN_PATH") and _os.path.isdir(plugins):
        _os.environ["VSSW_PLUGIN_PATH"] = plugins
    if not _os.environ.get("VSSW_DATA_DIR") and _os.path.isdir(_os.path.join(share, "data")):
        _os.environ["VSSW_DATA_DIR"] = _os.path.join(share, "data")
    if not _os.environ.get("VSSW_STUDIES_DIR") and _os.path.isdir(_os.path.join(share, "studies")):
        _os.environ["VSSW_STUDIES_DIR"] = _os.path.join(share, "studies")


def _check_interpreter():
    """The compiled part, _core, loads only into the Python version it was built for, whose tag its file name carries
    (_core.cpython-311-x86_64-linux-gnu.so: CPython 3.11); and the package needs NumPy. Either missing is said here in
    one message, instead of the import system's "partially initialized module ... circular import" or a bare
    "No module named 'numpy'" from deep inside the package."""
    import importlib.machinery
    import re
    import sys

    here = _os.path.dirname(_os.path.abspath(__file__))
    running = f"{sys.version_info.major}.{sys.version_info.minor}"
    build = ("build it for this one with `pip install --no-build-isolation .` from vssw's source tree "
             "(docs/guide/install.md)")
    built = sorted(name for name in _os.listdir(here) if name.startswith("_core.") and name.endswith(".so"))
    loadable = {"_core" + suffix for suffix in importlib.machinery.EXTENSION_SUFFIXES}
    if built and not loadable.intersection(built):
        tag = re.search(r"cpython-(\d)(\d+)", built[0])
        built_for = f"{tag[1]}.{tag[2]}" if tag else "another Python"
        raise ImportError(f"vssw was built for Python {built_for} ({built[0]} in {here}), and this is Python {running} "
                          f"({sys.executable}): run it with Python {built_for}, or {build}")
    try:
        import numpy  # noqa: F401
    except ImportError:
        raise ImportError(f"vssw needs NumPy, which this Python {running} ({sys.executable}) does not have: run it "
                          f"with a Python that has NumPy (Debian's /usr/bin/python3 with python3-numpy), or install "
                          f"NumPy for this one") from None


_locate_installed_files()
_check_interpreter()

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (type checkers take the name as True)

from ._errors import BoundsError, Error, InputError, SimulationError  # noqa: E402

# The rest is imported when first named (vssw.simulate, from vssw import Comparison, ...), not by `import vssw`: the
# typed API's modules (their dataclasses, typing, tempfile, decimal) and the compiled part cost three times what the
# package's own first line does, and a script that only checks vssw.__version__ or catches vssw.InputError needs
# none of it. Each name below: the module that holds it; "" for the module itself (vssw.cli).
_LAZY = {
    **dict.fromkeys(["compare", "data_dir", "engine_settings", "engines", "report", "simulate", "study"], "._api"),
    **dict.fromkeys(["ClosedForms", "Comparison", "Impact", "Metric", "ReportResult", "ResponseComparison",
                     "ResponseRun", "Simulation", "Slip", "SlipAt", "StudyResult"], "._results"),
    **dict.fromkeys(["export_scene", "free", "help", "history", "run", "wall"], ".cli"),
    "cli": "",
    # The project's version (`project()` in CMakeLists.txt, the one place it is set); the commit the module was built
    # from is __commit__ ("" outside a git checkout; "+changes" when the work tree differed from it).
    "__version__": "._core",
    "__commit__": "._core",
}
_CORE_NAMES = {"__version__": "VERSION", "__commit__": "COMMIT"}


def __getattr__(name):
    """A name of _LAZY, imported on first use and kept (PEP 562: called only for names the module does not hold)."""
    if name not in _LAZY:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    import importlib

    module = importlib.import_module(_LAZY[name] or "." + name, __name__)
    value = module if not _LAZY[name] else getattr(module, _CORE_NAMES.get(name, name))
    globals()[name] = value
    return value


def __dir__():
    return sorted(set(globals()) | set(_LAZY))


if TYPE_CHECKING:  # what the names are, to a type checker (which does not run __getattr__)
    from . import _core, cli
    from ._api import compare, data_dir, engine_settings, engines, report, simulate, study
    from ._results import (ClosedForms, Comparison, Impact, Metric, ReportResult, ResponseComparison, ResponseRun,
                           Simulation, Slip, SlipAt, StudyResult)
    from .cli import export_scene, free, help, history, run, wall  # noqa: A004 (help: the program's, as before)

    __version__: str = _core.VERSION
    __commit__: str = _core.COMMIT

# help() is left out of __all__: `from vssw import *` must not hide the built-in help.
__all__ = ["simulate", "compare", "study", "report", "engines", "engine_settings", "data_dir", "wall", "free",
           "export_scene",
           "history", "run", "cli", "Simulation", "Impact", "Comparison", "Metric", "ClosedForms", "ResponseComparison",
           "ResponseRun", "Slip", "SlipAt", "StudyResult",
           "ReportResult", "Error", "InputError", "SimulationError", "BoundsError", "__version__"]
