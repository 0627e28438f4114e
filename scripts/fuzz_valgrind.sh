#!/usr/bin/env bash
# Replays the fuzz inputs under valgrind (memcheck) in a plain build of the targets (fuzz/ with
# KS_FUZZ_PLAIN=ON: no libFuzzer, no sanitizers, fuzz/replay_main.cpp as main). The sanitizers see only the
# code they instrument, so a read or write past a buffer inside Debian's assimp (or Recast, Qhull) shows in
# a fuzz run only when it crashes; valgrind sees it anywhere in the process.
#   scripts/fuzz_valgrind.sh [TARGET...]      (default: fuzz_model_import, the one reaching most library code)
# Inputs: the kept corpus fuzz/corpus/<target>.tar.xz, or KS_FUZZ_INPUTS (a folder) instead, and
# tests/data/fuzz/<target>/ (seeds and findings). KS_FUZZ_PLAIN_BUILD: the build folder (default
# build-fuzz-plain). valgrind's report: <build>/valgrind/<target>.log (the target's own messages beside it,
# .stderr); exits 1 when it found an error.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
targets=("$@")
(( ${#targets[@]} )) || targets=(fuzz_model_import)
build=${KS_FUZZ_PLAIN_BUILD:-$root/build-fuzz-plain}

for tool in clang++ valgrind; do
    if ! command -v "$tool" >/dev/null; then
        echo "fuzz_valgrind.sh: $tool not found (Debian: apt-get install clang valgrind)" >&2
        exit 2
    fi
done
cmake -S "$root/fuzz" -B "$build" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DKS_FUZZ_PLAIN=ON >/dev/null
cmake --build "$build" -j"$(nproc 2>/dev/null || echo 2)" --target "${targets[@]}"

status=0
for target in "${targets[@]}"; do
    inputs=$build/inputs/$target
    log=$build/valgrind/$target.log
    rm -rf "$inputs"
    mkdir -p "$inputs" "$(dirname "$log")"
    if [[ -n ${KS_FUZZ_INPUTS:-} ]]; then
        cp "$KS_FUZZ_INPUTS"/* "$inputs/"
    elif [[ -f $root/fuzz/corpus/$target.tar.xz ]]; then
        tar -xJf "$root/fuzz/corpus/$target.tar.xz" -C "$inputs"
    fi
    find "$root/tests/data/fuzz/$target" -maxdepth 1 -type f -exec cp {} "$inputs/" \; 2>/dev/null || true
    count=$(find "$inputs" -maxdepth 1 -type f | wc -l)
    echo "== $target: $count inputs under valgrind (log: $log)"
    # Leaks are not errors here (assimp's are known, and LSan covers ours in the fuzz runs).
    start=$(date +%s)
    if valgrind --error-exitcode=99 --leak-check=no --log-file="$log" "$build/bin/$target" "$inputs" \
        >/dev/null 2>"${log%.log}.stderr"; then
        echo "   clean: no invalid read, write, free or uninitialised jump in $(($(date +%s) - start)) s"
    else
        echo "   valgrind reported errors (or the target stopped): $log" >&2
        grep -h -m 5 -E "Invalid|uninitialised|Process terminating|fuzz property" "$log" "${log%.log}.stderr" >&2 || true
        status=1
    fi
done
exit $status
