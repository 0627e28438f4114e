#include "jsonio/object_reader.h"

#include "jsonio/describe.h"
#include "jsonio/json_path.h"
#include "jsonio/number_text.h"
#include "jsonio/suggest.h"
#include "jsonio/text.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>

namespace ks::jsonio {
namespace {

constexpr double kUnbounded = Range::kUnbounded;

std::string lower(std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

std::string did_you_mean(std::string_view word, const std::vector<std::string>& candidates) {
    const std::string near = closest_match(word, candidates);
    return near.empty() ? std::string() : "did you mean " + quote_text(near) + "? ";
}

void error(ProblemSink& sink, const std::string& path, std::string message, std::string hint) {
    sink.report(Severity::Error, path, std::move(message), std::move(hint));
}

} // namespace

std::string Range::text() const {
    const std::string suffix = unit.empty() ? std::string() : " " + unit;
    if (min <= -kUnbounded && max >= kUnbounded) return "any finite number";
    if (max >= kUnbounded) return "at least " + format_readable(min) + suffix;
    if (min <= -kUnbounded) return "at most " + format_readable(max) + suffix;
    return format_readable(min) + " .. " + format_readable(max) + suffix;
}

bool read_finite(const Json& value, const std::string& path, ProblemSink& sink, double& out,
                 const std::string& valid) {
    if (sink.already_reported(path)) return false;
    if (value.is_number()) {
        const double number = value.get<double>();
        if (!std::isfinite(number)) {
            error(sink, path, "number is not finite", "write a finite number; valid: " + valid);
            return false;
        }
        out = number;
        return true;
    }
    if (value.is_string()) {
        const std::string& raw = value.get_ref<const std::string&>();
        static const char* const kNonFinite[] = {"nan",  "-nan",     "+nan",      "inf",      "-inf",
                                                 "+inf", "infinity", "-infinity", "+infinity"};
        if (std::find(std::begin(kNonFinite), std::end(kNonFinite), lower(raw)) != std::end(kNonFinite)) {
            error(sink, path, quote_text(raw) + " is not a finite number (NaN and infinity are not allowed)",
                  "write a finite number; valid: " + valid);
            return false;
        }
        char* end = nullptr;
        std::strtod(raw.c_str(), &end);
        if (!raw.empty() && end == raw.c_str() + raw.size()) {
            error(sink, path, "number written as a string " + quote_text(raw),
                  "remove the quotes; valid: " + valid);
            return false;
        }
    }
    error(sink, path, "expected a number, found " + describe_value(value), "valid: " + valid);
    return false;
}

namespace {
// The common case: a finite number in range, nothing marked reported in the document; read without
// building the path or the messages a problem would need.
bool read_plain_number(const Json& value, const ProblemSink& sink, double& out, const Range& range) {
    if (!value.is_number() || sink.any_reported()) return false;
    const double number = value.get<double>();
    if (!std::isfinite(number) || !range.contains(number)) return false;
    out = number;
    return true;
}
} // namespace

bool read_number(const Json& value, const std::string& path, ProblemSink& sink, double& out,
                 const Range& range) {
    if (read_plain_number(value, sink, out, range)) return true;
    double number = 0;
    if (!read_finite(value, path, sink, number, range.text())) return false;
    if (!range.contains(number)) {
        error(sink, path, format_readable(number) + " is out of range", "valid: " + range.text());
        return false;
    }
    out = number;
    return true;
}

bool read_whole(const Json& value, const std::string& path, ProblemSink& sink, long long& out,
                const Range& range) {
    double number = 0;
    if (!read_finite(value, path, sink, number, "whole numbers " + range.text())) return false;
    if (number != std::floor(number) || std::fabs(number) > 9.0e15) {
        error(sink, path, format_readable(number) + " is not a whole number",
              "valid: whole numbers " + range.text());
        return false;
    }
    if (!range.contains(number)) {
        error(sink, path, format_readable(number) + " is out of range",
              "valid: whole numbers " + range.text());
        return false;
    }
    out = static_cast<long long>(number);
    return true;
}

bool read_text(const Json& value, const std::string& path, ProblemSink& sink, std::string& out,
               std::size_t max_characters, const std::string& hint) {
    if (sink.already_reported(path)) return false;
    if (!value.is_string()) {
        error(sink, path, "expected a string, found " + describe_value(value),
              hint.empty() ? "put the text in double quotes" : hint);
        return false;
    }
    const std::string& text = value.get_ref<const std::string&>();
    if (max_characters > 0) {
        if (const std::size_t length = character_count(text); length > max_characters) {
            error(sink, path, "text of " + std::to_string(length) + " characters is too long",
                  "at most " + std::to_string(max_characters) + " characters");
            return false;
        }
    }
    out = text;
    return true;
}

bool read_flag(const Json& value, const std::string& path, ProblemSink& sink, bool& out) {
    if (sink.already_reported(path)) return false;
    if (!value.is_boolean()) {
        error(sink, path, "expected true or false, found " + describe_value(value), "valid: true, false");
        return false;
    }
    out = value.get<bool>();
    return true;
}

bool read_choice(const Json& value, const std::string& path, ProblemSink& sink, std::string& out,
                 const std::vector<std::string>& choices) {
    std::string text;
    if (!read_text(value, path, sink, text, 0, "valid: " + join(choices))) return false;
    if (std::find(choices.begin(), choices.end(), text) == choices.end()) {
        error(sink, path, "unknown value " + quote_text(text),
              did_you_mean(text, choices) + "valid: " + join(choices));
        return false;
    }
    out = std::move(text);
    return true;
}

std::string unknown_field_message(std::string_view key) {
    return "unknown field " + quote_text(key) + " is ignored";
}

std::string unknown_field_hint(std::string_view key, const std::vector<std::string>& known,
                               std::string_view what) {
    return did_you_mean(key, known) + "known " + std::string(what) + " fields: " + join(known);
}

void report_unknown_members(const Json& object, const std::string& path,
                            const std::vector<std::string>& known, std::string_view what, ProblemSink& sink) {
    if (!object.is_object()) return;
    for (auto it = object.begin(); it != object.end(); ++it) {
        const std::string& key = it.key();
        if (std::find(known.begin(), known.end(), key) != known.end()) continue;
        sink.report(Severity::Warning, member_path(path, key), unknown_field_message(key),
                    unknown_field_hint(key, known, what));
    }
}

ObjectReader::ObjectReader(const Json& value, std::string path, ProblemSink& sink, std::string what)
    : path_(std::move(path)), sink_(sink), what_(std::move(what)) {
    if (value.is_object())
        object_ = &value;
    else if (!sink.already_reported(path_))
        error(sink, path_, "expected " + what_ + " as an object {...}, found " + describe_value(value),
              "write it as {\"key\": value, ...}");
}

std::string ObjectReader::path_of(std::string_view key) const {
    return member_path(path_, key);
}

void ObjectReader::claim(std::string_view key) {
    if (std::find(known_.begin(), known_.end(), key) == known_.end()) known_.emplace_back(key);
}

const Json* ObjectReader::get(std::string_view key, Need need, const std::string& hint) {
    claim(key);
    if (!object_) return nullptr;
    if (auto it = object_->find(key); it != object_->end()) return &*it;
    if (need == Need::Required)
        error(sink_, path_of(key), "missing required field " + quote_text(key),
              hint.empty() ? "add \"" + std::string(key) + "\"" : hint);
    return nullptr;
}

bool ObjectReader::text(std::string_view key, std::string& out, Need need, std::size_t max_characters,
                        const std::string& hint) {
    const Json* value = get(key, need, hint);
    return value && read_text(*value, path_of(key), sink_, out, max_characters, hint);
}

bool ObjectReader::flag(std::string_view key, bool& out, Need need) {
    const Json* value = get(key, need, "add \"" + std::string(key) + "\": true or false");
    return value && read_flag(*value, path_of(key), sink_, out);
}

bool ObjectReader::number(std::string_view key, double& out, const Range& range, Need need) {
    const Json* value = get(key, need, "valid: " + range.text());
    return value && read_number(*value, path_of(key), sink_, out, range);
}

bool ObjectReader::number(std::string_view key, float& out, const Range& range, Need need) {
    double value = 0;
    if (!number(key, value, range, need)) return false;
    out = static_cast<float>(value);
    return true;
}

bool ObjectReader::whole(std::string_view key, int& out, const Range& range, Need need) {
    Range bounded = range;
    bounded.min = std::max(bounded.min, static_cast<double>(std::numeric_limits<int>::min()));
    bounded.max = std::min(bounded.max, static_cast<double>(std::numeric_limits<int>::max()));
    const Json* value = get(key, need, "valid: whole numbers " + bounded.text());
    long long number = 0;
    if (!value || !read_whole(*value, path_of(key), sink_, number, bounded)) return false;
    out = static_cast<int>(number);
    return true;
}

bool ObjectReader::choice(std::string_view key, std::string& out, const std::vector<std::string>& choices,
                          Need need) {
    const Json* value = get(key, need, "valid: " + join(choices));
    return value && read_choice(*value, path_of(key), sink_, out, choices);
}

bool ObjectReader::numbers(std::string_view key, double* out, std::size_t count, const Range& range,
                           Need need) {
    const Json* value = get(key, need);
    if (!value) return false;
    const std::string path = path_of(key);
    if (sink_.already_reported(path)) return false;
    if (!value->is_array() || value->size() != count) {
        error(sink_, path,
              "expected an array of " + std::to_string(count) + " numbers, found " + describe_value(*value) +
                  (value->is_array() ? " of " + std::to_string(value->size()) : ""),
              "valid components: " + range.text());
        return false;
    }
    std::vector<double> read(count);
    bool ok = true;
    for (std::size_t i = 0; i < count; ++i)
        if (!read_plain_number((*value)[i], sink_, read[i], range))
            ok &= read_number((*value)[i], element_path(path, i), sink_, read[i], range);
    if (ok) std::copy(read.begin(), read.end(), out);
    return ok;
}

void ObjectReader::finish() {
    if (object_) report_unknown_members(*object_, path_, known_, what_, sink_);
}

} // namespace ks::jsonio
