#include "core/files.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace ks::files {
namespace {
Fault g_fault = Fault::None;

Error io_error(const std::filesystem::path& path, const std::string& what, int err, std::string hint = {}) {
    return Error(what + ": " + std::strerror(err), Location{path.string()}, std::move(hint));
}

bool write_all(int fd, const char* data, size_t size) {
    while (size > 0) {
        ssize_t n = ::write(fd, data, size);
        if (n < 0) {
            if (errno == EINTR) continue;
            return false;
        }
        data += n;
        size -= static_cast<size_t>(n);
    }
    return true;
}
} // namespace

void inject_fault(Fault fault) {
    g_fault = fault;
}

Result<std::vector<std::filesystem::path>> list(const std::filesystem::path& folder,
                                                std::string_view ending) {
    namespace fs = std::filesystem;
    std::vector<fs::path> found;
    std::error_code ec;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        std::error_code type_ec;
        if (name.size() > ending.size() && name.ends_with(ending) && it->is_regular_file(type_ec))
            found.push_back(it->path());
    }
    if (ec)
        return Error("cannot list the folder: " + ec.message(), Location{folder.string()},
                     "check that the folder exists and that it can be read");
    std::sort(found.begin(), found.end()); // the same order on every file system
    return found;
}

Result<std::string> read_text(const std::filesystem::path& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
        return Error("file not found", Location{path.string()},
                     "check the path; it is resolved from the current folder");
    if (std::filesystem::is_directory(path, ec))
        return Error("is a folder, not a file", Location{path.string()});
    // One read into a string of the file's size (the disk cache's entries are megabytes): no stream copies.
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return io_error(path, "cannot open for reading", errno, "check the file's permissions");
    struct stat st {};
    std::string data;
    if (::fstat(fd, &st) == 0 && st.st_size > 0) data.reserve(static_cast<size_t>(st.st_size));
    char chunk[1 << 16];
    for (;;) {
        // Straight into the string's reserved space while it lasts (files of a known size), else by chunks
        // (a size of 0 is what /proc's files and pipes report).
        const size_t room = data.capacity() - data.size();
        if (room > 0) {
            const size_t at = data.size();
            data.resize(data.capacity());
            const ssize_t n = ::read(fd, data.data() + at, room);
            data.resize(at + static_cast<size_t>(std::max<ssize_t>(n, 0)));
            if (n > 0) continue;
            if (n == 0) break;
        } else {
            const ssize_t n = ::read(fd, chunk, sizeof chunk);
            if (n > 0) {
                data.append(chunk, static_cast<size_t>(n));
                continue;
            }
            if (n == 0) break;
        }
        if (errno == EINTR) continue;
        const int err = errno;
        ::close(fd);
        return io_error(path, "read failed", err);
    }
    ::close(fd);
    return data;
}

Result<TempFile> create_temp_beside(const std::filesystem::path& path) {
    const std::filesystem::path folder =
        path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
    std::string temp = (folder / ("." + path.filename().string() + ".tmp-XXXXXX")).string();
    int fd = -1;
    if (g_fault == Fault::OpenTemp) {
        errno = EROFS;
    } else {
        fd = ::mkstemp(temp.data());
    }
    if (fd < 0)
        return io_error(path, "cannot create a temporary file in " + folder.string(), errno,
                        "the folder must exist and be writable; the previous file was left untouched");
    return TempFile{fd, temp};
}

Result<void> write_atomic(const std::filesystem::path& path, std::string_view data) {
    const std::filesystem::path folder =
        path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
    auto created = create_temp_beside(path);
    if (!created) return created.error();
    const int fd = created->fd;
    const std::string temp = created->path.string();

    auto fail = [&](const std::string& what, int err) {
        ::close(fd);
        ::unlink(temp.c_str());
        return io_error(path, what, err, "the previous file was left untouched");
    };

    size_t to_write = data.size();
    if (g_fault == Fault::ShortWrite) to_write /= 2;
    if (!write_all(fd, data.data(), to_write)) return fail("write failed", errno);
    if (g_fault == Fault::ShortWrite) return fail("write failed", ENOSPC);
    if (::fsync(fd) != 0) return fail("flush to disk failed", errno);
    // Keep the permissions of the file being replaced, or the usual 0644 for a new one.
    struct stat st {};
    ::fchmod(fd, ::stat(path.c_str(), &st) == 0 ? (st.st_mode & 07777) : 0644);
    if (::close(fd) != 0) {
        ::unlink(temp.c_str());
        return io_error(path, "close failed", errno, "the previous file was left untouched");
    }
    if (g_fault == Fault::BeforeRename) {
        // A crash here leaves the temporary file behind and the target untouched; emulate exactly that.
        return Error("simulated crash before rename", Location{path.string()},
                     "the previous file was left untouched");
    }
    if (::rename(temp.c_str(), path.c_str()) != 0) {
        int err = errno;
        ::unlink(temp.c_str());
        return io_error(path, "rename over the target failed", err, "the previous file was left untouched");
    }
    // Make the rename itself durable.
    int dir_fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY);
    if (dir_fd >= 0) {
        ::fsync(dir_fd);
        ::close(dir_fd);
    }
    return ok();
}

} // namespace ks::files
