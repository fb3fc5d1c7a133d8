#!/bin/sh
# with-private-display.sh COMMAND...: runs COMMAND on a virtual X display (Xvfb) of its own and
# ends the display after it; exits with COMMAND's status.
#
# Every OpenGL, widget and workbench test process runs through this (tests/CMakeLists.txt makes
# it the suites' launcher). CTest runs two tests at once; on one shared display a test's window
# could lose the keyboard focus (and with it its shortcuts) or its pointer to the window of the
# test beside it, and fail now and then for no fault of the code. A display each makes every
# GUI test see only its own windows.
#
# Xvfb picks a free display number itself and writes it to a pipe (-displayfd), so two of these
# started at the same moment never race for one number (xvfb-run -a can). 24-bit colour so
# images compare exactly. The display has no window manager: with-window-manager.sh adds one.
set -eu
command -v Xvfb >/dev/null || {
    echo "with-private-display.sh: Xvfb is missing (packaging/install-deps.sh installs it)" >&2
    exit 1
}
dir=$(mktemp -d "${TMPDIR:-/tmp}/ensil-display.XXXXXX")
server=
cleanup() {
    if [ -n "$server" ]; then
        kill "$server" 2>/dev/null || true
        wait "$server" 2>/dev/null || true
    fi
    rm -rf "$dir"
}
trap cleanup EXIT
trap 'exit 143' TERM
trap 'exit 130' INT
mkfifo "$dir/number"
Xvfb -displayfd 3 -screen 0 1920x1200x24 -nolisten tcp -noreset 3>"$dir/number" \
    >"$dir/log" 2>&1 &
server=$!
number=
read -r number <"$dir/number" || true
if [ -z "$number" ]; then
    echo "with-private-display.sh: Xvfb did not start:" >&2
    cat "$dir/log" >&2
    exit 1
fi
status=0
DISPLAY=":$number" "$@" || status=$?
exit "$status"
