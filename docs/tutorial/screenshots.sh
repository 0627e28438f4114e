#!/bin/sh
# Re-takes docs/tutorial.md's screenshots (docs/screenshots/tutorial_*.png) from the tutorial's scripts:
# each editor shot runs the first N steps (docs/tutorial/0N_*.kss) in the window with --run, then a few
# commands of its own, with a camera and an inspector tab. Run from the repository root after a build.
set -e
out=docs/screenshots
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

shot() { # shot N NAME "COMMANDS" EDITOR-ARGS...
    n=$1 name=$2 extra=$3
    shift 3
    : >"$work/run.kss"
    for step in $(ls docs/tutorial/0*.kss | head -n "$n"); do cat "$step" >>"$work/run.kss"; echo >>"$work/run.kss"; done
    printf '%b\n' "$extra" >>"$work/run.kss"
    xvfb-run -a -s "-screen 0 1280x720x24" ./build/bin/killswitch-editor --run "$work/run.kss" --width 1280 \
        --height 720 --screenshot "$out/tutorial_$name.png" --frames 30 "$@"
}

shot 1 rooms "select none" --camera 0,60,55,0,-50
shot 2 trigger "select 24" --camera 14,22,34,30,-35 --inspector links
shot 3 spawner "select 24" --camera 14,30,34,20,-40 --inspector links
shot 3 locked_door "select 14\nname 14 Exit_door\nset locked true" --camera 0,14,10,0,-25 --inspector properties
shot 4 objective "select 14" --camera -14,30,16,-25,-40 --inspector objectives
shot 4 panel_fix "objective add shutdown Shut down the simulation at the control panel\nselect 19" \
    --camera 0,34,-8,0,-60 --inspector properties

# The play-test: the whole tutorial saved, then the game with the player warped into the hall's trigger.
for step in docs/tutorial/0*.kss; do cat "$step"; echo; done >"$work/all.kss"
./build/bin/killswitch-editor --script "$work/all.kss"
xvfb-run -a -s "-screen 0 1280x720x24" ./build/bin/killswitch --level "$work/tutorial.json" --screen play \
    --warp 0,0,16,0,0 --frames 200 --screenshot "$out/tutorial_playtest.png"
