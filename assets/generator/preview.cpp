#include "preview.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace ks::assetgen {
namespace {

struct Raster {
    explicit Raster(int size)
        : size(size), color(size, size, Color(0.2f, 0.22f, 0.25f, 1.0f)),
          depth(static_cast<size_t>(size) * size, -INFINITY) {}
    int size;
    Image color;
    std::vector<float> depth;
};

struct ViewVertex {
    vec3 p; // x, y in pixels, z toward the viewer
    vec3 n;
    vec2 uv;
};

Color shade(const Material& m, const Image* base, const Image* glow, vec3 n, vec2 uv) {
    Color albedo = m.base_color;
    if (base) {
        const float u = uv.x - std::floor(uv.x), v = uv.y - std::floor(uv.y);
        albedo *= base->sample(u * static_cast<float>(base->width) - 0.5f,
                               v * static_cast<float>(base->height) - 0.5f);
    }
    const vec3 light = glm::normalize(vec3(0.4f, 0.7f, 0.6f));
    const float diffuse = std::max(0.0f, glm::dot(glm::normalize(n), light));
    vec3 emissive = m.emissive;
    if (glow) {
        const float u = uv.x - std::floor(uv.x), v = uv.y - std::floor(uv.y);
        emissive *= vec3(glow->sample(u * static_cast<float>(glow->width) - 0.5f,
                                      v * static_cast<float>(glow->height) - 0.5f));
    }
    const vec3 lit = vec3(albedo) * (0.35f + 0.75f * diffuse) + emissive;
    return Color(glm::min(lit, vec3(1.0f)), 1.0f);
}

void raster_triangle(Raster& r, const ViewVertex& a, const ViewVertex& b, const ViewVertex& c,
                     const Material& m, const Image* base, const Image* glow) {
    const float area = (b.p.x - a.p.x) * (c.p.y - a.p.y) - (b.p.y - a.p.y) * (c.p.x - a.p.x);
    if (area >= 0.0f) return; // back face (y grows downward in the image, so front faces have negative area)
    const int x0 = std::max(0, static_cast<int>(std::floor(std::min({a.p.x, b.p.x, c.p.x}))));
    const int kView = r.size;
    const int x1 = std::min(kView - 1, static_cast<int>(std::ceil(std::max({a.p.x, b.p.x, c.p.x}))));
    const int y0 = std::max(0, static_cast<int>(std::floor(std::min({a.p.y, b.p.y, c.p.y}))));
    const int y1 = std::min(kView - 1, static_cast<int>(std::ceil(std::max({a.p.y, b.p.y, c.p.y}))));
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            const vec2 p(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
            const float wa = ((b.p.x - p.x) * (c.p.y - p.y) - (b.p.y - p.y) * (c.p.x - p.x)) / area;
            const float wb = ((c.p.x - p.x) * (a.p.y - p.y) - (c.p.y - p.y) * (a.p.x - p.x)) / area;
            const float wc = 1.0f - wa - wb;
            if (wa < 0 || wb < 0 || wc < 0) continue;
            const float z = wa * a.p.z + wb * b.p.z + wc * c.p.z;
            float& d = r.depth[static_cast<size_t>(y) * kView + x];
            if (z <= d) continue;
            d = z;
            r.color.at(x, y) =
                shade(m, base, glow, wa * a.n + wb * b.n + wc * c.n, wa * a.uv + wb * b.uv + wc * c.uv);
        }
}

Image render_view(const Output& out, const Model& model, const glm::mat3& view, int kView) {
    // Fit the model's bounds in this view.
    vec3 lo(INFINITY), hi(-INFINITY);
    for (size_t i = 0; i < model.nodes().size(); ++i) {
        const mat4 world = model.world_transform(static_cast<int>(i));
        for (const auto& [mat, mesh] : model.nodes()[i].parts)
            for (const Vertex& v : mesh.vertices) {
                const vec3 p = view * vec3(world * vec4(v.position, 1.0f));
                lo = glm::min(lo, p);
                hi = glm::max(hi, p);
            }
    }
    Raster r(kView);
    if (lo.x > hi.x) return r.color;
    const float scale = 0.9f * kView / std::max(hi.x - lo.x, hi.y - lo.y);
    const vec3 centre = (lo + hi) * 0.5f;
    for (size_t i = 0; i < model.nodes().size(); ++i) {
        const mat4 world = model.world_transform(static_cast<int>(i));
        const glm::mat3 normal_matrix = view * glm::transpose(glm::inverse(glm::mat3(world)));
        for (const auto& [mat, mesh] : model.nodes()[i].parts) {
            const Material& m = model.materials()[static_cast<size_t>(mat)];
            const Image* base = m.basecolor_texture.empty() ? nullptr : out.find_texture(m.basecolor_texture);
            const Image* glow = m.emissive_texture.empty() ? nullptr : out.find_texture(m.emissive_texture);
            std::vector<ViewVertex> vv;
            vv.reserve(mesh.vertices.size());
            for (const Vertex& v : mesh.vertices) {
                const vec3 p = view * vec3(world * vec4(v.position, 1.0f)) - centre;
                vv.push_back({vec3(kView * 0.5f + p.x * scale, kView * 0.5f - p.y * scale, p.z),
                              normal_matrix * v.normal, v.uv});
            }
            for (size_t k = 0; k + 2 < mesh.indices.size(); k += 3)
                raster_triangle(r, vv[mesh.indices[k]], vv[mesh.indices[k + 1]], vv[mesh.indices[k + 2]], m,
                                base, glow);
        }
    }
    return r.color;
}

glm::mat3 look(float yaw, float pitch) {
    // Rows map world to view: rotate the model by -yaw about y, then tilt by pitch about x.
    const mat4 m = glm::rotate(glm::rotate(mat4(1.0f), pitch, vec3(1, 0, 0)), -yaw, vec3(0, 1, 0));
    return glm::mat3(m);
}
} // namespace

Result<void> write_previews(const Output& out, const std::filesystem::path& folder, int kView) {
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (ec) return Error("cannot create the preview folder: " + ec.message(), Location{folder.string()});
    const glm::mat3 views[4] = {look(0.0f, 0.0f), look(1.5707963f, 0.0f), look(0.7853982f, 0.45f),
                                look(3.926991f, -0.45f)};
    for (const Model& model : out.models()) {
        Image sheet(kView * 4, kView);
        for (int v = 0; v < 4; ++v) {
            const Image view = render_view(out, model, views[v], kView);
            for (int y = 0; y < kView; ++y)
                for (int x = 0; x < kView; ++x) sheet.at(v * kView + x, y) = view.at(x, y);
        }
        KS_ASSETGEN_TRY(write_png(folder / (model.name() + ".png"), sheet, PngChannels::Rgb));
    }
    return ok();
}

} // namespace ks::assetgen
