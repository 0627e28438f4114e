#pragma once
// The renderer's programs, built from files in a shader folder, with optional hot reload: poll() checks the
// files' modification times (at most once per interval) and rebuilds a program whose file changed. A
// program that fails to compile or link keeps the previous, working one and logs "path:line: message".
#include "core/result.h"
#include "render/shaders.h"

#include <chrono>
#include <filesystem>
#include <functional>
#include <vector>

namespace ks::render {

// Debug builds reload shaders by default; KS_SHADER_HOT_RELOAD=1/0 overrides in any build.
bool default_shader_hot_reload();

class ShaderLibrary {
  public:
    using Clock = std::chrono::steady_clock;

    explicit ShaderLibrary(std::filesystem::path dir = default_shader_dir()) : dir_(std::move(dir)) {}

    // Builds `files` into `target` (which must outlive the library); `on_built` runs after every successful
    // (re)build with the new program in use (set sampler units there).
    Result<void> add(const ProgramFiles& files, ShaderProgram& target,
                     std::function<void(ShaderProgram&)> on_built = {});

    // Rebuilds programs whose files changed since they were built. Checks the files at most once per
    // `interval` unless `force`. Returns how many programs were replaced.
    int poll(Clock::time_point now = Clock::now(), bool force = false);
    // Failed rebuilds since creation (each logged once).
    int failures() const { return failures_; }
    const std::filesystem::path& dir() const { return dir_; }
    std::chrono::milliseconds interval{1000};

  private:
    struct Entry {
        const ProgramFiles* files;
        ShaderProgram* target;
        std::function<void(ShaderProgram&)> on_built;
        std::filesystem::file_time_type vertex_time, fragment_time;
    };
    std::filesystem::file_time_type mtime(const char* file) const;
    std::filesystem::path dir_;
    std::vector<Entry> entries_;
    Clock::time_point last_poll_{};
    int failures_ = 0;
};

} // namespace ks::render
