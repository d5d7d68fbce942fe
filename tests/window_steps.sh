#!/usr/bin/env bash
# Run under xvfb-run in a scratch directory. Two ways to act on the viewer's window as a user would:
#   window_steps.sh BINARY SCENE KEY...      with script.txt in the directory: after each `status`
#       line of the script, presses the next KEY (xdotool names) and prints whether the viewer still
#       runs ("running after KEY" / "exited after KEY");
#   window_steps.sh BINARY SCENE --prompt KEY  opens SCENE for 3 frames and a screenshot
#       (window.png), waits for the question before a folder is read and answers it with KEY.
# Prints the viewer's output and exits with its exit code.
set -u
source "$(dirname "$0")/window_driver.sh"
binary=$1; scene=$2; shift 2

if [ "${1:-}" = "--prompt" ]; then
  start_viewer "$scene" --frames 3 --screenshot window.png
  for _ in $(seq 1 600); do grep -q 'asking in the window' out.txt && break; sleep 0.1; done
  sleep 1  # a few frames of the question, at a slow software rasterizer's pace
  focus_viewer
  xdotool key "$2"
  finish_viewer 120
fi

start_viewer "$scene" --script script.txt
focus_viewer
count=0
for key in "$@"; do
  count=$((count + 1))
  wait_for_status $count || break
  xdotool key "$key"
  sleep 1
  # Not into out.txt, which the viewer writes at its own offset.
  if kill -0 $pid 2>/dev/null; then echo "running after $key" >> steps.txt; else echo "exited after $key" >> steps.txt; fi
done
cat steps.txt
finish_viewer
