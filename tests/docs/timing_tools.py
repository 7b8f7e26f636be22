#!/usr/bin/env python3
"""Speed figures quote tools the project ships: every timing or profiling program named in docs/ or in a comment of
the code, scripts, tests, bounds and studies is a Debian package that scripts/setup.sh installs (in any mode) or a
script in scripts/. A figure measured with anything else cannot be rerun from a checkout.

The programs looked for are those below (a name and the Debian package that ships it; None: no Debian package).
Exit 0 when every one named is shipped; otherwise 1, one line per place (file:line, the program, why).
usage: timing_tools.py SOURCE_DIR
"""
import pathlib
import re
import sys

TOOLS = {  # how a text names the program -> its Debian package
    r"\bhyperfine\b": "hyperfine",
    r"/usr/bin/time\b|\bGNU time\b|\btime -v\b": "time",
    r"\bcallgrind\b|\bcachegrind\b|\bvalgrind\b|\bmassif\b": "valgrind",
    r"\bperf (?:stat|record|report)\b|\(perf[,)]|\bperf's\b|, perf\)": "linux-perf",
    r"\bheaptrack\b": "heaptrack",
    r"\bmultitime\b": None,
}
SCANNED = ["docs", "analytic", "io", "multibody", "compare", "study", "stress", "validation", "motions", "cli",
           "python", "bench", "tests", "scripts", "cmake", "bounds", "studies"]
SUFFIXES = {".md", ".cpp", ".hpp", ".h", ".py", ".sh", ".cmake", ".toml", ".txt"}


def installed_packages(root):
    """Every Debian package named in scripts/setup.sh's package lists (packages=( ... ) and packages+=( ... ))."""
    text = (root / "scripts" / "setup.sh").read_text(encoding="utf-8")
    names = set()
    # A list over several lines ends at a line holding only ")" (comments inside it hold parentheses); one on a
    # line ends at its ")".
    blocks = re.findall(r"packages\+?=\(\n(.*?)\n\)", text, re.S) + re.findall(r"packages\+?=\(([^\n)]+)\)", text)
    for block in blocks:
        for line in block.splitlines():
            names.update(re.findall(r"[a-z0-9][a-z0-9.+-]+", line.split("#")[0]))
    return names


def main(source):
    root = pathlib.Path(source).resolve()
    shipped = installed_packages(root) if (root / "scripts" / "setup.sh").is_file() else set()
    problems = []
    for folder in SCANNED:
        for path in sorted((root / folder).rglob("*")):
            relative = path.relative_to(root).as_posix()
            if not path.is_file() or path.suffix not in SUFFIXES or "timing_fixture" in relative:
                continue  # the fixture is a tree of its own (tests/docs/timing_fixture names unshipped tools)
            if relative == "tests/docs/timing_tools.py":
                continue  # this file names them all
            for number, line in enumerate(path.read_text(encoding="utf-8", errors="replace").splitlines(), 1):
                for pattern, package in TOOLS.items():
                    match = re.search(pattern, line)
                    if match and package not in shipped:
                        why = "no Debian package" if package is None else f"Debian {package}, not in scripts/setup.sh"
                        problems.append(f"{relative}:{number}: names {match.group(0)!r} ({why}); quote hyperfine "
                                        f"or a script in scripts/")
    for p in problems:
        print(p)
    print(f"timing_tools: {len(problems)} places name a timing program the project does not ship")
    return 1 if problems else 0


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1]))
