#!/usr/bin/env bash
# Run under xvfb-run in an empty directory: opens the viewer, presses F12 the way a user does
# until screenshots/ holds its PNG, then quits with Escape. Exits with the viewer's exit code; a
# crash or hang fails the test.
set -u
binary=$1 scene=$2
shift 2
"$binary" "$scene" "$@" & pid=$!  # further arguments go to the viewer
window=$(timeout 30 xdotool search --sync --name '^ptview' | head -1)
if [ -z "$window" ]; then echo "the viewer window never appeared"; kill $pid; exit 1; fi
xdotool windowfocus "$window" 2>/dev/null
# A screenshot needs a finished sample; a press before that is refused (and said so in the panel).
# Up to two minutes of presses: on a loaded 2-core machine the first 768x768 sample took longer
# than the ten seconds this loop once allowed.
for attempt in $(seq 1 80); do
  sleep 1
  xdotool key F12
  sleep 0.5
  ls screenshots/*.png >/dev/null 2>&1 && break
done
xdotool key Escape
( sleep 30; kill $pid ) >/dev/null 2>&1 & watchdog=$!  # no pipe held open
wait $pid; code=$?
kill $watchdog 2>/dev/null
echo "viewer exit code $code"
exit $code
