#!/usr/bin/env bash
# Run under xvfb-run in a directory holding scene.json and script.txt (see ScriptedViewerTest):
# the script prints a status line, then waits for a reload of scene.json; meanwhile this
# Alt+clicks on the image at window position $2 $3 (a window of 380 + 768 pixels: the sidebar,
# then the image), as a user pinning a pixel would, then touches the file. Prints the viewer's output.
set -u
source "$(dirname "$0")/window_driver.sh"
binary=$1 x=$2 y=$3
start_viewer scene.json --script script.txt
focus_viewer
wait_for_status 1 && xdotool mousemove --window "$window" "$x" "$y" sleep 0.3 keydown alt sleep 0.2 \
                             click 1 sleep 0.3 keyup alt sleep 0.5 && touch scene.json
finish_viewer
