#pragma once
// The sound names a level may use: the files a designer has in assets/sounds. The validation's sound rule
// and the inspector's sound combo read them.
#include <filesystem>
#include <string>
#include <vector>

namespace ks::editor {

// The names of the *.wav files in `folder` without ".wav", sorted; empty when the folder is missing or
// cannot be read (the caller decides what no names means).
std::vector<std::string> sound_names_in(const std::filesystem::path& folder);
// sound_names_in(assets/sounds), the folder found through core/paths.
std::vector<std::string> shipped_sound_names();

} // namespace ks::editor
