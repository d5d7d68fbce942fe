#!/usr/bin/env bash
# Run under xvfb-run in a directory holding scene.json and script.txt (see ScriptedViewerTest):
# the script edits the scene and prints status lines, each followed by a wait-reload. After each
# status line this records the window's title in titles.txt, then does one step as a user would
# (the arguments after the binary, one per status line): a key for xdotool, `close` (the window
# manager's close button) or `none`; then writes whether the viewer still runs to steps.txt and
# touches scene.json, which ends the script's wait-reload. Prints the viewer's output and exits
# with its exit code.
set -u
source "$(dirname "$0")/window_driver.sh"
binary=$1; shift
here=$(dirname "$0")
start_viewer scene.json --script script.txt
focus_viewer

count=0
for step in "$@"; do
  count=$((count + 1))
  wait_for_status $count || break
  sleep 0.5  # the title follows the edits within a quarter of a second
  xdotool getwindowname "$window" >> titles.txt
  case $step in
    none) ;;
    close) /usr/bin/python3 "$here/x11_close_window.py" "$window" ;;
    *) xdotool key "$step" ;;
  esac
  sleep 1  # a few frames, at a slow software rasterizer's pace
  if kill -0 $pid 2>/dev/null; then echo "running after $step" >> steps.txt; else echo "exited after $step" >> steps.txt; fi
  touch scene.json
done
finish_viewer
