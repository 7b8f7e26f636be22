"""docs/notebooks/first-steps.ipynb runs from top to bottom today and prints what its committed outputs say, and the
site's page (docs/tutorials/first-steps.md, scripts/notebook_page.py) is what that notebook gives."""
import json
import os
import pathlib
import subprocess
import sys

import pytest

from conftest import REPO

NOTEBOOK = REPO / "docs" / "notebooks" / "first-steps.ipynb"
PAGE = REPO / "docs" / "tutorials" / "first-steps.md"
CELL_TIMEOUT_S = 120  # a ceiling per cell against a hung kernel; the whole notebook takes a few seconds


def printed(notebook):
    """Each code cell's printed text (its stream outputs joined: the kernel may send one print in several messages,
    as its buffer is flushed), the figures left out: what the numbers are."""
    return ["".join("".join(o["text"]) for o in cell.get("outputs", []) if o["output_type"] == "stream")
            for cell in notebook["cells"] if cell["cell_type"] == "code"]


def test_the_notebook_runs_and_prints_its_committed_outputs(monkeypatch):
    nbclient = pytest.importorskip("nbclient")
    nbformat = pytest.importorskip("nbformat")
    monkeypatch.delenv("MPLBACKEND", raising=False)  # the kernel's inline backend, which shows the figures
    import vssw

    # The kernel imports the module this test imports (PYTHONPATH may be relative to another folder than the kernel's).
    monkeypatch.setenv("PYTHONPATH", str(pathlib.Path(vssw.__file__).resolve().parents[1]))
    monkeypatch.setenv("PYDEVD_DISABLE_FILE_VALIDATION", "1")  # the kernel's debugger: no warning per start
    monkeypatch.chdir(REPO)
    notebook = nbformat.read(NOTEBOOK, as_version=4)
    committed = printed(json.loads(NOTEBOOK.read_text(encoding="utf-8")))
    nbclient.NotebookClient(notebook, timeout=CELL_TIMEOUT_S, kernel_name="python3",
                            resources={"metadata": {"path": str(REPO)}}).execute()
    assert printed(notebook) == committed
    # Every cell that draws shows its figure.
    figures = [o for cell in notebook.cells if cell.cell_type == "code" for o in cell.outputs
               if "image/png" in o.get("data", {})]
    assert len(figures) == 2


def page_check(notebook, page, *label):
    return subprocess.run([sys.executable, str(REPO / "scripts" / "notebook_page.py"), "--check",
                           "--notebook", str(notebook), "--page", str(page), *label],
                          capture_output=True, text=True, cwd=REPO, check=False, env=dict(os.environ))


def test_the_page_is_what_the_notebook_gives(tmp_path):
    done = page_check(NOTEBOOK.relative_to(REPO), PAGE.relative_to(REPO))
    assert done.returncode == 0, done.stderr
    # Read from elsewhere under its name in the repository, the same notebook gives the same page ...
    label = ("--label", NOTEBOOK.relative_to(REPO).as_posix())
    copy = tmp_path / "first-steps.ipynb"
    copy.write_bytes(NOTEBOOK.read_bytes())
    done = page_check(copy, PAGE.relative_to(REPO), *label)
    assert done.returncode == 0, done.stderr
    # ... and the check fails a page the notebook no longer gives: one of its printed numbers changed.
    notebook = json.loads(NOTEBOOK.read_text(encoding="utf-8"))
    stream = next(o for cell in notebook["cells"] for o in cell.get("outputs", []) if o["output_type"] == "stream")
    stream["text"] = ["changed\n"]
    copy.write_text(json.dumps(notebook), encoding="utf-8")
    done = page_check(copy, PAGE.relative_to(REPO), *label)
    assert done.returncode == 1 and "first-steps.md is not what" in done.stderr
