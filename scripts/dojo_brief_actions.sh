#!/usr/bin/env bash
# The animator's brief (issue 31) done in the real editor and game with real X input, and its actions counted.
#
# "Make a 2-second wave clip with eases; blend it from and back to idle; add an event with a sound; preview it
# on a robot in a level; save and play it in the game's Dojo." Drives build/bin/killswitch-editor with
# xdotool as an animator would (the mouse and key shortcuts only; every click, drag, key chord, double-click
# and typed value counted as one action), then starts the game's Dojo and plays the clip there. Each input
# waits on the editor's --status-file JSON for the state it should produce (never a fixed sleep). At the end
# it checks the saved clip file and prints the actions per step and the total (docs/animation.md, "The
# brief's action count").
#
# Usage (a tool run by hand, not a CI test):
#   scripts/dojo_brief_actions.sh [--keep DIR] [--shots DIR] [--slow]
#     --keep DIR   work in DIR (the data folder with the saved robot.json, the status files, the logs)
#     --shots DIR  save window screenshots of the main steps into DIR (needs ImageMagick's `import`)
#     --slow       pause a second after each action (to watch it on a real display)
# Needs: xdotool, jq, and a display: it starts Xvfb on a free display number unless $DISPLAY is set
# (KS_BRIEF_XVFB=1 forces its own Xvfb). The binaries: $BUILD (default build)/bin/killswitch-editor and
# killswitch. The shipped robot.json is never written: both programs run on a data folder (KS_DATA_DIR) whose
# assets/animations holds a copy, everything else linked to the source tree's.
set -euo pipefail

ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=${BUILD:-$ROOT/build}
EDITOR_BIN=$BUILD/bin/killswitch-editor
GAME_BIN=$BUILD/bin/killswitch
# --- the editor's state and the counted actions: scripts/brief_lib.sh --------------------------------
# shellcheck source=scripts/brief_lib.sh
. "$ROOT/scripts/brief_lib.sh"
brief_setup dojo_brief_actions.sh dojo_brief "xdotool jq bc" "$@"
STATUS=$WORK/status.json
GAME_STATUS=$WORK/game_status.txt
PIDS=()
cleanup() {
    for pid in "${PIDS[@]}"; do kill "$pid" 2>/dev/null || true; done
}
trap cleanup EXIT

# --- the data folder: the source tree's, with its own copy of the clip file -----------------------------
DATA=$WORK/data
rm -rf "$DATA"
mkdir -p "$DATA/assets/animations"
ln -s "$ROOT/levels" "$DATA/levels"
for entry in "$ROOT"/assets/*; do
    [ "$(basename "$entry")" = animations ] || ln -s "$entry" "$DATA/assets/$(basename "$entry")"
done
cp "$ROOT"/assets/animations/* "$DATA/assets/animations/"
CLIPS=$DATA/assets/animations/robot.json
export KS_DATA_DIR=$DATA

# --- the display ------------------------------------------------------------------------------------------
if [ -z "${DISPLAY:-}" ] || [ "${KS_BRIEF_XVFB:-0}" = 1 ]; then
    command -v Xvfb >/dev/null || { echo "dojo_brief_actions.sh: no DISPLAY and no Xvfb" >&2; exit 2; }
    n=90
    while [ -e /tmp/.X11-unix/X$n ] || [ -e /tmp/.X$n-lock ]; do n=$((n + 1)); done
    Xvfb :$n -screen 0 1280x720x24 -noreset >"$WORK/xvfb.log" 2>&1 &
    PIDS+=($!)
    export DISPLAY=:$n
    for _ in $(seq 100); do [ -e /tmp/.X11-unix/X$n ] && break; sleep 0.1; done
fi

# dspot NAME: window coordinates of a widget of the Dojo tab ("x y").
dspot() {
    wait_for "the dojo's spot $1" ".dojo.spots[\"$1\"] != null"
    q ".dojo.spots[\"$1\"] | \"\\(.[0]) \\(.[1])\""
}
# point JQ: window coordinates of a point ([x, y]) the status holds ("x y").
point() { q "$1 | \"\\(.[0]) \\(.[1])\""; }
# ctrl_click X Y WHY: one action (Ctrl held over a click).
ctrl_click() {
    focus
    move_to "$1" "$2"
    xdotool keydown ctrl
    frames 2
    xdotool click 1
    frames 2
    xdotool keyup ctrl
    frames 2
    counted "Ctrl+click: $3"
}
# double_click X Y WHY: one action; each press in its own frame (ImGui needs both within 0.3 s), again when
# slow frames let the editor miss it (a harness retry, not the animator's: counted once).
double_click() {
    focus
    move_to "$1" "$2"
    local try
    for try in 1 2 3; do
        xdotool mousedown 1 mouseup 1
        frames 1
        xdotool mousedown 1 mouseup 1
        frames 3
        [ "$(q '.dojo.spots["event.add"] != null')" = true ] && break
    done
    counted "double-click: $3"
}
# hand_drag DX DY WHY: one action, the selected hand's joint dragged by (DX, DY) pixels with IK on; waits
# until auto-key has written it.
hand_drag() {
    local hx hy before
    read -r hx hy < <(point '.dojo.pose.joints.hand_r')
    before=$(undo_count)
    drag "$hx" "$hy" "$(echo "$hx + $1" | bc -l)" "$(echo "$hy + $2" | bc -l)" "$3"
    wait_for "the drag keyed" ".dojo.undo > $before and .dojo.undo_name == \"IK hand_r\""
}
undo_count() { q '.dojo.undo'; }

rm -f "$STATUS"
XDG_CONFIG_HOME=$WORK/config XDG_DATA_HOME=$WORK/xdg_data \
    "$EDITOR_BIN" --level "$DATA/levels/dojo.json" --width 1280 --height 720 --status-file "$STATUS" \
    >"$WORK/editor.log" 2>&1 &
EDITOR_PID=$!
PIDS+=("$EDITOR_PID")
wait_for "the editor's first frames" '.frame >= 3'
echo "editor pid $EDITOR_PID, work folder $WORK"

# --- 1. the Dojo tab, from the Level tab --------------------------------------------------------------------
step "open the Dojo"
click $(spot tab.dojo) "the Dojo tab"
wait_for "the Dojo tab" '.tab == "dojo" and .dojo.spots.new_clip != null'

# --- 2. the clip: one empty key, eased, a second (the end key), posed, duplicated twice ----------------------
step "new clip"
click $(dspot new_clip) "New clip..."
wait_for "the name field" '.input.text_input == true'
type_value wave "the clip's name"
key Return "create it"
wait_for "the wave clip" '.dojo.clip == "wave"'

step "ease"
click $(dspot easing) "key 1's easing combo"
click $(dspot "combo:Quadratic.InOut") "Quadratic.InOut"
wait_for "key 1 eased" '.dojo.undo_name == "key easing"'

step "the end key"
click $(dspot duplicate_key) "Duplicate key: key 2, empty (the arms go home at its end)"
wait_for "two keys" '.dojo.phases == 2'

step "pose key 1 (0.5 s)"
click $(dspot marker:1) "the timeline on key 1's diamond"
click $(dspot auto_key) "Auto-key"
wait_for "auto-key on" '.dojo.pose.auto_key == true'
click $(point '.dojo.pose.joints.hand_r') "hand_r's joint"
wait_for "the hand selected" '.dojo.pose.node == "hand_r"'
click $(dspot ik) "IK"
wait_for "IK on" '.dojo.pose.ik == true'
hand_drag -30 -75 "the hand up (IK turns the arm and forearm)"
shot pose

step "wave out (1 s)"
click $(dspot key:1) "key 1 on the Keys page"
wait_for "key 1 shown" '.dojo.phase == 0'
click $(dspot duplicate_key) "Duplicate key: a copy holding the pose"
wait_for "three keys" '.dojo.phases == 3'
click $(dspot marker:2) "the timeline on key 2's diamond"
hand_drag -25 8 "the hand one way"

step "wave back (1.5 s)"
click $(dspot duplicate_key) "Duplicate key"
wait_for "four keys" '.dojo.phases == 4'
click $(dspot marker:3) "the timeline on key 3's diamond"
hand_drag 45 0 "the hand the other way"

step "back to idle"
click $(dspot loop:next) "Loop: next (idle, the first other clip)"
wait_for "next: idle" '.dojo.undo_name == "loop mode next"'

# --- 3. blends ------------------------------------------------------------------------------------------------
step "blends"
click $(dspot page_blends) "the Blends page"
for pair in "idle>wave" "wave>idle"; do
    # The new clip's row is the grid's last: below its edge at 1280 x 720, a wheel turn brings it up.
    for _ in 1 2 3; do
        frames 2
        [ "$(q ".dojo.blend_cells[\"$pair\"] != null")" = true ] && break
        read -r gx gy < <(point '.dojo.blend_cells["idle>idle"] // .dojo.blend_cells["alert>idle"]')
        move_to "$gx" "$gy"
        xdotool click --repeat 2 5
        frames 3
        counted "scroll the blend grid down (one wheel turn)"
    done
    wait_for "the $pair cell" ".dojo.blend_cells[\"$pair\"] != null"
    ctrl_click $(point ".dojo.blend_cells[\"$pair\"]") "the $pair cell"
    wait_for "the cell taking text" '.input.text_input == true'
    type_value 0.3 "its blend time"
    key Return "set it"
    wait_for "the $pair blend" ".dojo.undo_name == \"blend ${pair%>*} -> ${pair#*>}\""
done

# --- 4. an event with a sound, at the last wave ----------------------------------------------------------------
step "event with a sound"
# The last blend cell left the tester playing idle -> wave: off, the timeline is the clip's again.
if [ "$(q .dojo.transition)" = true ]; then
    click $(dspot transition_test) "Transition test off (back to the clip's timeline)"
    wait_for "the clip's timeline" '.dojo.transition == false and .dojo.clip == "wave"'
fi
read -r mx _ < <(dspot marker:3)
read -r _ ly < <(dspot event_lane)
double_click "$mx" "$ly" "the event lane at 1.5 s"
wait_for "the Add event popup" '.input.text_input == true and .dojo.spots["event.add"] != null'
type_value wave "the event's name (the name field has the keyboard)"
click $(dspot sound_list) "the sound list"
click $(dspot "combo:computer_beeps") "computer_beeps (in the list's first rows)"
wait_for "the list closed" '.dojo.spots["combo:computer_beeps"] == null'
click $(dspot event.add) "Add"
wait_for "the event" '.dojo.events == 1'
shot event

step "save"
key ctrl+s "save robot.json"
wait_for "saved" '.dojo.dirty == false'

# --- 5. previewed on the level's robot ----------------------------------------------------------------------------
step "preview in the level"
click $(spot tab.level) "the Level tab"
wait_for "the Level tab" '.tab == "level"'
ROBOT=$(jq '[.entities[] | select(.type == "robot")][0].id' "$DATA/levels/dojo.json")
# The outliner lists the level's entities by id; the robot, the last, is below its fold at 1280 x 720.
for _ in 1 2 3; do
    [ "$(q ".spots[\"outliner.entity:$ROBOT\"] != null")" = true ] && break
    move_to $(spot outliner.entity:1)
    xdotool click --repeat 4 5
    frames 3
    counted "scroll the outliner down (one wheel turn)"
done
click $(spot "outliner.entity:$ROBOT") "the robot in the outliner"
wait_for "the robot selected" ".selection == [$ROBOT]"
wait_for "the preview toggle" '.clip_preview.toggle[0] > 0'
click $(point '.clip_preview.toggle') "Preview clip on the robot"
wait_for "the clip on the robot" '.clip_preview.on == true'
shot level_preview

# --- 6. the game's Dojo: the saved clip played ----------------------------------------------------------------------
step "the game's Dojo"
rm -f "$GAME_STATUS"
"$GAME_BIN" --dojo --width 1280 --height 720 --status-file "$GAME_STATUS" >"$WORK/game.log" 2>&1 &
GAME_PID=$!
PIDS+=("$GAME_PID")
counted "start killswitch --dojo"
game_line() { sed -n "s/^$1 //p" "$GAME_STATUS" 2>/dev/null | head -1; }
for _ in $(seq 1500); do
    case "$(game_line dojo)" in "") sleep 0.1 ;; *) break ;; esac
    kill -0 "$GAME_PID" 2>/dev/null || { echo "the game exited (see $WORK/game.log)" >&2; exit 1; }
done
[ -n "$(game_line dojo)" ] || { echo "the game's Dojo did not start (see $WORK/game.log)" >&2; exit 1; }
GAME_WINDOW=$(xdotool search --sync --onlyvisible --pid "$GAME_PID" | head -1)
xdotool windowfocus --sync "$GAME_WINDOW"
xdotool keydown 7
sleep 0.3
xdotool keyup 7
counted "key 7: the first clip after the shipped ones"
PLAYED=""
for _ in $(seq 300); do
    case "$(game_line dojo)" in *"playing wave"*) PLAYED=$(game_line dojo); break ;; *) sleep 0.1 ;; esac
done
echo "   the game's Dojo: ${PLAYED:-$(game_line dojo)}"
shot game_dojo

# --- the saved clip has what the brief asks ---------------------------------------------------------------------------
check() { # check WHAT JQ: on the saved clip file
    if jq -e "$2" "$CLIPS" >/dev/null; then echo "  ok   $1"; else echo "  FAIL $1" >&2; FAILED=1; fi
}
FAILED=0
echo "== the saved clips: $CLIPS"
W='(.clips[] | select(.name == "wave"))'
check "a wave clip of 2 s in four keys" "[$W.phases[].duration] | (length == 4 and add == 2)"
check "every key eased Quadratic.InOut" "[$W.phases[].ease] | all(. == \"Quadratic.InOut\")"
check "the arm and forearm keyed in keys 1-3" "[$W.phases[0:3][].targets | has(\"arm_r\") and has(\"forearm_r\")] | all"
check "the arm waves (keys 1, 2, 3 differ)" "[$W.phases[0:3][].targets.arm_r.rot] | unique | length == 3"
check "then idle" "$W.loop == \"next\" and $W.next == \"idle\""
check "blended from idle and back" '[.blend.pairs[] | select((.from == "idle" and .to == "wave") or (.from == "wave" and .to == "idle")) | .time] == [0.3, 0.3]'
check "an event with a sound" "[$W.events[] | select(.sound == \"computer_beeps\")] | length == 1"
check "the game's Dojo played it (${PLAYED:-never}; then idle, its next clip)" "$([ -n "$PLAYED" ] && echo true || echo false)"

echo
printf '| %-26s | %7s |\n' step actions
printf '|%s|%s|\n' "$(printf -- '-%.0s' $(seq 28))" "$(printf -- '-%.0s' $(seq 9))"
TOTAL=0
for s in "${STEPS[@]}"; do
    printf '| %-26s | %7d |\n' "$s" "${COUNT[$s]}"
    TOTAL=$((TOTAL + COUNT[$s]))
done
printf '| %-26s | %7d |\n' "**total**" "$TOTAL"
exit $FAILED
