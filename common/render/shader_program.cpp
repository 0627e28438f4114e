#include "render/shader_program.h"

#include <epoxy/gl.h>

#include <regex>
#include <sstream>

namespace ks::render {

std::string format_shader_log(std::string_view log, const std::string& name) {
    // Mesa: "0:12(5): error: msg"; NVIDIA: "0(12) : error C0000: msg"; AMD/Intel: "ERROR: 0:12: msg".
    static const std::regex mesa(R"(^\s*\d+:(\d+)\(\d+\):\s*(.*)$)");
    static const std::regex nvidia(R"(^\s*\d+\((\d+)\)\s*:\s*(.*)$)");
    static const std::regex other(R"(^\s*(?:ERROR|WARNING):\s*\d+:(\d+):\s*(.*)$)");
    std::istringstream in{std::string(log)};
    std::string line, out;
    while (std::getline(in, line)) {
        if (line.empty()) continue;
        std::smatch m;
        if (std::regex_match(line, m, mesa) || std::regex_match(line, m, nvidia) ||
            std::regex_match(line, m, other))
            out += name + ":" + m[1].str() + ": " + m[2].str() + "\n";
        else
            out += name + ": " + line + "\n";
    }
    if (!out.empty() && out.back() == '\n') out.pop_back();
    return out;
}

namespace {
std::string info_log(unsigned object, bool program) {
    GLint length = 0;
    if (program)
        glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
    else
        glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    std::string text(static_cast<size_t>(std::max(length, 1)), '\0');
    if (program)
        glGetProgramInfoLog(object, length, nullptr, text.data());
    else
        glGetShaderInfoLog(object, length, nullptr, text.data());
    while (!text.empty() && (text.back() == '\0' || text.back() == '\n')) text.pop_back();
    return text;
}

Result<unsigned> compile(GLenum stage, const ShaderSource& source) {
    unsigned shader = glCreateShader(stage);
    const char* text = source.text.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        std::string log = format_shader_log(info_log(shader, false), source.name);
        glDeleteShader(shader);
        return Error("shader compile failed:\n" + log, Location{source.name},
                     "fix the GLSL at that line (the renderer reads it from assets/shaders/)");
    }
    return shader;
}
} // namespace

Result<ShaderProgram> ShaderProgram::build(const ShaderSource& vertex, const ShaderSource& fragment) {
    auto vs = compile(GL_VERTEX_SHADER, vertex);
    if (!vs) return vs.error();
    auto fs = compile(GL_FRAGMENT_SHADER, fragment);
    if (!fs) {
        glDeleteShader(*vs);
        return fs.error();
    }
    ShaderProgram program;
    program.id_ = glCreateProgram();
    glAttachShader(program.id_, *vs);
    glAttachShader(program.id_, *fs);
    glLinkProgram(program.id_);
    glDeleteShader(*vs);
    glDeleteShader(*fs);
    GLint ok = 0;
    glGetProgramiv(program.id_, GL_LINK_STATUS, &ok);
    if (!ok)
        return Error("shader link failed: " + info_log(program.id_, true),
                     Location{vertex.name + "+" + fragment.name},
                     "the vertex outputs must match the fragment inputs");
    return program;
}

ShaderProgram::~ShaderProgram() {
    if (id_) glDeleteProgram(id_);
}

ShaderProgram::ShaderProgram(ShaderProgram&& other) noexcept
    : id_(other.id_), locations_(std::move(other.locations_)) {
    other.id_ = 0;
}

ShaderProgram& ShaderProgram::operator=(ShaderProgram&& other) noexcept {
    if (this != &other) {
        if (id_) glDeleteProgram(id_);
        id_ = other.id_;
        locations_ = std::move(other.locations_);
        other.id_ = 0;
    }
    return *this;
}

void ShaderProgram::use() const {
    glUseProgram(id_);
}

int ShaderProgram::location(const char* name) const {
    auto it = locations_.find(std::string_view(name));
    if (it != locations_.end()) return it->second;
    int loc = glGetUniformLocation(id_, name);
    locations_.emplace(name, loc);
    return loc;
}

} // namespace ks::render
