#include "anim/clip_issues.h"

#include "jsonio/suggest.h"
#include "jsonio/text.h"

namespace ks::anim {

std::string did_you_mean(std::string_view given, const std::vector<std::string>& candidates) {
    const std::string best = jsonio::closest_match(given, candidates);
    return best.empty() ? "" : "did you mean " + quoted_name(best) + "? ";
}

std::string quoted_name(std::string_view name) {
    const std::string literal = jsonio::quote_text(name);
    return "'" + literal.substr(1, literal.size() - 2) + "'";
}

} // namespace ks::anim
