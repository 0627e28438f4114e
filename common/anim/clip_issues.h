#pragma once
// Help text shared by the animation file's reader and its semantic checks (clip_reader, clip_validate).
#include <string>
#include <string_view>
#include <vector>

namespace ks::anim {

// "did you mean 'x'? " for a near miss (a typo), else "": goes in front of the list of valid names.
std::string did_you_mean(std::string_view given, const std::vector<std::string>& candidates);

} // namespace ks::anim
