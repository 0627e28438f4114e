#include "model/recent_files.h"

#include "core/files.h"

#include <nlohmann/json.hpp>

namespace ks::editor {
namespace fs = std::filesystem;

RecentFiles::RecentFiles(fs::path config_file, size_t capacity)
    : config_file_(std::move(config_file)), capacity_(capacity) {}

Result<void> RecentFiles::load() {
    entries_.clear();
    std::error_code ec;
    if (!fs::exists(config_file_, ec)) return ok();
    auto text = files::read_text(config_file_);
    if (!text) return text.error();
    auto json = nlohmann::json::parse(*text, nullptr, false);
    const char* hint = "delete the file; the editor writes a fresh one on the next open or save";
    if (json.is_discarded() || !json.is_object() || !json.contains("recent") || !json["recent"].is_array())
        return Error("recent files list is not {\"recent\": [\"path\", ...]}",
                     Location{config_file_.string()}, hint);
    for (const auto& item : json["recent"]) {
        if (!item.is_string())
            return Error("recent files list holds a non-string entry", Location{config_file_.string()}, hint);
        if (entries_.size() < capacity_) entries_.emplace_back(item.get<std::string>());
    }
    return ok();
}

Result<void> RecentFiles::save() const {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& p : entries_) list.push_back(p.string());
    std::error_code ec;
    if (config_file_.has_parent_path()) fs::create_directories(config_file_.parent_path(), ec);
    if (ec)
        return Error("cannot create the config folder: " + ec.message(),
                     Location{config_file_.parent_path().string()},
                     "set XDG_CONFIG_HOME to a writable folder");
    return files::write_atomic(config_file_, nlohmann::json{{"recent", list}}.dump(2) + "\n");
}

void RecentFiles::add(const fs::path& file) {
    std::error_code ec;
    fs::path absolute = fs::absolute(file, ec).lexically_normal();
    if (ec) absolute = file;
    remove(absolute);
    entries_.insert(entries_.begin(), absolute);
    if (entries_.size() > capacity_) entries_.resize(capacity_);
}

void RecentFiles::remove(const fs::path& file) {
    std::error_code ec;
    fs::path absolute = fs::absolute(file, ec).lexically_normal();
    std::erase_if(entries_, [&](const fs::path& p) { return p == absolute || p == file; });
}

} // namespace ks::editor
