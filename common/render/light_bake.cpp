#include "render/light_bake.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>

namespace ks::render {

namespace {
struct Face {
    Vertex* corner[4]; // v0, v0 + U, v0 + U + V, v0 + V (append_box's order)
    Vec3 origin, u, v, normal;
    int w = 0, h = 0; // texels
    int x = 0, y = 0; // atlas position
};

double cpu_ms() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
}

// Shelf packing, tallest first. Returns the atlas height, or -1 when a face is wider than the atlas.
int pack(std::vector<Face>& faces, int atlas_width) {
    std::vector<Face*> order;
    order.reserve(faces.size());
    for (auto& f : faces) order.push_back(&f);
    std::stable_sort(order.begin(), order.end(), [](const Face* a, const Face* b) { return a->h > b->h; });
    int x = 0, y = 0, shelf = 0;
    for (Face* f : order) {
        if (f->w > atlas_width) return -1;
        if (x + f->w > atlas_width) {
            x = 0;
            y += shelf;
            shelf = 0;
        }
        f->x = x;
        f->y = y;
        x += f->w;
        shelf = std::max(shelf, f->h);
    }
    return y + shelf;
}

int texels_along(float length, float texel_size) {
    return std::max(2, static_cast<int>(std::ceil(length / texel_size)) + 1);
}
} // namespace

bool LightBake::occluded(const Vec3& from, const Vec3& dir, float length, bool sun,
                         const std::vector<int>* subset) const {
    if (subset) {
        for (int i : *subset)
            if (hits(occluders_[static_cast<size_t>(i)], from, dir, length)) return true;
        return false;
    }
    for (const Occluder& o : occluders_) {
        if (sun && !o.blocks_sun) continue;
        if (hits(o, from, dir, length)) return true;
    }
    return false;
}

bool LightBake::hits(const Occluder& o, const Vec3& from, const Vec3& dir, float length) const {
    // Slab test in the box's frame.
    Vec3 p = Vec3(o.to_local * Vec4(from, 1.0f));
    Vec3 d = Mat3(o.to_local) * dir;
    float t0 = 0.0f, t1 = length;
    bool miss = false;
    for (int a = 0; a < 3 && !miss; ++a) {
        if (std::abs(d[a]) < 1e-12f) {
            miss = std::abs(p[a]) > o.half[a];
            continue;
        }
        float inv = 1.0f / d[a];
        float n = (-o.half[a] - p[a]) * inv, f = (o.half[a] - p[a]) * inv;
        if (n > f) std::swap(n, f);
        t0 = std::max(t0, n);
        t1 = std::min(t1, f);
        miss = t0 > t1;
    }
    return !miss;
}

BakeStats LightBake::bake(const std::vector<BakeSurface>& surfaces, const Environment& env,
                          const std::vector<Light>& lights, const BakeSettings& settings) {
    const double start = cpu_ms();
    BakeStats stats;
    occluders_.clear();
    std::vector<Face> faces;
    for (const BakeSurface& s : surfaces) {
        auto& verts = s.mesh->vertices;
        // Boxes: 24 vertices each, faces in append_box's order (+x, -x, +y, -y, +z, -z in box space).
        for (size_t b = 0; b + 24 <= verts.size(); b += 24) {
            Vec3 center(0.0f);
            for (size_t i = 0; i < 24; ++i) center += verts[b + i].position / 24.0f;
            Vec3 axis[3] = {verts[b].normal, verts[b + 8].normal, verts[b + 16].normal};
            Vec3 half(0.0f);
            for (int a = 0; a < 3; ++a) {
                axis[a] = glm::normalize(axis[a]);
                for (size_t i = 0; i < 24; ++i)
                    half[a] = std::max(half[a], std::abs(glm::dot(verts[b + i].position - center, axis[a])));
            }
            Mat4 to_box(1.0f); // rows = axes: world -> box
            for (int a = 0; a < 3; ++a) {
                to_box[0][a] = axis[a].x;
                to_box[1][a] = axis[a].y;
                to_box[2][a] = axis[a].z;
                to_box[3][a] = -glm::dot(axis[a], center);
            }
            Vec3 reach = glm::abs(axis[0]) * half.x + glm::abs(axis[1]) * half.y + glm::abs(axis[2]) * half.z;
            occluders_.push_back({to_box, half, s.blocks_sun, center - reach, center + reach});
        }
        for (size_t q = 0; q + 4 <= verts.size(); q += 4) {
            Face f;
            for (int i = 0; i < 4; ++i) f.corner[i] = &verts[q + static_cast<size_t>(i)];
            f.origin = verts[q].position;
            f.u = verts[q + 1].position - verts[q].position;
            f.v = verts[q + 3].position - verts[q].position;
            f.normal = glm::normalize(verts[q].normal);
            faces.push_back(f);
        }
    }
    stats.faces = static_cast<int>(faces.size());
    stats.occluders = static_cast<int>(occluders_.size());

    // Lay out: coarsen the texels until the atlas fits.
    float texel = std::max(settings.texel_size, 1e-3f);
    const int atlas_width = std::clamp(settings.atlas_width, 64, 8192);
    for (;;) {
        for (Face& f : faces) {
            f.w = texels_along(glm::length(f.u), texel);
            f.h = texels_along(glm::length(f.v), texel);
        }
        int h = pack(faces, atlas_width);
        if (h > 0 && h <= 8192 && static_cast<long long>(h) * atlas_width <= settings.max_texels) {
            height_ = h;
            break;
        }
        if (faces.empty()) {
            height_ = 1;
            break;
        }
        texel *= 2.0f;
    }
    width_ = atlas_width;
    stats.texel_size = texel;
    const size_t count = static_cast<size_t>(width_) * static_cast<size_t>(height_);
    base_.assign(count, Vec3(0.0f));
    shares_.assign(lights.size(), {});
    light_color_.clear();
    for (const Light& l : lights) light_color_.push_back(l.color * l.intensity);
    light_on_.assign(lights.size(), 1);

    // Each light's candidate occluders: boxes whose bounds touch its range sphere.
    std::vector<std::vector<int>> near(lights.size());
    for (size_t k = 0; k < lights.size(); ++k)
        for (size_t i = 0; i < occluders_.size(); ++i) {
            const Occluder& o = occluders_[i];
            Vec3 d = glm::max(glm::max(o.lo - lights[k].position, lights[k].position - o.hi), Vec3(0.0f));
            if (glm::dot(d, d) <= lights[k].range * lights[k].range) near[k].push_back(static_cast<int>(i));
        }
    const Vec3 to_sun = -glm::normalize(env.sun_direction);
    const bool sun_on = glm::length(env.sun_color) > 0.0f && is_finite(to_sun);
    constexpr float kLift = 0.02f; // ray origins leave the surface by this much (no self-shadowing)
    const float sun_reach = 1e4f;
    for (Face& f : faces) {
        const float inv_w = 1.0f / static_cast<float>(width_), inv_h = 1.0f / static_cast<float>(height_);
        auto uv = [&](float tx, float ty) { return Vec2((f.x + tx) * inv_w, (f.y + ty) * inv_h); };
        f.corner[0]->lightmap_uv = uv(0.5f, 0.5f);
        f.corner[1]->lightmap_uv = uv(f.w - 0.5f, 0.5f);
        f.corner[2]->lightmap_uv = uv(f.w - 0.5f, f.h - 0.5f);
        f.corner[3]->lightmap_uv = uv(0.5f, f.h - 0.5f);
        const Vec3 n = f.normal;
        const Vec3 ambient = glm::mix(env.ground_color, env.sky_color, n.y * 0.5f + 0.5f);
        const float sun_cos = sun_on ? std::max(glm::dot(n, to_sun), 0.0f) : 0.0f;
        // Texel centres lie on the face's edges; the points they sample are nudged 0.05 units inside so
        // an edge texel sees this face, not the neighbouring box's.
        const float inset_u = std::min(0.05f / std::max(glm::length(f.u), 1e-4f), 0.25f);
        const float inset_v = std::min(0.05f / std::max(glm::length(f.v), 1e-4f), 0.25f);
        for (int j = 0; j < f.h; ++j)
            for (int i = 0; i < f.w; ++i) {
                float s = std::clamp(static_cast<float>(i) / (f.w - 1), inset_u, 1.0f - inset_u);
                float t = std::clamp(static_cast<float>(j) / (f.h - 1), inset_v, 1.0f - inset_v);
                const Vec3 p = f.origin + f.u * s + f.v * t + n * kLift;
                const auto index = static_cast<std::uint32_t>((f.y + j) * width_ + f.x + i);
                Vec3 e = ambient;
                if (sun_cos > 0.0f && !occluded(p, to_sun, sun_reach, true)) e += env.sun_color * sun_cos;
                base_[index] = e;
                for (size_t k = 0; k < lights.size(); ++k) {
                    const Light& l = lights[k];
                    Vec3 to_light = l.position - p;
                    float dist = glm::length(to_light);
                    if (!(dist < l.range) || dist < 1e-4f) continue;
                    Vec3 dir = to_light / dist;
                    float cosine = glm::dot(n, dir);
                    if (cosine <= 0.0f) continue;
                    float atten = 1.0f - dist / l.range;
                    if (l.type == Light::Type::Spot) {
                        float inner = std::max(l.cos_inner, l.cos_outer + 1e-3f);
                        float x = std::clamp((glm::dot(-dir, glm::normalize(l.direction)) - l.cos_outer) /
                                                 (inner - l.cos_outer),
                                             0.0f, 1.0f);
                        atten *= x * x * (3.0f - 2.0f * x); // GLSL smoothstep
                    }
                    if (atten <= 0.0f) continue;
                    // Stop short of the light: fixtures sit on ceilings and walls.
                    if (occluded(p, dir, dist - 0.05f, false, &near[k])) continue;
                    shares_[k].push_back({index, atten * cosine});
                }
            }
    }
    for (const auto& s : shares_) stats.light_texels += static_cast<long long>(s.size());
    stats.texels = static_cast<long long>(count);
    dirty_ = true;
    update();
    stats.bake_ms = cpu_ms() - start;
    return stats;
}

void LightBake::set_light_on(int light, bool on) {
    if (light < 0 || static_cast<size_t>(light) >= light_on_.size()) return;
    if ((light_on_[static_cast<size_t>(light)] != 0) == on) return;
    light_on_[static_cast<size_t>(light)] = on ? 1 : 0;
    dirty_ = true;
}

bool LightBake::light_on(int light) const {
    return light >= 0 && static_cast<size_t>(light) < light_on_.size() &&
           light_on_[static_cast<size_t>(light)] != 0;
}

bool LightBake::update() {
    if (!dirty_) return false;
    combined_ = base_;
    for (size_t k = 0; k < shares_.size(); ++k) {
        if (!light_on_[k]) continue;
        const Vec3 c = light_color_[k];
        for (const Share& s : shares_[k]) combined_[s.texel] += c * s.amount;
    }
    dirty_ = false;
    return true;
}

Vec3 LightBake::sample(const Vec2& uv) const {
    if (combined_.empty()) return Vec3(0.0f);
    int x = std::clamp(static_cast<int>(uv.x * width_), 0, width_ - 1);
    int y = std::clamp(static_cast<int>(uv.y * height_), 0, height_ - 1);
    return combined_[static_cast<size_t>(y * width_ + x)];
}

} // namespace ks::render
