#pragma once
// Reading, validating and writing animation files (assets/animations/*.json; format in docs/animation.md).
//
// Loading reports every problem at once, each with file, line:column, JSON path and what would be valid.
// Saving is deterministic (fixed key order, shortest round-trip numbers), so load -> save of a saved file
// is byte-identical, and atomic (core/files write_atomic).
#include "anim/clip.h"
#include "core/result.h"
#include "jsonio/json_path.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace ks::anim {

inline constexpr const char* kAnimationFormat = "killswitch-animations";
inline constexpr int kAnimationVersion = 1;

// Issue paths are the toolkit's JSON paths ("clips[2].phases[0].duration").
using JsonPath = jsonio::JsonPath;

// An error, or a warning (an unknown field, ignored: the same rule as in every file the programs read).
struct Issue {
    JsonPath path;
    std::string message;
    std::string hint;
    bool warning = false;
};

// Semantic checks on an in-memory file (what the loader runs after parsing; the editor calls it live):
// unknown or duplicate names, parents after children, negative or absurd durations and angles, non-finite
// numbers, invalid custom easings, loop clips of zero length, Next clips without a valid target.
std::vector<Issue> validate(const AnimationFile& file);

Result<AnimationFile> load_animation_string(std::string_view text, const std::string& file_name);
Result<AnimationFile> load_animation_file(const std::filesystem::path& path);

std::string save_animation_string(const AnimationFile& file);
Result<void> save_animation_file(const std::filesystem::path& path, const AnimationFile& file);

// The file, its rig and the clips compiled for that rig: what the game and tests load in one call.
struct AnimationLibrary {
    AnimationFile file;
    Rig rig;
    ClipSet clips;
    std::filesystem::path source; // the file it was read from: what problems found later are reported against
};
Result<AnimationLibrary> load_animation_library(const std::filesystem::path& path);

} // namespace ks::anim
