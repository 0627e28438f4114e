#pragma once
// File access that reports failures as values, and atomic writes: the data goes to a temporary file in the
// same folder, is flushed to disk, then renamed over the target, so a crash mid-save leaves either the old
// file or the new one, never a torn mix.
#include "core/result.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace ks::files {

Result<std::string> read_text(const std::filesystem::path& path);

// The regular files in `folder` (links to them included) whose names end with `ending` (".json",
// "_basecolor.png") after at least one more character, sorted by path. Never throws: a folder that is
// missing, is not a folder or cannot be read is an error naming it (callers that treat that as "no files" say
// so with value_or).
Result<std::vector<std::filesystem::path>> list(const std::filesystem::path& folder, std::string_view ending);
Result<void> write_atomic(const std::filesystem::path& path, std::string_view data);

// A new, empty temporary file beside `path` (same folder, so a rename over `path` is atomic), open for
// writing: the first step of write_atomic and of streamed writers that rename their result into place.
struct TempFile {
    int fd = -1;
    std::filesystem::path path;
};
Result<TempFile> create_temp_beside(const std::filesystem::path& path);

// Fault injection for tests: make the next atomic writes fail at a chosen stage, as a full disk, a crash
// between write and rename, or a read-only folder would.
enum class Fault : std::uint8_t {
    None,
    OpenTemp,     // the temporary file cannot be created (read-only folder)
    ShortWrite,   // the disk fills up after half the data
    BeforeRename, // the process "dies" after writing the temp file, before the rename
};
void inject_fault(Fault fault); // applies to every write until reset with Fault::None

} // namespace ks::files
