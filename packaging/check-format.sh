#!/usr/bin/env bash
# Checks that every C++ file of the repository is laid out as .clang-format says (clang-format
# 14, Debian 12's), and names each one that is not. CI runs it first: a layout slip fails in
# seconds, before any build. Fix with: clang-format-14 -i FILE... (or git clang-format-14 for
# what you changed).
set -euo pipefail
cd "$(dirname "$0")/.."
formatter=clang-format-14
command -v "$formatter" >/dev/null || {
    echo "check-format.sh: $formatter is missing (packaging/install-deps.sh installs it)" >&2
    exit 1
}
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    mapfile -t files < <(git ls-files '*.cpp' '*.h')
else
    mapfile -t files < <(find . -path ./build -prune -o \( -name '*.cpp' -o -name '*.h' \) -print)
fi
# One clang-format for all files (a process per file takes minutes); it names each violation
# "FILE:LINE:COL: error: code should be clang-formatted". Any other complaint (a broken
# .clang-format, a file it cannot read) fails the check too.
report=$(mktemp)
trap 'rm -f "$report"' EXIT
status=0
printf '%s\0' "${files[@]}" | xargs -0 "$formatter" --dry-run --Werror 2>"$report" >/dev/null ||
    status=$?
mapfile -t unformatted < <(
    sed -n 's/^\(.*\):[0-9]*:[0-9]*: error: code should be clang-formatted.*/\1/p' "$report" |
        sort -u)
if [ "$status" -ne 0 ] && [ ${#unformatted[@]} -eq 0 ]; then
    echo "check-format.sh: $formatter failed:" >&2
    head -n 20 "$report" >&2
    exit 1
fi
if [ ${#unformatted[@]} -ne 0 ]; then
    echo "check-format.sh: ${#unformatted[@]} of ${#files[@]} C++ files differ from .clang-format:" >&2
    printf '  %s\n' "${unformatted[@]}" >&2
    echo "fix them with: $formatter -i FILE..." >&2
    exit 1
fi
echo "check-format.sh: all ${#files[@]} C++ files follow .clang-format"
