#include "model/autosave.h"

#include "core/files.h"
#include "core/paths.h"
#include "level/level_io.h"

#include <algorithm>
#include <charconv>
#include <chrono>

namespace ks::editor {
namespace fs = std::filesystem;
namespace {
// The counter n of "<stem>.<n>.json", or -1 when the name is not one of stem's autosaves.
long long autosave_number(const std::string& filename, const std::string& stem) {
    const std::string prefix = stem + ".", suffix = ".json";
    if (filename.size() <= prefix.size() + suffix.size() || filename.compare(0, prefix.size(), prefix) != 0 ||
        filename.compare(filename.size() - suffix.size(), suffix.size(), suffix) != 0)
        return -1;
    const char* first = filename.data() + prefix.size();
    const char* last = filename.data() + filename.size() - suffix.size();
    long long n = -1;
    auto res = std::from_chars(first, last, n);
    return res.ec == std::errc() && res.ptr == last ? n : -1;
}

std::string stem_of(const fs::path& level_file) {
    return level_file.empty() ? std::string("untitled") : level_file.stem().string();
}
} // namespace

double steady_seconds() {
    using namespace std::chrono;
    return duration<double>(steady_clock::now().time_since_epoch()).count();
}

fs::path autosave_dir_for(const fs::path& level_file) {
    const fs::path folder = level_file.has_parent_path() ? level_file.parent_path() : fs::path(".");
    return folder / ".autosave";
}

std::vector<fs::path> list_autosaves(const fs::path& dir, const std::string& stem) {
    std::vector<std::pair<long long, fs::path>> found;
    std::error_code ec;
    for (auto it = fs::directory_iterator(dir, ec); !ec && it != fs::directory_iterator(); it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (long long n = autosave_number(name, stem); n >= 0 && it->is_regular_file(ec))
            found.emplace_back(n, it->path());
    }
    std::sort(found.begin(), found.end());
    std::vector<fs::path> out;
    for (auto& [n, p] : found) out.push_back(std::move(p));
    return out;
}

std::optional<RecoveryOffer> find_recovery(const fs::path& level_file) {
    auto saves = list_autosaves(autosave_dir_for(level_file), stem_of(level_file));
    if (saves.empty()) return std::nullopt;
    const fs::path& newest = saves.back();
    std::error_code ec1, ec2;
    auto file_time = fs::last_write_time(level_file, ec1);
    auto save_time = fs::last_write_time(newest, ec2);
    if (ec2 || (!ec1 && save_time <= file_time)) return std::nullopt;
    auto file_text = files::read_text(level_file);
    auto save_text = files::read_text(newest);
    if (!save_text || (file_text && *file_text == *save_text)) return std::nullopt;
    return RecoveryOffer{level_file, newest};
}

fs::path untitled_autosave_dir(const AutosaveConfig& config) {
    if (!config.untitled_dir.empty()) return config.untitled_dir;
    fs::path base = paths::user_config_dir();
    return base.empty() ? fs::temp_directory_path() / "killswitch-autosave" : base / "autosave";
}

std::optional<RecoveryOffer> find_untitled_recovery(const AutosaveConfig& config) {
    auto saves = list_autosaves(untitled_autosave_dir(config), stem_of({}));
    if (saves.empty()) return std::nullopt;
    return RecoveryOffer{{}, saves.back()};
}

void remove_autosaves(const fs::path& dir, const std::string& stem) {
    std::error_code ec;
    for (const auto& p : list_autosaves(dir, stem)) fs::remove(p, ec);
}

Autosaver::Autosaver(AutosaveConfig config, Clock clock)
    : config_(std::move(config)), clock_(std::move(clock)) {
    config_.untitled_dir = untitled_autosave_dir(config_);
    config_.keep = std::max(config_.keep, 1);
}

Result<std::optional<fs::path>> Autosaver::update(const Editor& editor) {
    const double now = clock_();
    const std::uint64_t revision = editor.revision();
    if (revision != seen_revision_) {
        seen_revision_ = revision;
        last_change_ = now;
        if (!pending_since_) pending_since_ = now;
    }
    if (!editor.has_unsaved_changes() || revision == saved_revision_) {
        pending_since_.reset();
        return std::optional<fs::path>();
    }
    const bool idle = now - last_change_ >= config_.idle_seconds;
    const bool overdue = pending_since_ && now - *pending_since_ >= config_.max_delay_seconds;
    if (!idle && !overdue) return std::optional<fs::path>();
    if (now < retry_after_) return std::optional<fs::path>();
    auto written = write(editor);
    if (!written) {
        // The edits are still unsaved: try again after another idle period (not every frame), even if the
        // user makes no further change (a full disk that frees up must not leave the edits unprotected).
        retry_after_ = now + config_.idle_seconds;
        return written.error();
    }
    saved_revision_ = revision;
    pending_since_.reset();
    retry_after_ = 0;
    return std::optional<fs::path>(*written);
}

Result<fs::path> Autosaver::write(const Editor& editor) {
    const fs::path& file = editor.file_path();
    const fs::path dir = file.empty() ? config_.untitled_dir : autosave_dir_for(file);
    const std::string stem = stem_of(file);
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec)
        return Error("autosave: cannot create " + dir.string() + ": " + ec.message(), Location{dir.string()},
                     "make the level's folder writable");
    auto existing = list_autosaves(dir, stem);
    long long n = existing.empty() ? 1 : autosave_number(existing.back().filename().string(), stem) + 1;
    const fs::path target = dir / (stem + "." + std::to_string(n) + ".json");
    if (auto r = files::write_atomic(target, level::save_level_string(editor.level())); !r) return r.error();
    existing.push_back(target);
    for (size_t i = 0; i + static_cast<size_t>(config_.keep) < existing.size(); ++i)
        fs::remove(existing[i], ec);
    return target;
}

} // namespace ks::editor
