#!/usr/bin/env bash
# Run under xvfb-run (screen 1000x520: a window of 380 + 472 by 472 pixels, the sidebar, then the
# image) in a directory holding scene.json (one principled material), script.txt, good.png and
# broken.png (see ScriptedViewerTest.TexturePanelLoadsShowsAndRemovesATextureByMouse). The script
# opens the Materials panel at that material (open-material: its node scrolled to the top of the
# sidebar), prints a status line and waits for a reload of scene.json; meanwhile this acts as a
# user, then touches the file:
#   1. clicks the base colour texture's path field, types good.png, clicks Load;
#   2. (the slot now shows the texture, which moves the field down) selects the field's text
#      (Ctrl+A), types broken.png, clicks Load;
#   3. clicks Remove.
# Coordinates are window pixels from the window's top-left, for the layout the script sets up;
# the test checks in its screenshots that a button is where each click goes. Prints the output.
set -u
source "$(dirname "$0")/window_driver.sh"
binary=$1
start_viewer scene.json --script script.txt
focus_viewer

click() {  # $1 $2: where, in window coordinates
  xdotool mousemove --window "$window" "$1" "$2" sleep 0.3 click 1 sleep 0.3
}
load() {  # $1: the field's y; types $2 into it (after selecting what it holds) and clicks Load
  # Ctrl+A held down over a few frames: ImGui 1.86 misses a key pressed and released between two.
  click 160 "$1" && xdotool keydown ctrl keydown a sleep 0.3 keyup a keyup ctrl sleep 0.2 type --delay 50 "$2" &&
    sleep 0.3 && click 324 "$1"
}

# Field and Load at y 252 with no texture; at 304 with one (a 48-pixel thumbnail above); Remove at
# 284. The second of sleep lets a slow frame take the click before the reload ends the wait.
wait_for_status 1 && load 252 good.png && sleep 1 && touch scene.json
wait_for_status 2 && load 304 broken.png && sleep 1 && touch scene.json
wait_for_status 3 && click 109 284 && sleep 1 && touch scene.json
finish_viewer 60
