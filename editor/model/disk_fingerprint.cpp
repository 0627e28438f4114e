#include "model/disk_fingerprint.h"

#include "core/files.h"

namespace ks::editor {

std::uint64_t fnv1a64(std::string_view data) {
    std::uint64_t h = 14695981039346656037ull;
    for (unsigned char c : data) {
        h ^= c;
        h *= 1099511628211ull;
    }
    return h;
}

DiskFingerprint fingerprint_text(std::string_view text, std::filesystem::file_time_type mtime) {
    return {true, text.size(), mtime, fnv1a64(text)};
}

DiskFingerprint fingerprint_file(const std::filesystem::path& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return {};
    auto mtime = std::filesystem::last_write_time(path, ec);
    auto text = files::read_text(path);
    if (!text) return {};
    return fingerprint_text(*text, mtime);
}

} // namespace ks::editor
