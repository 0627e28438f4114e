#!/usr/bin/env bash
# The designer's brief (issue 25/26) built in the real editor with real X input, and its actions counted.
#
# Drives build/bin/killswitch-editor with xdotool as a designer would: the mouse and key shortcuts only,
# every click, drag, key chord and typed value counted as one action. It builds a 20 x 20 room with an
# arched doorway, a window cut through a wall, a ramp to a platform and the textures aligned on every face,
# then places the door, the lamp, a robot with a patrol and the control panel, saves and play-tests. Each
# input waits on the editor's --status-file JSON for the state it should produce (never a fixed sleep).
# At the end it checks the saved level and prints the actions per step and the total.
#
# Usage (a tool run by hand, not a CI test; docs/tutorial.md "Build a room with brushes"):
#   scripts/brief_actions.sh [--keep DIR] [--shots DIR] [--slow]
#     --keep DIR   work in DIR (the saved level, the status file, the log) and leave it there
#     --shots DIR  save window screenshots of the main steps into DIR (needs ImageMagick's `import`)
#     --slow       pause a second after each action (to watch it on a real display)
# Needs: xdotool, jq, and a display: it starts Xvfb on a free display number unless $DISPLAY is set
# (KS_BRIEF_XVFB=1 forces its own Xvfb). The binaries: $BUILD (default build)/bin/killswitch-editor and
# killswitch (the play-test runs the game, headless with the autoplay bot, see play_command below).
set -euo pipefail

ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=${BUILD:-$ROOT/build}
EDITOR_BIN=$BUILD/bin/killswitch-editor
GAME_BIN=$BUILD/bin/killswitch
# --- the editor's state and the counted actions: scripts/brief_lib.sh --------------------------------
# shellcheck source=scripts/brief_lib.sh
. "$ROOT/scripts/brief_lib.sh"
brief_setup brief_actions.sh brief_actions "xdotool jq" "$@"
STATUS=$WORK/status.json
PIDS=()
cleanup() {
    if [ -s "$WORK/game.pid" ]; then kill "$(cat "$WORK/game.pid")" 2>/dev/null || true; fi
    for pid in "${PIDS[@]}"; do kill "$pid" 2>/dev/null || true; done
}
trap cleanup EXIT

# --- the display -------------------------------------------------------------------------------------
if [ -z "${DISPLAY:-}" ] || [ "${KS_BRIEF_XVFB:-0}" = 1 ]; then
    command -v Xvfb >/dev/null || { echo "brief_actions.sh: no DISPLAY and no Xvfb" >&2; exit 2; }
    n=90
    while [ -e /tmp/.X11-unix/X$n ] || [ -e /tmp/.X$n-lock ]; do n=$((n + 1)); done
    Xvfb :$n -screen 0 1280x720x24 -noreset >"$WORK/xvfb.log" 2>&1 &
    PIDS+=($!)
    export DISPLAY=:$n
    for _ in $(seq 100); do [ -e /tmp/.X11-unix/X$n ] && break; sleep 0.1; done
fi

# world X Y Z: where a world point is in the current axis view (window coordinates "x y").
world() {
    wait_for "an axis view" '.axes_on_screen != null'
    status | jq -r --argjson p "[$1,$2,$3]" '.axes_on_screen as $a |
        [range(2) as $i | $a.origin[$i] + ($p[0] * ($a.x[$i] - $a.origin[$i])) +
            ($p[1] * ($a.y[$i] - $a.origin[$i])) + ($p[2] * ($a.z[$i] - $a.origin[$i]))] |
        "\(.[0]) \(.[1])"'
}

# at X Y Z: click/drag helpers take window coordinates; this names a world point in the axis view.
at() { world "$1" "$2" "$3"; }
# menu_item MENU ITEM WHY: open a menu of the menu bar (one click) and click one of its items (one click).
menu_item() {
    local m i
    m=$(spot "$1")
    # shellcheck disable=SC2086
    click $m "open the ${1#menu.} menu"
    i=$(spot "$2")
    # shellcheck disable=SC2086
    click $i "$3"
}
undo_now() { q '.undo'; }

# --- the editor ------------------------------------------------------------------------------------------
# The play-test runs the real game; it is told to write a status file so this script can see it playing.
cat >"$WORK/playtest.sh" <<PLAY
#!/usr/bin/env bash
[ "\${1:-}" = --help ] && exec "$GAME_BIN" --help
echo \$\$ >"$WORK/game.pid"
exec "$GAME_BIN" "\$@" --status-file "$WORK/game_status.json"
PLAY
chmod +x "$WORK/playtest.sh"
rm -f "$STATUS" "$WORK/game_status.json"
XDG_CONFIG_HOME=$WORK/config XDG_DATA_HOME=$WORK/data KS_PLAYTEST_COMMAND=$WORK/playtest.sh \
    "$EDITOR_BIN" --width 1280 --height 720 --status-file "$STATUS" >"$WORK/editor.log" 2>&1 &
EDITOR_PID=$!
PIDS+=("$EDITOR_PID")
wait_for "the editor's first frames" '.frame >= 3'
echo "editor pid $EDITOR_PID, work folder $WORK"

# --- 1. the room: a box 22 x 10 x 22 drawn in the top view, hollowed -------------------------------------
step "room (box, hollow)"
key KP_7 "top view"
key b "draw tool (box)"
click $(spot tool.height) "the next brush's height field"
type_value 10 "room height"
key Return "set the height"
drag $(at -11 0 -11) $(at 11 0 11) "drag the room's box"
wait_for "the room's box" '.entities == 1 and .undo_name == "Place box brush"'
m=$(spot menu.brush)
click $m "open the Brush menu"
click $(spot brush.hollow) "Hollow (its thickness: the grid step, 1)"
click $(spot brush.hollow_apply) "Hollow"
wait_for "the room hollowed" '.entities == 6'
key Escape "leave the draw tool"
shot room

# --- 2. the player start onto the new floor (Hollow made the top piece the ceiling, hidden from above) --
step "player start onto the floor"
click $(spot "fix:Drop to floor") "validation's quick fix: the player start (sunk into the new floor) onto it"
wait_for "the start on the floor" '.player_start.position[1] > 0.2'

# --- 3. the arched doorway: an 8-sided arch drawn in the front view through the south wall, subtracted ----
step "arched doorway (polygon, subtract)"
key KP_1 "front view"
click $(at 0 9 11) "select the south wall (the front view's nearest brush)"
wait_for "the south wall" '.selection | length == 1'
key b "draw tool"
[ "$(q .tool.draw.shape)" = polygon ] || key b "polygon shape"
for corner in "-3 1" "3 1" "3 5" "2 7" "0 8" "-2 7" "-3 5"; do
    set -- $corner
    click $(at "$1" "$2" 11) "arch corner ($1, $2)"
done
shot arch_polygon
click $(at -3 1 11) "close on the first corner"
wait_for "the arch closed" '.tool.draw.stage == "extruding"'
key Return "place the arch brush (through the selected wall)"
wait_for "the arch brush" '.entities == 7'
menu_item menu.brush brush.subtract "Subtract"
wait_for "the doorway cut" '.undo_name == "Subtract brushes"'
key Escape "leave the draw tool"
shot doorway

# --- 4. the window: a box dragged in the side view through the east wall, subtracted ---------------------
step "window (box, subtract)"
key KP_3 "side view"
click $(at 11 8 4) "select the east wall"
wait_for "the east wall" '.selection | length == 1'
key b "draw tool"
[ "$(q .tool.draw.shape)" = box ] || key b "box shape"
drag $(at 11 3 -9) $(at 11 6 -3) "drag the window through the wall"
wait_for "the window brush" '.undo_name == "Place box brush"'
menu_item menu.brush brush.subtract "Subtract"
wait_for "the window cut" '.undo_name == "Subtract brushes"'
shot window

# --- 5. a platform and a ramp up to it, in the front view: two boxes, the second clipped to a wedge -------
step "platform and ramp (box, box, clip)"
key Escape "leave the draw tool"
key Escape "clear the selection (the wall's pieces: a brush drawn now would take their depth)"
key KP_1 "front view"
key b "draw tool (box)"
drag $(at -10 1 -6) $(at -4 4 -6) "drag the platform (6 x 3, as deep as the window)"
wait_for "the platform" '.undo_name == "Place box brush"'
drag $(at -4 1 -6) $(at 2 4 -6) "drag the ramp's box beside it"
wait_for "the ramp's box" '.undo_name == "Place box brush" and .undo > 0'
key c "clip tool"
click $(at -4 4 -6) "clip point: the platform's top edge"
click $(at 2 1 -6) "clip point: the ramp's foot"
wait_for "the slope previewed" '.tool.clip.points == 2 and .tool.clip.plane != null'
shot clip_preview
# Keep the side below the slope: the box's top far corner (2, 4) must be cut off.
for _ in 1 2 3; do
    keep=$(q .tool.clip.keep)
    side=$(status | jq -r '.tool.clip.plane as $p | ($p[0] * 2 + $p[1] * 4 - $p[3]) | if . > 0 then "front" else "back" end')
    [ "$keep" != both ] && [ "$keep" != "$side" ] && break
    key Tab "the side kept"
done
key Return "clip"
wait_for "the ramp" '.undo_name == "Clip brushes"'
key Escape "leave the clip tool"
shot ramp

# --- 6. textures: every face of every brush one material, world-aligned (the default mapping) -------------
step "textures (all faces)"
key ctrl+a "select everything"
menu_item menu.brush brush.select_faces "Select faces of selected brushes"
wait_for "the faces selected" '.faces.selected | length > 30'
click $(spot face.material) "the faces' material: open the texture browser"
wait_for "the texture browser" '(.spots | keys | map(select(startswith("texture:"))) | length) > 0'
shot texture_browser
TEXTURE=$(status | jq -r '.faces.selected[0].material as $now | [.spots | keys[] | select(startswith("texture:")) |
    ltrimstr("texture:")] as $shown | ["concrete", "metal", "tiles", "wood"] + $shown |
    map(select(. != $now and (. as $t | $shown | index($t)))) | .[0]')
click $(spot "texture:$TEXTURE") "the texture $TEXTURE"
wait_for "the faces textured" "[.faces.selected[].material] | all(. == \"$TEXTURE\")"
click $(spot texture_close) "close the texture browser (it covers the viewport)"
click $(spot face.clear) "clear the face selection (its section tops every inspector; Esc leaves it)"
key Escape "clear the selection"

# --- 7. the door, the lamp, the robot and its patrol, the control panel (top view) -----------------------
step "door"
key KP_7 "top view"
click $(q '.palette.door | "\(.[0]) \(.[1])"') "palette: door"
click $(at 0 1 9.5) "place the door in the doorway (inside the wall's line: from above the lintel is hit first)"
wait_for "the door" '.primary.type == "door" and .gizmo_handles.z != null'
# From above the wall over the arch is met first, so the door went in just inside; its z arrow moves it
# one grid step into the wall's line.
read -r hx hy < <(q '.gizmo_handles.z | "\(.[0]) \(.[1])"')
dz=$(status | jq -r '.axes_on_screen | .z[1] - .origin[1]')
drag "$hx" "$hy" "$hx" "$(echo "$hy + $dz" | bc -l)" "drag the door's z arrow one step into the doorway"
wait_for "the door moved" '.primary.position[2] > 9.9'

step "lamp"
click $(q '.palette.top_light | "\(.[0]) \(.[1])"') "palette: top_light"
click $(at 3 0 3) "place the lamp under the ceiling (off the player start)"
wait_for "the lamp" '.primary.type == "top_light"'

step "robot with a patrol"
click $(q '.palette.robot | "\(.[0]) \(.[1])"') "palette: robot"
click $(at 5 0 -6) "place the robot"
wait_for "the robot" '.primary.type == "robot"'
# The robot's fields fill the inspector (about 300 pixels tall at 1280 x 720): its Patrol section is below.
for _ in 1 2 3 4 5 6; do
    [ "$(q '.spots["patrol.add_here"][1] < 340')" = true ] && break
    move_to 1110 250
    xdotool click --repeat 4 5
    frames 3
    counted "scroll the inspector down to the Patrol section (one wheel turn)"
done
click $(spot patrol.add_here) "Add patrol point here"
click $(spot patrol0.add) "+ a point after it"
click $(spot patrol1.add) "+ a point after that"
wait_for "three patrol points" '.spots["patrol2.add"] != null'
drag $(at 9 0 -6) $(at 6 0 6) "drag the last point across the room"
wait_for "the point dragged" '.undo_name | test("atrol")'

step "control panel"
click $(q '.palette.control_panel | "\(.[0]) \(.[1])"') "palette: control_panel"
click $(at -8 4 -6) "place the panel on the platform"
wait_for "the panel" '.primary.type == "control_panel"'

# --- 8. save, play-test -----------------------------------------------------------------------------------
step "save"
key ctrl+s "save (an untitled level asks where)"
frames 4 # the path prompt opens with its field focused, the proposed file in it
if [ "$(q .dirty)" = true ]; then key Return "accept the proposed file"; fi
wait_for "saved" '.dirty == false and .file != ""'
LEVEL=$(q .file)

step "play-test"
key F5 "play from start"
# The game's status file is text, a "key value" line each; past "loading" the level is being played.
game_screen() { sed -n 's/^screen //p' "$WORK/game_status.json" 2>/dev/null | head -1; }
for _ in $(seq 1500); do
    case "$(game_screen)" in "" | loading) sleep 0.1 ;; *) break ;; esac
done
GAME_SCREEN=$(game_screen)
[ -n "$GAME_SCREEN" ] && [ "$GAME_SCREEN" != loading ] ||
    { echo "the play-test did not start the level (see $WORK/editor.log)" >&2; exit 1; }
echo "   the game is on its '$GAME_SCREEN' screen"
shot playtest
kill "$(cat "$WORK/game.pid")" 2>/dev/null || true

# --- the saved level has what the brief asks ---------------------------------------------------------------
check() { # check WHAT JQ: on the saved level
    if jq -e "$2" "$LEVEL" >/dev/null; then echo "  ok   $1"; else echo "  FAIL $1" >&2; FAILED=1; fi
}
FAILED=0
echo "== the saved level: $LEVEL"
B='[.entities[] | select(.type == "brush")]'
check "the room, cut: more than 6 brushes" "$B | length > 6"
check "the doorway: a brush face on the arch's slanted edges (normal along x and y)" \
    "[$B[] | .props.faces[] | .plane | select(.[0] != 0 and .[1] != 0 and .[2] == 0)] | length >= 4"
check "a ceiling brush" "$B | map(select(.props.ceiling == true)) | length == 1"
# Only the brushes drawn at the ramp's depth (z < 0): the arch's wall pieces have sloped cut faces too.
check "the ramp: a face sloped up along x" "[$B[] | select(.position[2] < 0) | .props.faces[] | .plane | select(.[0] != 0 and .[1] > 0 and .[2] == 0)] | length == 1"
check "every brush face textured $TEXTURE" "[$B[] | .props.faces[] | .material] | all(. == \"$TEXTURE\")"
check "a door" '[.entities[] | select(.type == "door")] | length == 1'
check "a lamp" '[.entities[] | select(.type == "top_light")] | length == 1'
check "a robot with a 3-point patrol" '[.entities[] | select(.type == "robot") | .props.patrol.points | length] == [3]'
check "a control panel" '[.entities[] | select(.type == "control_panel")] | length == 1'
check "the play-test started the level (game screen: $GAME_SCREEN)" "true"

# --- the count -----------------------------------------------------------------------------------------------
echo
printf '| %-38s | %7s |\n' step actions
printf '|%s|%s|\n' "$(printf -- '-%.0s' $(seq 40))" "$(printf -- '-%.0s' $(seq 9))"
TOTAL=0
for s in "${STEPS[@]}"; do
    printf '| %-38s | %7d |\n' "$s" "${COUNT[$s]}"
    TOTAL=$((TOTAL + COUNT[$s]))
done
printf '| %-38s | %7d |\n' "**total**" "$TOTAL"
[ "$FAILED" = 0 ] || { echo "some checks failed (the level: $LEVEL)" >&2; exit 1; }
