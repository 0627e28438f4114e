#include "model/sound_names.h"

#include "core/files.h"
#include "core/paths.h"

#include <algorithm>
#include <system_error>

namespace ks::editor {

std::vector<std::string> sound_names_in(const std::filesystem::path& folder) {
    std::vector<std::string> names;
    for (const std::filesystem::path& file :
         files::list(folder, ".wav").value_or(std::vector<std::filesystem::path>{}))
        names.push_back(file.stem().string());
    std::sort(names.begin(), names.end()); // by name: "a" before "a-b" (their files sort the other way)
    return names;
}

std::vector<std::string> shipped_sound_names() {
    return sound_names_in(paths::asset("sounds"));
}

} // namespace ks::editor
