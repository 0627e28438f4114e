#pragma once
// Helpers shared by the test suites: where test data lives, scratch folders, running our binaries.
#include <filesystem>
#include <string>

namespace ks::test {

std::filesystem::path source_dir(); // the repository root
std::filesystem::path data_dir();   // tests/data
std::filesystem::path bin_dir();    // where killswitch, killswitch-editor live
std::string editor_binary();        // bin_dir() / killswitch-editor
std::string read_file(const std::filesystem::path& path);
// `text` contains `part` (a report line, a message).
bool contains_text(const std::string& text, const std::string& part);
// The AddressSanitizer + UBSan build (KS_SANITIZE), where code runs several times slower: long property loops
// take `sanitized_share` of their iterations there; the Release pass runs them in full.
bool sanitized_build();
inline int iterations(int full, double sanitized_share = 0.25) {
    return sanitized_build() ? static_cast<int>(full * sanitized_share) : full;
}
// Writes `text` to `path` (replacing it); the path back.
std::filesystem::path write_file(const std::filesystem::path& path, const std::string& text);

// A fresh empty folder removed when the object dies.
class ScratchDir {
  public:
    ScratchDir();
    ~ScratchDir();
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;
    const std::filesystem::path& path() const { return path_; }
    std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

  private:
    std::filesystem::path path_;
};

// XDG_DATA_HOME pointed at a fresh folder for the object's life, so the user's models folder
// (`models()`, created) is the test's own; the old value is put back.
class ScratchDataHome {
  public:
    ScratchDataHome();
    ~ScratchDataHome();
    ScratchDataHome(const ScratchDataHome&) = delete;
    ScratchDataHome& operator=(const ScratchDataHome&) = delete;
    const std::filesystem::path& path() const { return dir_.path(); }
    std::filesystem::path models() const { return dir_ / "killswitch/models"; }

  private:
    ScratchDir dir_;
    std::string old_;
    bool had_ = false;
};

struct CommandResult {
    int exit_code = -1;
    std::string output; // stdout and stderr together
};
// Runs a shell command line, capturing its output.
CommandResult run_command(const std::string& command_line);

} // namespace ks::test
