#pragma once
// The level files of a folder as a menu lists them: each with the name from the file, or the error that
// keeps it from loading (so a broken file is shown, not played, and never crashes the list).
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace ks::level {

struct LevelFileEntry {
    std::filesystem::path file;
    std::string name;  // the level's "name", else its file name without .json
    std::string error; // empty when the file loads; else the loader's message (file, place, fix)
    bool ok() const { return error.empty(); }
};

struct LevelFolder {
    std::filesystem::path folder;
    std::vector<LevelFileEntry> levels; // sorted by file name
    std::size_t left_out = 0;           // files past `max_files`, not read
    bool exists = false;                // the folder is there (an empty list in a missing folder is normal)
};

// Every *.json file directly in `folder` except the file names in `skip`, each loaded and validated with
// load_level_file. At most `max_files` are read (a folder of thousands stays quick to open).
LevelFolder list_level_files(const std::filesystem::path& folder, const std::vector<std::string>& skip = {},
                             std::size_t max_files = 200);

} // namespace ks::level
