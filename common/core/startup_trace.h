#pragma once
// The start-up trace: when KS_STARTUP_TRACE names a file, each mark() appends one line to it,
//   PHASE <tab> monotonic ns <tab> this thread's CPU ns <tab> the process's CPU ns
// (CLOCK_MONOTONIC is one clock for every process, so a launcher that noted the time before exec() reads the
// time spent in the dynamic linker from the first line). scripts/startup_bench.py launches the game with it
// and reads the file back (docs/performance.md, "Start-up"). Unset, a mark costs one branch.
#include <string_view>

namespace ks::startup {

// True when KS_STARTUP_TRACE was set when the process first asked.
bool enabled();
// Appends PHASE's line (a phase name without tabs or newlines). The trace follows the thread of the first
// mark (main()): marks from other threads (work started early on a worker) are left out, so every line's CPU
// column is that thread's. Thread-safe; never fails loudly: a file that cannot be written turns the trace
// off.
void mark(std::string_view phase);

} // namespace ks::startup
