#include "model/prefab_library.h"

#include "core/files.h"
#include "core/paths.h"
#include "jsonio/suggest.h"

#include <algorithm>
#include <map>

#include <unistd.h>

namespace ks::editor {

namespace fs = std::filesystem;

std::vector<fs::path> default_prefab_folders() {
    const fs::path shipped = paths::data_root() / "prefabs";
    const fs::path user_data = paths::user_data_dir();
    if (user_data.empty()) return {shipped};
    const fs::path own = user_data / "prefabs";
    return ::access(shipped.c_str(), W_OK) == 0 ? std::vector<fs::path>{shipped, own}
                                                : std::vector<fs::path>{own, shipped};
}

void PrefabLibrary::set_folders(std::vector<fs::path> folders) {
    folders_ = std::move(folders);
    entries_.clear();
    ++revision_;
}

bool PrefabLibrary::rescan() {
    std::map<std::string, std::pair<fs::path, fs::file_time_type>> found; // sorted by name
    for (const fs::path& folder : folders_) {
        for (const fs::path& path : files::list(folder, ".json").value_or(std::vector<fs::path>{})) {
            const std::string name = path.stem().string();
            std::error_code ec;
            if (!found.contains(name)) found[name] = {path, fs::last_write_time(path, ec)};
        }
    }
    bool changed = found.size() != entries_.size();
    std::vector<PrefabEntry> next;
    next.reserve(found.size());
    for (auto& [name, file] : found) {
        const PrefabEntry* old = find(name);
        if (old && old->path == file.first && old->mtime == file.second) {
            next.push_back(*old);
            continue;
        }
        changed = true;
        PrefabEntry entry{name, file.first, file.second, Error("not read yet")};
        auto text = files::read_text(file.first);
        entry.prefab = text ? prefab_from_text(*text, file.first.string()) : Result<Prefab>(text.error());
        if (entry.prefab && entry.prefab->name != name)
            entry.prefab = Error("the file says its name is '" + entry.prefab->name + "'",
                                 Location{file.first.string() + ": name"},
                                 "a prefab's \"name\" is its file's name: write \"" + name + "\"");
        next.push_back(std::move(entry));
    }
    entries_ = std::move(next);
    if (changed) ++revision_;
    return changed;
}

const PrefabEntry* PrefabLibrary::find(std::string_view name) const {
    for (const PrefabEntry& e : entries_)
        if (e.name == name) return &e;
    return nullptr;
}

Result<Prefab> PrefabLibrary::get(std::string_view name) const {
    if (const PrefabEntry* e = find(name)) return e->prefab;
    std::vector<std::string> names;
    for (const PrefabEntry& e : entries_) names.push_back(e.name);
    const std::string near = jsonio::closest_match(name, names);
    return Error("no prefab named '" + std::string(name) + "'", Location{},
                 (near.empty() ? std::string() : "did you mean '" + near + "'? ") +
                     (names.empty() ? "the prefab folders hold none; save a selection as a prefab first"
                                    : "prefabs: " + jsonio::join(names)));
}

Result<fs::path> PrefabLibrary::save(const Prefab& prefab) {
    if (std::string problem = prefab_name_problem(prefab.name); !problem.empty())
        return Error(problem, Location{}, "choose another name");
    if (folders_.empty()) return Error("no prefab folder is set", Location{}, "restart the editor");
    std::error_code ec;
    fs::create_directories(folders_.front(), ec);
    const fs::path path = folders_.front() / (prefab.name + ".json");
    if (auto r = files::write_atomic(path, prefab_to_text(prefab)); !r) return r.error();
    rescan();
    ++revision_;
    return path;
}

} // namespace ks::editor
