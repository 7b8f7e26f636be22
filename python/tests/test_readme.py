"""The README's Python example runs as printed and prints the output the README shows."""
import contextlib
import io
import re

from conftest import REPO


def python_section():
    text = (REPO / "README.md").read_text(encoding="utf-8")
    start = text.index("## Python (`import vssw`)")
    return text[start:text.index("\n## ", start + 1)]


def test_the_readme_example_runs_and_prints_what_the_readme_shows():
    section = python_section()
    code = re.search(r"```python\n(.*?)```", section, re.S).group(1)
    shown = re.search(r"```text\n(.*?)```", section, re.S).group(1)
    assert len(code.strip().splitlines()) <= 10, "the README promises a loop in ten lines"
    printed = io.StringIO()
    with contextlib.redirect_stdout(printed):
        exec(compile(code, "README.md", "exec"), {})  # noqa: S102 (the README's own example)
    assert printed.getvalue() == shown


def test_the_readme_import_line_works():
    section = python_section()
    line = re.search(r'-c "(import vssw;.*?)"\n', section).group(1)
    printed = io.StringIO()
    with contextlib.redirect_stdout(printed):
        exec(line, {})  # noqa: S102
    assert float(printed.getvalue()) > 0  # Eq. (12) of the Fig. 6 wall, in g
