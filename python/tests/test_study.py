"""vssw.study: the results of a study file as a pandas DataFrame (or a list of dicts without pandas), the same rows
as the program's results.csv for the same file."""
import json

import pandas as pd
import pytest

import vssw
from conftest import RECORD, REPO

# A small grid: 2 thicknesses x 2 hinges x 2 impact laws, closed forms and a free vibration's measured metrics.
FREE_STUDY = {
    "name": "python-module-free",
    "metrics": ["period", "restitution", "peak_rotation"],
    "wall": {"height": 4.0, "thickness": [0.2, 0.4], "hinge": [0.5, 0.7]},
    "assumptions": {"impact": ["eq19", "whole-mechanism"]},
    "excitation": {"kind": "free", "theta0": 0.5},
}
FREE_ROWS = 2 * 2 * 2 * 3  # cases x runs (impact laws) x metrics


def program_results(cli, study_file, out):
    cli.json(["study", study_file, "--out", out, "--threads", "1", "--no-plots"])
    return read_results(out)


def read_results(folder):
    # round_trip: the 17 digits results.csv writes read back to the same doubles (pandas' default may be 1 ulp off).
    return pd.read_csv(folder / "results.csv", float_precision="round_trip")


def test_a_study_file_gives_the_programs_results_csv(cli, tmp_path):
    study_file = tmp_path / "free.json"
    study_file.write_text(json.dumps(FREE_STUDY))
    program = program_results(cli, study_file, tmp_path / "program")
    module = vssw.cli.study(study_file, threads=1)
    assert isinstance(module, pd.DataFrame)
    assert len(module) == FREE_ROWS
    pd.testing.assert_frame_equal(module, program)
    assert (module["status"] == "ok").all()
    assert module.attrs["summary"]["rows"] == FREE_ROWS
    assert set(module["impact"]) == {"eq19", "whole-mechanism"}


def test_a_dict_is_a_study_and_out_keeps_the_folder(cli, tmp_path):
    out = tmp_path / "kept"
    module = vssw.cli.study(FREE_STUDY, out=out, threads=1, no_plots=True)
    assert (out / "results.csv").is_file() and (out / "study.md").is_file()
    study_file = tmp_path / "free.json"  # the same study as a file (it names no record), run by the program
    study_file.write_text(json.dumps(FREE_STUDY))
    pd.testing.assert_frame_equal(module, program_results(cli, study_file, tmp_path / "program"))
    assert module.attrs["summary"]["study"] == FREE_STUDY["name"]


def test_a_dict_reads_a_relative_record_from_the_current_directory(cli, monkeypatch):
    monkeypatch.chdir(RECORD.parent)
    spec = {"metrics": ["peak_rotation", "overturned"], "wall": {"height": 4.0, "thickness": 0.4, "hinge": 0.7},
            "excitation": {"kind": "record", "file": RECORD.name, "scale": [0.45, 0.6]}}
    frame = vssw.cli.study(spec, threads=1)
    assert len(frame) == 2 * 2
    assert (frame["status"] == "ok").all()
    direct = cli.json(["history", "--record", RECORD, "--scale", "0.45", "--height", "4", "--thickness", "0.4",
                       "--hinge", "0.7"])
    peak = frame[(frame["scale"] == 0.45) & (frame["metric"] == "peak_rotation")]["value"].item()
    # The study measures the same run as `vssw history` (README "Tests", studies): the same peak to the digit
    # results.csv prints (17 significant digits: exact). At 0.45 the default model rocks and stands; at 0.6 it
    # overturns, where a study's peak is the mechanism's collapse angle and history's the angle its run stopped at.
    assert peak == direct["max_theta_over_alpha1"]


def test_without_pandas_the_rows_are_a_list_of_dicts(monkeypatch, tmp_path):
    monkeypatch.setattr(vssw.cli, "_pandas", lambda: None)
    rows = vssw.cli.study(FREE_STUDY, out=tmp_path / "s", threads=1, no_plots=True)
    assert isinstance(rows, list) and len(rows) == FREE_ROWS
    frame = read_results(tmp_path / "s")
    assert [r["case_id"] for r in rows] == frame["case_id"].tolist()
    assert [r["value"] for r in rows] == frame["value"].tolist()  # results.json's numbers, exactly


def test_a_bad_study_is_a_value_error_naming_the_key():
    with pytest.raises(ValueError, match="colour"):
        vssw.cli.study({**FREE_STUDY, "colour": "red"})


# The typed vssw.study and vssw.report: the same files, as DataFrames, with the folders they are in.

def test_the_typed_study_gives_the_programs_results_and_its_folder(cli, tmp_path):
    study_file = tmp_path / "free.json"
    study_file.write_text(json.dumps(FREE_STUDY))
    program = program_results(cli, study_file, tmp_path / "program")
    calls = []
    result = vssw.study(study_file, out=tmp_path / "typed", threads=1, plots=False,
                        progress=lambda done, total, what: calls.append((done, total)))
    assert isinstance(result, vssw.StudyResult)
    assert result.folder == tmp_path / "typed" and (result.folder / "results.csv").is_file()
    pd.testing.assert_frame_equal(result.results, program)
    assert result.summary["rows"] == FREE_ROWS
    assert calls and calls[-1][0] == calls[-1][1], "the progress callback saw the last task"


# Without `out` nothing is left behind: the study runs in a temporary folder that is removed once its results are read
# (every call used to leave one in the temporary directory), and the same for a failed study.
def test_the_typed_study_without_out_leaves_no_folder(tmp_path, monkeypatch):
    import tempfile

    monkeypatch.setattr(tempfile, "tempdir", str(tmp_path))
    result = vssw.study(FREE_STUDY, threads=1)
    assert len(result.results) == FREE_ROWS and (result.results["status"] == "ok").all()
    assert result.folder is None
    assert list(tmp_path.iterdir()) == []
    with pytest.raises(vssw.InputError):
        vssw.study({**FREE_STUDY, "metrics": ["no_such_metric"]}, threads=1)
    assert list(tmp_path.iterdir()) == []


def test_the_typed_report_gives_its_csv_files_as_dataframes(tmp_path):
    # One case, the analytic model alone (no engine library): the report's tables without the minutes of a suite.
    result = vssw.report(tmp_path / "report", engines=["analytic"], cases=["fig6-vssw"], threads=1, plots=False)
    assert isinstance(result, vssw.ReportResult)
    assert result.markdown.is_file() and result.html.is_file()
    # metrics.csv's values are the program's results.json rows, read from the other file the report writes.
    from_json = {(r["case_id"], r["engine"], r["metric"]): r["engine_value"] for _, r in result.rows.iterrows()}
    assert len(result.metrics) == len(from_json)
    for _, m in result.metrics.iterrows():
        assert m["engine_value"] == from_json[(m["case_id"], m["engine"], m["metric"])], m["metric"]
    assert set(result.metrics["case_id"]) == {"fig6-vssw"}
    assert {"error", "target", "within_target"} <= set(result.rows.columns)


def test_the_typed_report_gives_its_verdicts_at_a_glance_and_under_records(tmp_path):
    # ODE on one wall and a small record ensemble (tests/cli/earthquake_small.toml: 2 records x 2 PGAs). The
    # earthquake table's agreement is counted here from the ensemble's own rows: the runs on which ODE and the
    # reference (the unperturbed analytic series) agree whether the wall overturns.
    ensemble = REPO / "tests" / "cli" / "earthquake_small.toml"
    result = vssw.report(tmp_path / "report", engines=["ode"], cases=["fig6-pw"], earthquake=str(ensemble),
                         threads=1, plots=False)
    rows = pd.read_csv(tmp_path / "report" / "earthquake" / "results.csv")
    over = rows[(rows["metric"] == "overturned") & (rows["perturbation"] == "none")]
    by_run = over.pivot_table(index=["file", "pga"], columns="engine", values="value", aggfunc="first")
    agree = int((by_run["ode"] == by_run["analytic"]).sum())
    table = result.earthquake
    assert list(table["engine"]) == ["ode"]
    assert table.loc[0, "runs"] == len(by_run) == 4
    assert table.loc[0, "overturning_agreement"] == agree / 4
    assert table.loc[0, "overturning_pass"] == (agree / 4 >= 0.9)
    assert table.loc[0, "overturning_agreement_lo"] <= agree / 4 <= table.loc[0, "overturning_agreement_hi"]
    # The matrix: a cell passes exactly when every row of its engine and metric is within its target.
    for _, cell in result.matrix.iterrows():
        mine = result.rows[(result.rows["engine"] == cell["engine"]) & (result.rows["metric"] == cell["metric"])]
        assert bool(cell["pass"]) == bool(mine["within_target"].all()), (cell["engine"], cell["metric"])
    # No earthquake part: None, not an empty table.
    plain = vssw.report(tmp_path / "plain", engines=["ode"], cases=["fig6-pw"], threads=1, plots=False)
    assert plain.earthquake is None


def test_a_dict_chooses_the_analytic_models_assumption_set():
    # {"assumptions": {"set": ...}} goes through as the study file's key: the set's three parts are the rows' columns,
    # the default set (mechanism, every entry point's) when the dict names none.
    base = {"metrics": ["period"], "wall": {"height": 4.0, "thickness": 0.4, "hinge": 0.7},
            "excitation": {"kind": "free", "theta0": 0.5}}
    columns = ["kinematics", "impact", "roller"]
    paper = vssw.cli.study({**base, "assumptions": {"set": "paper"}}, threads=1)
    assert paper[columns].drop_duplicates().values.tolist() == [["paper", "eq19", "bilateral"]]
    default = vssw.cli.study(base, threads=1)
    assert default[columns].drop_duplicates().values.tolist() == [["exact", "whole-mechanism", "unilateral"]]
    assert paper["value"].iloc[0] != default["value"].iloc[0], "the two sets' periods differ"


# A bad key or value in a study given as a dict is named in the dict, not against the temporary file it was written to
# (the message said "study file /tmp/vssw-study-file-.../study.json: ..."), by the typed and the command's function.
@pytest.mark.parametrize("run", [vssw.study, vssw.cli.study])
def test_a_bad_study_dict_is_named_as_a_dict(run):
    bad = {**FREE_STUDY, "wall": {**FREE_STUDY["wall"], "thickness": -0.4}}
    with pytest.raises(vssw.InputError) as raised:
        run(bad, threads=1)
    message = str(raised.value)
    assert message.startswith("study dict: wall.thickness: ") and "-0.4" in message, message
    assert "study.json" not in message and "/tmp" not in message, message
