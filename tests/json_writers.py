#!/usr/bin/env python3
"""Every JSON text the program makes goes through io/json.hpp's dump_json, which writes a string that is not UTF-8
with U+FFFD instead of throwing (nlohmann's dump() throws type_error 316: a study ran to its end, then exited 2 on a
file name holding the byte 0xff). Lists each bare `.dump(` in the program's C++ (tests excluded), exit 1 if any.
usage: json_writers.py SOURCE_DIR
"""
import pathlib
import re
import sys

PROGRAM = ["analytic", "io", "multibody", "compare", "study", "stress", "validation", "motions", "cli", "python", "bench"]
HELPER = pathlib.Path("io/json.hpp")  # the one place that calls dump()


def bare_dumps(root):
    for folder in PROGRAM:
        for path in sorted((root / folder).rglob("*")):
            rel = path.relative_to(root)
            if not path.is_file() or path.suffix not in (".cpp", ".hpp") or "tests" in rel.parts or rel == HELPER:
                continue
            for number, line in enumerate(path.read_text(encoding="utf-8", errors="replace").splitlines(), 1):
                if re.search(r"\.dump\s*\(", line.split("//")[0]):
                    yield f"{rel}:{number}: a bare .dump( (use dump_json from io/json.hpp): {line.strip()}"


def main():
    found = list(bare_dumps(pathlib.Path(sys.argv[1])))
    for line in found:
        print(line)
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
