#pragma once
// Line:column of a place in a JSON text, as error messages show it, and the step from there to the
// Location an Error carries.
#include "core/result.h"

#include <cstddef>
#include <string>
#include <string_view>

namespace ks::jsonio {

struct TextPosition {
    int line = 0;   // 1-based; 0 = unknown
    int column = 0; // 1-based, in characters (UTF-8 code points), so a designer's editor shows the same
};

// Line and column of a byte offset (clamped to the text). Only '\n' ends a line, so "\r\n" files get the
// same line numbers as "\n" files.
TextPosition position_of_offset(std::string_view text, std::size_t offset);

// Where an Error points: the file, the position (unknown parts stay 0) and the JSON path.
Location location_at(std::string file, TextPosition position, std::string path = {});

} // namespace ks::jsonio
