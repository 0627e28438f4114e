#include "core/startup_trace.h"

#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <mutex>
#include <string>

namespace ks::startup {
namespace {

struct Trace {
    std::mutex mutex;
    std::FILE* file = nullptr;
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

bool read_number(std::string_view& rest, long long& out) {
    const std::size_t tab = rest.find('\t');
    const std::string_view field = rest.substr(0, tab);
    const auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), out);
    if (ec != std::errc() || end != field.data() + field.size() || field.empty()) return false;
    rest = tab == std::string_view::npos ? std::string_view() : rest.substr(tab + 1);
    return true;
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
    const int written = std::fprintf(t.file, "%.*s\t%lld\t%lld\t%lld\n", static_cast<int>(phase.size()),
                                     phase.data(), mono, thread, process);
    if (written < 0 || std::fflush(t.file) != 0) {
        std::fclose(t.file);
        t.file = nullptr;
    }
}

bool parse_mark(std::string_view line, Mark& out) {
    if (!line.empty() && line.back() == '\n') line.remove_suffix(1);
    const std::size_t tab = line.find('\t');
    if (tab == std::string_view::npos || tab == 0) return false;
    out.phase = line.substr(0, tab);
    std::string_view rest = line.substr(tab + 1);
    return read_number(rest, out.monotonic_ns) && read_number(rest, out.thread_cpu_ns) &&
           read_number(rest, out.process_cpu_ns) && rest.empty();
}

} // namespace ks::startup
