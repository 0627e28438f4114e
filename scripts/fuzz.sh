#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/, clang) and runs each for a bounded time.
#   scripts/fuzz.sh [SECONDS_PER_TARGET] [TARGET...]      (default 60 s, all seven targets)
# Environment: KS_FUZZ_BUILD (build folder, default build-fuzz), KS_FUZZ_FLAGS (extra libFuzzer flags),
# KS_FUZZ_NO_BUILD=1 (run the targets already built there), KS_FUZZ_TIMEOUT (seconds one input may take,
# default 30: wall-clock, so generous on a shared machine), KS_FUZZ_MAX_LEN (default 32768 bytes: the largest
# shipped file is 18 KB; bigger seeds such as the 200 KB nesting bomb are cut to this for mutation).
# The growing corpus stays in $KS_FUZZ_BUILD/corpus/<target>; seeds are read from the shipped files and the
# test corpora, and the kept corpus fuzz/corpus/<target>.tar.xz (minimised, in the repository) is unpacked into
# it first. A "slow unit" (an input over 10 s) is replayed alone and kept only if it is slow again (one in
# flight while the fuzzer was paused is not a finding). KS_FUZZ_SAVE_CORPUS=1: after each run the corpus is minimised (libFuzzer -merge=1) and written
# back to fuzz/corpus/<target>.tar.xz. Any crash, timeout, leak or out-of-memory input is copied to tests/data/fuzz/<target>/,
# where the GCC regression tests (tests/{level,anim,editor}/test_fuzz_regressions.cpp) replay it; the script
# then exits 1.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
seconds=${1:-60}
shift || true
if ! [[ $seconds =~ ^[0-9]+$ ]] || (( seconds < 1 )); then
    echo "fuzz.sh: SECONDS_PER_TARGET must be a positive whole number, got '$seconds'" >&2
    exit 2
fi
targets=("$@")
(( ${#targets[@]} )) || targets=(fuzz_level_loader fuzz_campaign_loader fuzz_clip_loader fuzz_editor_script fuzz_prefab_loader
    fuzz_brush_ops fuzz_model_import)
build=${KS_FUZZ_BUILD:-$root/build-fuzz}
jobs=$(nproc 2>/dev/null || echo 2)

if ! command -v clang++ >/dev/null; then
    echo "fuzz.sh: clang++ not found (Debian: apt-get install clang libclang-rt-dev)" >&2
    exit 2
fi
if [[ ${KS_FUZZ_NO_BUILD:-0} != 1 ]]; then
    cmake -S "$root/fuzz" -B "$build" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
    cmake --build "$build" -j"$jobs" --target "${targets[@]}"
fi

seeds_for() {
    case $1 in
    fuzz_level_loader) echo "$root/levels $root/tests/data/levels/good $root/tests/data/levels/bad" ;;
    fuzz_campaign_loader) echo "$root/levels $root/tests/data/campaign" ;;
    fuzz_clip_loader) echo "$root/assets/animations $root/tests/data/anim/bad" ;;
    fuzz_editor_script) echo "" ;;
    fuzz_prefab_loader) echo "$root/prefabs" ;;
    fuzz_brush_ops) echo "" ;;
    fuzz_model_import) echo "" ;; # seeds: tests/data/fuzz/fuzz_model_import/seed-* (a format byte, then the file)
    *) echo "fuzz.sh: unknown target '$1'" >&2; exit 2 ;;
    esac
}
dict_for() {
    case $1 in
    fuzz_level_loader) echo "$root/fuzz/level.dict" ;;
    fuzz_campaign_loader) echo "$root/fuzz/campaign.dict" ;;
    fuzz_clip_loader) echo "$root/fuzz/clip.dict" ;;
    fuzz_editor_script) echo "$root/fuzz/script.dict" ;;
    fuzz_prefab_loader) echo "$root/fuzz/level.dict" ;;
    fuzz_brush_ops) echo "" ;;
    fuzz_model_import) echo "$root/fuzz/model.dict" ;;
    esac
}

# Assimp's OBJ reader allocates and fills a 16 MB buffer per input, so the model import target spends most of
# its time in page faults; with transparent huge pages always on it runs about 2.5x as many inputs a second
# (docs/reliability.md, session 26). A system setting, so only a note.
thp=/sys/kernel/mm/transparent_hugepage/enabled
if [[ " ${targets[*]} " == *" fuzz_model_import "* && -r $thp ]] && ! grep -q '\[always\]' "$thp"; then
    echo "fuzz.sh: note: transparent huge pages are not always on ($(cat "$thp")); fuzz_model_import runs" \
        "about 2.5x faster with them (as root: echo always > $thp)" >&2
fi

status=0
summary=()
for target in "${targets[@]}"; do
    corpus=$build/corpus/$target
    artifacts=$build/artifacts/$target
    regressions=$root/tests/data/fuzz/$target
    log=$build/logs/$target.log
    mkdir -p "$corpus" "$artifacts" "$regressions" "$(dirname "$log")"
    rm -f "$artifacts"/*
    # Hand-written seeds join the corpus; known crash files stay out of it, or an unfixed bug would stop
    # every run at start-up (the regression tests replay them instead).
    find "$regressions" -maxdepth 1 -type f -name 'seed-*' -exec cp -n {} "$corpus/" \;
    kept=$root/fuzz/corpus/$target.tar.xz
    [[ -f $kept ]] && tar -xJf "$kept" -C "$corpus" --skip-old-files
    echo "== $target: ${seconds}s (log: $log)"
    # The first folder receives new inputs; the seed folders are only read.
    dict=$(dict_for "$target")
    # assimp 5.2.5 (Debian's, not ours) leaks on malformed files; its leaks are reported in
    # docs/reliability.md, and checking for them would stop the model target at its first bad file.
    leaks=1
    [[ $target == fuzz_model_import ]] && leaks=0
    set +e
    # shellcheck disable=SC2046 # the seed list is meant to split into folders
    ASAN_OPTIONS=${ASAN_OPTIONS:-}:detect_leaks=$leaks "$build/bin/$target" "$corpus" $(seeds_for "$target") \
        ${dict:+-dict="$dict"} -detect_leaks=$leaks \
        -max_total_time="$seconds" -timeout="${KS_FUZZ_TIMEOUT:-30}" -max_len="${KS_FUZZ_MAX_LEN:-32768}" -rss_limit_mb=2048 \
        -artifact_prefix="$artifacts/" -print_final_stats=1 ${KS_FUZZ_FLAGS:-} >"$log" 2>&1
    rc=$?
    set -e
    found=0
    for artifact in "$artifacts"/crash-* "$artifacts"/timeout-* "$artifacts"/leak-* "$artifacts"/oom-* "$artifacts"/slow-unit-*; do
        [[ -e $artifact ]] || continue
        # libFuzzer reports an input over 10 s of wall time as slow; one that was in flight while the machine
        # was paused or busy (a benchmark stopping the fuzzer) is not: it is kept only if it is slow again alone.
        if [[ $(basename "$artifact") == slow-unit-* ]]; then
            started=$(date +%s%N)
            ASAN_OPTIONS=${ASAN_OPTIONS:-}:detect_leaks=0 "$build/bin/$target" "$artifact" >/dev/null 2>&1 || true
            took_ms=$((($(date +%s%N) - started) / 1000000))
            if ((took_ms < 10000)); then
                echo "   not kept: $(basename "$artifact") (replays in $took_ms ms: slow only in the run)"
                rm -f "$artifact"
                continue
            fi
        fi
        cp -n "$artifact" "$regressions/"
        echo "   found: $regressions/$(basename "$artifact")"
        found=$((found + 1))
    done
    execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
    speed=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
    cov=$(grep -Eo 'cov: [0-9]+ ft: [0-9]+ corp: [0-9]+' "$log" | tail -1 || true)
    summary+=("$target: ${execs:-?} execs, ${speed:-?} exec/s, ${cov:-no coverage line}, exit $rc, $found new finding(s)")
    if (( rc != 0 || found > 0 )); then status=1; fi
    if [[ ${KS_FUZZ_SAVE_CORPUS:-0} == 1 && $rc == 0 && $found == 0 ]]; then
        minimised=$(mktemp -d)
        ASAN_OPTIONS=${ASAN_OPTIONS:-}:detect_leaks=0 "$build/bin/$target" -merge=1 -rss_limit_mb=2048 \
            -max_len="${KS_FUZZ_MAX_LEN:-32768}" "$minimised" "$corpus" >>"$log" 2>&1
        mkdir -p "$root/fuzz/corpus"
        tar --sort=name --mtime=@0 --owner=0 --group=0 --numeric-owner -cJf "$kept" -C "$minimised" .
        echo "   kept: $kept ($(find "$minimised" -type f | wc -l) inputs)"
        rm -rf "$minimised"
    fi
done

echo "== summary"
printf '   %s\n' "${summary[@]}"
exit $status
