#!/usr/bin/env bash
# README command 1: install dependencies, build a Release, and open the workbench.
# Arguments are passed to ensil (none: the built-in demo ensemble).
set -euo pipefail
cd "$(dirname "$0")/.."

packaging/install-deps.sh
cmake --preset release
cmake --build --preset release

if [ -z "${DISPLAY:-}" ] && [ -z "${WAYLAND_DISPLAY:-}" ]; then
    echo "No display found. ensil is built at build/release/app/ensil; to try it on a virtual" >&2
    echo "display run: xvfb-run -a -s '-screen 0 1600x1000x24' build/release/app/ensil" >&2
    exit 1
fi
exec build/release/app/ensil "$@"
