#!/bin/sh
# with-window-manager.sh COMMAND...: runs COMMAND on a virtual display of its own
# (with-private-display.sh) with a window manager (openbox), for tests of what only a window
# manager does: maximising a window, placing it, deciding its size. The other GUI tests' displays
# have none, and giving them one would change every other test's windows. Exits with COMMAND's
# status.
set -eu
for tool in openbox wmctrl; do
    command -v "$tool" >/dev/null || {
        echo "with-window-manager.sh: $tool is missing (packaging/install-deps.sh installs it)" >&2
        exit 1
    }
done
exec "$(dirname "$0")/with-private-display.sh" sh -c '
    openbox --sm-disable >/dev/null 2>&1 &
    manager=$!
    # Wait until openbox manages the display (it says so on the root window), at most 30 s.
    tries=0
    until wmctrl -m >/dev/null 2>&1; do
        tries=$((tries + 1))
        if [ "$tries" -gt 300 ]; then
            echo "with-window-manager.sh: openbox did not start on $DISPLAY" >&2
            exit 1
        fi
        sleep 0.1
    done
    status=0
    "$@" || status=$?
    kill "$manager" 2>/dev/null || true
    exit "$status"' with-window-manager "$@"
