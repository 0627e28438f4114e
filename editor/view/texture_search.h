#pragma once
// The texture browser's search, window-free: which of the surface materials (level/texture_names.h) a
// query shows.
#include <string>
#include <string_view>
#include <vector>

namespace ks::editor {

// The names containing `query` (ignoring case and surrounding spaces), in their order; all of them for an
// empty query; when none contains it, the closest by edit distance (a typo: "concret" shows concrete), or
// nothing.
std::vector<std::string> texture_matches(const std::vector<std::string>& names, std::string_view query);

} // namespace ks::editor
