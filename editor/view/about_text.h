#pragma once
// Help > About's text, window-free so it is tested: the editor's name and version (core/version.h, from the
// one project version in CMake), what it is, and the licences.
#include <string>
#include <vector>

namespace ks::editor {

// The lines of the About box, the first one "Killswitch Editor 0.9.0".
std::vector<std::string> about_lines();

} // namespace ks::editor
