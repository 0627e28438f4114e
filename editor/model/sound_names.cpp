#include "model/sound_names.h"

#include "core/paths.h"

#include <algorithm>
#include <system_error>

namespace ks::editor {

std::vector<std::string> sound_names_in(const std::filesystem::path& folder) {
    std::vector<std::string> names;
    std::error_code ec;
    for (std::filesystem::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        const std::filesystem::path& path = it->path();
        std::error_code file_ec;
        if (path.extension() == ".wav" && it->is_regular_file(file_ec)) names.push_back(path.stem().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

std::vector<std::string> shipped_sound_names() {
    return sound_names_in(paths::asset("sounds"));
}

} // namespace ks::editor
