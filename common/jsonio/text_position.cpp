#include "jsonio/text_position.h"

namespace ks::jsonio {

TextPosition position_of_offset(std::string_view text, std::size_t offset) {
    if (offset > text.size()) offset = text.size();
    TextPosition pos{1, 1};
    for (std::size_t i = 0; i < offset; ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c == '\n') {
            ++pos.line;
            pos.column = 1;
        } else if ((c & 0xC0) != 0x80) { // count code points, not UTF-8 continuation bytes
            ++pos.column;
        }
    }
    return pos;
}

Location location_at(std::string file, TextPosition position, std::string path) {
    return Location(std::move(file), position.line, position.column, std::move(path));
}

} // namespace ks::jsonio
