#pragma once
// The prefabs a designer can place: every prefabs/*.json of the library's folders (the shipped ones in the
// data folder, the designer's own), read once and again when a file changes. A broken file is listed with
// its error (the palette shows it, placing it explains), never dropped silently. New prefabs are saved into
// the first folder.
#include "core/result.h"
#include "model/prefab.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ks::editor {

struct PrefabEntry {
    std::string name; // the file's stem
    std::filesystem::path path;
    std::filesystem::file_time_type mtime{};
    Result<Prefab> prefab = Error("not read yet");
};

// The shipped prefabs (the data folder's prefabs/) and the designer's own ($XDG_DATA_HOME/killswitch/
// prefabs, next to the user levels folder), the writable one first: new prefabs go into the source tree's
// prefabs/ when working from a checkout, and into the designer's folder when the data is installed read-only.
std::vector<std::filesystem::path> default_prefab_folders();

class PrefabLibrary {
  public:
    PrefabLibrary() = default;
    explicit PrefabLibrary(std::vector<std::filesystem::path> folders) : folders_(std::move(folders)) {}

    const std::vector<std::filesystem::path>& folders() const { return folders_; }
    void set_folders(std::vector<std::filesystem::path> folders);

    // Lists the folders again, re-reading the files whose time changed; true when anything changed. A name
    // in two folders: the first folder's file wins.
    bool rescan();
    const std::vector<PrefabEntry>& entries() const { return entries_; }
    const PrefabEntry* find(std::string_view name) const;
    // The prefab, or why it cannot be placed (unknown name with did-you-mean, or the file's error).
    Result<Prefab> get(std::string_view name) const;
    // Writes prefabs/NAME.json in the first folder (created when missing) and lists it.
    Result<std::filesystem::path> save(const Prefab& prefab);
    // Bumps whenever the listing or a prefab changes (thumbnails cache against it).
    std::uint64_t revision() const { return revision_; }

  private:
    std::vector<std::filesystem::path> folders_;
    std::vector<PrefabEntry> entries_;
    std::uint64_t revision_ = 0;
};

struct Issue;
// The `prefab` rule: an instance whose prefab is not in `library` (with a did-you-mean) or does not load
// is a warning on its first member, fixed by unlinking it (it keeps its entities as they are).
void check_prefab_instances(const level::Level& level, const PrefabLibrary& library, std::vector<Issue>& out);

} // namespace ks::editor
