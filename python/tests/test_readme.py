"""The Python page's example (docs/guide/python.md, moved from the README) runs as printed and prints the output the
page shows."""
import contextlib
import io
import re

import pytest

from conftest import REPO

# The printed threshold against the closed form: rounding of a few operations, and print()'s 17 significant digits.
PRINTED_CLOSED_FORM_RTOL = 1e-12


def python_section():
    return (REPO / "docs" / "guide" / "python.md").read_text(encoding="utf-8")


def test_the_readme_example_runs_and_prints_what_the_readme_shows():
    section = python_section()
    code = re.search(r"```python\n(.*?)```", section, re.S).group(1)
    shown = re.search(r"```text\n(.*?)```", section, re.S).group(1)
    assert len(code.strip().splitlines()) <= 10, "the README promises a loop in ten lines"
    printed = io.StringIO()
    with contextlib.redirect_stdout(printed):
        exec(compile(code, "docs/guide/python.md", "exec"), {})  # noqa: S102 (the README's own example)
    assert printed.getvalue() == shown


def test_the_readme_import_line_works():
    section = python_section()
    line = re.search(r'-c "(import vssw;.*?)"\n', section).group(1)
    printed = io.StringIO()
    with contextlib.redirect_stdout(printed):
        exec(line, {})  # noqa: S102
    # Eq. (13) for the Fig. 6 wall (homogeneous blocks, no overburden): 2 tan(alpha1) g, tan(alpha1) = b / h1 with
    # b = 0.4 / 2 m and h1 = 0.7 x 4 / 2 m, the half-thickness and the hinge's half-height.
    assert float(printed.getvalue()) == pytest.approx(2 * (0.4 / 2) / (0.7 * 4 / 2), rel=PRINTED_CLOSED_FORM_RTOL)
