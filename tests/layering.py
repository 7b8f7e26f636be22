#!/usr/bin/env python3
"""The code's layering as a check: each folder includes only the folders below it, and each engine library's headers
stay inside that engine's adapter folder (the starts of their names: the HEADERS lines of its engine.cmake).

    analytic  <-  io
    analytic, io  <-  motions  <-  cli
    analytic  <-  multibody  <-  compare  <-  study (+ io), stress  <-  validation (+ io)  <-  cli  <-  python
    (python also binds analytic, multibody and compare directly)
    (bench and tests may include any folder of the program; so may an engine folder's own multibody/<engine>/tests/;
    tests may also include bench/, whose floor step, a yardstick, is tested there)

Inside multibody/, three rooms around the interface both sides share (engine.hpp, engine_plugin.hpp at its top):
    multibody/host  (registry, loader, isolation, budget: what the program uses to find and run backends)
    multibody/kit   (what an adapter links in: geometry, run monitor, settings, the stepping loop, the energy sum)
    multibody/<engine>  (one adapter each: the top, the kit and its own folder only)
The kit includes no host file and no adapter; the host includes no adapter and, of the kit, only HOST_USES_OF_KIT.

Exit 0 when every `#include "..."` and every engine header include keeps to that; otherwise 1, one line per include
that does not (file:line, what it includes, what the folder may include). A quoted include is resolved as the compiler
does (beside the including file first, then from the source root), so the folder it reaches is the one checked; an
include that climbs with `../` is refused outright (write it from the source root: "study/grid.hpp"). Update LAYERS
together with the layout when the folders change.
usage: layering.py SOURCE_DIR
"""
import os
import pathlib
import re
import sys

# What each folder may include besides itself.
PROGRAM = {"analytic", "io", "multibody", "compare", "study", "stress", "validation", "motions", "cli"}
LAYERS = {
    "analytic": set(),
    "io": {"analytic"},
    "multibody": {"analytic"},
    "compare": {"analytic", "multibody"},
    "study": {"analytic", "io", "multibody", "compare"},
    "stress": {"analytic", "io", "multibody", "compare"},
    "validation": {"analytic", "io", "multibody", "compare", "study", "stress"},
    "motions": {"analytic", "io"},
    "cli": {"analytic", "io", "multibody", "compare", "study", "stress", "validation", "motions"},
    # The typed API binds the library (simulate, compare: multibody/, compare/), the commands through cli.
    "python": {"analytic", "multibody", "compare", "cli"},
    "bench": PROGRAM,
    "tests": PROGRAM | {"tests", "bench"},
}


def engine_headers(root):
    """Each engine folder and the starts of its library's header names, which only that folder may include: the words
    of the "  HEADERS prefix..." lines of its multibody/<engine>/engine.cmake (cmake/engines.cmake)."""
    homes = {}
    for cmake in sorted(root.glob("multibody/*/engine.cmake")):
        lines = cmake.read_text(encoding="utf-8").splitlines()
        # A line's words after HEADERS, up to a comment or the call's closing parenthesis.
        prefixes = [word for line in lines if re.match(r"\s*HEADERS\s", line)
                    for word in re.split(r"[#)]", line)[0].split()[1:]]
        if prefixes:
            homes[cmake.parent.relative_to(root).as_posix()] = tuple(prefixes)
    return homes


ENGINE_TESTS = re.compile(r"multibody/[^/]+/tests/")
# What the host takes from the kit: the analytic backend reads its settings as an adapter does (settings_reader), and
# the isolated engine checks a run's settings and step before it forks the worker (settings_reader, step_resolution).
HOST_USES_OF_KIT = {"multibody/kit/settings_reader.hpp", "multibody/kit/step_resolution.hpp"}
QUOTED = re.compile(r'^\s*#\s*include\s+"([^"]+)"')
ANGLED = re.compile(r"^\s*#\s*include\s+<([^>]+)>")


def included_folder(root, path, name):
    """The top folder of the source tree that `#include "name"` in path reaches: the file beside path when it exists
    there (or when name climbs with ../), else name from the source root, the program's one include directory."""
    beside = pathlib.Path(os.path.normpath(path.parent / name))
    if name.startswith("../") or "/../" in name or beside.is_file():
        try:
            return beside.relative_to(root).parts[0]
        except ValueError:
            return None  # outside the tree: the ../ refusal names it
    return name.split("/")[0] if "/" in name else None


def quoted_problems(root, path, where, name, folder, allowed):
    problems = []
    if "../" in name:
        problems.append(f'{where}: includes "{name}", a path that climbs with ../ (name it from the source root)')
    target = included_folder(root, path, name)
    if target is not None and target != folder and target not in allowed and target in LAYERS:
        may = f"only {', '.join(sorted(allowed))}" if allowed else "no other folder"
        problems.append(f"{where}: includes {target}/, but {folder}/ may include {may}")
    return problems


def room_of(relative):
    """The room of multibody/ a file (source-root relative, posix) is in: "top", "host", "kit" or an adapter's name;
    None outside multibody/."""
    parts = relative.split("/")
    if parts[0] != "multibody":
        return None
    return parts[1] if len(parts) > 2 else "top"


def room_problems(where, relative, target):
    """The includes of one multibody/ room that reach a room they may not (target: the included file, source-root
    relative)."""
    mine, theirs = room_of(relative), room_of(target)
    if mine is None or theirs is None or mine == theirs:
        return []
    allowed = {
        "top": set(),
        "kit": {"top"},
        "host": {"top"},
    }.get(mine, {"top", "kit"})  # an adapter: the interface and the kit
    if theirs in allowed or (mine == "host" and target in HOST_USES_OF_KIT):
        return []
    who = f"multibody/{mine}/" if mine != "top" else "multibody/ (its top)"
    return [f"{where}: includes {target}, but {who} may include only "
            f"{', '.join('multibody/' + r + '/' if r != 'top' else 'the top of multibody/' for r in sorted(allowed))}"
            + (" and, of the kit, " + ", ".join(sorted(HOST_USES_OF_KIT)) if mine == "host" else "")]


def main(source):
    root = pathlib.Path(os.path.abspath(source))
    problems = []
    checked = 0
    homes = engine_headers(root)
    for folder, allowed in LAYERS.items():
        for path in sorted((root / folder).rglob("*")):
            relative = path.relative_to(root).as_posix()
            if path.suffix not in (".cpp", ".hpp", ".h") or not path.is_file() or "layering_fixture" in relative:
                continue  # the fixture is a tree of its own (tests/layering_fixture: two includes out of place)
            # An engine folder's own tests (multibody/<engine>/tests/) are tests: they may include what tests/ may.
            layer = "tests" if ENGINE_TESTS.match(relative) else folder
            for number, line in enumerate(path.read_text(encoding="utf-8", errors="replace").splitlines(), 1):
                quoted = QUOTED.match(line)
                if quoted:
                    checked += 1
                    problems += quoted_problems(root, path, f"{relative}:{number}", quoted.group(1), layer,
                                                LAYERS[layer])
                    if layer == "multibody":
                        problems += room_problems(f"{relative}:{number}", relative, quoted.group(1))
                angled = ANGLED.match(line)
                if angled:
                    for home, prefixes in homes.items():
                        if angled.group(1).startswith(prefixes) and not relative.startswith(home + "/"):
                            checked += 1
                            problems.append(f"{relative}:{number}: includes <{angled.group(1)}>, an engine library's "
                                            f"header, outside {home}/")
    for p in problems:
        print(p)
    print(f"layering: {checked} includes checked, {len(problems)} out of place")
    return 1 if problems else 0


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1]))
