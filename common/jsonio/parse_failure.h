#pragma once
// A JSON syntax error as a designer reads it: the place the parser stopped (line:column) and a message
// without nlohmann's "[json.exception.parse_error.101] parse error at line 3, column 5: " prefix, since the
// place goes into the Error's Location instead.
#include "jsonio/text_position.h"

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>

namespace ks::jsonio {

struct ParseFailure {
    TextPosition position;
    std::string message; // "JSON syntax error while parsing object - ..."
    bool at_end = false; // the text ended before the document did (a truncated file)
};

ParseFailure describe_parse_error(std::string_view text, const nlohmann::json::parse_error& error);

} // namespace ks::jsonio
