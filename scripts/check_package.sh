#!/usr/bin/env bash
# scripts/check_package.sh DEB: install the built Debian package with apt on this machine, check what it
# installed, then remove it again (./run.sh package --check). Needs root or sudo. Refuses to run when a
# killswitch package is already installed, so it never removes one it did not install.
#   - both programs run from /tmp and print their version; the bot wins the installed main level headless;
#   - the shared libraries all resolve (the package's dependencies are complete);
#   - the desktop entries, AppStream metadata and manual pages validate; the icons are in the theme;
#   - a level the installed editor saves into the user levels folder is listed by the installed game.
set -euo pipefail
[ $# -eq 1 ] && [ -f "$1" ] || { echo "usage: $0 build/package/killswitch_VERSION_amd64.deb" >&2; exit 2; }
deb="$(readlink -f "$1")"
version="$(dpkg-deb -f "$deb" Version)"
sudo=""
[ "$(id -u)" -ne 0 ] && sudo="sudo"
say() { printf '\033[1;34m[check_package]\033[0m %s\n' "$*" >&2; }
fail() { printf '\033[1;31m[check_package]\033[0m %s\n' "$*" >&2; exit 1; }

if dpkg-query -W -f='${Status}' killswitch 2>/dev/null | grep -q "install ok installed"; then
    fail "a killswitch package is installed already; remove it first (apt remove killswitch)"
fi
say "apt install $deb"
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "$deb" >/dev/null
remove() {
    say "apt remove killswitch"
    DEBIAN_FRONTEND=noninteractive $sudo apt-get remove -y -qq killswitch >/dev/null
    [ ! -e /usr/games/killswitch ] && [ ! -e /usr/share/killswitch ] || fail "files left after apt remove"
}
trap remove EXIT

cd "$(mktemp -d)"
broken="$(find /usr/share/killswitch -xtype l)"
[ -z "$broken" ] || fail "links to nothing in the package: $broken"
# Debian's games layout: the programs are in /usr/games (on users' PATH; not on root's).
for program in killswitch killswitch-editor; do
    path="/usr/games/$program"
    [ -x "$path" ] || fail "$path is not installed"
    out="$(env -u DISPLAY "$path" --version)"
    [ "$out" = "$program $version" ] || fail "$path --version printed '$out', not '$program $version'"
    if ldd "$path" | grep -q "not found"; then
        ldd "$path" | grep "not found" >&2
        fail "$path: shared libraries missing (the package's Depends are incomplete)"
    fi
    say "$path --version: $out"
done
summary="$(env -u DISPLAY -u KS_DATA_DIR /usr/games/killswitch --headless --autoplay --seed 1 --seconds 200)"
case "$summary" in win\ after*) ;; *) fail "the installed game's bot did not win: $summary" ;; esac
say "installed killswitch --headless --autoplay from $PWD: $summary"

# The windowed programs with the installed shaders and the fonts linked from fonts-dejavu-core (under a
# virtual display when there is none; skipped without xvfb-run).
if command -v xvfb-run >/dev/null; then
    for program in killswitch killswitch-editor; do
        args=(--width 640 --height 360 --frames 5 --screenshot "$PWD/$program.png")
        [ "$program" = killswitch ] && args+=(--screen menu)
        xvfb-run -a -s "-screen 0 1280x720x24 -noreset" "/usr/games/$program" "${args[@]}" >"$program.log" 2>&1 ||
            { cat "$program.log" >&2; fail "/usr/games/$program could not draw its window"; }
        [ -s "$program.png" ] || fail "/usr/games/$program wrote no screenshot"
        if grep -E '^\[(warning|error)\]' "$program.log" >&2; then
            fail "/usr/games/$program warned while starting (above): an installed file is missing or unreadable"
        fi
    done
    say "both programs drew their windows (screenshots in $PWD)"

    # A designer's level: saved by the installed editor into the user levels folder, listed by the
    # installed game's Custom level... screen (both under a scratch XDG_DATA_HOME), and won by its bot.
    export XDG_DATA_HOME="$PWD/data"
    levels="$XDG_DATA_HOME/killswitch/levels"
    mkdir -p "$levels"
    cat >designer.kss <<KSS
level_name A designer's level
place floor at 0,0,0 name Ground
set size 20,20
place control_panel at 0,0,-6 name Panel
player_start 0,0,6
objective add shutdown Shut the simulation down
link 2 add on_use shutdown complete
prefab place doorway at 0,0,-9
save $levels/designers_level.json
KSS
    env -u DISPLAY /usr/games/killswitch-editor --script designer.kss >editor_script.log 2>&1 ||
        { cat editor_script.log >&2; fail "the installed editor could not build and save a level"; }
    xvfb-run -a -s "-screen 0 1280x720x24 -noreset" /usr/games/killswitch --screen custom-levels \
        --status-file custom.txt --width 640 --height 360 --frames 5 --screenshot "$PWD/custom.png" \
        >custom.log 2>&1 || { cat custom.log >&2; fail "the installed game's Custom level screen failed"; }
    grep -q "^custom_level .* ok designers_level.json A designer's level$" custom.txt ||
        { cat custom.txt >&2; fail "the installed game does not list the level the installed editor saved"; }
    won="$(env -u DISPLAY /usr/games/killswitch --headless --autoplay --level "$levels/designers_level.json")"
    case "$won" in win\ after*) ;; *) fail "the bot did not win the designer's level: $won" ;; esac
    unset XDG_DATA_HOME
    say "a level saved by the installed editor (with the shipped doorway prefab) is listed and won by the installed game"
fi

desktop-file-validate /usr/share/applications/killswitch.desktop /usr/share/applications/killswitch-editor.desktop
appstreamcli validate --no-net --override=cid-desktopapp-is-not-rdns=info \
    /usr/share/metainfo/killswitch.metainfo.xml /usr/share/metainfo/killswitch-editor.metainfo.xml >/dev/null
for page in /usr/share/man/man6/killswitch.6.gz /usr/share/man/man1/killswitch-editor.1.gz; do
    warnings="$(LC_ALL=C.UTF-8 MANROFFSEQ='' MANWIDTH=80 man --warnings -E UTF-8 -l -Tutf8 -Z "$page" 2>&1 >/dev/null)"
    [ -z "$warnings" ] || fail "$page: $warnings"
done
for size in 16 24 32 48 64 128 256; do
    for name in killswitch killswitch-editor; do
        [ -f "/usr/share/icons/hicolor/${size}x${size}/apps/$name.png" ] || fail "no ${size}x${size} icon $name"
    done
done
say "desktop entries, metadata, manual pages and icons valid"
