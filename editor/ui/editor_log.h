#pragma once
// The editor window's log: the lines the Log panel shows (editor messages, the model's log, the play-test's
// output), the last 500 of them, and the error count and last error the status file reports.
#include "core/result.h"

#include <cstdint>
#include <deque>
#include <string>
#include <utility>

namespace ks::editor::ui {

class EditorLog {
  public:
    void line(std::string text, bool error = false) {
        if (error) ++error_lines_, last_error_ = text;
        lines_.emplace_back(std::move(text), error);
        while (lines_.size() > kMaxLines) lines_.pop_front();
        ++revision_;
    }
    // An edit's result: nothing when it succeeded, "what: message" as an error otherwise.
    void report(const Result<void>& result, const char* what) {
        if (!result) line(std::string(what) + ": " + result.error().str(), true);
    }
    void clear() { lines_.clear(), ++revision_; }

    const std::deque<std::pair<std::string, bool>>& lines() const { return lines_; } // text, error
    int error_lines() const { return error_lines_; } // every error line since start-up (Clear keeps it)
    const std::string& last_error() const { return last_error_; }
    std::uint64_t revision() const { return revision_; } // counts additions and clears

  private:
    static constexpr std::size_t kMaxLines = 500;
    std::deque<std::pair<std::string, bool>> lines_;
    int error_lines_ = 0;
    std::string last_error_;
    std::uint64_t revision_ = 0;
};

} // namespace ks::editor::ui
