#!/usr/bin/env bash
# Run under xvfb-run in a directory holding scene.json and script.txt (see ScriptedViewerTest):
# the script prints a status line, then waits for a reload of scene.json; meanwhile this
# Alt+clicks on the image at window position $2 $3 (a window of 380 + 768 pixels: the sidebar,
# then the image), as a user pinning a pixel would, then touches the file. Prints the viewer's output.
set -u
binary=$1 x=$2 y=$3
"$binary" scene.json --script script.txt > out.txt 2>&1 & pid=$!
window=$(timeout 30 xdotool search --sync --name '^ptview' | head -1)
if [ -z "$window" ]; then echo "the viewer window never appeared"; kill $pid; exit 1; fi
xdotool windowfocus "$window" 2>/dev/null

wait_for_status() {  # $1: how many status lines to wait for
  for _ in $(seq 1 300); do [ "$(grep -c '^status ' out.txt)" -ge "$1" ] && return 0; sleep 0.1; done
  echo "timed out waiting for status line $1"; return 1
}
wait_for_status 1 && xdotool mousemove --window "$window" "$x" "$y" sleep 0.3 keydown alt sleep 0.2 \
                             click 1 sleep 0.3 keyup alt sleep 0.5 && touch scene.json
( sleep 30; kill $pid ) >/dev/null 2>&1 & watchdog=$!
wait $pid; code=$?
kill $watchdog 2>/dev/null
cat out.txt
echo "viewer exit code $code"
exit $code
