#pragma once
// Where readers send what they find in a file: each problem an error or a warning, pinned to a JSON path
// and, through the document's position map, to its line:column. Every reader of every file kind reports
// the same way (docs/level-format.md, "One strictness"): problems with the document, a wrong type, a value
// out of range or a missing required field are errors; an unknown field is a warning with a did-you-mean.
#include "core/result.h"
#include "jsonio/position_map.h"

#include <set>
#include <string>
#include <vector>

namespace ks::jsonio {

enum class Severity { Warning, Error };

class ProblemSink {
  public:
    virtual ~ProblemSink() = default;
    // A problem with the value at `path`; the sink finds its place.
    virtual void report(Severity severity, const std::string& path, std::string message,
                        std::string hint) = 0;
    // A problem at a known place (the document's own checks: syntax, a duplicate key, ...).
    virtual void report_at(Severity severity, TextPosition position, const std::string& path,
                           std::string message, std::string hint) = 0;
    // A path whose value was already reported (a number that overflowed before parsing): readers say
    // nothing more about it, so one mistake gives one message.
    virtual void mark_reported(const std::string& path) { reported_.insert(path); }
    virtual bool already_reported(const std::string& path) const { return reported_.count(path) > 0; }
    // Whether any path was marked: when none was, a reader may skip building a path to ask about it.
    virtual bool any_reported() const { return !reported_.empty(); }

  private:
    std::set<std::string> reported_;
};

struct Problem {
    Severity severity = Severity::Error;
    Error error;
};

// A sink that keeps the problems, for the file kinds without a report of their own.
class Problems : public ProblemSink {
  public:
    Problems(std::string file, const PositionMap* positions)
        : file_(std::move(file)), positions_(positions) {}

    void report(Severity severity, const std::string& path, std::string message, std::string hint) override;
    void report_at(Severity severity, TextPosition position, const std::string& path, std::string message,
                   std::string hint) override;

    bool has_errors() const;
    // In document order (those without a place last).
    std::vector<Error> errors() const;
    std::vector<Error> warnings() const;
    // The errors as one Error (at most 50 listed), for a Result.
    Error combined() const;
    // Each warning to the log, or to `out` when given.
    void pass_warnings(std::vector<Error>* out) const;

  private:
    std::vector<Error> of(Severity severity) const;
    std::string file_;
    const PositionMap* positions_;
    std::vector<Problem> list_;
};

// Sorts errors into document order (those without a line last) and joins them into one, listing at most
// `max_listed` and counting the rest; the file is set when the errors name none.
Error combined_error(std::vector<Error> errors, const std::string& file, std::size_t max_listed = 50);

} // namespace ks::jsonio
