#!/usr/bin/env bash
# One window-mode session driven by synthetic pointer events (xdotool, through the X server's
# XTEST extension), for window_test.cpp's drag tests. Run under xvfb-run (DISPLAY set).
# usage: drag_session.sh RBSIM SCENE MODE SCREENSHOT
#   MODE none:    no press; quit
#   MODE hold:    press on the box at (386, 180), drag up to (386, 60) and quit while holding
#   MODE release: the same drag, release, wait, then quit
# The window's last frame is written to SCREENSHOT (--screenshot).
set -euo pipefail
rbsim=$1 scene=$2 mode=$3 shot=$4
"$rbsim" run "$scene" --window --window-frames 1000000 --screenshot "$shot" --quiet &
pid=$!
trap 'kill $pid 2> /dev/null || true' EXIT
window=$(timeout 30 xdotool search --sync --onlyvisible --name "window test: drag" | head -1)
[ -n "$window" ] || { echo "drag_session: the window did not appear" >&2; exit 1; }
xdotool mousemove --window "$window" 386 180
sleep 1  # the first frames drawn, with the box under the pointer, on a loaded machine too
if [ "$mode" != none ]; then
  xdotool mousedown 1
  for y in 170 155 140 125 110 95 80 65 60; do
    xdotool mousemove --window "$window" 386 "$y"
    sleep 0.1
  done
  sleep 1  # time for the spring to pull the box up, in a sanitizer build too
  if [ "$mode" = release ]; then
    xdotool mouseup 1
    sleep 1  # frames enough for the released box to fly off, on a loaded machine too
  fi
fi
xdotool key --window "$window" q 2> /dev/null
wait $pid
status=$?
trap - EXIT
[ "$mode" = hold ] && xdotool mouseup 1
exit $status
