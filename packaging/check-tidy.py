#!/usr/bin/env python3
"""Runs clang-tidy (14, Debian 12's; the checks are .clang-tidy's, every layer) on every C++ file
that changed since the tree that last landed, and fails on any finding in those files.

Why not the whole tree in CI: clang-tidy parses each translation unit with Qt's and VTK's headers
(about 11 s a file here), so the ~330 files of every layer would take about 20 minutes on two
cores, half of CI's budget. Instead packaging/tidy-checked.txt holds each C++ file's git blob hash
in the tree that last landed (CI had checked every file changed before it): a file whose content
differs, or that is new, is checked and must be free of findings, old ones included; one unchanged
is not parsed again. A header is checked through its own .cpp, or else through a translation unit
that includes it, and only findings in the changed files count (an unchanged header's findings
are its own debt, not the change's).

The hashes were first taken when the check began (the tree of 1a08487, session 27): findings in
files nobody has changed since are the debt of before, and go as their files are changed.

Usage:
  packaging/check-tidy.py BUILD_DIR   check the files changed since the record (CI: build/ci)
  packaging/check-tidy.py --record    record every file's hash: run it on a tree that landed
                                      (CI passed on it), at the start of new work, and commit it
The build directory needs compile_commands.json and the generated headers (a configured and
built tree: CI runs this after the optimised build).
"""

import concurrent.futures
import functools
import json
import os
import pathlib
import re
import shutil
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
RECORD = ROOT / "packaging" / "tidy-checked.txt"
TIDY = "clang-tidy-14"
# "path:line:col: warning: text [check-name]", as clang-tidy prints a finding.
FINDING = re.compile(r"^(?P<path>[^:\s][^:]*):(?P<line>\d+):(?P<col>\d+): "
                     r"(?:warning|error): (?P<text>.*) \[(?P<check>[\w\-.,]+)\]$")


def git(*args: str) -> str:
    return subprocess.run(["git", "-C", str(ROOT), *args], check=True, capture_output=True,
                          text=True).stdout


def current_hashes() -> dict:
    files = git("ls-files", "--cached", "--others", "--exclude-standard", "*.cpp", "*.h").split()
    files = [f for f in files if (ROOT / f).is_file()]
    hashes = git("hash-object", "--", *files).split() if files else []
    return dict(zip(files, hashes))


def recorded_hashes() -> dict:
    recorded = {}
    if RECORD.exists():
        for line in RECORD.read_text(encoding="utf-8").splitlines():
            if line and not line.startswith("#"):
                blob, path = line.split(maxsplit=1)
                recorded[path] = blob
    return recorded


def write_record(hashes: dict) -> None:
    lines = ["# Each C++ file's git blob hash in the tree that last landed (packaging/check-tidy.py",
             "# --record writes this; CI runs clang-tidy on the files that differ from it)."]
    lines += [f"{blob} {path}" for path, blob in sorted(hashes.items())]
    RECORD.write_text("\n".join(lines) + "\n", encoding="utf-8")


def translation_units(build: pathlib.Path) -> dict:
    """Each source file (relative to the repository) and the file clang-tidy parses for it: itself,
    or the unity file that includes it (the test suites are unity builds, tests/CMakeLists.txt)."""
    units = {}
    unity_include = re.compile(r'^#include "(?P<path>[^"]+)"$', re.MULTILINE)
    for entry in json.loads((build / "compile_commands.json").read_text(encoding="utf-8")):
        parsed = pathlib.Path(entry["directory"], entry["file"]).resolve()
        sources = [parsed]
        if "unity_" in parsed.name:
            text = parsed.read_text(encoding="utf-8", errors="replace")
            sources = [pathlib.Path(m["path"]).resolve() for m in unity_include.finditer(text)]
        for source in sources:
            try:
                units[source.relative_to(ROOT).as_posix()] = parsed
            except ValueError:
                pass  # generated (moc, resources) in the build tree
    return units


@functools.lru_cache(maxsize=None)
def text_of(path: pathlib.Path) -> str:
    """A file's text, read once however many headers are looked up in it."""
    return path.read_text(encoding="utf-8", errors="replace")


def unit_for(path: str, units: dict, seen: set | None = None) -> pathlib.Path | None:
    """The file clang-tidy parses to check `path` (`seen`: headers already followed)."""
    seen = set() if seen is None else seen
    seen.add(path)
    if path in units:
        return units[path]
    if path.endswith(".h"):
        own = path[:-2] + ".cpp"
        if own in units:
            return units[own]
        # A source that includes it, or else one that includes a header that does (a header
        # of settings included only through another header, say).
        include = f'#include "{path}"'
        for source in sorted(units):
            if include in text_of(ROOT / source):
                return units[source]
        for header in sorted(ROOT.glob("*/*.h")):
            if include in text_of(header):
                relative = header.relative_to(ROOT).as_posix()
                if relative not in seen and (unit := unit_for(relative, units, seen)) is not None:
                    return unit
    return None


def tidy(unit: pathlib.Path, build: pathlib.Path) -> str:
    run = subprocess.run([TIDY, "--quiet", "-p", str(build), str(unit)],
                         capture_output=True, text=True, cwd=ROOT)
    return run.stdout + run.stderr


def main() -> int:
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    if sys.argv[1:] == ["--record"]:
        hashes = current_hashes()
        write_record(hashes)
        print(f"check-tidy.py: recorded {len(hashes)} files' hashes in {RECORD.relative_to(ROOT)}")
        return 0
    if len(args) != 1 or len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    build = pathlib.Path(args[0]).resolve()
    if not (build / "compile_commands.json").exists():
        print(f"check-tidy.py: {build}/compile_commands.json is missing: configure first",
              file=sys.stderr)
        return 2
    if shutil.which(TIDY) is None:
        print(f"check-tidy.py: {TIDY} is missing (packaging/install-deps.sh installs it)",
              file=sys.stderr)
        return 2

    hashes = current_hashes()
    recorded = recorded_hashes()
    changed = sorted(p for p, blob in hashes.items() if recorded.get(p) != blob)
    units = translation_units(build)
    by_unit: dict = {}
    unchecked = []
    for path in changed:
        unit = unit_for(path, units)
        if unit is None:
            unchecked.append(path)  # built by no target here (another system's branch)
        else:
            by_unit.setdefault(unit, []).append(path)
    print(f"check-tidy.py: {len(changed)} of {len(hashes)} C++ files changed since their last "
          f"check; {len(by_unit)} translation units to parse", flush=True)

    findings = []
    jobs = max(1, os.cpu_count() or 1)
    with concurrent.futures.ThreadPoolExecutor(jobs) as pool:
        outputs = dict(zip(by_unit, pool.map(lambda u: tidy(u, build), by_unit)))
    changed_set = set(changed)
    for unit, output in outputs.items():
        for line in output.splitlines():
            match = FINDING.match(line)
            if not match:
                continue
            path = pathlib.Path(match["path"])
            path = (path if path.is_absolute() else ROOT / path).resolve()
            try:
                relative = path.relative_to(ROOT).as_posix()
            except ValueError:
                continue  # a system or library header
            if relative in changed_set:
                findings.append(f"  {relative}:{match['line']}:{match['col']}: {match['text']} "
                                f"[{match['check']}]")
    findings = sorted(set(findings))
    if unchecked:
        print("check-tidy.py: not built here, so not checked: " + ", ".join(unchecked))
    if findings:
        print(f"check-tidy.py: {len(findings)} findings in the changed files:", file=sys.stderr)
        print("\n".join(findings), file=sys.stderr)
        print("fix them (or, for a false finding, add NOLINT(check-name) with the reason)",
              file=sys.stderr)
        return 1
    print("check-tidy.py: no finding in the changed files")
    return 0


if __name__ == "__main__":
    sys.exit(main())
