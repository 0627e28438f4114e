#pragma once
// Minimal levelled logging to stderr, with a replaceable sink so tests can capture what was said.
#include <functional>
#include <sstream>
#include <string>
#include <string_view>

namespace ks::log {

enum class Level { Debug, Info, Warn, Error };

using Sink = std::function<void(Level, std::string_view)>;

// Replaces the sink (nullptr restores stderr); returns the previous one.
Sink set_sink(Sink sink);
void set_min_level(Level level);
Level min_level();
void write(Level level, std::string_view message);
const char* level_name(Level level);

template <class... Args>
std::string concat(const Args&... args) {
    std::ostringstream out;
    (out << ... << args);
    return out.str();
}

template <class... Args>
void debug(const Args&... args) {
    if (min_level() <= Level::Debug) write(Level::Debug, concat(args...));
}
template <class... Args>
void info(const Args&... args) {
    if (min_level() <= Level::Info) write(Level::Info, concat(args...));
}
template <class... Args>
void warn(const Args&... args) {
    write(Level::Warn, concat(args...));
}
template <class... Args>
void error(const Args&... args) {
    write(Level::Error, concat(args...));
}

// Captures log lines for the lifetime of the object (tests).
class Capture {
public:
    Capture();
    ~Capture();
    Capture(const Capture&) = delete;
    Capture& operator=(const Capture&) = delete;
    const std::string& text() const { return text_; }
    int count(Level level) const;

private:
    std::string text_;
    int counts_[4] = {0, 0, 0, 0};
    Sink previous_;
};

} // namespace ks::log
