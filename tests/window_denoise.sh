#!/usr/bin/env bash
# Run under xvfb-run in a directory holding scene.json and script.txt (see ScriptedViewerTest):
# the script prints a status line once its render is done, then lets a few seconds of frames go by,
# in which this presses N as a user would (the denoiser on). Prints the viewer's output.
set -u
source "$(dirname "$0")/window_driver.sh"
binary=$1
start_viewer scene.json --script script.txt
focus_viewer
wait_for_status 1 && focus_viewer && xdotool key n
finish_viewer 90
