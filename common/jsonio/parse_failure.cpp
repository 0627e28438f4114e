#include "jsonio/parse_failure.h"

namespace ks::jsonio {

ParseFailure describe_parse_error(std::string_view text, const nlohmann::json::parse_error& error) {
    // error.byte is 1-based, pointing just past the offending character.
    const std::size_t offset = error.byte > 0 ? error.byte - 1 : 0;
    std::string message = error.what();
    if (auto at = message.find("syntax error"); at != std::string::npos)
        message = message.substr(at);
    else if (auto colon = message.find(": "); colon != std::string::npos)
        message = message.substr(colon + 2);
    return {position_of_offset(text, offset), "JSON " + message, offset >= text.size()};
}

} // namespace ks::jsonio
