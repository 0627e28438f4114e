#pragma once
// The start-up trace: when KS_STARTUP_TRACE names a file, each mark() appends one line to it,
//   PHASE <tab> monotonic ns <tab> this thread's CPU ns <tab> the process's CPU ns
// (CLOCK_MONOTONIC is one clock for every process, so a launcher that noted the time before exec() reads the
// time spent in the dynamic linker from the first line). `ks_bench startup` launches the game with it and
// reads the file back (docs/performance.md, "Start-up"). Unset, a mark costs one branch.
#include <string_view>

namespace ks::startup {

// True when KS_STARTUP_TRACE was set when the process first asked.
bool enabled();
// Appends PHASE's line (a phase name without tabs or newlines). Thread-safe; never fails loudly: a file that
// cannot be written turns the trace off.
void mark(std::string_view phase);

// One line read back.
struct Mark {
    std::string_view phase;
    long long monotonic_ns = 0, thread_cpu_ns = 0, process_cpu_ns = 0;
};
// Parses one line of the file; false when it is not a mark's line.
bool parse_mark(std::string_view line, Mark& out);

} // namespace ks::startup
