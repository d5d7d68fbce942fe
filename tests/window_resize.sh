#!/usr/bin/env bash
# Run under xvfb-run: opens the viewer, resizes its window through several sizes (tiny included),
# then quits with Escape. Exits with the viewer's exit code; a crash or hang fails the test.
set -u
binary=$1 scene=$2
"$binary" "$scene" & pid=$!
window=$(timeout 30 xdotool search --sync --name '^ptview' | head -1)
if [ -z "$window" ]; then echo "the viewer window never appeared"; kill $pid; exit 1; fi
for size in "900 500" "300 700" "40 30" "1000 600"; do
  xdotool windowsize "$window" $size
  sleep 0.7
  kill -0 $pid 2>/dev/null || break
done
xdotool windowfocus "$window" 2>/dev/null
sleep 0.3
xdotool key Escape
( sleep 30; kill $pid ) >/dev/null 2>&1 & watchdog=$!  # no pipe held open
wait $pid; code=$?
kill $watchdog 2>/dev/null
echo "viewer exit code $code"
exit $code
