#include "jsonio/text.h"

#include "jsonio/json_writer.h"

namespace ks::jsonio {

namespace {
bool is_continuation(char c) {
    return (static_cast<unsigned char>(c) & 0xC0) == 0x80;
}
} // namespace

std::size_t character_count(std::string_view text) {
    std::size_t count = 0;
    for (char c : text)
        if (!is_continuation(c)) ++count;
    return count;
}

std::string quote_text(std::string_view text, std::size_t max_characters) {
    if (character_count(text) <= max_characters) return json_string(text);
    // Cut at a character boundary, leaving room for the "...".
    const std::size_t keep = max_characters > 3 ? max_characters - 3 : 0;
    std::size_t characters = 0, end = 0;
    while (end < text.size()) {
        if (!is_continuation(text[end]) && characters++ == keep) break;
        ++end;
    }
    std::string literal = json_string(text.substr(0, end));
    literal.insert(literal.size() - 1, "...");
    return literal;
}

} // namespace ks::jsonio
