#pragma once
// The models a designer can place (the Models tab, ui/model_browser.h): every file with a model extension
// (modelio::supported_extensions) under the shipped assets/models and the designer's own models folder
// (modelio::user_models_dir), sub-folders included, named as a level names them (relative, '/'). A name in
// both folders is the shipped file (modelio::resolve_model_file looks there first): the designer's is listed
// as shadowed. Rescanned by file times, so a file added, removed or changed on disk shows.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace ks::editor {

struct ModelEntry {
    std::string name; // as the model entity's `file` names it: "props/crate.glb"
    std::filesystem::path path;
    bool shipped = false;  // in assets/models
    bool shadowed = false; // the designer's file of a shipped name: the level would read the shipped one
    std::uintmax_t bytes = 0;
    std::filesystem::file_time_type mtime{};
};

class ModelLibrary {
  public:
    // The shipped folder, then the designer's (an empty path is skipped).
    ModelLibrary(std::filesystem::path shipped, std::filesystem::path user);
    static ModelLibrary with_default_folders();

    // Lists both folders again; true when a file was added, removed or changed (size or time).
    bool rescan();
    const std::vector<ModelEntry>& entries() const { return entries_; } // by name, shipped first on a tie
    // The entries whose name contains every word of `query` (case-insensitive, any order); all for "".
    std::vector<const ModelEntry*> search(std::string_view query) const;
    const ModelEntry* find(std::string_view name) const; // the one a level would read
    // Bumps whenever rescan finds a change (thumbnails cache against it).
    std::uint64_t revision() const { return revision_; }

  private:
    std::filesystem::path shipped_, user_;
    std::vector<ModelEntry> entries_;
    std::uint64_t revision_ = 0;
};

} // namespace ks::editor
