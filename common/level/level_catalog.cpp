#include "level/level_catalog.h"

#include "level/level_io.h"

#include <algorithm>

namespace ks::level {
namespace fs = std::filesystem;

LevelFolder list_level_files(const fs::path& folder, const std::vector<std::string>& skip,
                             std::size_t max_files) {
    LevelFolder out;
    out.folder = folder;
    std::error_code ec;
    out.exists = !folder.empty() && fs::is_directory(folder, ec);
    if (!out.exists) return out;
    std::vector<fs::path> files;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        const fs::path& path = it->path();
        const std::string name = path.filename().string();
        if (path.extension() != ".json" || std::find(skip.begin(), skip.end(), name) != skip.end()) continue;
        if (std::error_code type_ec; !it->is_regular_file(type_ec)) continue;
        files.push_back(path);
    }
    std::sort(files.begin(), files.end());
    if (files.size() > max_files) {
        out.left_out = files.size() - max_files;
        files.resize(max_files);
    }
    for (const fs::path& file : files) {
        LevelFileEntry entry;
        entry.file = file;
        entry.name = file.stem().string();
        LoadReport report;
        Result<Level> loaded = load_level_file(file, &report);
        if (!loaded)
            entry.error = loaded.error().str();
        else if (!loaded->name.empty())
            entry.name = loaded->name;
        out.levels.push_back(std::move(entry));
    }
    return out;
}

} // namespace ks::level
