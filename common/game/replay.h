#pragma once
// Input recordings: one Input per fixed step, plus the seed and level they were recorded with. The text
// format stores floats as hexadecimal (%a), so a replay feeds bit-identical inputs and reproduces the final
// state hash exactly:
//   killswitch-replay 1
//   seed 42
//   level levels/main.json
//   difficulty hard                                   (only when not normal)
//   steps 3600
//   <move_forward> <move_right> <look_yaw> <look_pitch> <flags>   (one line per step; flags: j f e p)
#include "core/result.h"
#include "game/game_types.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace ks::game {

struct Recording {
    std::uint64_t seed = 1;
    std::string level;                          // as given on the command line (informational)
    Difficulty difficulty = Difficulty::Normal; // the robots played against: a replay plays them again
    std::vector<Input> inputs;
};

std::string save_recording_string(const Recording& recording);
Result<void> save_recording_file(const std::filesystem::path& path, const Recording& recording);
// Errors name the file, the line and what was expected there.
Result<Recording> load_recording_string(std::string_view text, const std::string& file_name);
Result<Recording> load_recording_file(const std::filesystem::path& path);

} // namespace ks::game
