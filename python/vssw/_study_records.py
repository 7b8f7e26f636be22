"""The records of a study given as a dict: a path made absolute (the dict has no folder of its own), and a record given
by its samples written as a two-column file beside the study file the dict is written to, under its name, so that the
program reads it as it reads any record file and names it by that name in the study's results."""

from __future__ import annotations

import os
import re
from typing import Any, Dict, List, Tuple

from . import _core
from ._errors import InputError

# The name of a record given as samples without one: "array-1", "array-2", ... in the order the dict holds them.
_DEFAULT_NAME = "array-{}"
# A record's name is its file's name beside the study file: a plain file name, never a path (no '/', no leading '.').
_NAME = re.compile(r"[A-Za-z0-9_][A-Za-z0-9_.-]{0,99}")
# The study file the dict is written to, in the same folder: no record may take its name.
STUDY_FILE = "study.json"


def write_two_columns(path: str, times: List[float], values: List[float]) -> None:
    """Times [s] and accelerations as two columns, each number as repr writes it (17 digits: read back to the same
    doubles, so a run on the file is the run on the samples)."""
    with open(path, "w", encoding="utf-8") as f:
        f.writelines(f"{t!r} {a!r}\n" for t, a in zip(times, values))


def _is_path(value: Any) -> bool:
    return isinstance(value, (str, os.PathLike))


class _Records:
    """Writes the records given as samples into `folder`; remembers each name's key so a name is used once."""

    def __init__(self, folder: str) -> None:
        self.folder = folder
        self.written: Dict[str, str] = {}  # name -> the key that gave it
        self.unnamed = 0

    def item(self, value: Any, where: str) -> Any:
        """One record as the study file holds it: a path made absolute, samples written and named; anything else
        unchanged (the program refuses it naming the key)."""
        if _is_path(value):
            return os.path.abspath(value)
        if isinstance(value, dict):
            return self._named(value, where)
        if isinstance(value, tuple):
            self.unnamed += 1
            return self._write(_DEFAULT_NAME.format(self.unnamed), value, where)
        return value

    def _named(self, value: Dict[Any, Any], where: str) -> str:
        unknown = sorted(str(k) for k in value if k not in ("name", "samples"))
        if unknown or "samples" not in value:
            raise InputError(f"{where}: a record given by its samples is {{'name': NAME, 'samples': (dt, values) or "
                             f"(t, values)}}, got the keys {sorted(str(k) for k in value)}", _core.EXIT_BAD_INPUT)
        name = value.get("name")
        if not isinstance(name, str) or not _NAME.fullmatch(name) or name == STUDY_FILE:
            raise InputError(f"{where}['name']: a record's name is a file name of 1 to 100 letters, digits, '_', '-' "
                             f"and '.', not starting with '.' and not {STUDY_FILE!r}; got {name!r}",
                             _core.EXIT_BAD_INPUT)
        samples = value["samples"]
        if not isinstance(samples, (tuple, list)):
            raise InputError(f"{where}['samples']: (dt, values) or (t, values) is expected, got "
                             f"{type(samples).__name__}", _core.EXIT_BAD_INPUT)
        return self._write(name, tuple(samples), f"{where}['samples']")

    def _write(self, name: str, record: Tuple[Any, ...], where: str) -> str:
        from ._api import _record_samples

        if name in self.written:
            raise InputError(f"{where}: the record name {name!r} is taken by {self.written[name]}: give each record "
                             f"its own name", _core.EXIT_BAD_INPUT)
        try:
            times, values = _record_samples(record)
        except InputError as e:
            raise InputError(f"{where}: {e.args[0]}", e.code) from None
        write_two_columns(os.path.join(self.folder, name), times, values)
        self.written[name] = where
        return name  # relative: the program reads it from the study file's folder, and names the record by it

    def excitation(self, excitation: Any, where: str) -> Any:
        """An excitation's `file` (one record, or a list of them: a tuple of paths is such a list), `files` (an
        ensemble's list) and `ensemble` (a folder) as the study file holds them."""
        if not isinstance(excitation, dict):
            return excitation
        out = dict(excitation)
        if "file" in out:
            given = out["file"]
            if isinstance(given, tuple) and given and all(_is_path(f) for f in given):
                given = list(given)
            out["file"] = ([self.item(f, f"{where}['file'][{i}]") for i, f in enumerate(given)]
                           if isinstance(given, list) else self.item(given, f"{where}['file']"))
        if isinstance(out.get("files"), (list, tuple)):
            out["files"] = [self.item(f, f"{where}['files'][{i}]") for i, f in enumerate(out["files"])]
        if _is_path(out.get("ensemble")):
            out["ensemble"] = os.path.abspath(out["ensemble"])
        return out


def with_record_files(spec: Dict[str, Any], folder: str) -> Dict[str, Any]:
    """The study dict with its records as the study file written into `folder` reads them: paths absolute (relative
    ones from the current directory), records given as samples written into `folder` and named (InputError naming the
    key, study['excitation']['file'], for a bad one)."""
    records = _Records(folder)
    spec = dict(spec)
    if "excitation" in spec:
        spec["excitation"] = records.excitation(spec["excitation"], "study['excitation']")
    if isinstance(spec.get("part"), list):
        spec["part"] = [{**p, "excitation": records.excitation(p["excitation"], f"study['part'][{i}]['excitation']")}
                        if isinstance(p, dict) and "excitation" in p else p for i, p in enumerate(spec["part"])]
    return spec
