#pragma once
// The File > Open Recent list, kept in a small JSON file under the user's config folder
// (paths::user_config_dir(): $XDG_CONFIG_HOME/killswitch/, else ~/.config/killswitch/); tests pass their own
// path.
#include "core/result.h"

#include <filesystem>
#include <vector>

namespace ks::editor {

class RecentFiles {
  public:
    explicit RecentFiles(std::filesystem::path config_file, size_t capacity = 10);
    // A missing file is an empty list; an unreadable or malformed one is an error (the list stays empty,
    // and the next save replaces the file).
    Result<void> load();
    Result<void> save() const;
    // Moves (or inserts) the file to the front, as an absolute path.
    void add(const std::filesystem::path& file);
    void remove(const std::filesystem::path& file);
    const std::vector<std::filesystem::path>& entries() const { return entries_; }
    const std::filesystem::path& config_file() const { return config_file_; }

  private:
    std::filesystem::path config_file_;
    size_t capacity_;
    std::vector<std::filesystem::path> entries_;
};

} // namespace ks::editor
