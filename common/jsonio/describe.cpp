#include "jsonio/describe.h"

#include "jsonio/json_writer.h"

namespace ks::jsonio {

const char* type_name(const Json& value) {
    switch (value.type()) {
    case Json::value_t::null:
        return "null";
    case Json::value_t::boolean:
        return "a boolean";
    case Json::value_t::string:
        return "a string";
    case Json::value_t::array:
        return "an array";
    case Json::value_t::object:
        return "an object";
    case Json::value_t::discarded:
        return "invalid";
    default:
        return "a number";
    }
}

std::string describe_value(const Json& value) {
    if (value.is_string()) return "the string " + quote(value);
    if (value.is_boolean()) return std::string("the boolean ") + (value.get<bool>() ? "true" : "false");
    if (value.is_number()) return "the number " + quote(value);
    return type_name(value);
}

std::string quote(const Json& value) {
    std::string text = compact_text(value);
    if (text.size() > 80) text = text.substr(0, 77) + "...";
    return text;
}

} // namespace ks::jsonio
