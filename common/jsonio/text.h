#pragma once
// Text from a file inside a message: quoted, with control characters escaped (an embedded NUL or newline
// must not cut a diagnostic short or break it over lines), and lengths counted in characters, as a designer
// counts them, not in UTF-8 bytes.
#include <cstddef>
#include <string>
#include <string_view>

namespace ks::jsonio {

// Characters (UTF-8 code points) in `text`; a stray continuation byte counts as none.
std::size_t character_count(std::string_view text);

// `text` as a JSON string literal for a message: "abc", control characters escaped (\n, \u0000), invalid
// UTF-8 replaced, cut to `max_characters` characters with "..." when longer.
std::string quote_text(std::string_view text, std::size_t max_characters = 80);

} // namespace ks::jsonio
