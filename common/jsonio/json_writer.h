#pragma once
// Deterministic JSON text for files designers read: keys in insertion order, 2-space indentation, arrays
// of scalars on one line, numbers in their shortest round-trip form, a trailing newline. nlohmann's own
// dump() puts every array element on its own line and prints integral doubles as "100.0".
#include <nlohmann/json.hpp>

#include <string>
#include <string_view>

namespace ks::jsonio {

using Json = nlohmann::ordered_json;

// A value on one line. Strings in memory may hold invalid UTF-8 (typed or pasted in the editor); it is
// replaced rather than thrown over, so saving never fails on it.
std::string compact_text(const Json& value);

// A string as a JSON string literal, quotes and escapes included (invalid UTF-8 replaced).
std::string json_string(std::string_view text);

// The whole document, formatted as above.
std::string write_document(const Json& document);

} // namespace ks::jsonio
