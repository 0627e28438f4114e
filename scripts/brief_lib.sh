#!/usr/bin/env bash
# Shared by the briefs replayed with real X input (scripts/brief_actions.sh: the level brief;
# scripts/dojo_brief_actions.sh: the animator's): reading the editor's --status-file, waiting on it (never a
# fixed sleep), and the counted actions (a click, a drag, a key chord or a typed value is one action).
# Sourced, not run. brief_setup needs BUILD, EDITOR_BIN and GAME_BIN; the rest expects STATUS (the status
# file), EDITOR_PID, SLOW (1: a second after each action) and SHOTS (a folder for screenshots, or empty).

# --- the command line and the checks both briefs start with ---------------------------------------------
# brief_setup NAME PREFIX "TOOLS" ARGS...: reads --keep DIR, --shots DIR, --slow and --help (the calling
# script's header, lines 2-20) from ARGS; checks TOOLS and that $EDITOR_BIN and $GAME_BIN are built; sets
# WORK (made and absolute: DIR, or a fresh /tmp/PREFIX.XXXXXX), SHOTS (made and absolute, or empty) and SLOW.
brief_setup() {
    local name=$1 prefix=$2 tools=$3 tool
    shift 3
    WORK="" SHOTS="" SLOW=0
    while [ $# -gt 0 ]; do
        case $1 in
        --keep) WORK=$2; shift 2 ;;
        --shots) SHOTS=$2; shift 2 ;;
        --slow) SLOW=1; shift ;;
        -h | --help) sed -n 2,20p "$0"; exit 0 ;;
        *) echo "$name: unknown option $1 (see --help)" >&2; exit 2 ;;
        esac
    done
    for tool in $tools; do
        command -v "$tool" >/dev/null || { echo "$name: needs $tool (apt-get install $tool)" >&2; exit 2; }
    done
    [ -x "$EDITOR_BIN" ] && [ -x "$GAME_BIN" ] ||
        { echo "$name: build killswitch-editor and killswitch first ($BUILD/bin)" >&2; exit 2; }
    if [ -z "$WORK" ]; then WORK=$(mktemp -d "/tmp/$prefix.XXXXXX"); fi
    mkdir -p "$WORK"
    WORK=$(cd "$WORK" && pwd)
    if [ -n "$SHOTS" ]; then mkdir -p "$SHOTS" && SHOTS=$(cd "$SHOTS" && pwd); fi
}

# --- reading the editor's state ------------------------------------------------------------------------
status() { cat "$STATUS" 2>/dev/null || echo '{}'; }
# q JQ: one value of the status.
q() { status | jq -r "$1"; }
# wait_for WHAT JQ: until JQ is true of the status (90 s at most; frames can be slow under llvmpipe).
wait_for() {
    local what=$1 expr=$2 i
    for i in $(seq 2250); do
        if status | jq -e "$expr" >/dev/null 2>&1; then return 0; fi
        kill -0 "$EDITOR_PID" 2>/dev/null || { echo "the editor exited while waiting for: $what" >&2; exit 1; }
        sleep 0.04
    done
    echo "timed out waiting for: $what" >&2
    status | jq -c '{frame, selection, undo, undo_name, last_error, tool: .tool.active}' >&2
    exit 1
}
# frames N: until the editor has drawn N more frames (it has seen what was sent before).
frames() {
    local start
    start=$(q '.frame // 0')
    wait_for "$1 frames" ".frame >= $start + $1"
}

# --- counted actions -----------------------------------------------------------------------------------
STEPS=() # in order
declare -A COUNT
STEP=""
step() {
    STEP=$1
    STEPS+=("$1")
    COUNT[$1]=0
    echo "== $1"
}
counted() {
    COUNT[$STEP]=$((COUNT[$STEP] + 1))
    echo "   $((COUNT[$STEP])). $*"
    [ "$SLOW" = 1 ] && sleep 1
    return 0
}
WINDOW=""
focus() {
    [ -n "$WINDOW" ] || WINDOW=$(xdotool search --sync --onlyvisible --pid "$EDITOR_PID" | head -1)
    xdotool windowfocus --sync "$WINDOW"
}
# screen X Y: window coordinates to the screen's.
screen() {
    local wx wy
    wx=$(q '.window[0]') wy=$(q '.window[1]')
    echo "$(printf '%.0f' "$(echo "$wx + $1" | bc -l)") $(printf '%.0f' "$(echo "$wy + $2" | bc -l)")"
}
move_to() {
    # shellcheck disable=SC2046
    xdotool mousemove $(screen "$1" "$2")
    frames 2
}
# key CHORD WHY: one action. Held until a frame has seen it (ImGui 1.86 samples keys once a frame).
key() {
    focus
    xdotool keydown "$1"
    wait_for "$1 seen pressed" '.input.keys_down > 0'
    xdotool keyup "$1"
    wait_for "$1 seen released" '.input.keys_down == 0'
    counted "key $1: $2"
}
# click X Y WHY: one action, at window coordinates.
click() {
    focus
    move_to "$1" "$2"
    xdotool click 1
    frames 2
    counted "click: $3"
}
# drag X1 Y1 X2 Y2 WHY: one action (press, a few moves, release).
drag() {
    focus
    move_to "$1" "$2"
    xdotool mousedown 1
    frames 2
    local i
    for i in 1 2 3 4 5 6; do
        xdotool mousemove $(screen "$(echo "$1 + ($3 - $1) * $i / 6" | bc -l)" "$(echo "$2 + ($4 - $2) * $i / 6" | bc -l)")
        frames 1
    done
    xdotool mouseup 1
    frames 2
    counted "drag: $5"
}
# type_value TEXT WHY: one action (the text typed into the focused field; Enter is its own action).
type_value() {
    focus
    xdotool type --delay 60 "$1"
    frames 2
    counted "type \"$1\": $2"
}
# spot NAME: window coordinates of a widget the status names ("x y").
spot() {
    wait_for "the spot $1" ".spots[\"$1\"] != null"
    q ".spots[\"$1\"] | \"\\(.[0]) \\(.[1])\""
}
shot() {
    [ -n "$SHOTS" ] || return 0
    frames 3
    import -window root "$SHOTS/$1.png"
}
