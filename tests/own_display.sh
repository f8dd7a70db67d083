#!/usr/bin/env bash
# Runs one GUI test executable on an X server of its own. CTest runs tests in parallel, and
# windows of two tests on one server without a window manager take the keyboard focus from
# each other, so a test waiting for its window to become active could fail at random. Xvfb
# picks a free display itself (-displayfd), so parallel tests never race for a number.
set -uo pipefail
work=$(mktemp -d)
fifo="$work/display"
mkfifo "$fifo"
Xvfb -displayfd 3 -screen 0 1920x1080x24 -nolisten tcp 3>"$fifo" 2>"$work/xvfb.log" &
server=$!
cleanup() {
  kill "$server" 2>/dev/null
  wait "$server" 2>/dev/null
  rm -rf "$work"
}
trap cleanup EXIT
# Xvfb writes its display number to the pipe once it accepts connections.
if ! read -r -t 30 display <"$fifo" || [ -z "$display" ]; then
  echo "own_display.sh: Xvfb did not start:" >&2
  cat "$work/xvfb.log" >&2
  exit 1
fi
DISPLAY=":$display" "$@"
