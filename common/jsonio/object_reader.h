#pragma once
// Typed reading of a parsed document, the same for every file kind: one JSON object's members by name
// (ObjectReader) and single values (read_*), each with its type, range and whether it is required. A value
// that cannot be read is reported at its path (so at its line:column) with what would be valid, and the
// output keeps its value; reading goes on, so one load reports everything. ObjectReader::finish() warns
// about every member no read asked for, with a did-you-mean. Strings from the file appear in messages
// through quote_text() (control characters escaped); text limits count characters.
#include "jsonio/json_writer.h"
#include "jsonio/problems.h"

#include <cstddef>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace ks::jsonio {

enum class Need { Optional, Required };

// A number's valid range as messages show it: "0.01 .. 10000 units".
struct Range {
    static constexpr double kUnbounded = std::numeric_limits<double>::max();
    Range() = default;
    Range(double lowest, double highest = kUnbounded, std::string unit_name = {})
        : min(lowest), max(highest), unit(std::move(unit_name)) {}
    double min = -kUnbounded;
    double max = kUnbounded;
    std::string unit;
    std::string text() const;
    bool contains(double value) const { return value >= min && value <= max; }
};

// A JSON number that is finite; "nan", "inf" and numbers in quotes get their own messages (JSON has no
// NaN, and a designer who typed one needs to know). `valid` goes into the hint. No range check.
bool read_finite(const Json& value, const std::string& path, ProblemSink& sink, double& out,
                 const std::string& valid);
// A finite number inside `range`.
bool read_number(const Json& value, const std::string& path, ProblemSink& sink, double& out,
                 const Range& range);
// A whole number inside `range`.
bool read_whole(const Json& value, const std::string& path, ProblemSink& sink, long long& out,
                const Range& range);
// A string of at most `max_characters` characters (0: no limit); `hint` replaces the default fix.
bool read_text(const Json& value, const std::string& path, ProblemSink& sink, std::string& out,
               std::size_t max_characters = 0, const std::string& hint = {});
bool read_flag(const Json& value, const std::string& path, ProblemSink& sink, bool& out);
// One of `choices`, with a did-you-mean.
bool read_choice(const Json& value, const std::string& path, ProblemSink& sink, std::string& out,
                 const std::vector<std::string>& choices);

// The words of every unknown-field warning, for readers that report through their own lists: "unknown
// field \"colour\" is ignored", and "did you mean \"color\"? known settings fields: ...".
std::string unknown_field_message(std::string_view key);
std::string unknown_field_hint(std::string_view key, const std::vector<std::string>& known,
                               std::string_view what);

// Warns about each member of `object` not in `known`: "unknown field \"colour\" is ignored" with a
// did-you-mean and the known fields of `what` ("settings").
void report_unknown_members(const Json& object, const std::string& path,
                            const std::vector<std::string>& known, std::string_view what, ProblemSink& sink);

class ObjectReader {
  public:
    // Reports "expected <what> as an object {...}" when `value` is not an object; every read then finds
    // nothing. `what` also names the object in finish()'s warnings.
    ObjectReader(const Json& value, std::string path, ProblemSink& sink, std::string what);

    bool is_object() const { return object_ != nullptr; }
    const std::string& path() const { return path_; }
    std::string path_of(std::string_view key) const;
    ProblemSink& sink() { return sink_; }

    // The member, claimed so that finish() does not call it unknown; nullptr when absent (an error when
    // required, with `hint` as the fix).
    const Json* get(std::string_view key, Need need = Need::Optional, const std::string& hint = {});
    // A member read some other way.
    void claim(std::string_view key);

    // Each returns whether the member was present and good; `out` is left alone otherwise.
    bool text(std::string_view key, std::string& out, Need need = Need::Optional,
              std::size_t max_characters = 0, const std::string& hint = {});
    bool flag(std::string_view key, bool& out, Need need = Need::Optional);
    bool number(std::string_view key, double& out, const Range& range, Need need = Need::Optional);
    bool number(std::string_view key, float& out, const Range& range, Need need = Need::Optional);
    bool whole(std::string_view key, int& out, const Range& range, Need need = Need::Optional);
    bool choice(std::string_view key, std::string& out, const std::vector<std::string>& choices,
                Need need = Need::Optional);
    // An array of `count` finite numbers, each in `range`.
    bool numbers(std::string_view key, double* out, std::size_t count, const Range& range,
                 Need need = Need::Optional);

    // Warns about every member that nothing claimed. Call once, after the reads.
    void finish();

  private:
    const Json* object_ = nullptr;
    std::string path_;
    ProblemSink& sink_;
    std::string what_;
    std::vector<std::string> known_;
};

} // namespace ks::jsonio
