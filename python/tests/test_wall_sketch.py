"""docs/img/wall-sketch.svg is what scripts/draw_wall_sketch.py writes today from the model's geometry and rotations."""
import importlib.util
import os
import pathlib
import subprocess
import sys

import pytest

from conftest import REPO

SCRIPT = REPO / "scripts" / "draw_wall_sketch.py"
COMMITTED = REPO / "docs" / "img" / "wall-sketch.svg"

pytest.importorskip("matplotlib")


def test_the_committed_sketch_is_what_the_script_draws(tmp_path):
    out = tmp_path / "wall-sketch.svg"
    import vssw

    # The script imports the module this test imports (PYTHONPATH may be relative to another folder than REPO).
    env = dict(os.environ, PYTHONPATH=str(pathlib.Path(vssw.__file__).resolve().parents[1]))
    subprocess.run([sys.executable, str(SCRIPT), "--out", str(out)], check=True, cwd=REPO, env=env)
    assert out.read_bytes() == COMMITTED.read_bytes(), "run scripts/draw_wall_sketch.py and commit the SVG"


def test_the_comparison_sees_the_drawn_geometry(tmp_path, monkeypatch):
    # The same script drawing the rocking wall at other rotations writes another file: the committed one would be
    # stale. Only the rotations the model gives change (the title, from RELEASE, stays), so only the drawing differs.
    import vssw

    spec = importlib.util.spec_from_file_location("draw_wall_sketch", SCRIPT)
    script = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(script)
    simulate = vssw.simulate
    monkeypatch.setattr(vssw, "simulate", lambda *args, **kwargs: simulate(*args, **{**kwargs, "theta0": 0.5}))
    out = tmp_path / "other.svg"
    script.draw(out)
    assert out.read_bytes() != COMMITTED.read_bytes()
