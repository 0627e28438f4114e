// The game's feedback drawn: the particles each event spawns (runtime/app/event_particles.h), the muzzle
// lights put first in the frame's lights (muzzle_lights.h), and the game itself, through its status file and
// a screenshot: a shot makes a light, then none; a robot hit turns red. The feedback's logic is
// tests/runtime_model/test_feedback.cpp's.
#include "game/game_test_levels.h"
#include "runtime/app/event_particles.h"
#include "runtime/app/muzzle_lights.h"
#include "runtime/screen_image.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <fstream>
#include <sstream>

using namespace ks;
using namespace ks::runtime;

namespace {
constexpr float kStep = 1.0f / 120.0f;

game::Event event_at(game::EventType type, const Vec3& position, float amount = 0.0f, int entity = -1) {
    game::Event e;
    e.type = type;
    e.position = position;
    e.amount = amount;
    e.entity = entity;
    return e;
}
} // namespace

TEST_CASE("muzzle lights go first in the frame's light list, as dynamic point lights") {
    feedback::Feedback f;
    const Vec3 eye(0.0f, 3.0f, 0.0f), tip(0.3f, 2.75f, -1.0f);
    std::vector<render::Light> lights(5); // the level's lights
    lights.reserve(32);
    f.update(kStep);
    f.on_event(event_at(game::EventType::ShotFired, tip), eye);
    std::vector<render::Light> frame = lights;
    add_muzzle_lights(f, frame, 0.0f);
    REQUIRE(frame.size() == 6);
    CHECK(frame[0].position == tip);
    CHECK(frame[0].type == render::Light::Type::Point);
    CHECK(frame[0].dynamic); // lights baked walls on the fast path too
    CHECK(frame[0].intensity == doctest::Approx(feedback::muzzle_light_intensity(0.0f)));
    CHECK_FALSE(frame[1].dynamic); // the level's lights follow
    for (int i = 0; i < 20; ++i) f.update(kStep);
    frame = lights;
    add_muzzle_lights(f, frame, 0.0f);
    CHECK(frame.size() == 5);
}

TEST_CASE("event particles: sparks out of a wall, a blue crackle on a robot, none on the player") {
    auto lv = game_test::flat_level();
    game_test::add_robot(lv, Vec3(0, 0, -20));
    lv.add(level::EntityType::GasCylinder, Vec3(4, 0, -10), "gas");
    auto g = game_test::make_game(lv);
    const int robot_id = g->robots()[0].entity_id, cylinder_id = g->cylinders()[0].entity_id;
    game::Event hit = event_at(game::EventType::Hit, Vec3(0, 2, -5));
    hit.end = Vec3(0, 0, 1); // a wall facing the player
    CHECK(hit_target(*g, hit) == HitTarget::Scenery);
    EventEmitters out;
    REQUIRE(event_particles(hit, HitTarget::Scenery, out) == 2);
    CHECK(out[0].texture == "spark");
    CHECK(glm::dot(out[0].drift, hit.end) > 1.0f); // sprayed out of the wall ...
    CHECK(out[0].gravity > 0.0f);                  // ... falling
    CHECK(out[0].position.z > hit.position.z);     // in front of the surface
    CHECK(out[0].color_start.r > out[0].color_start.b);
    CHECK(out[1].texture == "smoke"); // and a puff of dust
    CHECK(validate(out[0]));
    CHECK(validate(out[1]));

    game::Event on_robot = hit;
    on_robot.entity = robot_id;
    CHECK(hit_target(*g, on_robot) == HitTarget::Robot);
    REQUIRE(event_particles(on_robot, HitTarget::Robot, out) == 1);
    CHECK(out[0].color_end.b > out[0].color_end.r); // blue, unlike the wall's orange
    CHECK(out[0].per_frame > 8);

    game::Event on_cylinder = hit;
    on_cylinder.entity = cylinder_id;
    CHECK(hit_target(*g, on_cylinder) == HitTarget::Cylinder);

    game::Event on_player = hit;
    on_player.amount = 10.0f; // a robot's shot that hit the player: the HUD shows it
    CHECK(hit_target(*g, on_player) == HitTarget::Player);
    CHECK(event_particles(on_player, HitTarget::Player, out) == 0);

    CHECK(event_particles(event_at(game::EventType::ShotFired, Vec3(0, 3, -1)), HitTarget::Scenery, out) ==
          1);
    CHECK(event_particles(event_at(game::EventType::Explosion, Vec3(0, 1, -9), 7.0f), HitTarget::Scenery,
                          out) == 2);
    CHECK(event_particles(event_at(game::EventType::PickupTaken, Vec3(0)), HitTarget::Scenery, out) == 0);
}

TEST_CASE("the game: a shot lights up for a few frames then not, and the robot it hits turns red") {
    REQUIRE_MESSAGE(test::have_display(),
                    "no DISPLAY: GL screen tests cannot run (./run.sh test runs them under xvfb-run)");
    test::ScratchDir dir;
    // Robot 42 of the main level stands 7 ahead of this spot; the shot hits its chest.
    auto run = [&](const std::string& name, const std::string& args, int frames) {
        const auto png = dir / (name + ".png"), status = dir / (name + ".txt");
        auto r = test::run_command("env XDG_CONFIG_HOME=" + (dir / "config").string() + " " +
                                   (test::bin_dir() / "killswitch").string() +
                                   " --width 480 --height 270 --screen play --warp 35,0,17,0,-11 --frames " +
                                   std::to_string(frames) + " --screenshot " + png.string() +
                                   " --status-file " + status.string() + " " + args);
        INFO(r.output);
        REQUIRE(r.exit_code == 0);
        std::ifstream in(status);
        std::stringstream text;
        text << in.rdbuf();
        return std::pair{test::load_png(png), text.str()};
    };
    const auto [fired, fired_status] = run("fired", "--fire", 2);
    const auto [later, later_status] = run("later", "--fire", 12);
    const auto [calm, calm_status] = run("calm", "", 2);
    CHECK(fired_status.find("feedback arcs 0 shakes 0 lights 1") != std::string::npos);
    CHECK(later_status.find("lights 0") != std::string::npos);
    CHECK(calm_status.find("lights 0") != std::string::npos);
    // The robot's body (centre of the picture, below the crosshair) is red after the hit.
    auto redness = [](const test::Image& img) {
        double sum = 0.0;
        int n = 0;
        for (int y = img.height * 55 / 100; y < img.height * 62 / 100; ++y)
            for (int x = img.width * 47 / 100; x < img.width * 53 / 100; ++x, ++n) {
                const unsigned char* p = img.at(x, y);
                sum += p[0] - 0.5 * (p[1] + p[2]);
            }
        return sum / n;
    };
    REQUIRE(calm.width == 480);
    MESSAGE("robot redness: calm " << redness(calm) << ", just hit " << redness(fired) << ", 0.2 s later "
                                   << redness(later));
    CHECK(redness(fired) > redness(calm) + 40.0);
    CHECK(redness(later) > redness(calm) + 20.0);
}
