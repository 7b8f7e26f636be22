#!/usr/bin/env python3
"""Runs every example of the documentation that shows output, and compares what the program prints today.

    doc_examples.py --build BUILD_DIR [--repo REPO] [--python PYTHON] [FILE.md ...]

What runs (docs/contributing/docs.md says how to write one):

- a fenced block marked ```console: each line starting with `$ ` is a shell command (bash; a line ending with `\\`
  continues on the next), the lines up to the next `$ ` line are the output it must print: its standard output,
  then its error stream (each in order; the two are not interleaved, so a page shows the error stream last). In the expected output a line `...` stands for any number of lines (none included), and
  `...` inside a line for any text on that line (timings, paths). The command must exit 0, unless the expected
  output ends with a line `[exit N]`, then it must exit N;
- a block marked ```python, on a page that opts in with the line `<!-- doctest: python -->`: run with PYTHON and
  the build's Python module on PYTHONPATH; if a ```text block follows it directly, that is what it must print;
- a block preceded by a line `<!-- doctest: file NAME -->` is written to NAME first (a study file, a record), for
  the blocks after it on the same page.

Every page runs in a folder of its own, made for it, holding `build` (the build folder), `data`, `studies` and
`bounds` (the repository's, linked), so the examples read as a user types them from the repository's top folder.
Blocks marked ```sh are commands shown, not run (the full suites, MPI, set-up); they show no output.
"""
import argparse
import os
import pathlib
import re
import subprocess
import sys
import tempfile

FENCE = re.compile(r"^```(\w*)")
EXIT = re.compile(r"^\[exit (\d+)\]$")
TIMEOUT_S = 60  # a generous ceiling; the examples are meant to take a few seconds each on 2 cores


def blocks(text):
    """(kind, first line number, lines, file name from a directive or None) for every fenced block."""
    lines = text.split("\n")
    out, i, pending_file = [], 0, None
    while i < len(lines):
        # A plain file name: the file is written into the page's scratch folder, never beside or above it.
        directive = re.match(r"^<!-- doctest: file ([A-Za-z0-9_][A-Za-z0-9_.-]*) -->$", lines[i])
        if directive:
            pending_file = directive.group(1)
            i += 1
            continue
        m = FENCE.match(lines[i])
        if not m:
            if lines[i].strip():
                pending_file = None
            i += 1
            continue
        kind, start = m.group(1), i + 1
        j = start
        while j < len(lines) and not lines[j].startswith("```"):
            j += 1
        out.append((kind, start + 1, lines[start:j], pending_file))
        pending_file = None
        i = j + 1
    return out


def commands(block_lines):
    """[(command, expected output lines)] of a console block."""
    result, cmd, expected = [], None, []
    it = iter(block_lines)
    for line in it:
        if line.startswith("$ "):
            if cmd is not None:
                result.append((cmd, expected))
            cmd, expected = line[2:], []
            while cmd.endswith("\\"):
                cmd = cmd + "\n" + next(it)  # bash reads the backslash and newline as one line
        elif cmd is not None:
            expected.append(line)
    if cmd is not None:
        result.append((cmd, expected))
    return result


def matches(expected, actual):
    """True when the actual lines fit the expected ones, `...` lines and in-line `...` as wildcards."""
    pattern = []
    for line in expected:
        if line.strip() == "...":
            pattern.append(r"(?:[^\n]*\n)*?")
        else:
            pattern.append(".*?".join(re.escape(part) for part in line.rstrip().split("...")) + r"[ \t]*\n")
    actual_text = "".join(a.rstrip() + "\n" for a in actual)
    return re.fullmatch("".join(pattern), actual_text, re.S) is not None


def lines_of(data):
    text = data.decode("utf-8", "replace").rstrip("\n")
    return text.split("\n") if text else []


def prepare(folder, build, repo):
    for name, target in (("build", build), ("data", repo / "data"), ("studies", repo / "studies"),
                         ("bounds", repo / "bounds")):
        os.symlink(target, folder / name)


def run_page(page, build, repo, python):
    text = page.read_text(encoding="utf-8")
    python_opt_in = "<!-- doctest: python -->" in text
    failures, ran = [], 0
    with tempfile.TemporaryDirectory(prefix="vssw-doc-") as tmp:
        folder = pathlib.Path(tmp)
        prepare(folder, build, repo)
        env = dict(os.environ, PYTHONPATH=str(build / "python"), LC_ALL="C.UTF-8", COLUMNS="120")
        all_blocks = blocks(text)
        for index, (kind, line, body, file_name) in enumerate(all_blocks):
            where = "%s:%d" % (page, line)
            if file_name:
                (folder / file_name).write_text("\n".join(body) + "\n", encoding="utf-8")
                continue
            if kind == "console":
                for cmd, expected in commands(body):
                    ran += 1
                    want_exit = 0
                    if expected and EXIT.match(expected[-1].strip()):
                        want_exit = int(EXIT.match(expected[-1].strip()).group(1))
                        expected = expected[:-1]
                    while expected and not expected[-1].strip():
                        expected = expected[:-1]
                    proc = subprocess.run(["bash", "-c", cmd], cwd=folder, env=env, stdout=subprocess.PIPE,
                                          stderr=subprocess.PIPE, timeout=TIMEOUT_S)
                    actual = lines_of(proc.stdout) + lines_of(proc.stderr)
                    if proc.returncode != want_exit or not matches(expected, actual):
                        failures.append("%s: $ %s\n  exit %d (expected %d)\n  expected:\n%s\n  printed:\n%s" % (
                            where, cmd, proc.returncode, want_exit, "\n".join("    " + e for e in expected),
                            "\n".join("    " + a for a in actual)))
            elif kind == "python" and python_opt_in:
                ran += 1
                expected = None
                if index + 1 < len(all_blocks) and all_blocks[index + 1][0] == "text":
                    expected = all_blocks[index + 1][2]
                proc = subprocess.run([python, "-c", "\n".join(body)], cwd=folder, env=env, stdout=subprocess.PIPE,
                                      stderr=subprocess.STDOUT, timeout=TIMEOUT_S)
                actual = proc.stdout.decode("utf-8", "replace").rstrip("\n").split("\n")
                while expected and not expected[-1].strip():
                    expected = expected[:-1]
                if proc.returncode != 0 or (expected is not None and not matches(expected, actual)):
                    failures.append("%s: python block exit %d\n  printed:\n%s" % (
                        where, proc.returncode, "\n".join("    " + a for a in actual)))
    return ran, failures


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", required=True, type=pathlib.Path, help="the build folder (holding vssw)")
    parser.add_argument("--repo", type=pathlib.Path, default=pathlib.Path(__file__).resolve().parents[2])
    parser.add_argument("--python", default="/usr/bin/python3")
    parser.add_argument("pages", nargs="*", type=pathlib.Path)
    args = parser.parse_args()
    build, repo = args.build.resolve(), args.repo.resolve()
    pages = [p.resolve() for p in args.pages] or sorted([repo / "README.md"] + list((repo / "docs").rglob("*.md")))
    total, failures = 0, []
    for page in pages:
        ran, failed = run_page(page.resolve(), build, repo, args.python)
        if ran:
            print("%s: %d example(s), %d failed" % (page.relative_to(repo), ran, len(failed)))
        total += ran
        failures += failed
    for f in failures:
        print("FAILED " + f, file=sys.stderr)
    print("doc examples: %d run, %d failed" % (total, len(failures)))
    if total == 0:
        print("no example found: the documentation should have some", file=sys.stderr)
        return 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
