#include "level/level_catalog.h"

#include "core/files.h"
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
    std::vector<fs::path> listed = files::list(folder, ".json").value_or(std::vector<fs::path>{});
    std::erase_if(listed, [&](const fs::path& file) {
        return std::find(skip.begin(), skip.end(), file.filename().string()) != skip.end();
    });
    if (listed.size() > max_files) {
        out.left_out = listed.size() - max_files;
        listed.resize(max_files);
    }
    for (const fs::path& file : listed) {
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
