#!/usr/bin/env python3
"""The code's shape as a check: no folder of the program holds more than a quarter of its lines, no function
outside the tests is longer than 120 lines, and no comment cites a tracker issue by number ("issue 12"): a comment
says why itself or names the docs/ section that does (docs/architecture.md, "Rules the checks keep").

Lines are those of the C++ and Python files of the program's folders (tests excluded); functions are found by
Universal Ctags (Debian universal-ctags, installed by scripts/setup.sh test), which gives each function's first and
last line. Comments are those of the C++, Python, shell, CMake and TOML files of the program's folders, tests/,
scripts/, cmake/, bounds/ and studies/. Exit 0 when all three hold; otherwise 1, one line per folder or function over
its limit and per comment citing an issue.
usage: code_shape.py SOURCE_DIR
"""
import pathlib
import re
import shutil
import subprocess
import sys

PROGRAM = ["analytic", "io", "multibody", "compare", "study", "stress", "validation", "motions", "cli", "python", "bench"]
# A folder above a quarter of the code holds more than one thing (study/ held 34 % when it held four things).
MAX_FOLDER_SHARE = 0.25
# A function longer than two screens is several steps that want names (rocking_phase was 204 lines, run_study 165).
MAX_FUNCTION_LINES = 120
SOURCE_SUFFIXES = (".cpp", ".hpp", ".h", ".py")
# Where comments are read for issue numbers: the program and everything around it that carries comments.
COMMENTED = PROGRAM + ["tests", "scripts", "cmake", "bounds", "studies"]
HASH_COMMENTS = (".py", ".sh", ".cmake", ".toml", ".txt")
ISSUE_NUMBER = re.compile(r"\bissues?[ -]#?[0-9]+", re.IGNORECASE)


def program_files(root):
    for folder in PROGRAM:
        for path in sorted((root / folder).rglob("*")):
            parts = path.relative_to(root).parts
            if path.is_file() and path.suffix in SOURCE_SUFFIXES and "tests" not in parts:
                yield folder, path


def long_functions(root, files):
    ctags = shutil.which("ctags-universal") or shutil.which("ctags")
    if ctags is None:
        sys.exit("code_shape: Universal Ctags not found (Debian universal-ctags; scripts/setup.sh test installs it)")
    cpp = [str(p) for _, p in files if p.suffix != ".py"]
    out = subprocess.run([ctags, "-x", "--languages=C++", "--kinds-C++=f", "--fields=+ne",
                          "--_xformat=%{line} %{end} %N %F", *cpp],
                         capture_output=True, text=True, check=True, cwd=root).stdout
    found = []
    for line in out.splitlines():
        first, last, name, file = line.split(" ", 3)
        if last.isdigit():
            length = int(last) - int(first) + 1
            if length > MAX_FUNCTION_LINES:
                found.append((length, name, f"{pathlib.Path(file).relative_to(root)}:{first}"))
    return sorted(found, reverse=True)


def comment_of(path, line):
    """The comment part of a line (after // in C++, after # elsewhere); "" when it has none."""
    marker = "#" if path.suffix in HASH_COMMENTS else "//"
    at = line.find(marker)
    return line[at:] if at >= 0 else ""


def issue_citations(root):
    found = []
    for folder in COMMENTED:
        for path in sorted((root / folder).rglob("*")):
            relative = path.relative_to(root).as_posix()
            if not path.is_file() or "_fixture/" in relative or not (path.suffix in SOURCE_SUFFIXES + HASH_COMMENTS):
                continue  # fixtures are trees of their own (tests/code_shape_fixture cites an issue on purpose)
            for number, line in enumerate(path.read_text(encoding="utf-8", errors="replace").splitlines(), 1):
                match = ISSUE_NUMBER.search(comment_of(path, line))
                if match:
                    found.append(f"{relative}:{number}: a comment cites \"{match.group(0)}\"; name the docs/ section")
    return found


def main(source):
    root = pathlib.Path(source).resolve()
    files = list(program_files(root))
    lines = {}
    for folder, path in files:
        lines[folder] = lines.get(folder, 0) + len(path.read_text(encoding="utf-8", errors="replace").splitlines())
    total = sum(lines.values())
    problems = []
    for folder, n in sorted(lines.items(), key=lambda kv: -kv[1]):
        if n > MAX_FOLDER_SHARE * total:
            problems.append(f"{folder}/ holds {n} of {total} lines ({100 * n / total:.1f} %), more than "
                            f"{100 * MAX_FOLDER_SHARE:.0f} %")
    for length, name, where in long_functions(root, files):
        problems.append(f"{where}: {name} is {length} lines, more than {MAX_FUNCTION_LINES}")
    problems += issue_citations(root)
    for p in problems:
        print(p)
    largest = max(lines, key=lines.get)
    print(f"code_shape: {len(files)} files, {total} lines; largest folder {largest}/ "
          f"{100 * lines[largest] / total:.1f} %; {len(problems)} over a limit")
    return 1 if problems else 0


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1]))
