"""Importing the package with a Python it was not built for, or with one that has no NumPy, fails with one ImportError
that names both Pythons and the way out (docs/guide/install.md, "A Python it was not built for"), not with the import
system's "partially initialized module ... circular import" or a bare "No module named 'numpy'"."""
import os
import pathlib
import shutil
import subprocess
import sys

import vssw

PACKAGE = pathlib.Path(vssw.__file__).parent
RUNNING = f"{sys.version_info.major}.{sys.version_info.minor}"


def import_in_child(site, prelude=""):
    """`import vssw` in a new interpreter that finds the package only in `site`; its exit code and its last line."""
    env = {k: v for k, v in os.environ.items() if not k.startswith("VSSW_")}
    env.update(PYTHONPATH=str(site), PYTHONDONTWRITEBYTECODE="1")
    run = subprocess.run([sys.executable, "-c", prelude + "import vssw"], capture_output=True, text=True, env=env,
                         cwd=site, check=False)
    return run.returncode, (run.stderr.strip().splitlines() or [""])[-1], run.stderr


def test_a_module_built_for_another_python_names_both_versions(tmp_path):
    # The package with its compiled part renamed as a Python 3.99 build names it: to this interpreter it is what a
    # module built for another version is, a file it does not load.
    copy = tmp_path / "vssw"
    shutil.copytree(PACKAGE, copy, ignore=shutil.ignore_patterns("__pycache__"))
    (core,) = copy.glob("_core.*.so")
    tag = f"cpython-{sys.version_info.major}{sys.version_info.minor}"
    assert tag in core.name, core.name
    core.rename(copy / core.name.replace(tag, "cpython-399"))
    code, last, stderr = import_in_child(tmp_path)
    assert code != 0
    assert last.startswith("ImportError: vssw was built for Python 3.99 (_core.cpython-399"), stderr
    assert f"and this is Python {RUNNING} ({sys.executable})" in last
    assert "pip install --no-build-isolation ." in last
    assert "circular import" not in stderr


def test_a_python_without_numpy_is_told_so(tmp_path):
    # None in sys.modules makes `import numpy` fail as in a Python that has none (pyenv's, say).
    code, last, stderr = import_in_child(PACKAGE.parent, prelude="import sys; sys.modules['numpy'] = None\n")
    assert code != 0
    assert last.startswith(f"ImportError: vssw needs NumPy, which this Python {RUNNING} ({sys.executable}) does not"), \
        stderr


def test_the_module_built_for_this_python_imports(tmp_path):
    # The same child as above with nothing changed: the checks pass the build they were made for.
    code, _, stderr = import_in_child(PACKAGE.parent, prelude="")
    assert code == 0, stderr
