#pragma once
// A linked GLSL program. Compile and link errors come back as ks::Error naming "file:line: message" where
// the file is the shader's name (e.g. "pbr.frag") and the line is the driver's line in that source.
#include "core/result.h"

#include <functional>
#include <string>
#include <string_view>
#include <unordered_map>

namespace ks::render {

struct ShaderSource {
    std::string name; // e.g. "pbr.vert", used in error messages
    std::string text;
};

class ShaderProgram {
  public:
    ShaderProgram() = default;
    ~ShaderProgram();
    ShaderProgram(const ShaderProgram&) = delete;
    ShaderProgram& operator=(const ShaderProgram&) = delete;
    ShaderProgram(ShaderProgram&& other) noexcept;
    ShaderProgram& operator=(ShaderProgram&& other) noexcept;

    static Result<ShaderProgram> build(const ShaderSource& vertex, const ShaderSource& fragment);

    unsigned id() const { return id_; }
    void use() const;
    // Uniform location, cached; -1 for names the compiler optimised away (setting those is a no-op in GL).
    int location(const char* name) const;

  private:
    unsigned id_ = 0;
    // Looked up by string_view (transparent hash): a cached name costs no std::string per call, so the
    // per-frame uniform updates allocate nothing (most names are longer than the small-string buffer).
    struct NameHash {
        using is_transparent = void;
        size_t operator()(std::string_view s) const { return std::hash<std::string_view>{}(s); }
    };
    mutable std::unordered_map<std::string, int, NameHash, std::equal_to<>> locations_;
};

// Turns a driver info log ("0:12(5): error: ..." from Mesa, "0(12) : error ..." from NVIDIA) into lines
// "name:12: error: ...". Exposed for tests.
std::string format_shader_log(std::string_view log, const std::string& name);

} // namespace ks::render
