#pragma once
// The spelling rule for sound names (level::SoundName): what the loader, validate() and the editor's
// inspector accept, and the spelling to suggest when a designer wrote the name another way.
#include <string>
#include <string_view>

namespace ks::level {

// Lower-case letters, digits and underscores only, between `min_length` and `max_length` characters.
bool is_valid_sound_name(std::string_view name, int min_length, int max_length);

struct SoundNameProblem {
    std::string message; // "" when the name is fine
    std::string hint;
};
// What is wrong with `name`, phrased for a message about a field, with the fix in the hint; an empty
// message when nothing is.
SoundNameProblem sound_name_problem(std::string_view name, int min_length, int max_length);

// The name respelled by the rule: ".wav" dropped, letters lowered, runs of other characters made one
// underscore ("Machine Hum.wav" -> "machine_hum"); "" when nothing is left.
std::string respelled_sound_name(std::string_view name);

} // namespace ks::level
