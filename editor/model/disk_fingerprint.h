#pragma once
// What a file on disk looked like when the editor last read or wrote it, so Save can tell whether someone
// else changed it in between. The content hash decides: a touched but unchanged file is not a conflict.
#include <cstdint>
#include <filesystem>
#include <string_view>

namespace ks::editor {

struct DiskFingerprint {
    bool exists = false;
    std::uintmax_t size = 0;
    std::filesystem::file_time_type mtime{};
    std::uint64_t hash = 0;
    bool same_content(const DiskFingerprint& o) const {
        return exists == o.exists && size == o.size && hash == o.hash;
    }
};

std::uint64_t fnv1a64(std::string_view data);
DiskFingerprint fingerprint_file(const std::filesystem::path& path);
DiskFingerprint fingerprint_text(std::string_view text, std::filesystem::file_time_type mtime);

} // namespace ks::editor
