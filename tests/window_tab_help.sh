#!/usr/bin/env bash
# Run under xvfb-run in an empty directory, with a viewer script as $3 that prints `status` once
# its image has converged and then waits (wait-seconds): presses Tab (hide the sidebar) and F1
# (the help overlay) the way a user does, after that first status line. The script's later
# status lines and window screenshot show what the keys did. Exits with the viewer's exit code.
set -u
binary=$1 scene=$2 script=$3
"$binary" "$scene" --script "$script" >viewer.out 2>&1 & pid=$!
window=$(timeout 30 xdotool search --sync --name '^ptview' | head -1)
if [ -z "$window" ]; then echo "the viewer window never appeared"; kill $pid; exit 1; fi
for attempt in $(seq 1 600); do  # up to 120 s for the image to converge
  grep -q '^status ' viewer.out && break
  kill -0 $pid 2>/dev/null || break
  sleep 0.2
done
xdotool windowfocus "$window" 2>/dev/null
sleep 0.3
xdotool key Tab
sleep 0.3
xdotool key F1
( sleep 150; kill $pid ) >/dev/null 2>&1 & watchdog=$!  # no pipe held open
wait $pid; code=$?
kill $watchdog 2>/dev/null
cat viewer.out
echo "viewer exit code $code"
exit $code
