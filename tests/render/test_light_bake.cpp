// The fast path's light bake (CPU only): layout, sun shadows, light falloff and occlusion, re-combining
// when a light switches, bad input.
#include "brush/brush_build.h"
#include "render/brush_mesh.h"
#include "render/contact_shadows.h"
#include "render/light_bake.h"
#include "render/light_bake_cache.h"
#include "test_support.h"

#include <doctest/doctest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <array>
#include <cmath>
#include <filesystem>

using namespace ks;
using namespace ks::render;

namespace {
// A floor slab 20 x 20 (top at y = 0) and a wall 16 high standing on it along x = 0 (0.5 thick).
struct Room {
    MeshData floor, wall;
    Room() {
        append_box(floor, Vec3(0, -0.25f, 0), Vec3(20, 0.5f, 20), Mat4(1.0f), 2.0f);
        append_box(wall, Vec3(0, 8, 0), Vec3(0.5f, 16, 20), Mat4(1.0f), 4.0f);
    }
    std::vector<BakeSurface> surfaces() { return {{&floor, true}, {&wall, true}}; }
};

// The floor's top face (append_box's third face: +y) at world (x, z), through the vertices' light-map
// coordinates (bilinear weights over the face's corners).
Vec3 floor_light(const LightBake& bake, const MeshData& floor, float x, float z) {
    const Vertex* top = &floor.vertices[8];
    Vec3 o = top[0].position, u = top[1].position - o, v = top[3].position - o;
    float s = glm::dot(Vec3(x, 0, z) - o, u) / glm::dot(u, u);
    float t = glm::dot(Vec3(x, 0, z) - o, v) / glm::dot(v, v);
    Vec2 uv = top[0].lightmap_uv + (top[1].lightmap_uv - top[0].lightmap_uv) * s +
              (top[3].lightmap_uv - top[0].lightmap_uv) * t;
    return bake.sample(uv);
}

// The baked light at a point of any mesh: the triangle holding it, its light-map coordinate interpolated.
Vec3 light_at(const LightBake& bake, const MeshData& mesh, const Vec3& p) {
    for (size_t i = 0; i < mesh.indices.size(); i += 3) {
        const Vertex& a = mesh.vertices[mesh.indices[i]];
        const Vertex& b = mesh.vertices[mesh.indices[i + 1]];
        const Vertex& c = mesh.vertices[mesh.indices[i + 2]];
        const Vec3 n = glm::cross(b.position - a.position, c.position - a.position);
        const float area2 = glm::dot(n, n);
        if (area2 < 1e-12f || std::abs(glm::dot(p - a.position, n)) > 1e-3f * std::sqrt(area2)) continue;
        const float wb = glm::dot(glm::cross(p - a.position, c.position - a.position), n) / area2;
        const float wc = glm::dot(glm::cross(b.position - a.position, p - a.position), n) / area2;
        if (wb < -1e-4f || wc < -1e-4f || wb + wc > 1.0f + 1e-4f) continue;
        return bake.sample(a.lightmap_uv * (1.0f - wb - wc) + b.lightmap_uv * wb + c.lightmap_uv * wc);
    }
    FAIL("no triangle holds the point");
    return Vec3(0.0f);
}

Environment dark_with_sun(Vec3 sun_direction) {
    Environment env;
    env.sky_color = Vec3(0.1f);
    env.ground_color = Vec3(0.1f);
    env.sun_direction = glm::normalize(sun_direction);
    env.sun_color = Vec3(1.0f);
    return env;
}
} // namespace

TEST_CASE("light bake: every face gets its own texel rectangle, coordinates inside the atlas") {
    Room room;
    LightBake bake;
    BakeStats stats = bake.bake(room.surfaces(), Environment{}, {});
    CHECK(stats.faces == 12);
    CHECK(stats.occluders == 2);
    CHECK(stats.texel_size == doctest::Approx(0.5f));
    CHECK(bake.width() > 0);
    CHECK(bake.height() > 0);
    CHECK(static_cast<long long>(bake.texels().size()) == stats.texels);
    std::vector<std::array<float, 4>> rects;
    for (MeshData* m : {&room.floor, &room.wall})
        for (size_t q = 0; q < m->vertices.size(); q += 4) {
            Vec2 lo(1e9f), hi(-1e9f);
            for (size_t i = 0; i < 4; ++i) {
                Vec2 uv = m->vertices[q + i].lightmap_uv;
                CHECK(uv.x > 0.0f);
                CHECK(uv.x < 1.0f);
                CHECK(uv.y > 0.0f);
                CHECK(uv.y < 1.0f);
                lo = glm::min(lo, uv);
                hi = glm::max(hi, uv);
            }
            CHECK(hi.x > lo.x);
            CHECK(hi.y > lo.y);
            rects.push_back({lo.x, lo.y, hi.x, hi.y});
        }
    for (size_t a = 0; a < rects.size(); ++a)
        for (size_t b = a + 1; b < rects.size(); ++b) {
            bool apart = rects[a][2] < rects[b][0] || rects[b][2] < rects[a][0] ||
                         rects[a][3] < rects[b][1] || rects[b][3] < rects[a][1];
            CHECK(apart);
        }
}

TEST_CASE("light bake: the wall's sun shadow falls on the floor, on the side away from the sun") {
    Room room;
    LightBake bake;
    // Sunlight travels toward +x and down at 45 degrees: the wall (x = 0, 16 high) shades x in 0.25..16.
    bake.bake(room.surfaces(), dark_with_sun(Vec3(1, -1, 0)), {});
    Vec3 lit = floor_light(bake, room.floor, -5.0f, 0.0f);
    Vec3 shaded = floor_light(bake, room.floor, 5.0f, 0.0f);
    // Lit: ambient 0.1 + sun 1 * cos 45°; shaded: the ambient only.
    CHECK(lit.x == doctest::Approx(0.1f + std::sqrt(0.5f)).epsilon(0.02));
    CHECK(shaded.x == doctest::Approx(0.1f).epsilon(0.02));
    // A ceiling-like surface that does not block the sun casts nothing.
    std::vector<BakeSurface> no_block = {{&room.floor, true}, {&room.wall, false}};
    bake.bake(no_block, dark_with_sun(Vec3(1, -1, 0)), {});
    CHECK(floor_light(bake, room.floor, 5.0f, 0.0f).x == doctest::Approx(lit.x).epsilon(0.02));
}

TEST_CASE("light bake: point light falloff like the shader, blocked by walls, re-combined when switched") {
    Room room;
    render::Light light;
    light.position = Vec3(-5, 4, 0);
    light.range = 10.0f;
    light.color = Vec3(1.0f, 0.5f, 0.25f);
    light.intensity = 2.0f;
    LightBake bake;
    Environment env; // no ambient, no sun: only the light
    env.sky_color = env.ground_color = env.sun_color = Vec3(0.0f);
    BakeStats stats = bake.bake(room.surfaces(), env, {light});
    CHECK(stats.light_texels > 0);
    // Straight below: distance 4, cos 1 -> colour * intensity * (1 - 4/10).
    Vec3 below = floor_light(bake, room.floor, -5.0f, 0.0f);
    CHECK(below.x == doctest::Approx(2.0f * 0.6f).epsilon(0.02));
    CHECK(below.y == doctest::Approx(1.0f * 0.6f).epsilon(0.02));
    // Beyond the range: nothing. Behind the wall (x > 0.25), within range: occluded.
    CHECK(floor_light(bake, room.floor, -5.0f, 9.9f).x < 1e-3f);
    CHECK(floor_light(bake, room.floor, 1.0f, 0.0f).x < 1e-3f);
    // Switching it off leaves nothing; on again restores it exactly.
    bake.set_light_on(0, false);
    CHECK_FALSE(bake.light_on(0));
    CHECK(bake.update());
    CHECK(floor_light(bake, room.floor, -5.0f, 0.0f).x == 0.0f);
    CHECK_FALSE(bake.update()); // nothing changed since
    bake.set_light_on(0, true);
    CHECK(bake.update());
    CHECK(floor_light(bake, room.floor, -5.0f, 0.0f).x == doctest::Approx(below.x));
    bake.set_light_on(7, false); // no such light: ignored
    CHECK_FALSE(bake.update());
}

TEST_CASE("light bake: a spot light lights its cone only") {
    Room room;
    render::Light spot;
    spot.type = Light::Type::Spot;
    spot.position = Vec3(-5, 6, 0);
    spot.direction = Vec3(0, -1, 0);
    spot.range = 20.0f;
    spot.cos_outer = std::cos(radians(20.0f));
    spot.cos_inner = std::cos(radians(14.0f));
    Environment env;
    env.sky_color = env.ground_color = env.sun_color = Vec3(0.0f);
    LightBake bake;
    bake.bake(room.surfaces(), env, {spot});
    CHECK(floor_light(bake, room.floor, -5.0f, 0.0f).x == doctest::Approx(1.0f - 6.0f / 20.0f).epsilon(0.02));
    CHECK(floor_light(bake, room.floor, -5.0f, 5.0f).x < 1e-3f); // 40° off the axis
}

TEST_CASE("light bake: bad input gives finite texels, never a crash") {
    Room room;
    render::Light nan_light;
    nan_light.position = Vec3(std::nanf(""), 0, 0);
    render::Light huge;
    huge.position = Vec3(0, 4, 0);
    huge.range = 1e30f;
    Environment env = dark_with_sun(Vec3(0, -1, 0));
    env.sun_direction = Vec3(std::nanf(""));
    LightBake bake;
    BakeSettings tiny;
    tiny.texel_size = 1e-6f; // absurd: coarsened until the atlas fits
    BakeStats stats = bake.bake(room.surfaces(), env, {nan_light, huge}, tiny);
    CHECK(stats.texels <= tiny.max_texels);
    CHECK(stats.texel_size > 1e-6f);
    for (const Vec3& t : bake.texels()) REQUIRE(is_finite(t));
    // No surfaces at all: an empty (1-texel-high) atlas.
    LightBake empty;
    BakeStats none = empty.bake({}, Environment{}, {});
    CHECK(none.faces == 0);
}

TEST_CASE("light bake: a brush ramp gets texels on every face and casts its sloped shadow") {
    Room room;
    // A ramp on the floor at x 2..6, rising toward -z from z = 0 to 4 high at z = -8.
    const DVec3 profile[] = {{2, 0, 0}, {2, 0, -8}, {2, 4, -8}};
    auto ramp = brush::make_extrusion(profile, {4, 0, 0});
    REQUIRE(ramp.ok());
    MeshData mesh = build_brush_mesh(*ramp).mesh;
    std::vector<BakeSurface> surfaces = room.surfaces();
    surfaces.push_back({&mesh, true});
    LightBake bake;
    // Sunlight travels toward -z and down at 45 degrees: the ramp's back (4 high at z = -8) shades the floor
    // from z = -8 to -12 behind it; its slope faces the sun.
    const BakeStats stats = bake.bake(surfaces, dark_with_sun(Vec3(0, -1, -1)), {});
    CHECK(stats.faces == 12 + 5);
    CHECK(stats.occluders == 3);
    // Every polygon of the ramp has its own texels (the triangles too), apart from every other's.
    std::vector<std::array<float, 4>> rects;
    for (size_t p = 0, v = 0; p < mesh.polygon_sizes.size(); v += mesh.polygon_sizes[p], ++p) {
        Vec2 lo(1e9f), hi(-1e9f);
        for (size_t i = 0; i < mesh.polygon_sizes[p]; ++i) {
            const Vec2 uv = mesh.vertices[v + i].lightmap_uv;
            CHECK((uv.x > 0.0f && uv.x < 1.0f && uv.y > 0.0f && uv.y < 1.0f));
            lo = glm::min(lo, uv);
            hi = glm::max(hi, uv);
        }
        CHECK((hi.x > lo.x && hi.y > lo.y));
        rects.push_back({lo.x, lo.y, hi.x, hi.y});
    }
    for (size_t a = 0; a < rects.size(); ++a)
        for (size_t b = a + 1; b < rects.size(); ++b)
            CHECK((rects[a][2] < rects[b][0] || rects[b][2] < rects[a][0] || rects[a][3] < rects[b][1] ||
                   rects[b][3] < rects[a][1]));
    const float lit = 0.1f + std::sqrt(0.5f);
    CHECK(light_at(bake, room.floor, Vec3(4, 0, 5)).x == doctest::Approx(lit).epsilon(0.02));
    CHECK(light_at(bake, room.floor, Vec3(4, 0, -9.5f)).x == doctest::Approx(0.1f).epsilon(0.02));
    CHECK(light_at(bake, room.floor, Vec3(8, 0, -9.5f)).x == doctest::Approx(lit).epsilon(0.02)); // beside it
    // The slope, normal (0, 2, 1) / sqrt 5, faces the sun: cos = 3 / sqrt 10; the triangle ends are in the
    // sun's plane (cos 0): ambient only, and lit nowhere by a shadow leaking through.
    CHECK(light_at(bake, mesh, Vec3(4, 2, -4)).x ==
          doctest::Approx(0.1f + 3.0f / std::sqrt(10.0f)).epsilon(0.02));
    CHECK(light_at(bake, mesh, Vec3(2, 1, -6)).x == doctest::Approx(0.1f).epsilon(0.02));
}

TEST_CASE("contact shadows fall away from the light that casts them, as dark as its share, walls blocking") {
    Environment env;
    env.sky_color = Vec3(0.2f);
    env.sun_color = Vec3(0.0f);
    Light lamp;
    lamp.position = Vec3(0.0f, 16.0f, 0.0f);
    lamp.range = 24.0f;
    const std::vector<Light> lights{lamp};
    ShadowLights in;
    in.environment = &env;
    in.lights = &lights;
    auto caster_at = [](float x, float z) { // a robot-sized box standing on the floor at y = 0
        return ShadowCaster{{Vec3(x - 0.5f, 0.0f, z - 0.5f), Vec3(x + 0.5f, 3.0f, z + 0.5f)}, 0.0f};
    };
    // The last ellipse of a caster is the round one of the ambient light it hides, centred at its feet.
    auto check_ambient = [](const ContactShadow& s, const Vec3& feet, float ambient_share) {
        CHECK(glm::length(s.centre - feet) < 1e-4f);
        CHECK(s.half_length == doctest::Approx(s.half_width));
        CHECK(s.darkness == doctest::Approx(0.5f * ambient_share).epsilon(0.02));
    };
    std::vector<ContactShadow> out;

    // Beside the lamp (10 units along +z): stretched along +z, the caster's feet at its near end, as dark as
    // the lamp's share of the floor's light there.
    contact_shadows({caster_at(0.0f, 10.0f)}, in, out);
    REQUIRE(out.size() == 2);
    CHECK(out[0].axis.x == doctest::Approx(0.0f).epsilon(1e-4));
    CHECK(out[0].axis.y == doctest::Approx(1.0f));
    CHECK(out[0].centre.z > 10.5f);                // pushed away from the lamp
    CHECK(out[0].half_length > out[0].half_width); // stretched
    CHECK(out[0].feet < -0.3f);
    const float reach = light_reach(lamp, Vec3(0.0f, 0.05f, 10.0f), Vec3(0, 1, 0));
    CHECK(out[0].darkness == doctest::Approx(reach / (reach + 0.2f)).epsilon(0.02));
    check_ambient(out[1], Vec3(0.0f, 0.0f, 10.0f), 0.2f / (reach + 0.2f));

    // Right under it: round, centred on the feet, darker (the lamp gives more of the floor's light there).
    out.clear();
    contact_shadows({caster_at(0.0f, 0.0f)}, in, out);
    REQUIRE(out.size() == 2);
    CHECK(out[0].half_length == doctest::Approx(out[0].half_width));
    CHECK(glm::length(Vec2(out[0].centre.x, out[0].centre.z)) < 1e-3f);
    CHECK(out[0].darkness > 0.55f);

    // A wall between the lamp and the caster's floor: that light casts nothing there, only the ambient one.
    out.clear();
    in.blockers = {{Vec3(-10.0f, 0.0f, 5.0f), Vec3(10.0f, 16.0f, 5.5f)}};
    contact_shadows({caster_at(0.0f, 10.0f)}, in, out);
    REQUIRE(out.size() == 1);
    check_ambient(out[0], Vec3(0.0f, 0.0f, 10.0f), 1.0f);
    in.blockers.clear();

    // The sun (travelling toward +x, down at 45 degrees) alone: the shadow points along +x, as long as the
    // caster is high; with a shadow map for it (sun = false), none.
    env.sun_color = Vec3(0.5f);
    env.sun_direction = Vec3(1.0f, -1.0f, 0.0f);
    in.lights = nullptr;
    out.clear();
    contact_shadows({caster_at(0.0f, 0.0f)}, in, out);
    REQUIRE(out.size() == 2);
    CHECK(out[0].axis.x == doctest::Approx(1.0f));
    CHECK(out[0].half_length == doctest::Approx(1.5f + out[0].half_width).epsilon(0.01));
    in.sun = false;
    out.clear();
    contact_shadows({caster_at(0.0f, 0.0f)}, in, out);
    REQUIRE(out.size() == 1);
    check_ambient(out[0], Vec3(0.0f), 1.0f);

    // A faint light (under 8 % of the floor's light) casts nothing; a floating caster's shadow is fainter;
    // an empty or non-finite caster casts nothing (no NaN).
    in.sun = true;
    env.sun_color = Vec3(0.0f);
    Light faint = lamp;
    faint.intensity = 0.02f;
    const std::vector<Light> faint_lights{faint};
    in.lights = &faint_lights;
    out.clear();
    ShadowCaster bad = caster_at(0.0f, 0.0f), floating = caster_at(0.0f, 0.0f);
    bad.ground = std::nanf("");
    floating.ground = -2.0f;
    contact_shadows({caster_at(0.0f, 0.0f), ShadowCaster{geometry::Aabb::empty(), 0.0f}, bad, floating}, in,
                    out);
    REQUIRE(out.size() == 2);
    CHECK(out[1].darkness < out[0].darkness * 0.5f);
}

namespace {
// A small quality for the tests: every other texel gathers, enough rays for stable averages.
BakeSettings indirect_settings(int bounce_samples, int ao_samples) {
    BakeSettings s;
    s.bounce_samples = bounce_samples;
    s.ao_samples = ao_samples;
    s.indirect_stride = 2;
    return s;
}
Environment sun_only() {
    Environment env = dark_with_sun(Vec3(0, -1, 0)); // straight down: vertical faces get no direct sun
    env.sky_color = env.ground_color = Vec3(0.0f);
    return env;
}
} // namespace

TEST_CASE("light bake: one bounce lights a wall facing a lit floor, not one behind an occluder") {
    Room room;
    // A roofed hut (x -8..-4, z -2..2, 4 high) on the floor: its inner faces see only the shaded floor
    // under the roof.
    MeshData hut;
    append_box(hut, Vec3(-8, 2, 0), Vec3(0.5f, 4, 4), Mat4(1.0f), 2.0f);
    append_box(hut, Vec3(-4, 2, 0), Vec3(0.5f, 4, 4), Mat4(1.0f), 2.0f);
    append_box(hut, Vec3(-6, 2, -2), Vec3(4, 4, 0.5f), Mat4(1.0f), 2.0f);
    append_box(hut, Vec3(-6, 2, 2), Vec3(4, 4, 0.5f), Mat4(1.0f), 2.0f);
    append_box(hut, Vec3(-6, 4.25f, 0), Vec3(4.5f, 0.5f, 4.5f), Mat4(1.0f), 2.0f);
    const std::vector<Vec3> red(room.floor.polygon_sizes.size(), Vec3(1, 0, 0));
    std::vector<BakeSurface> surfaces = {{&room.floor, true, &red}, {&room.wall, true}, {&hut, true}};
    render::Light lamp;
    lamp.position = Vec3(-2, 1, 6);
    lamp.range = 6.0f;
    LightBake bake;
    const BakeStats stats = bake.bake(surfaces, sun_only(), {lamp}, indirect_settings(32, 0));
    CHECK(stats.rays > 0);
    // The big wall's -x face, 2 up: half its hemisphere is the sunlit red floor (albedo 1 here).
    const Vec3 facing = light_at(bake, room.wall, Vec3(-0.25f, 2, -6));
    CHECK(facing.x > 0.1f);
    CHECK(facing.y == doctest::Approx(0.0f)); // the floor's colour
    // The hut's west wall: its outer face sees the lit floor, its inner face the floor under the roof.
    CHECK(light_at(bake, hut, Vec3(-8.25f, 1, 0)).x > 0.1f);
    CHECK(light_at(bake, hut, Vec3(-7.75f, 1, 0)).x < 1e-3f);
    // The lamp's bounce switches with it.
    const Vec3 near_lamp = light_at(bake, room.wall, Vec3(-0.25f, 1, 6));
    bake.set_light_on(0, false);
    bake.update();
    const Vec3 lamp_off = light_at(bake, room.wall, Vec3(-0.25f, 1, 6));
    CHECK(lamp_off.x < near_lamp.x - 0.01f);
    CHECK(lamp_off.x > 0.0f); // the sun's bounce stays
}

TEST_CASE("light bake: ambient occlusion darkens the inside corner, not the open floor") {
    Room room;
    Environment env;
    env.sky_color = env.ground_color = Vec3(1.0f);
    env.sun_color = Vec3(0.0f);
    LightBake bake;
    bake.bake(room.surfaces(), env, {}, indirect_settings(0, 32));
    const float open = floor_light(bake, room.floor, -6.0f, 0.0f).x;
    const float corner = floor_light(bake, room.floor, -0.5f, 0.0f).x;
    CHECK(open == doctest::Approx(1.0f));
    CHECK(corner < 0.8f);
    CHECK(corner > 0.3f); // a wall covers at most half of the hemisphere
    // Without occlusion samples the ambient is untouched.
    bake.bake(room.surfaces(), env, {}, indirect_settings(0, 0));
    CHECK(floor_light(bake, room.floor, -0.5f, 0.0f).x == doctest::Approx(1.0f));
}

TEST_CASE("light bake: the indirect light is deterministic: same seed, same texels, any thread count") {
    Room room;
    Environment env = dark_with_sun(Vec3(1, -2, 0.5f));
    BakeSettings settings = indirect_settings(8, 8);
    auto texels = [&](std::uint32_t seed, int threads) {
        settings.seed = seed;
        settings.threads = threads;
        LightBake bake;
        bake.bake(room.surfaces(), env, {}, settings);
        return bake.texels();
    };
    const std::vector<Vec3> two = texels(7, 2);
    CHECK(texels(7, 2) == two);
    CHECK(texels(7, 1) == two);
    CHECK(texels(8, 2) != two);
    // layout() then compute() on a copy (the editor's worker thread) gives the same texels as bake().
    LightBake laid;
    laid.layout(room.surfaces(), settings);
    CHECK(laid.texels().empty()); // nothing to upload until computed
    LightBake copy = laid;
    settings.seed = 7;
    copy.compute(env, {}, settings);
    CHECK(copy.texels() == two);
    // A cancelled compute stops early and says so.
    BakeProgress progress;
    progress.cancel = true;
    LightBake cancelled = laid;
    CHECK(cancelled.compute(env, {}, settings, &progress).cancelled);
}

// The disk cache (render/light_bake_cache.h): a hit restores the atlas, the light switches and the meshes'
// light-map coordinates as baked; a moved light misses; a truncated, corrupt or foreign entry is ignored and
// written again; an unwritable folder just means no caching.
TEST_CASE("light bake cache: a hit is the bake, changed input misses, a bad entry is baked again") {
    Room room;
    render::Light light;
    light.position = Vec3(-5, 4, 0);
    light.range = 10.0f;
    const Environment env = dark_with_sun(Vec3(1, -1, 0.3f));
    test::ScratchDir dir;
    const disk_cache::Store store(dir / "cache");
    const std::uint64_t key = light_bake_key(room.surfaces(), env, {light}, {});
    const auto entry = store.file("lightbake", key);

    LightBake baked;
    const BakeStats first = bake_cached(baked, room.surfaces(), env, {light}, {}, store);
    REQUIRE(std::filesystem::exists(entry));
    const std::vector<Vertex> baked_vertices = room.wall.vertices;
    for (Vertex& v : room.wall.vertices) v.lightmap_uv = Vec2(0.0f); // as a fresh level build has them
    for (Vertex& v : room.floor.vertices) v.lightmap_uv = Vec2(0.0f);
    LightBake cached;
    const BakeStats second = bake_cached(cached, room.surfaces(), env, {light}, {}, store);
    CHECK(second.texels == first.texels);
    CHECK(second.light_texels == first.light_texels);
    CHECK(cached.width() == baked.width());
    CHECK(cached.height() == baked.height());
    CHECK(cached.update());
    baked.update();
    CHECK(cached.texels() == baked.texels());
    const std::vector<Vec3> lit = baked.texels();
    for (std::size_t i = 0; i < baked_vertices.size(); ++i)
        CHECK(room.wall.vertices[i].lightmap_uv == baked_vertices[i].lightmap_uv);
    cached.set_light_on(0, false); // the light's share is there to switch off
    baked.set_light_on(0, false);
    cached.update();
    baked.update();
    CHECK(cached.texels() == baked.texels());

    // The bounce's own shares travel too: a bake with indirect light comes back texel for texel, lamp off.
    const BakeSettings bounce = indirect_settings(8, 4);
    CHECK(light_bake_key(room.surfaces(), env, {light}, bounce) != key);
    LightBake bounced, bounced_cached;
    (void)bake_cached(bounced, room.surfaces(), env, {light}, bounce, store);
    (void)bake_cached(bounced_cached, room.surfaces(), env, {light}, bounce, store);
    CHECK(bounced_cached.face_count() == 0); // restored, not baked again
    for (LightBake* b : {&bounced, &bounced_cached}) {
        b->set_light_on(0, false);
        b->update();
    }
    CHECK(bounced_cached.texels() == bounced.texels());
    // An atlas whose parts disagree is refused whole.
    BakedAtlas broken = baked.atlas();
    broken.base.pop_back();
    LightBake untouched;
    CHECK_FALSE(untouched.adopt(broken, 1));
    CHECK(untouched.width() == 0);

    render::Light moved = light;
    moved.position.x += 0.5f;
    CHECK(light_bake_key(room.surfaces(), env, {moved}, {}) != key);
    BakeSettings finer;
    finer.texel_size = 0.25f;
    CHECK(light_bake_key(room.surfaces(), env, {light}, finer) != key);
    Room shifted;
    shifted.wall.vertices[0].position.y += 0.01f;
    CHECK(light_bake_key(shifted.surfaces(), env, {light}, {}) != key);

    const std::string good = test::read_file(entry);
    std::string flipped = good;
    flipped[flipped.size() - 3] = static_cast<char>(flipped[flipped.size() - 3] ^ 0x01);
    for (const std::string& bad :
         {good.substr(0, good.size() - 1), good.substr(0, 20), flipped, std::string("not a cache file")}) {
        test::write_file(entry, bad);
        LightBake again;
        CHECK(bake_cached(again, room.surfaces(), env, {light}, {}, store).texels == first.texels);
        again.update();
        CHECK(again.texels() == lit);
        CHECK(store.load("lightbake", key).has_value()); // written again (its stats' bake time differs)
    }

    test::write_file(dir / "blocked", "x");
    LightBake uncached;
    CHECK(bake_cached(uncached, room.surfaces(), env, {light}, {}, disk_cache::Store(dir / "blocked" / "c"))
              .texels == first.texels);
}

TEST_CASE("light bake cache: a bake laid out now and computed later (a worker) is stored and read back") {
    Room room;
    render::Light light;
    light.position = Vec3(-5, 4, 0);
    light.range = 10.0f;
    const Environment env = dark_with_sun(Vec3(1, -1, 0.3f));
    const BakeSettings bounce = indirect_settings(8, 4);
    test::ScratchDir dir;
    const disk_cache::Store store(dir / "cache");

    LightBake reference; // bake() in one go, no cache
    (void)reference.bake(room.surfaces(), env, {light}, bounce);
    for (Vertex& v : room.wall.vertices) v.lightmap_uv = Vec2(0.0f);
    for (Vertex& v : room.floor.vertices) v.lightmap_uv = Vec2(0.0f);

    LightBake scene_bake;
    BakeStats stats;
    auto slot = restore_or_layout(scene_bake, room.surfaces(), env, {light}, bounce, store, stats);
    REQUIRE(slot); // a miss: laid out only
    CHECK(slot->key == light_bake_key(room.surfaces(), env, {light}, bounce));
    CHECK(scene_bake.laid_out());
    CHECK_FALSE(store.load("lightbake", slot->key).has_value());
    LightBake worker = scene_bake; // what BackgroundBake computes
    const BakeStats computed = worker.compute(env, {light}, bounce);
    BakeStats cancelled = computed;
    cancelled.cancelled = true;
    CHECK_FALSE(store_bake(worker, cancelled, *slot, store)); // an unfinished bake is never stored
    REQUIRE(store_bake(worker, computed, *slot, store));
    worker.update();
    reference.update();
    CHECK(worker.texels() == reference.texels());

    for (Vertex& v : room.wall.vertices) v.lightmap_uv = Vec2(0.0f); // a fresh level build
    LightBake restored;
    CHECK_FALSE(restore_or_layout(restored, room.surfaces(), env, {light}, bounce, store, stats)); // a hit
    CHECK(stats.texels == computed.texels);
    restored.update();
    CHECK(restored.texels() == reference.texels());
    // Another light set: the slot's entry does not fit, it is laid out again.
    render::Light other = light;
    other.position.x += 1.0f;
    LightBake missed;
    CHECK(restore_or_layout(missed, room.surfaces(), env, {other}, bounce, store, stats));
    // No store: laid out, nothing stored.
    LightBake no_cache;
    auto none =
        restore_or_layout(no_cache, room.surfaces(), env, {light}, bounce, disk_cache::Store({}), stats);
    REQUIRE(none);
    CHECK_FALSE(store_bake(worker, computed, *none, disk_cache::Store({})));
}
