#include "render/shaders.h"

#include "core/files.h"
#include "core/paths.h"

namespace ks::render {

const ProgramFiles& pbr_program() {
    static const ProgramFiles p{"pbr", "pbr.vert", "pbr.frag"};
    return p;
}
const ProgramFiles& fast_program() {
    static const ProgramFiles p{"fast", "fast.vert", "fast.frag"};
    return p;
}
const ProgramFiles& fast_level_program() {
    static const ProgramFiles p{"fast_level", "fast_level.vert", "fast_level.frag"};
    return p;
}
const ProgramFiles& fast_level_lit_program() {
    static const ProgramFiles p{"fast_level_lit", "fast_level.vert", "fast_level.frag",
                                "#define DYNAMIC_LIGHTS\n"};
    return p;
}
const ProgramFiles& fast_model_program(int index) {
    static const ProgramFiles p[kFastModelPrograms] = {
        {"fast_model", "fast.vert", "fast.frag",
         "#define FIXED_MAPS\n#define FIXED_ORM 0\n#define FIXED_EMISSIVE false\n"},
        {"fast_model_orm", "fast.vert", "fast.frag",
         "#define FIXED_MAPS\n#define FIXED_ORM 1\n#define FIXED_EMISSIVE false\n"},
        {"fast_model_orm_in_base", "fast.vert", "fast.frag",
         "#define FIXED_MAPS\n#define FIXED_ORM 2\n#define FIXED_EMISSIVE false\n"},
        {"fast_model_emissive", "fast.vert", "fast.frag",
         "#define FIXED_MAPS\n#define FIXED_ORM 0\n#define FIXED_EMISSIVE true\n"},
        {"fast_model_orm_emissive", "fast.vert", "fast.frag",
         "#define FIXED_MAPS\n#define FIXED_ORM 1\n#define FIXED_EMISSIVE true\n"},
        {"fast_model_orm_in_base_emissive", "fast.vert", "fast.frag",
         "#define FIXED_MAPS\n#define FIXED_ORM 2\n#define FIXED_EMISSIVE true\n"}};
    return p[index];
}
const ProgramFiles& fast_model_program(ModelOrm orm, bool emissive_map) {
    return fast_model_program(static_cast<int>(orm) + (emissive_map ? 3 : 0));
}
const ProgramFiles& shadow_program() {
    static const ProgramFiles p{"shadow", "shadow.vert", "shadow.frag"};
    return p;
}
const ProgramFiles& particle_program() {
    static const ProgramFiles p{"particle", "particle.vert", "particle.frag"};
    return p;
}
const ProgramFiles& line_program() {
    static const ProgramFiles p{"line", "line.vert", "line.frag"};
    return p;
}
const ProgramFiles& view_model_composite_program() {
    static const ProgramFiles p{"view_model_composite", "view_model_composite.vert",
                                "view_model_composite.frag"};
    return p;
}
const ProgramFiles& view_model_mask_program() {
    static const ProgramFiles p{"view_model_mask", "view_model_composite.vert", "view_model_mask.frag"};
    return p;
}
const ProgramFiles& contact_shadow_program() {
    static const ProgramFiles p{"contact_shadow", "contact_shadow.vert", "contact_shadow.frag"};
    return p;
}
std::vector<const ProgramFiles*> all_programs() {
    return {&pbr_program(),
            &fast_program(),
            &fast_level_program(),
            &fast_level_lit_program(),
            &shadow_program(),
            &particle_program(),
            &line_program(),
            &view_model_composite_program(),
            &view_model_mask_program(),
            &contact_shadow_program(),
            &fast_model_program(0),
            &fast_model_program(1),
            &fast_model_program(2),
            &fast_model_program(3),
            &fast_model_program(4),
            &fast_model_program(5)};
}

std::filesystem::path default_shader_dir() {
    return paths::asset("shaders");
}

std::string with_defines(const std::string& text, const char* defines) {
    if (!defines || !*defines || text.rfind("#version", 0) != 0) return text;
    const std::size_t eol = text.find('\n');
    if (eol == std::string::npos) return text;
    // GLSL's "#line N": the line after the directive is line N (version line is line 1).
    return text.substr(0, eol + 1) + defines + "#line 2\n" + text.substr(eol + 1);
}

Result<ProgramSources> load_program(const ProgramFiles& files, const std::filesystem::path& dir) {
    ProgramSources out;
    out.name = files.name;
    for (auto [file, source] :
         {std::pair{files.vertex, &out.vertex}, std::pair{files.fragment, &out.fragment}}) {
        const std::filesystem::path path = dir / file;
        auto text = files::read_text(path);
        if (!text)
            return Error("cannot read shader " + path.string(), Location{path.string()},
                         "the renderer loads its GLSL from assets/shaders/ (KS_SHADER_DIR overrides it); "
                         "check the file exists and is readable");
        source->name = path.string();
        source->text = with_defines(*text, files.defines);
    }
    return out;
}

Result<ShaderProgram> build_program(const ProgramFiles& files, const std::filesystem::path& dir) {
    auto sources = load_program(files, dir);
    if (!sources) return sources.error();
    return ShaderProgram::build(sources->vertex, sources->fragment);
}

} // namespace ks::render
