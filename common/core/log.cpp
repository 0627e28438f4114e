#include "core/log.h"

#include <cstdio>
#include <mutex>

namespace ks::log {
namespace {
std::mutex g_mutex;
Sink g_sink;
Level g_min_level = Level::Info;
} // namespace

const char* level_name(Level level) {
    switch (level) {
    case Level::Debug: return "debug";
    case Level::Info: return "info";
    case Level::Warn: return "warning";
    case Level::Error: return "error";
    }
    return "?";
}

Sink set_sink(Sink sink) {
    std::lock_guard lock(g_mutex);
    Sink previous = std::move(g_sink);
    g_sink = std::move(sink);
    return previous;
}

void set_min_level(Level level) { g_min_level = level; }
Level min_level() { return g_min_level; }

void write(Level level, std::string_view message) {
    std::lock_guard lock(g_mutex);
    if (g_sink) {
        g_sink(level, message);
        return;
    }
    std::fprintf(stderr, "[%s] %.*s\n", level_name(level), static_cast<int>(message.size()), message.data());
}

Capture::Capture() {
    previous_ = set_sink([this](Level level, std::string_view message) {
        text_ += level_name(level);
        text_ += ": ";
        text_ += message;
        text_ += '\n';
        ++counts_[static_cast<int>(level)];
    });
}

Capture::~Capture() { set_sink(std::move(previous_)); }

int Capture::count(Level level) const { return counts_[static_cast<int>(level)]; }

} // namespace ks::log
