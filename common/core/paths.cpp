#include "core/paths.h"

#include <cstdlib>
#include <unistd.h>

namespace ks::paths {
namespace fs = std::filesystem;

namespace {
bool holds_data(const fs::path& dir) {
    std::error_code ec;
    return fs::is_directory(dir / "assets", ec) && fs::is_directory(dir / "levels", ec);
}

fs::path find_data_root() {
    if (const char* env = std::getenv("KS_DATA_DIR"); env && *env && holds_data(env)) return fs::path(env);
    const fs::path exe_dir = executable_dir();
    // An installed prefix first, so a prefix inside a source tree still uses its own copy.
    if (holds_data(exe_dir)) return exe_dir;
    if (const fs::path installed = installed_data_dir(exe_dir); holds_data(installed)) return installed;
    for (fs::path dir = exe_dir; !dir.empty(); dir = dir.parent_path()) {
        if (holds_data(dir)) return dir;
        if (dir == dir.root_path()) break;
    }
#ifdef KS_SOURCE_DIR
    if (holds_data(KS_SOURCE_DIR)) return fs::path(KS_SOURCE_DIR);
#endif
    return fs::current_path();
}
} // namespace

fs::path installed_data_dir(const fs::path& executable_dir) {
    return (executable_dir / ".." / "share" / "killswitch").lexically_normal();
}

fs::path executable_dir() {
    std::error_code ec;
    fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (ec) return fs::current_path();
    return exe.parent_path();
}

const fs::path& data_root() {
    static const fs::path root = find_data_root();
    return root;
}

fs::path asset(std::string_view relative) {
    return data_root() / "assets" / relative;
}
fs::path level(std::string_view relative) {
    return data_root() / "levels" / relative;
}

fs::path resolve_user_path(const fs::path& given) {
    std::error_code ec;
    if (given.is_absolute() || fs::exists(given, ec)) return given;
    if (fs::exists(data_root() / given, ec)) return data_root() / given;
    return given;
}

namespace {
// The XDG base directory rule: $<variable>/killswitch when it is an absolute path, else
// $HOME/<home_relative>/killswitch, else empty.
fs::path xdg_dir(const char* variable, const fs::path& home_relative) {
    if (const char* xdg = std::getenv(variable); xdg && *xdg && fs::path(xdg).is_absolute())
        return fs::path(xdg) / "killswitch";
    if (const char* home = std::getenv("HOME"); home && *home)
        return fs::path(home) / home_relative / "killswitch";
    return {};
}
} // namespace

fs::path user_data_dir() {
    return xdg_dir("XDG_DATA_HOME", fs::path(".local") / "share");
}

fs::path user_config_dir() {
    return xdg_dir("XDG_CONFIG_HOME", ".config");
}

fs::path user_cache_dir() {
    return xdg_dir("XDG_CACHE_HOME", ".cache");
}

fs::path user_levels_dir() {
    const fs::path data = user_data_dir();
    return data.empty() ? fs::path() : data / "levels";
}

fs::path ensure_user_levels_dir() {
    const fs::path dir = user_levels_dir();
    if (dir.empty()) return {};
    std::error_code ec;
    fs::create_directories(dir, ec);
    return fs::is_directory(dir, ec) ? dir : fs::path();
}

} // namespace ks::paths
