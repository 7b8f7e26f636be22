"""Ground motions given as arrays (record=(dt, values) or (t, values)), one time grid for every backend (sample_dt),
engine names in any letter case, and the names alpha and alpha1."""
import math
import warnings

import numpy as np
import pytest

import vssw
from conftest import FIG6

# A short pulse-like record: 0.5 s of a 0.4 g sine at 2 Hz sampled every 5 ms, then zeros to 1 s. Its numbers are
# chosen so that the wall rocks (the Fig. 6 wall lifts at 0.1 g, Eq. 12).
RECORD_DT = 0.005
RECORD_VALUES = np.concatenate([0.4 * np.sin(2 * math.pi * 2.0 * RECORD_DT * np.arange(100)), np.zeros(101)])
# The engines compared on one grid: two of this build's, when it has them.
GRID_ENGINES = [e for e in ["ode", "bullet", "box2d", "mujoco"] if e in vssw.engines()][:2]
ARRAYS = ["t", "theta1", "theta1_dot", "theta2", "top_dy", "kinetic", "potential", "contacts", "ground_acceleration"]


def write_two_columns(path, times, values):
    """The same numbers as a record file: repr gives the 17 digits the reader turns back into the same doubles."""
    path.write_text("".join(f"{t!r} {a!r}\n" for t, a in zip(times, values)), encoding="utf-8")
    return path


def same_run(a, b):
    """Two Simulations equal to the bit in every array and measure (the record's name aside)."""
    for name in ARRAYS:
        assert np.array_equal(getattr(a, name), getattr(b, name)), name
    assert (a.peak_rotation, a.peak_time, a.overturned, a.steps) == (b.peak_rotation, b.peak_time, b.overturned,
                                                                     b.steps)


@pytest.mark.parametrize("engine", ["analytic", *GRID_ENGINES[:1]])
def test_a_record_given_as_arrays_runs_as_the_file_of_the_same_numbers(tmp_path, engine):
    times = np.arange(len(RECORD_VALUES)) * RECORD_DT
    from_file = vssw.simulate(engine, **FIG6, record=write_two_columns(tmp_path / "r.txt", times, RECORD_VALUES),
                              t_end=2.0)
    assert from_file.max_abs_theta1 > 0.0, "the record rocks the wall: the comparison below is not of rest"
    same_run(vssw.simulate(engine, **FIG6, record=(RECORD_DT, RECORD_VALUES), t_end=2.0), from_file)
    same_run(vssw.simulate(engine, **FIG6, record=(list(times), list(RECORD_VALUES)), t_end=2.0), from_file)
    assert vssw.simulate(engine, **FIG6, record=(RECORD_DT, RECORD_VALUES), t_end=2.0).ground_motion == "array"


@pytest.mark.skipif(not GRID_ENGINES, reason="no rigid-body engine in this build")
def test_a_response_comparison_takes_a_record_as_arrays(tmp_path):
    times = np.arange(len(RECORD_VALUES)) * RECORD_DT
    from_file = vssw.compare(GRID_ENGINES[:1], **FIG6,
                             record=write_two_columns(tmp_path / "r.txt", times, RECORD_VALUES))
    from_arrays = vssw.compare(GRID_ENGINES[:1], **FIG6, record=(RECORD_DT, RECORD_VALUES))
    assert from_arrays[0].engine.peak == from_file[0].engine.peak
    assert from_arrays[0].reference.peak == from_file[0].reference.peak


def test_the_command_functions_take_a_record_as_arrays(tmp_path):
    times = np.arange(len(RECORD_VALUES)) * RECORD_DT
    from_file = vssw.history(**FIG6, record=str(write_two_columns(tmp_path / "r.txt", times, RECORD_VALUES)))
    from_arrays = vssw.history(**FIG6, record=(RECORD_DT, RECORD_VALUES))
    assert from_file["max_theta_over_alpha1"] > 0.0, "the record rocks the wall"
    assert from_arrays["max_theta_over_alpha1"] == from_file["max_theta_over_alpha1"]
    assert from_arrays["impacts"] == from_file["impacts"]


@pytest.mark.parametrize("record, named", [
    ((0.0, [0.1, 0.2]), "record's dt: must be a positive finite step"),
    ((-0.01, [0.1, 0.2]), "record's dt: must be a positive finite step"),
    ((math.inf, [0.1, 0.2]), "record's dt: must be a positive finite step"),
    ((math.nan, [0.1, 0.2]), "record's dt"),
    ((0.01, [0.1, math.nan, 0.2]), "record's values \\[g\\]: sample 1 is nan"),
    ((0.01, [0.1]), "record's values: 1 sample"),
    ((0.01, [[0.1, 0.2]]), "one-dimensional"),
    ((0.01, ["a", "b"]), "record's values \\[g\\]: numbers are expected"),
    (([0.0, 0.1, 0.1], [0.1, 0.2, 0.3]), "record's t: must increase strictly, but t\\[2\\] = 0.1"),
    (([0.0, 0.1], [0.1, 0.2, 0.3]), "record: 2 times but 3 values"),
    (([-0.1, 0.1], [0.1, 0.2]), "record's t: must start at 0 or later"),
    (([0.0, math.inf], [0.1, 0.2]), "record's t \\[s\\]: sample 1 is inf"),
    ((0.01, [0.1, 0.2], 3), "a tuple of 3 items"),
])
def test_a_bad_record_array_is_refused_naming_it(record, named):
    for call in [lambda: vssw.simulate("analytic", **FIG6, record=record),
                 lambda: vssw.history(**FIG6, record=record)]:
        with pytest.raises(vssw.InputError, match=named) as raised:
            call()
        assert "\n" not in str(raised.value)


def test_a_record_that_is_neither_a_path_nor_samples_is_refused():
    with pytest.raises(vssw.InputError, match=r"record: a file's path, \(dt, values\) or \(t, values\) is expected, "
                                              "got int"):
        vssw.simulate("analytic", **FIG6, record=12)


def test_sample_dt_puts_every_backend_on_one_time_grid():
    if len(GRID_ENGINES) < 2:
        pytest.skip("two rigid-body engines are needed")
    sample_dt, t_end = 0.01, 1.0
    runs = [vssw.simulate(e, **FIG6, theta0=0.5, t_end=t_end, sample_dt=sample_dt, stop_at_rest=False)
            for e in ["analytic", *GRID_ENGINES]]
    grid = np.arange(round(t_end / sample_dt) + 1) * sample_dt  # t_k = k sample_dt, to the bit
    for r in runs:
        assert np.array_equal(r.t, grid), r.engine
        assert all(len(getattr(r, name)) == len(grid) for name in ARRAYS), r.engine
        assert r.settings["sample_dt"] == sample_dt
    # Without it, each backend its own: the analytic model every 1e-4 s, an engine every step.
    own = [vssw.simulate(e, **FIG6, theta0=0.5, t_end=t_end, stop_at_rest=False) for e in ["analytic", GRID_ENGINES[0]]]
    assert len(own[0].t) != len(own[1].t)


def test_a_run_that_ends_between_two_times_of_the_grid_ends_at_the_last_one_before():
    # Released at 0.5 alpha1 the wall comes to rest, and its run ends there (stop_at_rest), between two times of the
    # grid.
    whole = vssw.simulate("analytic", **FIG6, theta0=0.5)
    on_grid = vssw.simulate("analytic", **FIG6, theta0=0.5, sample_dt=0.01)
    assert whole.at_rest_at_end and whole.t[-1] % 0.01 != 0.0, "the run must end off the grid for this test"
    assert np.array_equal(on_grid.t, np.arange(len(on_grid.t)) * 0.01)
    assert on_grid.t[-1] <= whole.t[-1] < on_grid.t[-1] + 0.01
    assert on_grid.peak_rotation == whole.peak_rotation  # the located turning point: not read off the samples


@pytest.mark.skipif("ode" not in vssw.engines(), reason="no ODE in this build")
def test_a_grid_that_is_no_whole_number_of_an_engines_steps_is_refused():
    with pytest.raises(vssw.InputError,
                       match=r"sample_dt 0.0015 s is not a whole number of ode's steps \(dt 0.001 s\)"):
        vssw.simulate("ode", **FIG6, theta0=0.5, sample_dt=0.0015)


def test_dt_is_an_engines_step_and_the_analytic_model_takes_none():
    with pytest.raises(vssw.InputError, match=r"dt 0.001: the analytic model takes no fixed step.*sample_dt"):
        vssw.simulate("analytic", **FIG6, theta0=0.5, dt=1e-3)
    r = vssw.simulate("analytic", **FIG6, theta0=0.5)
    assert r.settings["dt"] is None and r.settings["sample_dt"] == 1e-4  # its output interval, the default's
    assert "sample_dt" in [s["name"] for s in vssw.engine_settings("analytic")]
    assert "dt" not in [s["name"] for s in vssw.engine_settings("analytic")]


def test_engine_names_are_read_in_any_letter_case_and_printed_canonically():
    assert vssw.simulate("ANALYTIC", **FIG6, theta0=0.5).engine == "analytic"
    assert vssw.engine_settings("Analytic") == vssw.engine_settings("analytic")
    with pytest.raises(vssw.InputError, match=r"'analytik' is not one of this build's \(did you mean 'analytic'\?\)"):
        vssw.simulate("analytik", **FIG6, theta0=0.5)
    with pytest.raises(vssw.InputError, match="'analytic' more than once"):
        vssw.compare(["analytic", "Analytic"], **FIG6)
    if "simbody-rigid" in vssw.engines():
        assert vssw.engine_settings("Simbody-Rigid") == vssw.engine_settings("simbody-rigid")
    if "ode" in vssw.engines():
        assert vssw.simulate("ODE", **FIG6, theta0=0.5, t_end=0.1).engine == "ode"


def test_alpha_is_the_walls_slenderness_and_alpha1_the_lower_blocks():
    r = vssw.simulate("analytic", **FIG6, theta0=0.5)
    assert r.alpha == math.atan(FIG6["thickness"] / 2 / (FIG6["height"] / 2))  # a study's alpha (Fig. 10)
    assert r.alpha1 == vssw.wall(**FIG6)["alpha1"]  # the program's alpha1: the lower block's
    assert r.alpha < r.alpha1
    assert r.theta1[0] == 0.5 * r.alpha1  # rotations are in alpha1
    with pytest.warns(FutureWarning, match="theta1_over_alpha1"):
        assert np.array_equal(r.theta1_over_alpha, r.theta1_over_alpha1)
    parapet = vssw.simulate("analytic", model="parapet", height=1.0, thickness=0.12, theta0=0.5)
    assert parapet.alpha == parapet.alpha1  # one block: the wall's slenderness is the block's
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert (r.alpha, r.alpha1, r.theta1_over_alpha1[0]) == (r.alpha, r.alpha1, 0.5)  # the fields warn of nothing
