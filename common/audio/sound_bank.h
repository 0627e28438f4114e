#pragma once
// The game's sounds by name: every <name>.wav of a folder (assets/sounds/), decoded once at start-up. A
// missing or broken file is reported (one Error naming the file) and the game goes on without that sound.
#include "audio/wav.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace ks::audio {

class SoundBank {
  public:
    // Loads every *.wav in `folder` (not its subfolders); each file that cannot be read adds an Error to
    // `problems` and is left out. A missing folder is one Error.
    static SoundBank load_folder(const std::filesystem::path& folder, std::vector<Error>& problems);
    // load_folder(paths::asset("sounds")).
    static SoundBank load_assets(std::vector<Error>& problems);

    // Adds or replaces a sound (tests, tools, generated sounds).
    void add(std::string name, SoundData sound);

    // The sound called `name`, or nullptr.
    const SoundData* find(std::string_view name) const;
    // Index of `name` in 0..size()-1 (stable while no sound is added), or -1.
    int index_of(std::string_view name) const;
    const SoundData& at(int index) const { return entries_[static_cast<std::size_t>(index)].sound; }
    const std::string& name_at(int index) const { return entries_[static_cast<std::size_t>(index)].name; }

    // Every name, sorted (level validation offers these as did-you-mean suggestions).
    std::vector<std::string> names() const;
    int size() const { return static_cast<int>(entries_.size()); }

  private:
    struct Entry {
        std::string name;
        SoundData sound;
    };
    std::vector<Entry> entries_; // sorted by name
};

} // namespace ks::audio
