#include "model/model_library.h"

#include "core/paths.h"
#include "modelio/model_files.h"

#include <algorithm>
#include <cctype>
#include <system_error>

namespace ks::editor {

namespace fs = std::filesystem;

namespace {

std::string fold_case(std::string_view text) {
    std::string out(text);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

void list_model_folder(const fs::path& root, bool shipped, std::vector<ModelEntry>& out) {
    std::error_code ec;
    if (root.empty() || !fs::is_directory(root, ec)) return;
    for (fs::recursive_directory_iterator it(root, fs::directory_options::skip_permission_denied, ec), end;
         !ec && it != end; it.increment(ec)) {
        if (!it->is_regular_file(ec) || !modelio::has_supported_extension(it->path())) continue;
        const std::string name = it->path().lexically_relative(root).generic_string();
        if (!modelio::check_model_name(name)) continue; // a name a level could not write ("a\b.glb")
        ModelEntry entry{name, it->path(), shipped};
        entry.bytes = it->file_size(ec);
        entry.mtime = it->last_write_time(ec);
        out.push_back(std::move(entry));
    }
}

} // namespace

ModelLibrary::ModelLibrary(fs::path shipped, fs::path user)
    : shipped_(std::move(shipped)), user_(std::move(user)) {}

ModelLibrary ModelLibrary::with_default_folders() {
    return ModelLibrary(paths::asset("models"), modelio::user_models_dir());
}

bool ModelLibrary::rescan() {
    std::vector<ModelEntry> found;
    list_model_folder(shipped_, true, found);
    list_model_folder(user_, false, found);
    std::stable_sort(found.begin(), found.end(), [](const ModelEntry& a, const ModelEntry& b) {
        return a.name != b.name ? a.name < b.name : a.shipped > b.shipped;
    });
    for (std::size_t i = 1; i < found.size(); ++i)
        if (found[i].name == found[i - 1].name) found[i].shadowed = true;
    const bool changed = found.size() != entries_.size() ||
                         !std::equal(found.begin(), found.end(), entries_.begin(),
                                     [](const ModelEntry& a, const ModelEntry& b) {
                                         return a.path == b.path && a.bytes == b.bytes && a.mtime == b.mtime;
                                     });
    if (!changed) return false;
    entries_ = std::move(found);
    ++revision_;
    return true;
}

std::vector<const ModelEntry*> ModelLibrary::search(std::string_view query) const {
    std::vector<std::string> words;
    const std::string text = fold_case(query);
    for (std::size_t at = 0; at < text.size();) {
        const std::size_t end = std::min(text.find(' ', at), text.size());
        if (end > at) words.push_back(text.substr(at, end - at));
        at = end + 1;
    }
    std::vector<const ModelEntry*> out;
    for (const ModelEntry& entry : entries_) {
        const std::string name = fold_case(entry.name);
        if (std::ranges::all_of(words,
                                [&](const std::string& w) { return name.find(w) != std::string::npos; }))
            out.push_back(&entry);
    }
    return out;
}

const ModelEntry* ModelLibrary::find(std::string_view name) const {
    for (const ModelEntry& entry : entries_)
        if (entry.name == name && !entry.shadowed) return &entry;
    return nullptr;
}

} // namespace ks::editor
