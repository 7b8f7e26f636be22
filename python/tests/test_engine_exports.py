"""vssw.export_scene (`vssw scene`) and vssw.free/history with engine= (`--engine E --csv`): the module passes them
to the program and gives back its JSON, its file and its trajectory; bad input raises the module's InputError."""
import os
import xml.etree.ElementTree as ElementTree

import pytest

import vssw
from conftest import FIG6

needs_mujoco = pytest.mark.skipif("mujoco" not in vssw.engines(), reason="MuJoCo is not compiled in")


@needs_mujoco
def test_export_scene_writes_the_mjcf_mujoco_runs(tmp_path):
    path = tmp_path / "wall.xml"
    result = vssw.export_scene("mujoco", path, theta0=0.5, **FIG6)
    assert result["format"] == "MJCF" and result["engine"] == "mujoco"
    root = ElementTree.parse(path).getroot()  # well-formed XML (the comment before the root is allowed)
    assert root.tag == "mujoco"
    assert {body.get("name") for body in root.iter("body")} == {"lower", "upper"}
    assert root.find("keyframe/key").get("name") == "release"


@needs_mujoco
def test_export_scene_to_a_missing_folder_raises_and_writes_nothing(tmp_path):
    with pytest.raises(vssw.InputError, match="no_such_folder"):
        vssw.export_scene("mujoco", tmp_path / "no_such_folder" / "wall.xml", **FIG6)
    assert os.listdir(tmp_path) == []


def test_an_engine_without_a_scene_format_or_no_engine_raises():
    with pytest.raises(vssw.InputError, match="nosuch"):
        vssw.export_scene("nosuch", "unused.xml", **FIG6)
    with pytest.raises(vssw.InputError, match="analytic"):
        vssw.export_scene("analytic", "unused.xml", **FIG6)


@needs_mujoco
def test_free_with_an_engine_gives_its_trace():
    result = vssw.free(trace=True, engine="mujoco", theta0=0.5, **FIG6)
    assert result["engine"] == "mujoco"
    trace = result["trace"]
    assert list(trace) == ["t", "theta1_over_alpha1", "theta_dot_over_ref", "theta2_over_alpha1", "top_dy", "E_over_Vr",
                           "ag_g", "contacts"]
    assert trace["t"].size == result["samples"]
    assert trace["theta1_over_alpha1"][0] == pytest.approx(0.5)


def test_free_with_a_bad_engine_raises_naming_it():
    with pytest.raises(vssw.InputError, match="nosuch"):
        vssw.free(engine="nosuch", theta0=0.5, **FIG6)
