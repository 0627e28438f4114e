#include "render/light_bake.h"

#include "geometry/ray.h"
#include "render/contact_shadows.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <limits>

namespace ks::render {

namespace {
// The point of the polygon (in the face's rectangle coordinates) that a texel at `p` samples: `p` itself
// when it lies at least `inset` inside every edge, else pulled in across the edges it is too close to or
// beyond. Why: texel centres lie on the rectangle's edges, so an edge texel would see the neighbouring
// solid, and a polygon that does not fill its rectangle has texels outside it, which bilinear filtering
// still reads at the polygon's edges. On a rectangle this is clamping each coordinate.
struct FaceEdges {
    std::vector<Vec2> point, inward; // a point on each edge and its inward unit normal
    std::vector<float> inset;

    FaceEdges(const Vec3* corners, std::size_t count, const Vec3& origin, const Vec3& u_dir,
              const Vec3& v_dir) {
        std::vector<Vec2> c;
        Vec2 centre(0.0f);
        for (std::size_t i = 0; i < count; ++i) {
            const Vec3 d = corners[i] - origin;
            c.emplace_back(glm::dot(d, u_dir), glm::dot(d, v_dir));
            centre += c.back() / static_cast<float>(count);
        }
        for (std::size_t i = 0; i < c.size(); ++i) {
            const Vec2 e = c[(i + 1) % c.size()] - c[i];
            if (glm::length(e) < 1e-6f) continue;
            Vec2 n = glm::normalize(Vec2(-e.y, e.x));
            if (glm::dot(centre - c[i], n) < 0.0f) n = -n; // either winding
            point.push_back(c[i]);
            inward.push_back(n);
            // 0.05 units, or half the way to the centre on a face too thin for that.
            inset.push_back(std::min(0.05f, 0.5f * glm::dot(centre - c[i], n)));
        }
    }
    Vec2 pull_inside(Vec2 p) const {
        for (int pass = 0; pass < 4; ++pass) {
            bool moved = false;
            for (std::size_t e = 0; e < point.size(); ++e) {
                const float d = glm::dot(p - point[e], inward[e]);
                if (d >= inset[e]) continue;
                p += inward[e] * (inset[e] - d);
                moved = true;
            }
            if (!moved) break;
        }
        return p;
    }
};

double cpu_ms() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
}

double wall_ms() {
    using namespace std::chrono;
    return duration<double, std::milli>(steady_clock::now().time_since_epoch()).count();
}

// Shelf packing, tallest first. Returns the atlas height, or -1 when a face is wider than the atlas.
template <class FaceT>
int pack(std::vector<FaceT>& faces, int atlas_width) {
    std::vector<FaceT*> order;
    order.reserve(faces.size());
    for (auto& f : faces) order.push_back(&f);
    std::stable_sort(order.begin(), order.end(), [](const FaceT* a, const FaceT* b) { return a->h > b->h; });
    int x = 0, y = 0, shelf = 0;
    for (FaceT* f : order) {
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

constexpr float kLift = 0.02f; // ray origins leave the surface by this much (no self-shadowing)
} // namespace

BakeSettings BakeSettings::preview() {
    BakeSettings s;
    s.texel_size = 0.5f;
    s.bounce_samples = 16;
    s.indirect_stride = 4;
    s.ao_samples = 8;
    return s;
}

BakeSettings BakeSettings::full() {
    BakeSettings s;
    s.texel_size = 0.5f;
    s.bounce_samples = 32;
    s.indirect_stride = 2;
    s.ao_samples = 16;
    return s;
}

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
    // The segment clipped by each face's half-space (for a box: the slab test).
    float t0 = 0.0f, t1 = length;
    for (std::uint32_t i = o.first_plane; i < o.first_plane + o.plane_count; ++i) {
        const Vec4& plane = planes_[i];
        const Vec3 n(plane);
        const float outside = glm::dot(n, from) - plane.w, along = glm::dot(n, dir);
        if (std::abs(along) < 1e-12f) {
            if (outside > 0.0f) return false;
            continue;
        }
        const float t = -outside / along;
        if (along < 0.0f)
            t0 = std::max(t0, t);
        else
            t1 = std::min(t1, t);
        if (t0 > t1) return false;
    }
    return true;
}

namespace {
// The bounds of a face's polygon.
void face_bounds(const Vec3* corners, std::size_t count, Vec3& lo, Vec3& hi) {
    lo = Vec3(std::numeric_limits<float>::max());
    hi = -lo;
    for (std::size_t i = 0; i < count; ++i) {
        lo = glm::min(lo, corners[i]);
        hi = glm::max(hi, corners[i]);
    }
}
} // namespace

void LightBake::sun_occluders(const Face& face, const Vec3& dir, float length, std::vector<int>& out) const {
    // The polygon's bounds swept along the ray meet a solid's bounds exactly when the ray from the bounds'
    // centre meets the solid's bounds grown by their half size (with a margin for the rays' lift).
    Vec3 lo, hi;
    face_bounds(&corners_[face.first_corner], face.corner_count, lo, hi);
    const Vec3 centre = (lo + hi) * 0.5f, grow = (hi - lo) * 0.5f + Vec3(0.1f);
    const Vec3 inv = geometry::safe_inverse(dir);
    out.clear();
    for (std::size_t i = 0; i < occluders_.size(); ++i) {
        const Occluder& o = occluders_[i];
        float t_enter = 0.0f;
        if (o.blocks_sun && geometry::ray_aabb(centre, inv, o.lo - grow, o.hi + grow, length, t_enter))
            out.push_back(static_cast<int>(i));
    }
}

void LightBake::near_occluders(const Face& face, float reach, std::vector<int>& out) const {
    Vec3 lo, hi;
    face_bounds(&corners_[face.first_corner], face.corner_count, lo, hi);
    lo -= Vec3(reach);
    hi += Vec3(reach);
    out.clear();
    for (std::size_t i = 0; i < occluders_.size(); ++i) {
        const Occluder& o = occluders_[i];
        if (glm::all(glm::lessThanEqual(o.lo, hi)) && glm::all(glm::lessThanEqual(lo, o.hi)))
            out.push_back(static_cast<int>(i));
    }
}

void LightBake::add_occluders(const MeshData& mesh, bool blocks_sun) {
    std::size_t polygon = 0, vertex = 0;
    for (std::uint32_t faces : mesh.solid_sizes) {
        Occluder o;
        o.first_plane = static_cast<std::uint32_t>(planes_.size());
        o.blocks_sun = blocks_sun;
        o.lo = Vec3(std::numeric_limits<float>::max());
        o.hi = -o.lo;
        for (std::uint32_t k = 0; k < faces && polygon < mesh.polygon_sizes.size(); ++k, ++polygon) {
            const Vertex& first = mesh.vertices[vertex];
            const Vec3 n = glm::normalize(first.normal);
            planes_.emplace_back(n, glm::dot(n, first.position));
            for (std::size_t i = 0; i < mesh.polygon_sizes[polygon]; ++i) {
                o.lo = glm::min(o.lo, mesh.vertices[vertex + i].position);
                o.hi = glm::max(o.hi, mesh.vertices[vertex + i].position);
            }
            vertex += mesh.polygon_sizes[polygon];
        }
        o.plane_count = static_cast<std::uint32_t>(planes_.size()) - o.first_plane;
        occluders_.push_back(o);
    }
}

BakeStats LightBake::bake(const std::vector<BakeSurface>& surfaces, const Environment& env,
                          const std::vector<Light>& lights, const BakeSettings& settings) {
    const double cpu_start = cpu_ms(), wall_start = wall_ms();
    layout(surfaces, settings);
    BakeStats stats = compute(env, lights, settings);
    stats.bake_ms = cpu_ms() - cpu_start;
    stats.wall_ms = wall_ms() - wall_start;
    return stats;
}

BakeStats LightBake::layout(const std::vector<BakeSurface>& surfaces, const BakeSettings& settings) {
    const double cpu_start = cpu_ms(), wall_start = wall_ms();
    BakeStats stats;
    occluders_.clear();
    planes_.clear();
    plane_face_.clear();
    faces_.clear();
    corners_.clear();
    std::vector<Vertex*> first_vertex; // each face's first vertex in its mesh (for the coordinates)
    for (const BakeSurface& s : surfaces) {
        const std::size_t first_plane = planes_.size();
        add_occluders(*s.mesh, s.blocks_sun);
        plane_face_.resize(planes_.size(), -1);
        std::size_t vertex = 0, polygon = 0;
        for (std::uint32_t n : s.mesh->polygon_sizes) {
            if (n >= 3 && vertex + n <= s.mesh->vertices.size()) {
                if (first_plane + polygon < planes_.size())
                    plane_face_[first_plane + polygon] = static_cast<int>(faces_.size());
                Face f;
                f.first_corner = static_cast<std::uint32_t>(corners_.size());
                f.corner_count = n;
                for (std::uint32_t i = 0; i < n; ++i)
                    corners_.push_back(s.mesh->vertices[vertex + i].position);
                f.normal = glm::normalize(s.mesh->vertices[vertex].normal);
                f.blocks_sun = s.blocks_sun;
                if (s.albedo && polygon < s.albedo->size())
                    f.albedo = glm::clamp((*s.albedo)[polygon], 0.0f, 1.0f);
                faces_.push_back(f);
                first_vertex.push_back(&s.mesh->vertices[vertex]);
            }
            vertex += n;
            ++polygon;
        }
    }
    for (Face& f : faces_) {
        const Vec3* c = &corners_[f.first_corner];
        const Vec3 first_edge = c[1] - c[0];
        f.u_dir = glm::normalize(first_edge - f.normal * glm::dot(first_edge, f.normal));
        f.v_dir = glm::cross(f.normal, f.u_dir);
        Vec2 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
        for (std::size_t i = 0; i < f.corner_count; ++i) {
            const Vec3 d = c[i] - c[0];
            const Vec2 p(glm::dot(d, f.u_dir), glm::dot(d, f.v_dir));
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        f.origin = c[0] + f.u_dir * lo.x + f.v_dir * lo.y;
        f.extent = hi - lo;
    }
    stats.faces = static_cast<int>(faces_.size());
    stats.occluders = static_cast<int>(occluders_.size());

    // Lay out: coarsen the texels until the atlas fits.
    float texel = std::max(settings.texel_size, 1e-3f);
    const int atlas_width = std::clamp(settings.atlas_width, 64, 8192);
    for (;;) {
        for (Face& f : faces_) {
            f.w = texels_along(f.extent.x, texel);
            f.h = texels_along(f.extent.y, texel);
        }
        int h = pack(faces_, atlas_width);
        if (h > 0 && h <= 8192 && static_cast<long long>(h) * atlas_width <= settings.max_texels) {
            height_ = h;
            break;
        }
        if (faces_.empty()) {
            height_ = 1;
            break;
        }
        texel *= 2.0f;
    }
    width_ = atlas_width;
    texel_size_ = texel;
    stats.texel_size = texel;
    const size_t count = static_cast<size_t>(width_) * static_cast<size_t>(height_);
    points_.assign(count, Vec3(0.0f));
    const float inv_w = 1.0f / static_cast<float>(width_), inv_h = 1.0f / static_cast<float>(height_);
    for (size_t k = 0; k < faces_.size(); ++k) {
        const Face& f = faces_[k];
        // Texel centres: the rectangle's corners at texels (0.5, 0.5) and (w - 0.5, h - 0.5).
        for (std::size_t c = 0; c < f.corner_count; ++c) {
            const Vec3 d = corners_[f.first_corner + c] - f.origin;
            const float s = f.extent.x > 0.0f ? glm::dot(d, f.u_dir) / f.extent.x : 0.0f;
            const float t = f.extent.y > 0.0f ? glm::dot(d, f.v_dir) / f.extent.y : 0.0f;
            first_vertex[k][c].lightmap_uv = Vec2((f.x + 0.5f + s * static_cast<float>(f.w - 1)) * inv_w,
                                                  (f.y + 0.5f + t * static_cast<float>(f.h - 1)) * inv_h);
        }
        const FaceEdges edges(&corners_[f.first_corner], f.corner_count, f.origin, f.u_dir, f.v_dir);
        for (int j = 0; j < f.h; ++j)
            for (int i = 0; i < f.w; ++i) {
                const Vec2 q = edges.pull_inside(Vec2(f.extent.x * static_cast<float>(i) / (f.w - 1),
                                                      f.extent.y * static_cast<float>(j) / (f.h - 1)));
                points_[static_cast<size_t>((f.y + j) * width_ + f.x + i)] =
                    f.origin + f.u_dir * q.x + f.v_dir * q.y + f.normal * kLift;
            }
    }
    // No texels until compute(): a laid-out scene lights its geometry per vertex meanwhile.
    base_.clear();
    combined_.clear();
    dirty_ = false;
    shares_.clear();
    bounce_shares_.clear();
    light_color_.clear();
    light_on_.clear();
    stats.texels = static_cast<long long>(count);
    stats.bake_ms = cpu_ms() - cpu_start;
    stats.wall_ms = wall_ms() - wall_start;
    return stats;
}

BakeStats LightBake::compute(const Environment& env, const std::vector<Light>& lights,
                             const BakeSettings& settings, BakeProgress* progress) {
    const double cpu_start = cpu_ms(), wall_start = wall_ms();
    BakeStats stats;
    stats.faces = static_cast<int>(faces_.size());
    stats.occluders = static_cast<int>(occluders_.size());
    stats.texels = static_cast<long long>(points_.size());
    shares_.assign(lights.size(), {});
    bounce_shares_.assign(lights.size(), {});
    light_color_.clear();
    for (const Light& l : lights) light_color_.push_back(l.color * l.intensity);
    light_on_.assign(lights.size(), 1);
    compute_direct(env, lights, progress);
    stats.rays = compute_indirect(settings, progress);
    stats.cancelled = progress && progress->cancel.load();
    for (const auto& s : shares_) stats.light_texels += static_cast<long long>(s.size());
    for (const auto& s : bounce_shares_) stats.light_texels += static_cast<long long>(s.size());
    stats.texel_size = texel_size_;
    dirty_ = true;
    update();
    if (progress) progress->done.store(1.0f);
    stats.bake_ms = cpu_ms() - cpu_start;
    stats.wall_ms = wall_ms() - wall_start;
    return stats;
}

void LightBake::compute_direct(const Environment& env, const std::vector<Light>& lights,
                               BakeProgress* progress) {
    const size_t count = points_.size();
    ambient_.assign(count, Vec3(0.0f));
    sun_.assign(count, Vec3(0.0f));
    // Each light's candidate occluders: solids whose bounds touch its range sphere.
    std::vector<std::vector<int>> near(lights.size());
    for (size_t k = 0; k < lights.size(); ++k)
        for (size_t i = 0; i < occluders_.size(); ++i) {
            const Occluder& o = occluders_[i];
            Vec3 d = glm::max(glm::max(o.lo - lights[k].position, lights[k].position - o.hi), Vec3(0.0f));
            if (glm::dot(d, d) <= lights[k].range * lights[k].range) near[k].push_back(static_cast<int>(i));
        }
    const Vec3 to_sun = -glm::normalize(env.sun_direction);
    const bool sun_on = glm::length(env.sun_color) > 0.0f && is_finite(to_sun);
    const float sun_reach = 1e4f;
    std::vector<int> sun_subset;
    for (const Face& f : faces_) {
        if (progress && progress->cancel.load(std::memory_order_relaxed)) return;
        const Vec3 n = f.normal;
        const Vec3 ambient = glm::mix(env.ground_color, env.sky_color, n.y * 0.5f + 0.5f);
        const float sun_cos = sun_on ? std::max(glm::dot(n, to_sun), 0.0f) : 0.0f;
        if (sun_cos > 0.0f) sun_occluders(f, to_sun, sun_reach, sun_subset);
        for (int j = 0; j < f.h; ++j)
            for (int i = 0; i < f.w; ++i) {
                const auto index = static_cast<std::uint32_t>((f.y + j) * width_ + f.x + i);
                const Vec3 p = points_[index];
                ambient_[index] = ambient;
                if (sun_cos > 0.0f && !occluded(p, to_sun, sun_reach, true, &sun_subset))
                    sun_[index] = env.sun_color * sun_cos;
                for (size_t k = 0; k < lights.size(); ++k) {
                    const Light& l = lights[k];
                    const float reach = light_reach(l, p, n);
                    if (reach <= 0.0f) continue;
                    const Vec3 to_light = l.position - p;
                    const float dist = glm::length(to_light);
                    // Stop short of the light: fixtures sit on ceilings and walls.
                    if (occluded(p, to_light / dist, dist - 0.05f, false, &near[k])) continue;
                    shares_[k].push_back({index, reach});
                }
            }
    }
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
        if (k < bounce_shares_.size())
            for (const ColorShare& s : bounce_shares_[k]) combined_[s.texel] += c * s.amount;
    }
    dirty_ = false;
    return true;
}

BakedAtlas LightBake::atlas() const {
    return {width_, height_, base_, shares_, bounce_shares_, light_color_, light_on_};
}

bool LightBake::adopt(BakedAtlas atlas, std::size_t light_count) {
    const std::size_t texels = static_cast<std::size_t>(std::max(atlas.width, 0)) *
                               static_cast<std::size_t>(std::max(atlas.height, 0));
    if (atlas.base.size() != texels || atlas.shares.size() != light_count ||
        atlas.light_color.size() != light_count || atlas.light_on.size() != light_count ||
        atlas.bounce_shares.size() > light_count)
        return false;
    for (const auto& list : atlas.shares)
        for (const Share& share : list)
            if (share.texel >= texels) return false;
    for (const auto& list : atlas.bounce_shares)
        for (const ColorShare& share : list)
            if (share.texel >= texels) return false;
    *this = LightBake();
    width_ = atlas.width;
    height_ = atlas.height;
    base_ = std::move(atlas.base);
    shares_ = std::move(atlas.shares);
    bounce_shares_ = std::move(atlas.bounce_shares);
    light_color_ = std::move(atlas.light_color);
    light_on_ = std::move(atlas.light_on);
    dirty_ = true;
    return true;
}

Vec3 LightBake::sample(const Vec2& uv) const {
    if (combined_.empty()) return Vec3(0.0f);
    int x = std::clamp(static_cast<int>(uv.x * width_), 0, width_ - 1);
    int y = std::clamp(static_cast<int>(uv.y * height_), 0, height_ - 1);
    return combined_[static_cast<size_t>(y * width_ + x)];
}

Vec3 LightBake::face_irradiance(int face, const Vec2& st) const {
    if (combined_.empty() || face < 0 || face >= face_count()) return Vec3(0.0f);
    const Face& f = faces_[static_cast<size_t>(face)];
    const float x = std::clamp(st.x, 0.0f, 1.0f) * static_cast<float>(f.w - 1);
    const float y = std::clamp(st.y, 0.0f, 1.0f) * static_cast<float>(f.h - 1);
    const int i = std::min(static_cast<int>(x), f.w - 2), j = std::min(static_cast<int>(y), f.h - 2);
    auto at = [&](int a, int b) { return combined_[static_cast<size_t>((f.y + b) * width_ + f.x + a)]; };
    const float fx = x - static_cast<float>(i), fy = y - static_cast<float>(j);
    return glm::mix(glm::mix(at(i, j), at(i + 1, j), fx), glm::mix(at(i, j + 1), at(i + 1, j + 1), fx), fy);
}

glm::ivec2 LightBake::face_texels(int face) const {
    if (face < 0 || face >= face_count()) return glm::ivec2(0);
    return {faces_[static_cast<size_t>(face)].w, faces_[static_cast<size_t>(face)].h};
}

} // namespace ks::render
