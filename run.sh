#!/usr/bin/env bash
# Killswitch: one entry point for players, designers and CI.
#   ./run.sh play     build (Release) the game only and start it
#   ./run.sh test     build and run every test once (under xvfb-run when there is no display): the
#                     Release build (everything, and the suites that judge a picture, a timing or the build
#                     itself), then an ASan+UBSan build (build-asan/, -O1) that runs all the others; what CI runs
#                     (./run.sh test --release: Release only; ./run.sh test --sanitize: ASan+UBSan only)
#   ./run.sh editor   build the level editor (and the game, which its play-test starts) and start it
#   ./run.sh bench    build and run the benchmarks (tables on stdout, plots in docs/bench/)
#                     (./run.sh bench fuzz [SECONDS]: each libFuzzer target for SECONDS, default 60;
#                     ./run.sh bench fuzz-valgrind [TARGET...]: the kept fuzz corpora replayed under valgrind)
#   ./run.sh package  build (Release) and make the Debian package build/package/killswitch_<version>_amd64.deb,
#                     then check it with lintian (./run.sh package --check: also install it with apt, run
#                     both programs from it, validate its desktop files and remove it again; needs root/sudo)
# Extra arguments after the command go to the program, e.g. ./run.sh play --level levels/dojo.json
set -euo pipefail
cd "$(dirname "$(readlink -f "$0")")"

# The one list of Debian packages the project needs (build, run, test, bench).
PACKAGES=(
    build-essential cmake pkg-config git ccache
    libglfw3-dev libepoxy-dev libgl-dev libimgui-dev libglm-dev libassimp-dev nlohmann-json3-dev
    libstb-dev doctest-dev zlib1g-dev librecast-dev libopenal-dev libqhull-dev libmeshoptimizer-dev
    xvfb xauth libgl1-mesa-dri mesa-utils xdotool
    gnuplot-nox
    desktop-file-utils appstream groff-base
)
# Only for `./run.sh bench fuzz` (libFuzzer needs clang and its runtime) and `./run.sh bench fuzz-valgrind`
# (the same targets built plainly, under valgrind); installed on first use.
FUZZ_PACKAGES=(clang libclang-rt-14-dev valgrind)
# Only for `./run.sh package`: CPack's dependency lookup (dpkg-shlibdeps), fakeroot and the package checker.
PACKAGE_PACKAGES=(dpkg-dev fakeroot file lintian)

log() { printf '\033[1;34m[run.sh]\033[0m %s\n' "$*" >&2; }
die() { printf '\033[1;31m[run.sh]\033[0m %s\n' "$*" >&2; exit 1; }

install_missing_packages() { # [extra packages...]
    local missing=()
    for p in "${PACKAGES[@]}" "$@"; do
        dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
    done
    [ ${#missing[@]} -eq 0 ] && return 0
    command -v apt-get >/dev/null || die "missing packages (${missing[*]}) and no apt-get: this needs Debian 12"
    local sudo=""
    if [ "$(id -u)" -ne 0 ]; then
        command -v sudo >/dev/null || die "missing packages (${missing[*]}): run as root or install sudo"
        sudo="sudo"
    fi
    log "installing missing packages: ${missing[*]}"
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
}

# When both passes run, every test runs once. The Release pass runs the suites a sanitizer cannot improve:
# those that judge a picture or a timing (pixels of menus, views, particles, the rifle and its shadows, brushes and their frame times; idle
# CPU), whose code paths run sanitized in the real-input suites and render/test_render_gl(_main_level), and the build-system
# checks (tooling/: module boundaries, the install tree), which test CMake rather than our code. The sanitized
# pass runs all the others, the real-input window suites (xdotool) among them: their assertions, ImGui's
# included, are on only there. docs/building.md, "Build times", has the measurements behind the split.
PICTURE_TESTS='^(runtime/test_(game_app|play_views|dojo_views|play_feedback|menu_layout|idle_cpu)|render/test_render_(feedback|brushes))$'
RELEASE_ONLY_TESTS="^tooling/|${PICTURE_TESTS}"

njobs() { nproc 2>/dev/null || echo 2; }

# The compiler cache (ccache, in PACKAGES). Paths are hashed relative to the tree (CCACHE_BASEDIR) and not by
# the build folder (CCACHE_NOHASHDIR: the sanitized build's line tables then name the folder that compiled an
# object first), so a clone in another folder (CI's) reuses what a build of the same sources here compiled;
# an object's own absolute paths (KS_SOURCE_DIR, KS_BIN_DIR: only paths.cpp, test_support.cpp, ks_bench) are
# in its flags and so in its hash. Only read at configure time: a build folder configured without it keeps
# compiling without it.
use_compiler_cache() {
    command -v ccache >/dev/null || return 0
    export CMAKE_C_COMPILER_LAUNCHER=ccache CMAKE_CXX_COMPILER_LAUNCHER=ccache
    export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=1
}

build() { # build PRESET [TARGET...]
    local preset="$1"
    shift
    use_compiler_cache
    if [ ! -f "$(preset_dir "$preset")/CMakeCache.txt" ]; then
        log "configuring ($preset)"
        cmake --preset "$preset" >/dev/null
    fi
    local targets=()
    [ $# -gt 0 ] && targets=(--target "$@")
    log "building ($preset${*:+: $*})"
    cmake --build --preset "$preset" -j "$(njobs)" "${targets[@]}"
}

preset_dir() {
    case "$1" in release) echo build ;; debug) echo build-debug ;; asan) echo build-asan ;; esac
}

with_display() { # run a command, under a virtual X server when there is no display
    if [ -n "${DISPLAY:-}" ] || [ -n "${WAYLAND_DISPLAY:-}" ]; then
        "$@"
    else
        # -noreset: by default Xvfb resets when its last client leaves, and a test that connects during
        # that reset fails with "cannot open display" (seen in CI).
        xvfb-run -a -s "-screen 0 1280x720x24 -noreset" "$@"
    fi
}

cmd="${1:-}"
[ $# -gt 0 ] && shift
case "$cmd" in
    play)
        install_missing_packages
        # Only what it runs: not the tests, benchmarks or the editor (docs/building.md, "Build times").
        build release killswitch
        # Without a display, killswitch explains how to use xvfb-run and exits non-zero.
        exec ./build/bin/killswitch "$@"
        ;;
    editor)
        install_missing_packages
        build release killswitch-editor killswitch
        exec ./build/bin/killswitch-editor "$@"
        ;;
    test)
        install_missing_packages
        presets=(release asan)
        case "${1:-}" in
            --release) presets=(release); shift ;;
            --sanitize) presets=(asan); shift ;;
        esac
        for preset in "${presets[@]}"; do
            if [ "$preset" = asan ]; then
                # The asan build holds only what the suite needs (ks_tests and the binaries the GL tests
                # start), not the benchmarks. Every sanitizer report aborts its test: -fno-sanitize-recover
                # in the build, abort_on_error here; LeakSanitizer on (third-party leaks with readable stacks
                # may be suppressed by library name in .ci/lsan.supp, never ours).
                # quarantine_size_mb: freed memory waits in a 32 MB quarantine before reuse (ASan's default is
                # 256): a use after free is still caught unless 32 MB were freed in between, and the GL suites
                # touch half the memory (docs/building.md, "Build times").
                export ASAN_OPTIONS="${ASAN_OPTIONS:-abort_on_error=1:detect_leaks=1:check_initialization_order=1:strict_init_order=1:quarantine_size_mb=32}"
                export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
                export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$PWD/.ci/lsan.supp:print_suppressions=0}"
                build asan ks_tests
            else
                # ks_tests and the binaries its GL suites start (the game, the editor, the asset generator),
                # not the benchmarks: ./run.sh bench builds those (docs/building.md, "Build times").
                build release ks_tests
            fi
            log "running tests ($preset)"
            if [ "$preset" = asan ]; then
                # The GL suites (render/, runtime/: they open a context in Mesa's llvmpipe) run without
                # LeakSanitizer: Mesa leaks 240 bytes at GL start-up from code built without frame pointers,
                # so the stacks are garbage and no suppression can name the library. ASan and UBSan stay on.
                non_gl='^(render|runtime)/'
                gl_skipped='^$'
                if [ ${#presets[@]} -gt 1 ]; then
                    non_gl='^(render|runtime|tooling)/'
                    gl_skipped="$PICTURE_TESTS"
                fi
                with_display ctest --test-dir build-asan --output-on-failure -j "$(njobs)" -E "$non_gl" "$@"
                ASAN_OPTIONS="${ASAN_OPTIONS/detect_leaks=1/detect_leaks=0}" \
                    with_display ctest --test-dir build-asan --output-on-failure -j "$(njobs)" -R '^(render|runtime)/' \
                    -E "$gl_skipped" "$@"
            elif [ ${#presets[@]} -gt 1 ]; then
                # Both passes: the Release pass runs what the sanitized pass leaves out (see RELEASE_ONLY_TESTS).
                with_display ctest --test-dir build --output-on-failure -j "$(njobs)" -R "$RELEASE_ONLY_TESTS" "$@"
            else
                with_display ctest --test-dir build --output-on-failure -j "$(njobs)" "$@"
            fi
        done
        ;;
    bench)
        if [ "${1:-}" = "fuzz" ]; then # ./run.sh bench fuzz [seconds per target]: libFuzzer, crashes -> tests/data/fuzz/
            install_missing_packages "${FUZZ_PACKAGES[@]}"
            shift
            exec scripts/fuzz.sh "${1:-60}"
        fi
        if [ "${1:-}" = "fuzz-valgrind" ]; then # ./run.sh bench fuzz-valgrind [TARGET...]: the kept corpora under valgrind
            install_missing_packages "${FUZZ_PACKAGES[@]}"
            shift
            exec scripts/fuzz_valgrind.sh "$@"
        fi
        install_missing_packages
        build release
        mkdir -p docs/bench
        with_display ./build/bin/ks_bench "${@:-all}"
        ;;
    package)
        install_missing_packages "${PACKAGE_PACKAGES[@]}"
        build release
        log "packaging (cpack -G DEB)"
        rm -f build/package/killswitch_*.deb
        (cd build && cpack -G DEB >/dev/null)
        deb="$(ls build/package/killswitch_*_amd64.deb)"
        log "lintian $deb"
        lintian --display-info --fail-on error "$deb"
        log "built $deb ($(du -h "$deb" | cut -f1))"
        if [ "${1:-}" = "--check" ]; then
            exec scripts/check_package.sh "$deb"
        fi
        ;;
    ""|-h|--help|help)
        sed -n '2,13p' "$0" | sed 's/^# \{0,1\}//'
        ;;
    *)
        die "unknown command '$cmd' (use play, test, editor, bench or package)"
        ;;
esac
