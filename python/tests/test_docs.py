"""docs/guide/python.md's example runs as printed, with matplotlib (a plot saved) or without it (a table printed)."""
import builtins
import contextlib
import io
import re

from conftest import REPO

EXAMPLE_LINES = 20  # the page promises a wall to a plotted comparison in under 20 lines


def example():
    text = (REPO / "docs" / "guide" / "python.md").read_text(encoding="utf-8")
    return re.search(r"```python\n(.*?)```", text, re.S).group(1)


def run(code, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    printed = io.StringIO()
    with contextlib.redirect_stdout(printed):
        exec(compile(code, "docs/guide/python.md", "exec"), {})  # noqa: S102 (the page's own example)
    return printed.getvalue()


def test_the_example_is_short():
    assert len(example().strip().splitlines()) < EXAMPLE_LINES


def test_the_example_runs_without_matplotlib(tmp_path, monkeypatch):
    real_import = builtins.__import__

    def no_matplotlib(name, *args, **kwargs):
        if name == "matplotlib" or name.startswith("matplotlib."):
            raise ImportError("matplotlib hidden by the test")
        return real_import(name, *args, **kwargs)

    monkeypatch.setattr(builtins, "__import__", no_matplotlib)
    printed = run(example(), tmp_path, monkeypatch)
    for metric in ["threshold", "period", "restitution"]:
        assert re.search(rf"^{metric} +ode .* within", printed, re.M), printed
    assert "theta1_dot" in printed  # the table in place of the plot


def test_the_example_plots_with_matplotlib(tmp_path, monkeypatch):
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        import pytest

        pytest.skip("matplotlib is not installed (python3-matplotlib)")
    run(example(), tmp_path, monkeypatch)
    assert (tmp_path / "fig6-ode.png").stat().st_size > 0
