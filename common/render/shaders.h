#pragma once
// Every GLSL program the renderer uses, as files under assets/shaders/ (names appear in compile errors as
// the file's path, so "assets/shaders/pbr.frag:12: error: ..." points at the line to fix).
#include "core/result.h"
#include "render/shader_program.h"

#include <filesystem>
#include <vector>

namespace ks::render {

inline constexpr int kMaxLightsPerDraw = 8; // lights each object is shaded by (culled per object on the CPU)

// One program: its name and the vertex/fragment file names inside the shader folder.
struct ProgramFiles {
    const char* name;
    const char* vertex;
    const char* fragment;
};

struct ProgramSources {
    std::string name;
    ShaderSource vertex; // name = the file's full path
    ShaderSource fragment;
};

// The programs: pbr (full quality), fast (software rasterisers: baked light + per-vertex light), fast_level
// (fast, specialised for baked level surfaces), shadow,
// particle, line.
const ProgramFiles& pbr_program();
const ProgramFiles& fast_program();
const ProgramFiles& fast_level_program(); // the fast path's baked level surfaces (no branches)
const ProgramFiles& shadow_program();
const ProgramFiles& particle_program();
const ProgramFiles& line_program();
// All of the above (the shader compile test walks this list).
std::vector<const ProgramFiles*> all_programs();

// assets/shaders/, or $KS_SHADER_DIR when set (a scratch copy for experiments).
std::filesystem::path default_shader_dir();
// Reads both files; a missing or unreadable file is an error naming it.
Result<ProgramSources> load_program(const ProgramFiles& files, const std::filesystem::path& dir);
// Reads and builds (compile errors as "path:line: message").
Result<ShaderProgram> build_program(const ProgramFiles& files, const std::filesystem::path& dir);

} // namespace ks::render
