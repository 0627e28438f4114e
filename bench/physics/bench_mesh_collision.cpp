// ks_bench physics_mesh: a model's collision as a box, a hull and a triangle mesh (issue 27 item 3), in one
// run: the cost of building each body from the model, of a ray (a shot, a line of sight) and of one
// character step (a capsule walking into the model) against it, for models of about 1k, 10k and 100k
// triangles. The model is a bumpy sphere (concave between the bumps) written as an OBJ into a scratch models
// folder and read through the level's model entity, so each body is what the game builds.
#include "bench_registry.h"
#include "bench_util.h"
#include "core/random.h"
#include "level/model_entity.h"
#include "physics/brush_shape.h"
#include "physics/triangle_mesh.h"
#include "physics/world.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

namespace ks::physics::bench {
namespace {

constexpr float kRadius = 3.0f;

// rings x segments quads round a sphere of radius ~3 standing on y = 0, its radius rippled by 15 %.
void write_rock(const std::filesystem::path& path, int rings, int segments) {
    std::ofstream obj(path);
    for (int r = 0; r <= rings; ++r)
        for (int s = 0; s < segments; ++s) {
            const double t = kPi * r / rings, p = 2 * kPi * s / segments;
            const double radius = kRadius * (1.0 + 0.15 * std::sin(5 * t) * std::cos(7 * p));
            obj << "v " << radius * std::sin(t) * std::cos(p) << " " << kRadius + radius * std::cos(t) << " "
                << radius * std::sin(t) * std::sin(p) << "\n";
        }
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            const int a = r * segments + s + 1, b = r * segments + (s + 1) % segments + 1;
            obj << "f " << a << " " << a + segments << " " << b + segments << " " << b << "\n";
        }
}

// The model's static body for a collision choice, as game_build.cpp makes it.
std::optional<BrushBody> model_body(const level::Entity& e) {
    auto mesh = level::model_mesh_collision(e);
    if (mesh && mesh->has_value()) {
        auto body = mesh_body((*mesh)->vertices, (*mesh)->triangles, "rock");
        if (!body) return std::nullopt;
        return BrushBody{body->shape, body->transform};
    }
    auto brush = level::model_collision(e);
    if (!brush || brush->size() != 1) return std::nullopt;
    return brush_body(brush->front());
}

struct Measured {
    double build_ms = 0, ray_us = 0, step_us = 0, hit_share = 0;
};

Measured measure(const level::Entity& e, int rays, int steps) {
    Measured r;
    const double t0 = cpu_seconds();
    const std::optional<BrushBody> body = model_body(e);
    r.build_ms = (cpu_seconds() - t0) * 1e3;
    if (!body) return r;
    World w;
    BodyDesc floor;
    floor.shape = Shape::box({50, 0.5f, 50});
    floor.transform.position = {0, -0.5f, 0};
    (void)w.add(floor, "floor");
    BodyDesc model;
    model.shape = body->shape;
    model.transform = body->transform;
    (void)w.add(model, "rock");
    BodyDesc player;
    player.shape = Shape::capsule(1.0f, 0.5f);
    player.motion = Motion::Character;
    player.movement.max_speed = 100.0f;
    player.transform.position = {0, 20, 30};
    const BodyId p = *w.add(player, "player");
    w.build_static();

    Rng rng(27);
    int hits = 0;
    const double r0 = cpu_seconds();
    for (int i = 0; i < rays; ++i) {
        const float a = rng.uniform(0.0f, 2 * kPi), h = rng.uniform(0.5f, 6.0f);
        const Vec3 from(12 * std::cos(a), h, 12 * std::sin(a));
        const Vec3 to(rng.uniform(-2, 2), rng.uniform(1, 5), rng.uniform(-2, 2));
        RayHit hit;
        hits += w.ray_closest({from, glm::normalize(to - from), 30.0f}, hit, RayFilter(layer::kShootable, p))
                    ? 1
                    : 0;
    }
    r.ray_us = (cpu_seconds() - r0) * 1e6 / rays;
    r.hit_share = static_cast<double>(hits) / rays;
    const double s0 = cpu_seconds();
    for (int i = 0; i < steps; ++i) {
        if (i % 60 == 0) { // a fresh walk toward the rock from a point round it, every half second
            const float a = rng.uniform(0.0f, 2 * kPi);
            w.set_transform(p, {{6 * std::cos(a), 1.52f, 6 * std::sin(a)}, Quat(1, 0, 0, 0)});
            w.character(p).movement.velocity = Vec3(-8 * std::cos(a), 0, -8 * std::sin(a));
        }
        w.step(1.0f / 120.0f);
    }
    r.step_us = (cpu_seconds() - s0) * 1e6 / steps;
    return r;
}

int mesh_collision_command(int argc, const char* const* argv) {
    bool quick = false;
    for (int i = 1; i < argc; ++i) quick |= std::string(argv[i]) == "--quick";
    const int rays = quick ? 2000 : 20000, steps = quick ? 600 : 6000;
    const std::filesystem::path home = std::filesystem::temp_directory_path() / "ks_bench_physics_mesh";
    std::filesystem::create_directories(home / "killswitch/models");
    // The scratch folder is the user data folder while this runs (`ks_bench all` runs other benchmarks
    // after).
    const char* old_home = std::getenv("XDG_DATA_HOME");
    const std::string saved_home = old_home ? old_home : "";
    setenv("XDG_DATA_HOME", home.c_str(), 1);
    std::printf("physics_mesh: a bumpy rock as box / hull / mesh; load %s\n", load_average().c_str());
    std::printf("%-10s %-6s %10s %10s %12s %9s\n", "triangles", "as", "build ms", "us/ray", "us/step",
                "rays hit");
    std::vector<std::string> csv;
    for (const auto& [rings, segments] : {std::pair{16, 32}, std::pair{50, 100}, std::pair{160, 320}}) {
        const std::string file = "rock_" + std::to_string(rings) + ".obj";
        write_rock(home / "killswitch/models" / file, rings, segments);
        level::Level level;
        level::Entity& e = level.add(level::EntityType::Model, {0, 0, 0}, "Rock");
        e.as<level::ModelProps>().file = file;
        (void)level::entity_model(e); // imported once, outside the timings
        const int triangles = 2 * rings * segments;
        for (const char* choice : {"box", "hull", "mesh"}) {
            e.as<level::ModelProps>().collision.value = choice;
            const Measured r = measure(e, rays, steps);
            std::printf("%-10d %-6s %10.2f %10.3f %12.3f %8.0f%%\n", triangles, choice, r.build_ms, r.ray_us,
                        r.step_us, 100 * r.hit_share);
            csv.push_back(std::to_string(triangles) + "," + choice + "," + fmt("%.3f", r.build_ms) + "," +
                          fmt("%.4f", r.ray_us) + "," + fmt("%.4f", r.step_us) + "," +
                          fmt("%.4f", r.hit_share));
        }
    }
    std::filesystem::remove_all(home);
    old_home ? setenv("XDG_DATA_HOME", saved_home.c_str(), 1) : unsetenv("XDG_DATA_HOME");
    if (!quick) {
        const auto path = write_csv("physics_mesh",
                                    "triangles,collision,build_ms,us_per_ray,us_per_step,ray_hit_share", csv);
        std::printf("csv: %s\n", path.string().c_str());
    }
    return 0;
}

const ks::bench::Registrar registrar({"physics_mesh",
                                      "a model's collision as box / hull / triangle mesh: build, ray and "
                                      "character step costs at 1k, 10k, 100k triangles",
                                      mesh_collision_command});

} // namespace
} // namespace ks::physics::bench
