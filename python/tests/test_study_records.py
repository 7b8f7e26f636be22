"""Records given by their samples inside a study dict ((dt, values), (t, values), or named): the same results, to the
bit, as the same study naming files of the same numbers; a bad one refused naming its key in the dict."""
import math

import numpy as np
import pytest

import vssw

# Two short records that rock the Fig. 6 wall (it lifts at 0.1 g, Eq. 12): 0.5 s of a 0.4 g and a 0.3 g sine at
# 2 Hz sampled every 5 ms, then zeros to 1 s; the second given by its times.
DT = 0.005
FIRST = np.concatenate([0.4 * np.sin(2 * math.pi * 2.0 * DT * np.arange(100)), np.zeros(101)])
SECOND = np.concatenate([0.3 * np.sin(2 * math.pi * 2.0 * DT * np.arange(100)), np.zeros(101)])
TIMES = np.arange(len(SECOND)) * DT
WALL = {"height": 4.0, "thickness": 0.4, "hinge": 0.7}


def study_of(files, **excitation):
    return {"metrics": ["peak_rotation", "peak_time"], "engines": ["analytic"], "wall": WALL,
            "excitation": {"kind": "record", "file": files, **excitation}}


def write_two_columns(path, times, values):
    """The same numbers as a record file, written here: repr gives the 17 digits read back as the same doubles."""
    path.write_text("".join(f"{t!r} {a!r}\n" for t, a in zip(times, values)), encoding="utf-8")
    return str(path)


def test_records_given_as_samples_give_the_results_of_files_of_the_same_numbers(tmp_path):
    files = [write_two_columns(tmp_path / "first.txt", TIMES, FIRST),
             write_two_columns(tmp_path / "second.txt", TIMES, SECOND)]
    from_files = vssw.study(study_of(files, scale=[1.0, 1.5]), threads=1).results
    arrays = [(DT, FIRST), {"name": "sine-0.3g", "samples": (TIMES, SECOND)}]
    from_arrays = vssw.study(study_of(arrays, scale=[1.0, 1.5]), threads=1).results
    assert (from_files["status"] == "ok").all() and len(from_files) == 2 * 2 * 2
    assert (from_files[from_files["metric"] == "peak_rotation"]["value"] > 0.0).all(), "the records rock the wall"
    assert np.array_equal(from_arrays["value"].to_numpy(), from_files["value"].to_numpy())
    # Each record named by its name (array-1 without one), not by a temporary file's path.
    assert list(dict.fromkeys(from_arrays["file"])) == ["array-1", "sine-0.3g"]
    # One record as (dt, values), through the command function too.
    one = vssw.cli.study(study_of((DT, FIRST)), threads=1)
    assert np.array_equal(one["value"].to_numpy(), vssw.cli.study(study_of(files[0]), threads=1)["value"].to_numpy())


def test_an_ensemble_takes_records_given_as_samples(tmp_path):
    ensemble = {"kind": "ensemble", "intensity": "pga", "levels": [0.3]}
    files = [write_two_columns(tmp_path / "a.txt", TIMES, FIRST), write_two_columns(tmp_path / "b.txt", TIMES, SECOND)]
    spec = {"metrics": ["peak_rotation"], "engines": ["analytic"], "wall": WALL}
    from_files = vssw.study({**spec, "excitation": {**ensemble, "files": files}}, threads=1).results
    from_arrays = vssw.study({**spec, "excitation": {**ensemble, "files": [(DT, FIRST), (TIMES, SECOND)]}},
                             threads=1).results
    assert np.array_equal(from_arrays["value"].to_numpy(), from_files["value"].to_numpy())
    assert list(from_arrays["file"]) == ["array-1", "array-2"]


@pytest.mark.parametrize("files, key, what", [
    ((DT, [0.1, float("nan")]), "study['excitation']['file']", "not a finite number"),
    ([(DT, FIRST), (-DT, FIRST)], "study['excitation']['file'][1]", "positive finite step"),
    ((TIMES[::-1], SECOND), "study['excitation']['file']", "must increase strictly"),
    ({"name": "../up", "samples": (DT, FIRST)}, "study['excitation']['file']['name']", "'../up'"),
    ({"name": "study.json", "samples": (DT, FIRST)}, "study['excitation']['file']['name']", "'study.json'"),
    ({"samples": (DT, FIRST), "dt": DT}, "study['excitation']['file']", "'name'"),
    ([{"name": "r", "samples": (DT, FIRST)}, {"name": "r", "samples": (DT, SECOND)}],
     "study['excitation']['file'][1]['samples']", "taken by study['excitation']['file'][0]['samples']"),
])
def test_a_bad_record_given_as_samples_is_refused_naming_its_key(files, key, what):
    with pytest.raises(vssw.InputError) as e:
        vssw.study(study_of(files))
    assert str(e.value).startswith(key + ": ") and what in str(e.value), str(e.value)
    assert e.value.code == 2


def test_a_bad_record_of_an_ensemble_is_refused_naming_its_key():
    spec = {"wall": WALL, "excitation": {"kind": "ensemble", "intensity": "pga", "levels": [0.3],
                                         "files": [(DT, FIRST), (DT, FIRST[:1])]}}
    with pytest.raises(vssw.InputError, match=r"^study\['excitation'\]\['files'\]\[1\]: .*at least 2"):
        vssw.cli.study(spec)
