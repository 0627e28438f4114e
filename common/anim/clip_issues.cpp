#include "anim/clip_issues.h"

#include "jsonio/suggest.h"

namespace ks::anim {

std::string did_you_mean(std::string_view given, const std::vector<std::string>& candidates) {
    const std::string best = jsonio::closest_match(given, candidates);
    return best.empty() ? "" : "did you mean '" + best + "'? ";
}

} // namespace ks::anim
