#!/usr/bin/env python3
"""One version from one place: CMake's `project(vssw VERSION ...)` is the source; CITATION.cff's `version:`, the
newest release heading of CHANGELOG.md (`## X.Y.Z — date`, the `## Unreleased` section skipped) and, when given, the
first line of `vssw --version` and the Python module's `vssw.__version__` must say the same.

Exit 0 when they agree (prints `version: X.Y.Z`); otherwise 1 with one line per copy that differs; 2 when a copy
cannot be read. scripts/release.sh runs it with --expect VERSION; the CTest vssw_version_agrees runs it on the tree.
usage: check_version.py SOURCE_DIR [--expect VERSION] [--vssw PROGRAM] [--python-path DIR]
"""
import argparse
import pathlib
import re
import subprocess
import sys

VERSION = r"([0-9]+\.[0-9]+\.[0-9]+)"


def cmake_version(root):
    match = re.search(r"project\(\s*vssw\s+VERSION\s+" + VERSION, (root / "CMakeLists.txt").read_text(encoding="utf-8"))
    return match.group(1) if match else None


def citation_version(root):
    match = re.search(r"^version:\s*['\"]?" + VERSION, (root / "CITATION.cff").read_text(encoding="utf-8"), re.M)
    return match.group(1) if match else None


def changelog_version(root):
    # The first `## ` heading that names a version: "## Unreleased" (what is not released yet) comes before it.
    for line in (root / "CHANGELOG.md").read_text(encoding="utf-8").splitlines():
        match = re.match(r"^## " + VERSION + r"\b", line)
        if match:
            return match.group(1)
    return None


def program_version(program):
    out = subprocess.run([program, "--version"], capture_output=True, text=True, check=False).stdout
    match = re.match(r"vssw " + VERSION + r"\b", out)
    return match.group(1) if match else None


def python_version(path):
    code = "import vssw; print(vssw.__version__)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=False,
                         env={"PYTHONPATH": path, "PATH": "/usr/bin:/bin"}).stdout.strip()
    return out if re.fullmatch(VERSION, out) else None


def main():
    parser = argparse.ArgumentParser(usage=__doc__.splitlines()[-1].removeprefix("usage: "))
    parser.add_argument("source")
    parser.add_argument("--expect")
    parser.add_argument("--vssw")
    parser.add_argument("--python-path")
    args = parser.parse_args()
    root = pathlib.Path(args.source)
    try:
        source = cmake_version(root)
        copies = {"CITATION.cff (version:)": citation_version(root),
                  "CHANGELOG.md (newest release heading)": changelog_version(root)}
    except OSError as e:
        print(f"version: error: {e}", file=sys.stderr)
        return 2
    if source is None:
        print(f"version: error: no `project(vssw VERSION X.Y.Z)` in {root / 'CMakeLists.txt'}", file=sys.stderr)
        return 2
    if args.vssw:
        copies[f"`{args.vssw} --version`"] = program_version(args.vssw)
    if args.python_path:
        copies["vssw.__version__ (Python)"] = python_version(args.python_path)
    problems = [f"{name} says {found or 'no version'}, CMakeLists.txt project() says {source}"
                for name, found in copies.items() if found != source]
    if args.expect and args.expect != source:
        problems.insert(0, f"CMakeLists.txt project() says {source}, not {args.expect}")
    for p in problems:
        print(f"version: {p}")
    if not problems:
        print(f"version: {source}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
