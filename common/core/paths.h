#pragma once
// Finding the data folders (assets/, levels/) from any working directory: next to the executable first,
// then the installed layout (<prefix>/bin/../share/killswitch from `cmake --install`; the Debian package's
// /usr/games/../share/killswitch), then up from the executable (build/bin/ inside the source tree), then
// the source tree the binary was built from. KS_DATA_DIR overrides all of them.
#include <filesystem>
#include <string_view>

namespace ks::paths {

std::filesystem::path executable_dir();
// Where an installed executable's data lives: <executable_dir>/../share/killswitch (normalised).
std::filesystem::path installed_data_dir(const std::filesystem::path& executable_dir);
// The folder that holds assets/ and levels/ (found once, then cached).
const std::filesystem::path& data_root();
std::filesystem::path asset(std::string_view relative); // data_root()/assets/relative
std::filesystem::path level(std::string_view relative); // data_root()/levels/relative
// A path given by the user: absolute or relative to the current folder, else relative to data_root().
std::filesystem::path resolve_user_path(const std::filesystem::path& given);
// The player's data (levels, campaign saves): $XDG_DATA_HOME/killswitch, else ~/.local/share/killswitch (the
// XDG base directory rule; a relative XDG_DATA_HOME is ignored, as the rule says). Empty when neither
// variable gives a folder. Read from the environment on every call.
std::filesystem::path user_data_dir();
// The player's settings (options, key bindings, the editor's recent files and untitled autosaves):
// $XDG_CONFIG_HOME/killswitch, else ~/.config/killswitch, by the same rule as user_data_dir() (a relative
// XDG_CONFIG_HOME is ignored). Empty when neither variable gives a folder. Read on every call.
std::filesystem::path user_config_dir();
// Files the game can always make again, kept to start faster (the navigation mesh and light bake caches:
// core/disk_cache.h): $XDG_CACHE_HOME/killswitch, else ~/.cache/killswitch, by the same rule as
// user_data_dir() (a relative XDG_CACHE_HOME is ignored). Empty when neither variable gives a folder.
std::filesystem::path user_cache_dir();
// Where the player's own levels live: user_data_dir()/levels (empty when user_data_dir() is).
std::filesystem::path user_levels_dir();
// user_levels_dir(), created when missing (the editor's folder for a new level); empty when there is no such
// folder or it cannot be made.
std::filesystem::path ensure_user_levels_dir();

} // namespace ks::paths
