#include "jsonio/json_path.h"

namespace ks::jsonio {

std::string member_path(const std::string& parent, std::string_view key) {
    std::string out = parent;
    if (!out.empty()) out += '.';
    out += key;
    return out;
}

std::string element_path(const std::string& parent, std::size_t index) {
    return parent + "[" + std::to_string(index) + "]";
}

JsonPath JsonPath::operator/(std::string_view key) const {
    JsonPath p = *this;
    p.steps_.push_back({std::string(key), -1});
    return p;
}

JsonPath JsonPath::operator[](std::size_t index) const {
    JsonPath p = *this;
    p.steps_.push_back({{}, static_cast<long>(index)});
    return p;
}

std::string JsonPath::str() const {
    std::string out;
    for (const JsonPathStep& s : steps_)
        out = s.index >= 0 ? element_path(out, static_cast<std::size_t>(s.index)) : member_path(out, s.key);
    return out;
}

} // namespace ks::jsonio
