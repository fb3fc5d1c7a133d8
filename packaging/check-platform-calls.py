#!/usr/bin/env python3
"""Checks that the product's code calls the operating system only through data/platform.*.

ensil is built for Linux, macOS and Windows. The calls that exist on one of them only (POSIX
headers, /proc, stat's Linux field names, isatty, mmap, sysconf, the Win32 and Mach headers)
and the compilers' operating-system macros belong in data/platform.h and data/platform.cpp,
which has a branch for each system; anywhere else they break the build of another system
(as `st_mtim` and `/proc/meminfo` once did on macOS). Qt's own Q_OS_* macros are allowed: code
that asks Qt which windowing system it has (gl/offscreen_context.cpp) is Qt's portability, not
ours. Tests (tests/) run on Linux CI only and are not checked.

A file that breaks the rule is named with its line and what it uses, and the check fails. CI
runs it before any build (packaging/build-and-test.sh).

Usage: packaging/check-platform-calls.py [REPOSITORY_ROOT]
"""

import pathlib
import re
import subprocess
import sys

ALLOWED = {"data/platform.h", "data/platform.cpp"}

# What is system-specific, each with the reason given when it is found.
RULES = [
    (re.compile(r"#\s*include\s*<(unistd\.h|fcntl\.h|dlfcn\.h|pthread\.h|sys/[^>]+|mach/[^>]+"
                r"|windows\.h|io\.h|psapi\.h|malloc\.h)>"), "a system header"),
    (re.compile(r"/proc/"), "Linux's /proc"),
    (re.compile(r"\bst_[mca]tim(?:espec)?\b"), "a system's own stat field"),
    (re.compile(r"(?<![\w.])(?:::)?(sysconf|isatty|_isatty|mallopt|madvise|mmap|munmap|getuid|"
                r"syscall|setenv|unsetenv|getpriority|setpriority|getrusage|sysctl|sysctlbyname)"
                r"\s*\("), "a system call"),
    (re.compile(r"\b(__linux__|__GLIBC__|_WIN32|_WIN64|__APPLE__|__MACH__|__unix__)\b"),
     "an operating-system macro"),
]


def product_sources(root: pathlib.Path):
    listed = subprocess.run(["git", "-C", str(root), "ls-files", "*.cpp", "*.h", "*.c"],
                            check=True, capture_output=True, text=True).stdout.split()
    return [p for p in listed if not p.startswith("tests/") and p not in ALLOWED]


def main() -> int:
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".").resolve()
    found = []
    for name in product_sources(root):
        text = (root / name).read_text(encoding="utf-8", errors="replace")
        for number, line in enumerate(text.splitlines(), start=1):
            code = line.split("//", 1)[0]  # a comment may name a call
            for pattern, what in RULES:
                match = pattern.search(code)
                if match:
                    found.append(f"  {name}:{number}: {what} ({match.group(0).strip()})")
    if found:
        print("check-platform-calls.py: calls that differ between Linux, macOS and Windows "
              "outside data/platform.*:", file=sys.stderr)
        print("\n".join(found), file=sys.stderr)
        print("move them behind a function of data/platform.h, with a branch per system",
              file=sys.stderr)
        return 1
    print(f"check-platform-calls.py: no system-specific call outside data/platform.* "
          f"({len(product_sources(root))} files)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
