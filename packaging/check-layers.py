#!/usr/bin/env python3
"""Checks that every #include between ensil's rooms points down the layer graph.

The rooms and what each may include are the table below (ARCHITECTURE.md draws it). A file in
room R that includes "S/..." where S is not R and not in R's row is named with its line, and
the check fails. CI runs it before any build (packaging/build-and-test.sh), so a wrong arrow
fails in a second. The table is a DAG: the check also fails if a row names a room above it.

Usage: packaging/check-layers.py [REPOSITORY_ROOT]
"""

import pathlib
import re
import sys

# Room -> the rooms it may include, lowest rooms first. Order matters: a room may name only
# rooms listed before it, which keeps the graph free of cycles by construction.
LAYERS = {
    "data": [],
    "geo": ["data"],
    "preprocessing": ["data"],
    "mpi": ["data", "preprocessing"],
    "gl": ["data", "geo"],
    "session": ["data", "geo", "preprocessing", "gl"],
    "engine": ["data", "geo", "preprocessing", "gl", "session"],
    "workbench": ["data", "geo", "preprocessing", "gl", "session", "engine"],
    "widgets": ["data", "geo", "preprocessing", "gl", "session", "engine", "workbench"],
    "cli": ["data", "geo", "preprocessing", "mpi", "gl", "session", "engine"],
    "python": ["data", "geo", "preprocessing", "gl", "session", "engine"],
    "app": ["data", "geo", "preprocessing", "gl", "session", "engine", "workbench", "widgets",
            "cli"],
}

INCLUDE = re.compile(r'^\s*#\s*include\s+"([a-z_]+)/')


def table_problems():
    problems = []
    seen = []
    for room, allowed in LAYERS.items():
        for other in allowed:
            if other not in seen:
                problems.append(f"check-layers.py: {room} may include {other}, which is not "
                                f"below it in the table")
        seen.append(room)
    return problems


def include_problems(root):
    problems = []
    for room, allowed in LAYERS.items():
        folder = root / room
        if not folder.is_dir():
            problems.append(f"check-layers.py: the room {room}/ is missing")
            continue
        for path in sorted(folder.rglob("*")):
            if path.suffix not in (".h", ".cpp") or "build" in path.parts:
                continue
            lines = path.read_text(encoding="utf-8", errors="replace").splitlines()
            for number, line in enumerate(lines, start=1):
                match = INCLUDE.match(line)
                if not match:
                    continue
                target = match.group(1)
                if target == room or target not in LAYERS or target in allowed:
                    continue
                problems.append(f"{path.relative_to(root)}:{number}: {room} may not include "
                                f"{target}/ (it may include: {', '.join(allowed) or 'nothing'})")
    return problems


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else
                        pathlib.Path(__file__).resolve().parent.parent)
    problems = table_problems() + include_problems(root)
    for problem in problems:
        print(problem, file=sys.stderr)
    if problems:
        print(f"check-layers.py: {len(problems)} include(s) against the layer graph "
              f"(ARCHITECTURE.md)", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
