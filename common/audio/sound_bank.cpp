#include "audio/sound_bank.h"
#include "core/files.h"
#include "core/paths.h"

#include <algorithm>

namespace ks::audio {

SoundBank SoundBank::load_folder(const std::filesystem::path& folder, std::vector<Error>& problems) {
    SoundBank bank;
    std::error_code ec;
    if (!std::filesystem::is_directory(folder, ec)) {
        problems.emplace_back("the sound folder does not exist", Location{folder.string()},
                              "put the game's <name>.wav files there; the game runs without sound meanwhile");
        return bank;
    }
    auto listed = files::list(folder, ".wav"); // sorted: the same problems in the same order on every machine
    if (!listed) {
        problems.push_back(listed.error());
        return bank;
    }
    for (const auto& file : *listed) {
        auto sound = read_wav(file);
        if (!sound) {
            problems.push_back(sound.error());
            continue;
        }
        bank.add(file.stem().string(), std::move(*sound));
    }
    return bank;
}

SoundBank SoundBank::load_assets(std::vector<Error>& problems) {
    return load_folder(paths::asset("sounds"), problems);
}

void SoundBank::add(std::string name, SoundData sound) {
    auto it = std::lower_bound(entries_.begin(), entries_.end(), name,
                               [](const Entry& e, const std::string& n) { return e.name < n; });
    if (it != entries_.end() && it->name == name) {
        it->sound = std::move(sound);
        return;
    }
    entries_.insert(it, Entry{std::move(name), std::move(sound)});
}

int SoundBank::index_of(std::string_view name) const {
    auto it = std::lower_bound(entries_.begin(), entries_.end(), name,
                               [](const Entry& e, std::string_view n) { return e.name < n; });
    return it != entries_.end() && it->name == name ? static_cast<int>(it - entries_.begin()) : -1;
}

const SoundData* SoundBank::find(std::string_view name) const {
    const int i = index_of(name);
    return i < 0 ? nullptr : &entries_[static_cast<std::size_t>(i)].sound;
}

std::vector<std::string> SoundBank::names() const {
    std::vector<std::string> out;
    out.reserve(entries_.size());
    for (const Entry& e : entries_) out.push_back(e.name);
    return out;
}

} // namespace ks::audio
