#pragma once
// Help text shared by the animation file's reader and its semantic checks (clip_reader, clip_validate).
#include <string>
#include <string_view>
#include <vector>

namespace ks::anim {

// "did you mean 'x'? " for a near miss (a typo), else "": goes in front of the list of valid names.
std::string did_you_mean(std::string_view given, const std::vector<std::string>& candidates);

// A name from the file in single quotes for a message, control characters escaped ('a\u0000b'), so an
// embedded NUL or newline cannot cut the message short.
std::string quoted_name(std::string_view name);

} // namespace ks::anim
