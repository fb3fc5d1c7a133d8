#!/usr/bin/env bash
# Starts the ensil workbench on the current X display, waits for its main window and checks that
# the window carries an icon (_NET_WM_ICON), which Qt sets only when it could render the SVG
# embedded in ensil, that is when its SVG plugin (libqt6svg6) is installed. Run under xvfb-run:
#   xvfb-run -a packaging/window-icon-check.sh /usr/bin/ensil
set -euo pipefail

ensil=${1:?usage: packaging/window-icon-check.sh PATH/TO/ensil}
fail() { echo "window-icon-check: $*" >&2; exit 1; }
[ -n "${DISPLAY:-}" ] || fail "no DISPLAY; run it under xvfb-run -a"
home=$(mktemp -d)
HOME=$home XDG_RUNTIME_DIR=$home "$ensil" >"$home/log" 2>&1 &
pid=$!
trap 'kill "$pid" 2>/dev/null || true; wait "$pid" 2>/dev/null || true; rm -rf "$home"' EXIT

window=""
for _ in $(seq 1 120); do
    # The main window is the top-level one whose WM_CLASS is ("ensil" "ensil").
    window=$(xwininfo -root -children | awk '/\("ensil" "ensil"\)/ {print $1; exit}')
    [ -n "$window" ] && break
    kill -0 "$pid" 2>/dev/null || fail "ensil exited: $(cat "$home/log")"
    sleep 0.5
done
[ -n "$window" ] || fail "no ensil window after 60 s"

sizes=$(xprop -id "$window" _NET_WM_ICON | grep -o 'Icon ([0-9]* x [0-9]*)' | tr '\n' ' ' || true)
[ -n "$sizes" ] || fail "the ensil window $window has no icon"
echo "window-icon-check: window $window has ${sizes% }"
