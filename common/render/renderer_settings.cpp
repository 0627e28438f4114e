#include "render/renderer_settings.h"

#include "core/log.h"
#include "render/texture_cache.h"

#include <algorithm>
#include <cstdlib>
#include <string_view>

namespace ks::render {

int default_msaa_for(const std::string& gl_renderer) {
    return is_software_renderer(gl_renderer) ? 0 : 4;
}

RenderQuality default_quality_for(const std::string& gl_renderer) {
    return is_software_renderer(gl_renderer) ? RenderQuality::Fast : RenderQuality::Full;
}

float default_render_scale_for(const std::string& gl_renderer, float software_scale) {
    return is_software_renderer(gl_renderer) ? std::clamp(software_scale, 0.25f, 1.0f) : 1.0f;
}

std::vector<std::string> apply_environment_overrides(RendererSettings& settings,
                                                     const EnvironmentLookup& lookup) {
    std::vector<std::string> warnings;
    auto value = [&](const char* name) -> std::string_view {
        const char* v = lookup(name);
        return v ? std::string_view(v) : std::string_view();
    };
    if (const auto q = value("KS_RENDER_QUALITY"); !q.empty()) {
        if (q == "full")
            settings.automatic_quality = RenderQuality::Full;
        else if (q == "fast")
            settings.automatic_quality = RenderQuality::Fast;
        else
            warnings.push_back("KS_RENDER_QUALITY='" + std::string(q) +
                               "' is not 'full' or 'fast'; choosing from the GL renderer");
    }
    if (const auto v = value("KS_RENDER_SCALE"); !v.empty()) {
        const std::string text(v);
        char* end = nullptr;
        const float scale = std::strtof(text.c_str(), &end);
        if (end != text.c_str() && *end == '\0' && is_finite(scale) && scale > 0.0f)
            settings.automatic_render_scale = std::clamp(scale, 0.25f, 1.0f);
        else
            warnings.push_back("KS_RENDER_SCALE='" + text +
                               "' is not a number in 0.25..1; choosing from the GL renderer");
    }
    if (const auto v = value("KS_LIGHTMAP_FLOAT"); !v.empty()) {
        if (v == "1" || v == "0")
            settings.lightmap_float = v == "1";
        else
            warnings.push_back("KS_LIGHTMAP_FLOAT='" + std::string(v) +
                               "' is not 0 or 1; keeping the 8-bit light map");
    }
    if (const auto v = value("KS_VIEW_MODEL_MSAA"); !v.empty()) {
        if (v == "0" || v == "1" || v == "2" || v == "4" || v == "8")
            settings.view_model_msaa = v[0] - '0';
        else
            warnings.push_back("KS_VIEW_MODEL_MSAA='" + std::string(v) +
                               "' is not 0, 1, 2, 4 or 8; keeping " +
                               std::to_string(settings.view_model_msaa));
    }
    if (const auto v = value("KS_SHADER_DIR"); !v.empty()) settings.shader_dir = std::string(v);
    if (const auto v = value("KS_SHADER_HOT_RELOAD"); !v.empty())
        settings.shader_hot_reload = v == "0" ? 0 : 1;
    return warnings;
}

RendererSettings renderer_settings_from_environment(RendererSettings settings) {
    for (const auto& warning :
         apply_environment_overrides(settings, [](const char* name) { return std::getenv(name); }))
        log::warn(warning);
    return settings;
}

} // namespace ks::render
