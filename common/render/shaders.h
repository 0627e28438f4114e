#pragma once
// Every GLSL program the renderer uses, as named sources (names appear in compile errors).
#include "render/shader_program.h"

#include <vector>

namespace ks::render {

inline constexpr int kMaxLightsPerDraw = 8; // lights each object is shaded by (culled per object on the CPU)

struct ProgramSources {
    const char* name;
    ShaderSource vertex;
    ShaderSource fragment;
};

const ProgramSources& pbr_program();
const ProgramSources& shadow_program();
const ProgramSources& particle_program();
const ProgramSources& line_program();
// All of the above (the shader compile test walks this list).
std::vector<const ProgramSources*> all_programs();

} // namespace ks::render
