#pragma once
// The project version: one number, `project(Killswitch VERSION x.y.z)` in the top-level CMakeLists.txt,
// which reaches only version.cpp as compile definitions (KS_VERSION, KS_LICENSE). Both executables print
// it for --version; the main menu and the editor's About box show it; the package files carry it.
#include <string>
#include <string_view>

namespace ks::version {

std::string_view number();  // "0.9.0"
std::string_view license(); // the licence of the project's code and generated assets, e.g. "MIT"
// What `--version` prints (without the newline): "killswitch 0.9.0".
std::string line(std::string_view program);

} // namespace ks::version
