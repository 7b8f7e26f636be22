#!/usr/bin/env python3
"""Namespaces are folders, as a check: every namespace a file of a program folder opens is vssw::<its folder> (or one
inside it, vssw::multibody::simbody_wall), the analytic core's is vssw itself, and no header re-exports another
namespace's name (`using other::Name;` at namespace scope), so that a qualified name tells the reader which folder
holds it (docs/architecture.md, "Rules the checks keep").

Exit 0 when that holds; otherwise 1, one line per namespace or re-export out of place.
usage: namespaces.py SOURCE_DIR
"""
import pathlib
import re
import sys

# Folder -> the namespace its files open. tests/, bench/ and python/ are not the program's library and open their own.
NAMESPACE = {"analytic": "vssw", "io": "vssw::io", "multibody": "vssw::multibody", "compare": "vssw::compare",
             "study": "vssw::study", "stress": "vssw::stress", "validation": "vssw::validation",
             "motions": "vssw::motions", "cli": "vssw::cli"}
# A namespace opened for a block of code (a one-line forward declaration of another folder's name is not one).
OPENS = re.compile(r"^namespace (vssw(?:::\w+)*) \{\s*$")
REEXPORT = re.compile(r"^using (?:vssw::)?\w+(?:::\w+)*::\w+;")


def belongs(opened, folder):
    own = NAMESPACE[folder]
    if folder == "analytic":  # the core: vssw, or a detail namespace inside it that no other folder owns
        return opened == "vssw" or opened.split("::")[1] not in {n.split("::")[1] for n in NAMESPACE.values() if "::" in n}
    return opened == own or opened.startswith(own + "::")


def main(source):
    root = pathlib.Path(source)
    problems = []
    for folder in NAMESPACE:
        for path in sorted((root / folder).rglob("*")):
            if path.suffix not in (".cpp", ".hpp", ".h") or not path.is_file():
                continue
            relative = path.relative_to(root).as_posix()
            if "/tests/" in relative:
                continue  # an engine folder's own tests (multibody/<engine>/tests/) are tests
            for number, line in enumerate(path.read_text(encoding="utf-8", errors="replace").splitlines(), 1):
                opened = OPENS.match(line)
                if opened and not belongs(opened.group(1), folder):
                    problems.append(f"{relative}:{number}: opens {opened.group(1)}, but {folder}/ is "
                                    f"{NAMESPACE[folder]}")
                if path.suffix != ".cpp" and REEXPORT.match(line):
                    problems.append(f"{relative}:{number}: re-exports with '{line.strip()}': name the owner where "
                                    f"the name is used")
    for p in problems:
        print(p)
    print(f"namespaces: {len(problems)} out of place")
    return 1 if problems else 0


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1]))
