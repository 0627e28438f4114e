#!/usr/bin/env bash
# scripts/check_package.sh DEB: install the built Debian package with apt on this machine, check what it
# installed, then remove it again (./run.sh package --check). Needs root or sudo. Refuses to run when a
# killswitch package is already installed, so it never removes one it did not install.
#   - both programs run from /tmp and print their version; the bot wins the installed main level headless;
#   - the shared libraries all resolve (the package's dependencies are complete);
#   - the desktop entries, AppStream metadata and manual pages validate; the icons are in the theme.
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
