// A cache entry's bytes, mapped (core/disk_cache.h, Payload).
#include "core/disk_cache.h"

#include "core/files.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <utility>

namespace ks::disk_cache {

std::optional<Payload> Payload::of_file(const std::filesystem::path& path, std::string& error) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) {
        error = std::strerror(errno);
        return std::nullopt;
    }
    struct stat st {};
    Payload payload;
    if (::fstat(fd, &st) == 0 && st.st_size > 0) {
        const auto size = static_cast<std::size_t>(st.st_size);
        // MAP_POPULATE maps every page in one go (a warm entry is in the page cache): no fault per page.
        // The files are replaced by rename, never rewritten in place, so the mapping cannot shrink under us.
        void* map = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
        if (map != MAP_FAILED) {
            payload.map_ = map;
            payload.map_size_ = size;
            payload.view_ = std::string_view(static_cast<const char*>(map), size);
        }
    }
    ::close(fd);
    if (payload.map_ || (st.st_size == 0 && st.st_mode != 0)) return payload; // mapped, or an empty file
    auto text = files::read_text(path); // where mapping is refused: read it
    if (!text) {
        error = text.error().message;
        return std::nullopt;
    }
    return Payload(std::move(*text));
}

Payload::Payload(Payload&& other) noexcept {
    *this = std::move(other);
}

Payload& Payload::operator=(Payload&& other) noexcept {
    if (this == &other) return *this;
    unmap();
    const char* other_base = other.map_ ? static_cast<const char*>(other.map_) : other.owned_.data();
    const std::size_t offset =
        other.view_.data() ? static_cast<std::size_t>(other.view_.data() - other_base) : 0;
    const std::size_t size = other.view_.size();
    map_ = std::exchange(other.map_, nullptr);
    map_size_ = std::exchange(other.map_size_, 0);
    owned_ = std::move(other.owned_);
    // The view points into the mapping (which moves with us) or into the string (whose buffer may not).
    const char* base = map_ ? static_cast<const char*>(map_) : owned_.data();
    view_ = std::string_view(base + offset, size);
    other.owned_.clear();
    other.view_ = {};
    return *this;
}

Payload::~Payload() {
    unmap();
}

void Payload::unmap() {
    if (map_) ::munmap(map_, map_size_);
    map_ = nullptr;
    map_size_ = 0;
}

} // namespace ks::disk_cache
