#include "test_support.h"

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

namespace ks::test {
namespace fs = std::filesystem;

fs::path source_dir() {
    return fs::path(KS_SOURCE_DIR);
}
fs::path data_dir() {
    return source_dir() / "tests" / "data";
}
fs::path bin_dir() {
    return fs::path(KS_BIN_DIR);
}

std::string read_file(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream out;
    out << in.rdbuf();
    return out.str();
}

bool sanitized_build() {
#ifdef KS_SANITIZED_BUILD
    return true;
#else
    return false;
#endif
}

bool contains_text(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

std::string editor_binary() {
    return (bin_dir() / "killswitch-editor").string();
}

fs::path write_file(const fs::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

ScratchDir::ScratchDir() {
    static std::atomic<int> counter{0};
    path_ = fs::temp_directory_path() /
            ("ks-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter.fetch_add(1)));
    fs::remove_all(path_);
    fs::create_directories(path_);
}

ScratchDir::~ScratchDir() {
    std::error_code ec;
    fs::permissions(path_, fs::perms::owner_all, fs::perm_options::add, ec);
    fs::remove_all(path_, ec);
}

ScratchDataHome::ScratchDataHome() {
    if (const char* old = std::getenv("XDG_DATA_HOME")) old_ = old, had_ = true;
    setenv("XDG_DATA_HOME", dir_.path().c_str(), 1);
    fs::create_directories(models());
}

ScratchDataHome::~ScratchDataHome() {
    had_ ? setenv("XDG_DATA_HOME", old_.c_str(), 1) : unsetenv("XDG_DATA_HOME");
}

CommandResult run_command(const std::string& command_line) {
    CommandResult result;
    std::string full = command_line + " 2>&1";
    FILE* pipe = ::popen(full.c_str(), "r");
    if (!pipe) return result;
    char buffer[4096];
    size_t n;
    while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) result.output.append(buffer, n);
    int status = ::pclose(pipe);
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    return result;
}

} // namespace ks::test
