#pragma once
// Deterministic JSON text for level files: keys in insertion order, 2-space indentation, arrays of scalars
// on one line, numbers in their shortest round-trip form, a trailing newline. nlohmann's own dump() puts
// every array element on its own line and prints integral doubles as "100.0"; designers read these files.
#include <nlohmann/json.hpp>

#include <string>

namespace ks::level::json_text {

// A float as the double whose shortest decimal form is the float's shortest form, so 0.8f is stored (and
// later printed) as 0.8 rather than 0.800000011920929. Non-finite values pass through unchanged.
double float_to_double(float value);

// The shortest decimal text that reads back to exactly `value`; -0 prints as 0, non-finite as null.
std::string format_number(double value);

// For messages: whole numbers below 1e15 in plain digits (100000, not 1e+05), others as format_number.
std::string format_readable(double value);

// A JSON value as text for messages: invalid UTF-8 replaced rather than thrown over, long values cut short.
std::string quote(const nlohmann::ordered_json& value);

std::string write(const nlohmann::ordered_json& document);

} // namespace ks::level::json_text
