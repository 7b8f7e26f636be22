"""The module's results are the program's JSON: each function against `build/vssw COMMAND ... --json` on the same
inputs, written here twice (keyword arguments for the module, command-line flags for the program), so that the
translation of keywords into options is checked as well."""
import os

import numpy as np
import pytest

import vssw
from conftest import FIG6, FIG6_FLAGS, RECORD, REPO, without_timing


@pytest.mark.parametrize(
    "kwargs, flags",
    [
        (FIG6, FIG6_FLAGS),
        (dict(height=4.88, thickness=0.194, hinge=0.67, xi=0.1), ["--height", "4.88", "--thickness", "0.194",
                                                                   "--hinge", "0.67", "--xi", "0.1"]),
        (dict(height=3.05, thickness=0.143, hinge=0.46, density=2000, g=9.80665),  # hinge below mid-height
         ["--height", "3.05", "--thickness", "0.143", "--hinge", "0.46", "--density", "2000", "--g", "9.80665"]),
    ],
)
def test_wall_is_the_programs_json(cli, kwargs, flags):
    assert vssw.wall(**kwargs) == cli.json(["wall", *flags])


def test_free_is_the_programs_json(cli):
    module = vssw.free(**FIG6, theta0=0.9, kinematics="exact")
    assert module == cli.json(["free", *FIG6_FLAGS, "--theta0", "0.9", "--kinematics", "exact"])
    assert module["impacts"], "a free vibration from 0.9 alpha1 has impacts"


def test_free_of_a_parapet_is_the_programs_json(cli):
    module = vssw.free(model="parapet", height=0.9, thickness=0.11, theta0=0.7, impact="whole-mechanism")
    assert module == cli.json(["free", "--model", "parapet", "--height", "0.9", "--thickness", "0.11",
                               "--theta0", "0.7", "--impact", "whole-mechanism"])


def test_history_of_a_pulse_is_the_programs_json(cli):
    module = vssw.history(**FIG6, pulse="ricker", amplitude=0.4, pulse_period=0.5, kinematics="exact")
    assert module == cli.json(["history", *FIG6_FLAGS, "--pulse", "ricker", "--amplitude", "0.4",
                               "--pulse-period", "0.5", "--kinematics", "exact"])


def test_history_of_a_record_is_the_programs_json(cli):
    kwargs = dict(record=RECORD, pga=0.3, height=3.05, thickness=0.143, hinge=0.6, xi=0.1)
    flags = ["--record", RECORD, "--pga", "0.3", "--height", "3.05", "--thickness", "0.143", "--hinge", "0.6",
             "--xi", "0.1"]
    assert vssw.history(**kwargs) == cli.json(["history", *flags])


def test_a_relative_record_path_is_read_from_the_current_directory(cli, monkeypatch):
    # As the program reads it: from the folder it runs in (here the repository's top folder).
    monkeypatch.chdir(REPO)
    relative = os.path.relpath(RECORD, REPO)
    module = vssw.history(record=relative, scale=0.45, **FIG6)
    assert module == cli.json(["history", "--record", relative, "--scale", "0.45", *FIG6_FLAGS], cwd=REPO)


def test_compare_is_the_programs_json(cli):
    # The analytic backend against the analytic model: deterministic and quick (no engine library needed).
    kwargs = dict(engine="analytic", **FIG6, theta0=0.5)
    flags = ["--engine", "analytic", *FIG6_FLAGS, "--theta0", "0.5"]
    assert without_timing(vssw.cli.compare(**kwargs)) == without_timing(cli.json(["compare", *flags]))


def test_compare_takes_a_list_of_engines_and_a_dict_of_settings(cli):
    module = vssw.cli.compare(engine=["analytic"], **FIG6, set={"restitution": 0.5})
    program = cli.json(["compare", "--engine", "analytic", *FIG6_FLAGS, "--set", "restitution=0.5"])
    assert without_timing(module) == without_timing(program)  # the settings' knobs included


def test_the_trace_is_the_programs_csv(cli, tmp_path):
    csv = tmp_path / "program.csv"
    cli.json(["history", *FIG6_FLAGS, "--pulse", "sine", "--amplitude", "0.5", "--pulse-period", "0.4",
              "--csv", csv])
    header = csv.read_text().splitlines()[0].split(",")
    table = np.loadtxt(csv, delimiter=",", skiprows=1, ndmin=2)
    trace = vssw.history(**FIG6, pulse="sine", amplitude=0.5, pulse_period=0.4, trace=True)["trace"]
    assert list(trace) == header
    for i, name in enumerate(header):
        np.testing.assert_array_equal(trace[name], table[:, i], err_msg=name)


def test_the_free_vibration_trace_is_the_programs_csv(cli, tmp_path):
    csv = tmp_path / "program.csv"
    cli.json(["free", *FIG6_FLAGS, "--theta0", "0.6", "--output-dt", "0.005", "--csv", csv])
    header = csv.read_text().splitlines()[0].split(",")
    table = np.loadtxt(csv, delimiter=",", skiprows=1, ndmin=2)
    trace = vssw.free(**FIG6, theta0=0.6, output_dt=0.005, trace=True)["trace"]
    assert list(trace) == header
    assert len(trace["t"]) > 100, "a free vibration to rest, sampled every 5 ms"
    for i, name in enumerate(header):
        np.testing.assert_array_equal(trace[name], table[:, i], err_msg=name)


def test_keywords_become_the_programs_options():
    args = vssw.cli._arguments(dict(pulse_period=0.5, thickness=-0.2, json_like=None, force=True, resume=False,
                                engine=["ode", "bullet"], set={"dt": 1e-4, "slide_limit": 0.1}, theta0=np.float64(0.4),
                                threads=np.int64(2), record=REPO / "data" / "x.AT2"))
    assert args == ["--pulse-period=0.5", "--thickness=-0.2", "--force", "--engine=ode", "--engine=bullet",
                    "--set=dt=0.0001", "--set=slide_limit=0.1", "--theta0=0.4", "--threads=2",
                    f"--record={REPO / 'data' / 'x.AT2'}"]
