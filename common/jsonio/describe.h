#pragma once
// JSON values described for error messages: "expected a number, found the string \"12\"".
#include <nlohmann/json.hpp>

#include <string>

namespace ks::jsonio {

// The kind of a value with its article: "a number", "a string", "an object", "null"...
const char* type_name(const nlohmann::ordered_json& value);

// The kind and, for scalars, the value itself: "the string \"abc\"", "the number 3", "the boolean true".
std::string describe_value(const nlohmann::ordered_json& value);

// A value as JSON text for messages, cut short past 80 characters.
std::string quote(const nlohmann::ordered_json& value);

} // namespace ks::jsonio
