// Renderer pieces that need no GL context: culling math, level geometry, particles, HUD helpers, shader logs.
#include "geometry/frustum.h"
#include "level/level.h"
#include "render/level_scene.h"
#include "render/mesh_data.h"
#include "render/occlusion.h"
#include "render/particles.h"
#include "render/png_writer.h"
#include "render/scene_renderer.h"
#include "render/shader_program.h"
#include "render/texture_cache.h"
#include "render/view_model.h"
#include "shell/hud.h"
#include "shell/raster_threads.h"

#include <doctest/doctest.h>
#include <glm/gtc/matrix_transform.hpp>
#include <stb_image.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <thread>

using namespace ks;
using namespace ks::render;
using namespace ks::shell;

TEST_CASE("frustum keeps boxes in front of the camera and culls those behind or beside it") {
    geometry::Camera cam;
    cam.position = Vec3(0, 3, 0);
    cam.yaw = 0; // looks along -z
    geometry::Frustum f(cam.projection() * cam.view());
    CHECK(f.intersects({Vec3(-1, 2, -11), Vec3(1, 4, -9)}));
    CHECK_FALSE(f.intersects({Vec3(-1, 2, 9), Vec3(1, 4, 11)}));        // behind
    CHECK_FALSE(f.intersects({Vec3(100, 2, -11), Vec3(102, 4, -9)}));   // far to the right
    CHECK_FALSE(f.intersects({Vec3(-1, 2, -2000), Vec3(1, 4, -1500)})); // beyond the far plane
    CHECK(f.intersects({Vec3(-500, -1, -500), Vec3(500, 0, 500)}));     // a huge floor around the camera
    CHECK(f.intersects_sphere(Vec3(0, 3, 5), 6.0f)); // a light behind whose range reaches in
    CHECK_FALSE(f.intersects_sphere(Vec3(0, 3, 50), 6.0f));
    cam.yaw = kPi * 0.5f; // now looks along -x
    geometry::Frustum left(cam.projection() * cam.view());
    CHECK(left.intersects({Vec3(-11, 2, -1), Vec3(-9, 4, 1)}));
    CHECK_FALSE(left.intersects({Vec3(-1, 2, -11), Vec3(1, 4, -9)}));
}

TEST_CASE(
    "occlusion culling: a box behind a wall face is hidden, one that peeks out or stands in front is not") {
    geometry::Camera cam;
    cam.position = Vec3(0, 3, 25);
    cam.yaw = 0.0f; // looking along -z
    const geometry::Aabb wall{Vec3(-10, 0, -0.25f),
                              Vec3(10, 16, 0.25f)}; // a 20-wide, 16-high slab across the view
    std::vector<OccluderFace> faces;
    append_occluder_faces(wall, cam.position, faces);
    REQUIRE(faces.size() == 1); // the eye is level with the slab in x and y: only its +z face looks at it
    CHECK(faces[0].axis == 2);
    CHECK(faces[0].plane == doctest::Approx(0.25f));
    auto hidden = [&](const geometry::Aabb& box) {
        for (const auto& f : faces)
            if (hidden_behind(box, f, cam)) return true;
        return false;
    };
    const geometry::Aabb robot{Vec3(-1, 0, -20), Vec3(1, 4, -18)};
    CHECK(hidden(robot));                                                    // straight behind the wall
    CHECK_FALSE(hidden(geometry::Aabb{Vec3(-1, 0, 5), Vec3(1, 4, 7)}));      // in front of it
    CHECK_FALSE(hidden(geometry::Aabb{Vec3(8, 0, -20), Vec3(30, 4, -18)}));  // reaches past its end
    CHECK(hidden(geometry::Aabb{Vec3(-1, 0, -1), Vec3(1, 4, 0.1f)}));        // inside the slab: hidden too
    CHECK_FALSE(hidden(geometry::Aabb{Vec3(-1, 0, -1), Vec3(1, 4, 0.5f)}));  // pokes out of its face
    CHECK_FALSE(hidden(geometry::Aabb{Vec3(-1, 0, -20), Vec3(1, 40, -18)})); // seen over the top
    CHECK_FALSE(hidden(geometry::Aabb{Vec3(-1, 0, -20), Vec3(1, 4, 30)}));   // reaches behind the eye
    // The face is clipped by the near plane when the eye almost touches it: nothing is culled then.
    geometry::Camera close = cam;
    close.position = Vec3(0, 3, 0.25f + 0.05f);
    faces.clear();
    append_occluder_faces(wall, close.position, faces);
    REQUIRE(faces.size() == 1);
    CHECK_FALSE(hidden_behind(geometry::Aabb{Vec3(-30, 0, -20), Vec3(30, 4, -18)}, faces[0], close));
    // Orthographic views (the editor's axis views) are never occlusion-culled; an eye inside gives no faces.
    geometry::Camera ortho = cam;
    ortho.ortho_height = 40.0f;
    faces.clear();
    append_occluder_faces(wall, cam.position, faces);
    CHECK_FALSE(hidden_behind(robot, faces[0], ortho));
    faces.clear();
    append_occluder_faces(wall, Vec3(0, 3, 0), faces);
    CHECK(faces.empty());
}

TEST_CASE("occlusion culling: two leaves side by side hide what straddles their seam once merged") {
    geometry::Camera cam;
    cam.position = Vec3(0, 3, 25);
    const geometry::Aabb left{Vec3(-2.5f, 0, -0.05f), Vec3(0, 5, 0.05f)},
        right{Vec3(0, 0, -0.05f), Vec3(2.5f, 5, 0.05f)};
    std::vector<OccluderFace> faces;
    append_occluder_faces(left, cam.position, faces);
    append_occluder_faces(right, cam.position, faces);
    REQUIRE(faces.size() == 2);
    const geometry::Aabb robot{Vec3(-0.5f, 1, -20), Vec3(0.5f, 4, -19)}; // behind the seam
    auto hidden = [&](const geometry::Aabb& box) {
        for (const auto& f : faces)
            if (hidden_behind(box, f, cam)) return true;
        return false;
    };
    CHECK_FALSE(hidden(robot)); // neither leaf alone covers it
    merge_occluder_faces(faces);
    REQUIRE(faces.size() == 1);
    CHECK(faces[0].lo.x == doctest::Approx(-2.5f));
    CHECK(faces[0].hi.x == doctest::Approx(2.5f));
    CHECK(hidden(robot));
    CHECK_FALSE(hidden(geometry::Aabb{Vec3(-0.5f, 1, -20), Vec3(0.5f, 9, -19)})); // seen above the leaves
    // A gap between the leaves (a door opening) or a different height: not merged.
    faces.clear();
    append_occluder_faces(left, cam.position, faces);
    append_occluder_faces(geometry::Aabb{Vec3(0.2f, 0, -0.05f), Vec3(2.5f, 5, 0.05f)}, cam.position, faces);
    append_occluder_faces(geometry::Aabb{Vec3(-5.0f, 0, -0.05f), Vec3(-2.5f, 4, 0.05f)}, cam.position, faces);
    merge_occluder_faces(faces);
    CHECK(std::count_if(faces.begin(), faces.end(), [](const OccluderFace& f) { return f.axis == 2; }) == 3);
}

TEST_CASE("transformed bounds contain every transformed corner") {
    geometry::Aabb box{Vec3(-1, 0, -2), Vec3(1, 3, 2)};
    Mat4 m = glm::rotate(glm::translate(Mat4(1.0f), Vec3(5, 1, -3)), 0.7f, glm::normalize(Vec3(1, 2, 0.5f)));
    geometry::Aabb t = geometry::transform_aabb(box, m);
    for (int i = 0; i < 8; ++i) {
        Vec3 c((i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y,
               (i & 4) ? box.max.z : box.min.z);
        Vec3 w = Vec3(m * Vec4(c, 1.0f));
        CHECK(glm::all(glm::greaterThanEqual(w, t.min - 1e-4f)));
        CHECK(glm::all(glm::lessThanEqual(w, t.max + 1e-4f)));
    }
}

TEST_CASE("box UVs follow world units over texture_scale, on any wall size and orientation") {
    for (float yaw : {0.0f, 0.5f * kPi, 0.3f}) {
        MeshData mesh;
        Mat4 to_world = glm::rotate(glm::translate(Mat4(1.0f), Vec3(3, 0, -7)), yaw, Vec3(0, 1, 0));
        append_box(mesh, Vec3(0, 8, 0), Vec3(60, 16, 0.5f), to_world, 10.0f);
        REQUIRE(mesh.vertices.size() == 24);
        REQUIRE(mesh.indices.size() == 36);
        // On every face, UV distance / world distance along an edge is 1/texture_scale (no stretching).
        for (size_t f = 0; f < 6; ++f) {
            const Vertex& a = mesh.vertices[f * 4];
            const Vertex& b = mesh.vertices[f * 4 + 2]; // opposite corner
            Vec3 d = b.position - a.position;
            Vec2 duv = b.uv - a.uv;
            float world_len = glm::length(d), uv_len = glm::length(duv);
            if (yaw == 0.3f && std::abs(a.normal.y) < 0.5f) continue; // slanted walls project on one axis
            CHECK(uv_len * 10.0f == doctest::Approx(world_len).epsilon(1e-4));
        }
        // Faces wind counter-clockwise seen from outside.
        for (size_t i = 0; i < mesh.indices.size(); i += 3) {
            const Vertex& a = mesh.vertices[mesh.indices[i]];
            Vec3 n = glm::cross(mesh.vertices[mesh.indices[i + 1]].position - a.position,
                                mesh.vertices[mesh.indices[i + 2]].position - a.position);
            CHECK(glm::dot(n, a.normal) > 0.0f);
        }
    }
}

TEST_CASE("stairs are `steps` boxes that rise toward local -z to the full height") {
    level::Entity stair;
    stair.props = level::StairProps{Vec3(12, 6, 12), 10, "tiles"};
    const MeshData mesh = build_surface_mesh(stair);
    CHECK(mesh.vertices.size() == 10 * 24);
    CHECK(mesh.solid_sizes == std::vector<std::uint32_t>(10, 6)); // ten box solids for the light bake
    for (const Vertex& v : mesh.vertices) // risers and treads: 4 units per texture repeat
        if (v.normal.z > 0.5f || v.normal.y > 0.5f) CHECK(v.uv.x == doctest::Approx(v.position.x / 4.0f));
    geometry::Aabb b = mesh.bounds();
    CHECK(b.min.y == doctest::Approx(0.0f));
    CHECK(b.max.y == doctest::Approx(6.0f));
    CHECK(b.min.z == doctest::Approx(-6.0f));
    CHECK(b.max.z == doctest::Approx(6.0f));
    // The highest point is at the -z end: the top of the last box is 6 high and spans z -6..-4.8.
    float top_at_front = -1, top_at_back = -1;
    for (const auto& v : mesh.vertices) {
        if (v.position.z > 4.9f) top_at_front = std::max(top_at_front, v.position.y);
        if (v.position.z < -4.9f) top_at_back = std::max(top_at_back, v.position.y);
    }
    CHECK(top_at_front == doctest::Approx(0.6f));
    CHECK(top_at_back == doctest::Approx(6.0f));
}

TEST_CASE("level surfaces: floors lie below their surface, ceilings above, walls stand on their position") {
    level::Entity wall;
    wall.position = Vec3(10, 0, 0);
    wall.rotation = Vec3(90, 0, 0);
    wall.props = level::WallProps{Vec3(60, 16, 0.5f), "concrete", 10.0f};
    geometry::Aabb w = build_surface_mesh(wall).bounds();
    CHECK(w.min.y == doctest::Approx(0.0f));
    CHECK(w.max.y == doctest::Approx(16.0f));
    CHECK(w.max.z - w.min.z == doctest::Approx(60.0f).epsilon(1e-4)); // rotated 90 degrees: runs along z
    CHECK(w.max.x - w.min.x == doctest::Approx(0.5f).epsilon(1e-3));

    level::Entity floor;
    floor.position = Vec3(40, 0, 0);
    level::FloorProps fp;
    fp.size = Vec2(120, 200);
    fp.thickness = 0.5f;
    floor.props = fp;
    geometry::Aabb f = build_surface_mesh(floor).bounds();
    CHECK(f.max.y == doctest::Approx(0.0f));
    CHECK(f.min.y == doctest::Approx(-0.5f));
    fp.ceiling = true;
    floor.position.y = 16;
    floor.props = fp;
    geometry::Aabb c = build_surface_mesh(floor).bounds();
    CHECK(c.min.y == doctest::Approx(16.0f));
    CHECK(c.max.y == doctest::Approx(16.5f));
}

TEST_CASE("environment from level settings: linear colours, normalised sun, degenerate sun made safe") {
    level::Settings s;
    s.ambient_color = {1, 1, 1};
    s.ambient_intensity = 0.2f;
    s.sun_direction = Vec3(2, -2, 0);
    Environment env = environment_from_settings(s);
    CHECK(env.sky_color.r == doctest::Approx(0.2f));
    CHECK(glm::length(env.sun_direction) == doctest::Approx(1.0f));
    s.sun_direction = Vec3(0.0f);
    CHECK(environment_from_settings(s).sun_direction.y == doctest::Approx(-1.0f));
    CHECK(to_linear({0.5f, 0.5f, 0.5f}).r == doctest::Approx(0.214f).epsilon(0.01));
}

TEST_CASE("particle emitter spawns for its duration, particles die after their life, on_finish fires once") {
    ParticleParams p;
    p.duration = 0.1f;
    p.per_frame = 5;
    p.life = 0.5f;
    int finished = 0;
    ParticleEmitter e(p, 7, [&] { ++finished; });
    float dt = 1.0f / 60.0f;
    e.update(dt);
    CHECK(e.particles().size() == 5);
    for (int i = 0; i < 5; ++i) e.update(dt);
    CHECK(e.particles().size() == 30);
    CHECK_FALSE(e.spawning());
    for (const auto& q : e.particles()) {
        CHECK(glm::all(glm::lessThanEqual(glm::abs(q.position - p.position), p.spawn_radius + Vec3(0.5f))));
        CHECK(q.color.a >= 0.0f);
        CHECK(q.color.a <= 1.0f);
    }
    for (int i = 0; i < 60 && !e.finished(); ++i) e.update(dt);
    CHECK(e.finished());
    CHECK(e.particles().empty());
    CHECK(finished == 1);
    e.update(dt);
    CHECK(finished == 1);
}

TEST_CASE("infinite emitters keep spawning up to capacity; stop() lets them finish") {
    ParticleParams p;
    p.duration = 0.0f; // forever
    p.per_frame = 50;
    p.life = 10.0f;
    p.max_particles = 120;
    ParticleEmitter e(p, 1);
    for (int i = 0; i < 10; ++i) e.update(0.01f);
    CHECK(e.particles().size() == 120);
    CHECK(e.particles().capacity() == 120); // no growth beyond the capacity allocated up front
    e.stop();
    for (int i = 0; i < 2000 && !e.finished(); ++i) e.update(0.01f);
    CHECK(e.finished());
}

TEST_CASE("drift sprays every particle one way (a surface normal); gravity pulls them down") {
    ParticleParams p;
    p.spawn_radius = Vec3(0.0f);
    p.velocity = Vec3(1.0f, 0.0f, 1.0f); // random sign on x and z
    p.drift = Vec3(4.0f, 0.0f, 0.0f);    // out of a wall facing +x
    p.gravity = 20.0f;
    p.drag = 0.0f;
    p.life = 1.0f;
    p.per_frame = 20;
    p.duration = 0.01f;
    ParticleEmitter e(p, 5);
    e.update(0.01f);
    REQUIRE(e.particles().size() == 20);
    for (int i = 0; i < 10; ++i) e.update(0.01f);
    for (const auto& q : e.particles()) {
        CHECK(q.position.x > 0.05f); // 0.5..1 x (4 ± 1) for 0.1 s: always away from the wall
        CHECK(q.velocity.y < -1.5f); // 20 units/s² for 0.1 s
        CHECK(q.position.y < 0.0f);
    }
    p.gravity = std::numeric_limits<float>::quiet_NaN();
    CHECK_FALSE(validate(p));
    p.gravity = 0.0f;
    p.drift.z = std::numeric_limits<float>::infinity();
    CHECK_FALSE(validate(p));
}

TEST_CASE("particle parameters that are NaN or absurd are refused, and such an emitter spawns nothing") {
    ParticleParams p;
    p.life = std::numeric_limits<float>::quiet_NaN();
    auto r = validate(p);
    REQUIRE_FALSE(r);
    CHECK(r.error().str().find("life") != std::string::npos);
    p.life = 1.0f;
    p.size = -1.0f;
    CHECK_FALSE(validate(p));
    p.size = 1.0f;
    p.per_frame = -3;
    CHECK_FALSE(validate(p));
    p.per_frame = 3;
    p.velocity.x = std::numeric_limits<float>::infinity();
    ParticleEmitter e(p, 1);
    e.update(0.016f);
    CHECK(e.particles().empty());
    CHECK(e.finished());
    // A NaN time step does not poison the particles.
    ParticleEmitter good(ParticleParams{}, 3);
    good.update(std::numeric_limits<float>::quiet_NaN());
    good.update(0.016f);
    for (const auto& q : good.particles()) CHECK(is_finite(q.position));
}

TEST_CASE("HUD bar fractions clamp and survive bad values") {
    CHECK(bar_fraction(50, 100) == doctest::Approx(0.5f));
    CHECK(bar_fraction(150, 100) == 1.0f);
    CHECK(bar_fraction(-5, 100) == 0.0f);
    CHECK(bar_fraction(5, 0) == 0.0f);
    CHECK(bar_fraction(std::numeric_limits<float>::quiet_NaN(), 100) == 0.0f);
}

TEST_CASE("view model: recoil moves the rifle back toward the camera and tilts the muzzle up") {
    Mat4 rest = rifle_view_transform(0.0f), kick = rifle_view_transform(1.0f);
    CHECK(kick[3].z > rest[3].z); // closer to the camera (camera looks along -z)
    CHECK((kick * Vec4(0, 0, -1, 0)).y > (rest * Vec4(0, 0, -1, 0)).y); // barrel points higher
    Mat4 nan = rifle_view_transform(std::numeric_limits<float>::quiet_NaN());
    CHECK(nan == rest);
}

TEST_CASE("shader logs from Mesa and NVIDIA become file:line: message") {
    CHECK(format_shader_log("0:12(5): error: `foo' undeclared\n", "pbr.frag") ==
          "pbr.frag:12: error: `foo' undeclared");
    CHECK(format_shader_log("0(7) : error C1008: undefined variable \"x\"", "line.vert") ==
          "line.vert:7: error C1008: undefined variable \"x\"");
    CHECK(format_shader_log("ERROR: 0:3: 'y' : undeclared identifier", "a.frag") ==
          "a.frag:3: 'y' : undeclared identifier");
    CHECK(format_shader_log("something else", "b.vert") == "b.vert: something else");
}

TEST_CASE("software rasterisers get no MSAA and no anisotropic filtering; GPUs get 4x MSAA and 8x") {
    for (const char* soft : {"llvmpipe (LLVM 15.0.6, 256 bits)", "softpipe", "Google SwiftShader"}) {
        CAPTURE(soft);
        CHECK(is_software_renderer(soft));
        CHECK(default_anisotropy_for(soft) == 1.0f);
        CHECK(default_msaa_for(soft) == 0);
    }
    for (const char* gpu :
         {"NVIDIA H100 PCIe/PCIe/SSE2", "AMD Radeon RX 6800", "Mesa Intel(R) UHD 630", ""}) {
        CAPTURE(gpu);
        CHECK_FALSE(is_software_renderer(gpu));
        CHECK(default_anisotropy_for(gpu) == 8.0f);
        CHECK(default_msaa_for(gpu) == 4);
    }
}

TEST_CASE("the camera's view matrix agrees with forward/right/up, handles straight down, rolls and goes "
          "orthographic") {
    geometry::Camera cam;
    cam.position = Vec3(2, 5, -3);
    for (float yaw : {0.0f, 0.7f, -2.5f})
        for (float pitch : {-kPi * 0.5f, -0.4f, 0.0f, 0.9f, kPi * 0.5f})
            for (float roll : {0.0f, 0.3f, -1.2f}) {
                cam.yaw = yaw, cam.pitch = pitch, cam.roll = roll;
                const Mat4 v = cam.view();
                CAPTURE(yaw);
                CAPTURE(pitch);
                CAPTURE(roll);
                // A point ahead of the camera lands on the view axis; right and up map to +x and +y.
                const Vec3 ahead = Vec3(v * Vec4(cam.position + 4.0f * cam.forward(), 1.0f));
                CHECK(ahead.x == doctest::Approx(0).epsilon(1e-5));
                CHECK(ahead.y == doctest::Approx(0).epsilon(1e-5));
                CHECK(ahead.z == doctest::Approx(-4).epsilon(1e-5));
                const Vec3 r = Vec3(v * Vec4(cam.position + cam.right(), 1.0f));
                const Vec3 u = Vec3(v * Vec4(cam.position + cam.up(), 1.0f));
                CHECK(r.x == doctest::Approx(1).epsilon(1e-5));
                CHECK(u.y == doctest::Approx(1).epsilon(1e-5));
                CHECK(std::isfinite(v[0][0] + v[1][1] + v[2][2] + v[3][0]));
            }
    // Without roll the horizon stays level; a positive roll leans the camera's up towards its right.
    cam.yaw = 0.4f, cam.pitch = 0.2f, cam.roll = 0.0f;
    CHECK(cam.right().y == doctest::Approx(0).epsilon(1e-6));
    const Vec3 right_flat = cam.right();
    cam.roll = 0.5f;
    CHECK(glm::dot(cam.up(), right_flat) == doctest::Approx(std::sin(0.5f)).epsilon(1e-5));

    // Orthographic: size on screen does not depend on distance.
    geometry::Camera top;
    top.position = Vec3(0, 100, 0);
    top.pitch = -kPi * 0.5f;
    top.ortho_height = 40.0f;
    top.aspect = 2.0f;
    REQUIRE(top.orthographic());
    const Mat4 vp = top.projection() * top.view();
    auto ndc = [&](Vec3 p) {
        Vec4 c = vp * Vec4(p, 1.0f);
        return Vec3(c) / c.w;
    };
    CHECK(ndc(Vec3(0, 0, -20)).y == doctest::Approx(1.0f).epsilon(1e-5)); // -z is up on a top view
    CHECK(ndc(Vec3(0, 50, -20)).y == doctest::Approx(1.0f).epsilon(1e-5));
    CHECK(ndc(Vec3(40, 0, 0)).x == doctest::Approx(1.0f).epsilon(1e-5)); // half width = 20 * aspect
    geometry::Frustum f(vp);
    CHECK(f.intersects({Vec3(-1, 0, -1), Vec3(1, 1, 1)}));
    CHECK_FALSE(f.intersects({Vec3(60, 0, 0), Vec3(62, 1, 1)}));
}

TEST_CASE(
    "llvmpipe threads: twice the cores on 2..4 cores, the driver's default elsewhere; a set value wins") {
    CHECK(software_raster_threads_for(0) == 0); // unknown
    CHECK(software_raster_threads_for(1) == 0);
    CHECK(software_raster_threads_for(2) == 4); // the measured case
    CHECK(software_raster_threads_for(3) == 6);
    CHECK(software_raster_threads_for(4) == 8);
    CHECK(software_raster_threads_for(5) == 0);
    CHECK(software_raster_threads_for(64) == 0);

    std::optional<std::string> saved;
    if (const char* v = std::getenv("LP_NUM_THREADS")) saved = v;
    setenv("LP_NUM_THREADS", "7", 1);
    CHECK(configure_software_raster_threads() == "7"); // the user's choice is kept
    CHECK(std::string(std::getenv("LP_NUM_THREADS")) == "7");

    unsetenv("LP_NUM_THREADS");
    const int expected = software_raster_threads_for(std::thread::hardware_concurrency());
    const std::string chosen = configure_software_raster_threads();
    const char* now = std::getenv("LP_NUM_THREADS");
    if (expected == 0) {
        CHECK(chosen.empty());
        CHECK(now == nullptr);
    } else {
        CHECK(chosen == std::to_string(expected));
        REQUIRE(now != nullptr);
        CHECK(std::string(now) == chosen);
    }
    if (saved)
        setenv("LP_NUM_THREADS", saved->c_str(), 1);
    else
        unsetenv("LP_NUM_THREADS");
}

namespace {
// A fake process environment for the renderer's overrides.
EnvironmentLookup environment(std::map<std::string, std::string> values) {
    return [values = std::move(values)](const char* name) -> const char* {
        auto it = values.find(name);
        return it == values.end() ? nullptr : it->second.c_str();
    };
}
} // namespace

TEST_CASE("renderer environment overrides are parsed once into RendererSettings") {
    SUBCASE("unset: every field keeps its default") {
        RendererSettings s;
        CHECK(apply_environment_overrides(s, environment({})).empty());
        CHECK(s.automatic_quality == RenderQuality::Auto);
        CHECK(s.automatic_render_scale == 0.0f);
        CHECK_FALSE(s.lightmap_float);
        CHECK(s.shader_dir.empty());
        CHECK(s.shader_hot_reload == -1);
    }
    SUBCASE("valid values set their fields") {
        RendererSettings s;
        const auto warnings = apply_environment_overrides(s, environment({{"KS_RENDER_QUALITY", "fast"},
                                                                          {"KS_RENDER_SCALE", "0.6"},
                                                                          {"KS_LIGHTMAP_FLOAT", "1"},
                                                                          {"KS_SHADER_DIR", "/tmp/shaders"},
                                                                          {"KS_SHADER_HOT_RELOAD", "1"}}));
        CHECK(warnings.empty());
        CHECK(s.automatic_quality == RenderQuality::Fast);
        CHECK(s.automatic_render_scale == doctest::Approx(0.6f));
        CHECK(s.lightmap_float);
        CHECK(s.shader_dir == "/tmp/shaders");
        CHECK(s.shader_hot_reload == 1);
        CHECK(s.quality == RenderQuality::Auto); // explicit choices are left to options and menus
        CHECK(s.render_scale == 0.0f);
        apply_environment_overrides(
            s, environment({{"KS_RENDER_QUALITY", "full"}, {"KS_SHADER_HOT_RELOAD", "0"}}));
        CHECK(s.automatic_quality == RenderQuality::Full);
        CHECK(s.shader_hot_reload == 0);
    }
    SUBCASE("scales are clamped to 0.25..1") {
        RendererSettings s;
        apply_environment_overrides(s, environment({{"KS_RENDER_SCALE", "7"}}));
        CHECK(s.automatic_render_scale == 1.0f);
        apply_environment_overrides(s, environment({{"KS_RENDER_SCALE", "0.01"}}));
        CHECK(s.automatic_render_scale == 0.25f);
    }
    SUBCASE("bad values warn, name the variable and leave the field") {
        RendererSettings s;
        const auto warnings = apply_environment_overrides(s, environment({{"KS_RENDER_QUALITY", "ultra"},
                                                                          {"KS_RENDER_SCALE", "half"},
                                                                          {"KS_LIGHTMAP_FLOAT", "yes"}}));
        REQUIRE(warnings.size() == 3);
        CHECK(warnings[0].find("KS_RENDER_QUALITY='ultra'") != std::string::npos);
        CHECK(warnings[1].find("KS_RENDER_SCALE='half'") != std::string::npos);
        CHECK(warnings[2].find("KS_LIGHTMAP_FLOAT='yes'") != std::string::npos);
        CHECK(s.automatic_quality == RenderQuality::Auto);
        CHECK(s.automatic_render_scale == 0.0f);
        CHECK_FALSE(s.lightmap_float);
        for (const char* bad : {"nan", "inf", "-1", "0", "0.5x", ""}) {
            RendererSettings t;
            apply_environment_overrides(t, environment({{"KS_RENDER_SCALE", bad}}));
            CHECK(t.automatic_render_scale == 0.0f);
        }
    }
    SUBCASE("a level scene built for a renderer bakes only for the fast path, in its encoding") {
        RendererSettings fast;
        fast.quality = RenderQuality::Fast;
        fast.lightmap_float = true;
        CHECK(level_scene_options(fast).bake_light_map);
        CHECK(level_scene_options(fast).lightmap_float);
        RendererSettings full;
        full.quality = RenderQuality::Full;
        CHECK_FALSE(level_scene_options(full).bake_light_map);
        CHECK(lightmap_encoding_range(true) == 0.0f);
        CHECK(lightmap_encoding_range(false) > 0.0f);
    }
}

TEST_CASE(
    "screenshot PNGs decode to the pixels written, top-down and bottom-up; bad sizes and paths are errors") {
    const int w = 37, h = 23; // odd sizes: no row padding hides an off-by-one
    std::vector<unsigned char> rgb(static_cast<size_t>(w) * h * 3);
    for (size_t i = 0; i < rgb.size(); ++i) rgb[i] = static_cast<unsigned char>((i * 7919u) >> 3);
    auto decoded = [&](const std::vector<unsigned char>& png) {
        int dw = 0, dh = 0, channels = 0;
        unsigned char* px =
            stbi_load_from_memory(png.data(), static_cast<int>(png.size()), &dw, &dh, &channels, 3);
        REQUIRE(px != nullptr);
        CHECK(dw == w);
        CHECK(dh == h);
        std::vector<unsigned char> out(px, px + static_cast<size_t>(w) * h * 3);
        stbi_image_free(px);
        return out;
    };
    auto top_down = encode_png_rgb(w, h, rgb.data(), w * 3);
    REQUIRE(top_down);
    CHECK(decoded(*top_down) == rgb);

    // The same image stored bottom-up (GL's read-back), written from its last row with a negative stride.
    std::vector<unsigned char> flipped(rgb.size());
    for (int y = 0; y < h; ++y)
        std::copy_n(rgb.begin() + y * w * 3, w * 3, flipped.begin() + (h - 1 - y) * w * 3);
    auto bottom_up = encode_png_rgb(w, h, flipped.data() + (h - 1) * w * 3, -w * 3);
    REQUIRE(bottom_up);
    CHECK(decoded(*bottom_up) == rgb);

    CHECK_FALSE(encode_png_rgb(0, h, rgb.data(), w * 3));
    CHECK_FALSE(encode_png_rgb(w, -1, rgb.data(), w * 3));
    CHECK_FALSE(encode_png_rgb(w, h, nullptr, w * 3));
    auto unwritable = write_png_rgb("/nonexistent-folder/shot.png", w, h, rgb.data(), w * 3);
    REQUIRE_FALSE(unwritable);
    CHECK(unwritable.error().where.file.find("/nonexistent-folder/shot.png") != std::string::npos);
}
