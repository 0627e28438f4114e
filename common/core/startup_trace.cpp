#include "core/startup_trace.h"

#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <mutex>
#include <optional>
#include <thread>

namespace ks::startup {
namespace {

struct Trace {
    std::mutex mutex;
    std::FILE* file = nullptr;
    std::optional<std::thread::id> main; // the thread of the first mark: the only one traced
    Trace() {
        if (const char* path = std::getenv("KS_STARTUP_TRACE"); path && *path) file = std::fopen(path, "a");
    }
};

Trace& trace() {
    static Trace t;
    return t;
}

long long now_ns(clockid_t clock) {
    timespec ts{};
    clock_gettime(clock, &ts);
    return static_cast<long long>(ts.tv_sec) * 1000000000LL + ts.tv_nsec;
}

} // namespace

bool enabled() {
    return trace().file != nullptr;
}

void mark(std::string_view phase) {
    Trace& t = trace();
    if (!t.file) return;
    const long long mono = now_ns(CLOCK_MONOTONIC), thread = now_ns(CLOCK_THREAD_CPUTIME_ID),
                    process = now_ns(CLOCK_PROCESS_CPUTIME_ID);
    const std::lock_guard lock(t.mutex);
    if (!t.file) return;
    if (!t.main) t.main = std::this_thread::get_id();
    if (*t.main != std::this_thread::get_id()) return;
    const int written = std::fprintf(t.file, "%.*s\t%lld\t%lld\t%lld\n", static_cast<int>(phase.size()),
                                     phase.data(), mono, thread, process);
    if (written < 0 || std::fflush(t.file) != 0) {
        std::fclose(t.file);
        t.file = nullptr;
    }
}

} // namespace ks::startup
