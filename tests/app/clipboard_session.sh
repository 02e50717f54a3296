#!/usr/bin/env bash
# One window-mode session for window_test.cpp's clipboard test: open the window, press c ("copy as
# command"), read the CLIPBOARD selection back with xclip as another program would, quit.
# Run under xvfb-run (DISPLAY set).   usage: clipboard_session.sh RBSIM SCENE OUT
set -euo pipefail
rbsim=$1 scene=$2 out=$3
"$rbsim" run "$scene" --window --window-frames 1000000 --quiet > /dev/null &
pid=$!
trap 'kill $pid 2> /dev/null || true' EXIT
window=$(timeout 30 xdotool search --sync --onlyvisible --name "rbsim" | head -1)
[ -n "$window" ] || { echo "clipboard_session: the window did not appear" >&2; exit 1; }
sleep 0.5
xdotool key --window "$window" c
# The key is read at the next poll, a frame or more later (longer on a loaded machine): ask for
# the selection until its owner answers, for at most 20 s.
for _ in $(seq 40); do
  sleep 0.5
  if timeout 10 xclip -o -selection clipboard > "$out" 2> /dev/null && [ -s "$out" ]; then break; fi
done
xdotool key --window "$window" q 2> /dev/null
wait $pid
trap - EXIT
