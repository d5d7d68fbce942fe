#!/usr/bin/env bash
# Run under xvfb-run in a directory holding scene.json and script.txt (see ScriptedViewerTest):
# with the preferences in prefs.json there, presses Ctrl = (Ctrl +) twice once the script's first status
# line is out, as a user enlarging the interface for a projector would. Prints the viewer's output.
set -u
source "$(dirname "$0")/window_driver.sh"
binary=$1
export PTVIEW_CONFIG=$PWD/prefs.json
start_viewer scene.json --script script.txt
focus_viewer
wait_for_status 1 && focus_viewer && xdotool key ctrl+equal && sleep 0.3 && xdotool key ctrl+equal
finish_viewer 90
