#include "view/texture_search.h"

#include "jsonio/suggest.h"

#include <algorithm>
#include <cctype>

namespace ks::editor {
namespace {
std::string lowered(std::string_view text) {
    std::string out(text);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

std::string_view trimmed(std::string_view text) {
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front()))) text.remove_prefix(1);
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.remove_suffix(1);
    return text;
}
} // namespace

std::vector<std::string> texture_matches(const std::vector<std::string>& names, std::string_view query) {
    const std::string wanted = lowered(trimmed(query));
    if (wanted.empty()) return names;
    std::vector<std::string> out;
    std::copy_if(names.begin(), names.end(), std::back_inserter(out),
                 [&](const std::string& name) { return lowered(name).find(wanted) != std::string::npos; });
    if (out.empty())
        if (std::string closest = jsonio::closest_match(wanted, names); !closest.empty())
            out.push_back(std::move(closest));
    return out;
}

} // namespace ks::editor
