#pragma once
// Every GLSL program the renderer uses, as files under assets/shaders/ (names appear in compile errors as
// the file's path, so "assets/shaders/pbr.frag:12: error: ..." points at the line to fix).
#include "core/result.h"
#include "render/shader_program.h"

#include <filesystem>
#include <vector>

namespace ks::render {

inline constexpr int kMaxLightsPerDraw = 8; // lights each object is shaded by (culled per object on the CPU)

// One program: its name, the vertex/fragment file names inside the shader folder, and preprocessor lines
// put after both files' #version line (a variant of a program built from the same files).
struct ProgramFiles {
    const char* name;
    const char* vertex;
    const char* fragment;
    const char* defines = ""; // e.g. "#define DYNAMIC_LIGHTS\n"
};

struct ProgramSources {
    std::string name;
    ShaderSource vertex; // name = the file's full path
    ShaderSource fragment;
};

// The programs: pbr (full quality), fast (software rasterisers: baked light + per-vertex light), fast_level
// (fast, specialised for baked level surfaces), fast_level_lit (fast_level plus per-pixel dynamic lights, for
// the baked surfaces a muzzle flash reaches), shadow, particle, line, view_model_composite, view_model_mask
// (the view model's opaque pixels written into the scene, depth 0, before the scene: view_model_layer.h),
// contact_shadow
// (movers' shadows on the floor, contact_shadows.h).
const ProgramFiles& pbr_program();
const ProgramFiles& fast_program();
const ProgramFiles& fast_level_program();     // the fast path's baked level surfaces (no branches)
const ProgramFiles& fast_level_lit_program(); // ... with Light::dynamic lights added per pixel
// Where a fast-path model's occlusion and metalness come from: nowhere (the factors), the ORM map, or the
// base map itself (TextureCache::get_occluded_base: base x occlusion in rgb, metalness in alpha; one lookup).
enum class ModelOrm { None = 0, Map = 1, InBase = 2 };
inline constexpr int kFastModelPrograms = 6;
// The fast path's models (no light map) with the ORM and emissive maps fixed at compile time: llvmpipe pays
// for every lookup in a branch on a uniform, taken or not. Index of a variant: int(orm) + 3 * emissive.
const ProgramFiles& fast_model_program(ModelOrm orm, bool emissive_map);
const ProgramFiles& fast_model_program(int index);
const ProgramFiles& shadow_program();
const ProgramFiles& particle_program();
const ProgramFiles& line_program();
// The antialiased view model's resolved layer blended over the scene (render/view_model_layer.h).
const ProgramFiles& view_model_composite_program();
const ProgramFiles& view_model_mask_program();
const ProgramFiles& contact_shadow_program();
// All of the above (the shader compile test walks this list).
std::vector<const ProgramFiles*> all_programs();

// assets/shaders/, or $KS_SHADER_DIR when set (a scratch copy for experiments).
std::filesystem::path default_shader_dir();
// `text` with `defines` after its #version line, then a #line directive so that the driver's line numbers
// stay the file's.
std::string with_defines(const std::string& text, const char* defines);
// Reads both files; a missing or unreadable file is an error naming it.
Result<ProgramSources> load_program(const ProgramFiles& files, const std::filesystem::path& dir);
// Reads and builds (compile errors as "path:line: message").
Result<ShaderProgram> build_program(const ProgramFiles& files, const std::filesystem::path& dir);

} // namespace ks::render
