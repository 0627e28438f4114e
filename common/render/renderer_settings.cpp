#include "render/renderer_settings.h"

#include "core/log.h"
#include "render/texture_cache.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>

namespace ks::render {

int default_msaa_for(const std::string& gl_renderer) {
    return is_software_renderer(gl_renderer) ? 0 : 4;
}

RenderQuality default_quality_for(const std::string& gl_renderer) {
    if (const char* q = std::getenv("KS_RENDER_QUALITY"); q && *q) {
        if (std::strcmp(q, "full") == 0) return RenderQuality::Full;
        if (std::strcmp(q, "fast") == 0) return RenderQuality::Fast;
        log::warn("KS_RENDER_QUALITY='", q, "' is not 'full' or 'fast'; choosing from the GL renderer");
    }
    return is_software_renderer(gl_renderer) ? RenderQuality::Fast : RenderQuality::Full;
}

float default_render_scale_for(const std::string& gl_renderer, float software_scale) {
    if (const char* v = std::getenv("KS_RENDER_SCALE"); v && *v) {
        char* end = nullptr;
        float scale = std::strtof(v, &end);
        if (end != v && *end == '\0' && is_finite(scale) && scale > 0.0f)
            return std::clamp(scale, 0.25f, 1.0f);
        log::warn("KS_RENDER_SCALE='", v, "' is not a number in 0.25..1; choosing from the GL renderer");
    }
    return is_software_renderer(gl_renderer) ? std::clamp(software_scale, 0.25f, 1.0f) : 1.0f;
}

} // namespace ks::render
