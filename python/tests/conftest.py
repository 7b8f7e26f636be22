"""Shared by the Python module's tests: the built `vssw` program, run as a separate process, as the reference the
module's results are checked against (the same command, the same inputs, its own JSON)."""
import json
import os
import pathlib
import subprocess

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]
# CTest gives the program's path (python/CMakeLists.txt); by hand, the build folder the README uses.
VSSW = pathlib.Path(os.environ.get("VSSW_EXECUTABLE", REPO / "build" / "vssw"))
RECORD = REPO / "data" / "NGA_no_1063_RRS228.AT2"  # Rinaldi, Northridge 1994 (data/SOURCES.md)
# The Fig. 6 wall of the paper (README "Quick start"): keyword arguments for the module, flags for the program.
FIG6 = dict(height=4.0, thickness=0.4, hinge=0.7)
FIG6_FLAGS = ["--height", "4", "--thickness", "0.4", "--hinge", "0.7"]

# Keys whose values are measured, not computed: a run's own wall-clock time.
TIMING_KEYS = {"wall_time_s"}


def without_timing(value):
    """A JSON value with its timing keys removed, at any depth."""
    if isinstance(value, dict):
        return {k: without_timing(v) for k, v in value.items() if k not in TIMING_KEYS}
    if isinstance(value, list):
        return [without_timing(v) for v in value]
    return value


class Cli:
    """The program as a subprocess: run(args) -> (exit code, parsed JSON or None, stderr)."""

    def run(self, args, json_output=True, cwd=None):
        command = [str(VSSW), *map(str, args)] + (["--json"] if json_output else [])
        done = subprocess.run(command, capture_output=True, text=True, cwd=cwd or REPO, check=False)
        result = json.loads(done.stdout) if json_output and done.stdout.strip() else None
        return done.returncode, result, done.stderr

    def json(self, args, cwd=None):
        code, result, stderr = self.run(args, cwd=cwd)
        assert code == 0, stderr
        return result

    def error_line(self, args):
        """The exit code and the program's one error line (the last line of its stderr)."""
        code, _, stderr = self.run(args)
        return code, stderr.strip().splitlines()[-1]


@pytest.fixture(scope="session")
def cli():
    assert VSSW.is_file(), f"the vssw program is not built at {VSSW} (cmake --build build)"
    return Cli()
