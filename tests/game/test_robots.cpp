// Robot AI: sight needs line of sight, anger after a hit, cooldown and probability, robots never hurt
// robots, animation clips follow the AI state, muzzle at the hand tip.
#include "core/files.h"
#include "game/robot_rig.h"
#include "game_test_levels.h"

#include <algorithm>
#include <cmath>
#include <vector>

using namespace ks;
using namespace ks::game;
using namespace ks::game_test;

namespace {

int alerts_over(Game& g, double seconds, const Input& in = {}) {
    int n = 0;
    const auto steps = static_cast<int>(seconds / g.settings().step);
    for (int i = 0; i < steps; ++i) {
        g.step(in);
        n += count_events(g, EventType::RobotAlerted);
    }
    return n;
}

} // namespace

TEST_CASE("robots notice the player only with line of sight inside the minimum eye radius") {
    SUBCASE("a wall between them hides the player") {
        auto lv = flat_level();
        add_robot(lv, Vec3(0, 0, -15));
        add_wall(lv, Vec3(0, 0, -8), Vec3(60, 16, 0.5f));
        auto g = make_game(lv);
        CHECK(alerts_over(*g, 3.0) == 0);
        CHECK(g->robots()[0].mode == RobotMode::Idle);
    }
    SUBCASE("in the open the same robot is alerted at once") {
        auto lv = flat_level();
        add_robot(lv, Vec3(0, 0, -15));
        auto g = make_game(lv);
        CHECK(alerts_over(*g, 0.1) == 1);
        CHECK(g->robots()[0].mode == RobotMode::Alert);
    }
    SUBCASE("outside the minimum eye radius it does not notice") {
        auto lv = flat_level();
        add_robot(lv, Vec3(0, 0, -23)); // inside max (25) but outside min (19): hysteresis
        auto g = make_game(lv);
        CHECK(alerts_over(*g, 0.5) == 0);
    }
    SUBCASE("a different level (|dy| >= 6) is not seen") {
        auto lv = flat_level();
        auto& platform = lv.add(level::EntityType::Floor, Vec3(0, 7, -15), "platform");
        platform.as<level::FloorProps>().size = Vec2(10, 10);
        add_robot(lv, Vec3(0, 7, -15));
        auto g = make_game(lv);
        CHECK(alerts_over(*g, 1.0) == 0);
    }
}

TEST_CASE("a robot shot by the player becomes angry and follows regardless of distance") {
    auto lv = flat_level();
    add_robot(lv, Vec3(0, 0, -60));
    auto g = make_game(lv);
    run_for(*g, 1.0);
    CHECK(g->robots()[0].mode == RobotMode::Idle);
    const float before = glm::length(g->robots()[0].feet - g->player().feet);
    g->damage_robot(0, 20.0f, true);
    CHECK(g->robots()[0].angry == doctest::Approx(10.0f));
    run_for(*g, 3.0);
    const float after = glm::length(g->robots()[0].feet - g->player().feet);
    CHECK(after < before - 10.0f);
    CHECK(g->robots()[0].mode == RobotMode::Chase);
    CHECK(g->robot_pose(0).size() > 0);
}

TEST_CASE("robots shoot on their cooldown, with their hit probability, from the right hand's tip") {
    auto lv = flat_level();
    auto& r = add_robot(lv, Vec3(0, 0, -8));
    r.as<level::RobotProps>().hit_probability = 1.0f;
    r.as<level::RobotProps>().cooldown = 1.0f;
    auto g = make_game(lv);
    std::vector<double> times;
    for (int i = 0; i < 6 * 120; ++i) {
        g->step({});
        for (const Event& e : g->events())
            if (e.type == EventType::RobotShot) {
                times.push_back(g->time());
                // The muzzle is the hand tip: off the robot's axis and around chest height.
                const Vec3 axis = g->robots()[0].feet;
                CHECK(glm::length(Vec2(e.position.x - axis.x, e.position.z - axis.z)) > 0.3f);
                CHECK(e.position.y > 0.8f);
                CHECK(e.position.y < 3.5f);
            }
    }
    REQUIRE(times.size() >= 4);
    CHECK(times.size() <= 6);
    for (std::size_t i = 1; i < times.size(); ++i) CHECK(times[i] - times[i - 1] >= 1.0 - 1e-6);
    CHECK(g->player().health == doctest::Approx(100.0f - 10.0f * static_cast<float>(times.size())));

    SUBCASE("probability 0: every shot fires no ray") {
        auto lv0 = flat_level();
        add_robot(lv0, Vec3(0, 0, -8)).as<level::RobotProps>().hit_probability = 0.0f;
        auto g0 = make_game(lv0);
        int shots = 0;
        for (int i = 0; i < 4 * 120; ++i) {
            g0->step({});
            shots += count_events(*g0, EventType::RobotShot);
        }
        CHECK(shots >= 2);
        CHECK(g0->player().health == 100.0f);
    }
}

TEST_CASE("robots never hurt robots: shots pass through robots to the player") {
    auto lv = flat_level();
    for (float z : {-6.0f, -9.0f}) {
        auto& r = add_robot(lv, Vec3(0, 0, z));
        r.as<level::RobotProps>().hit_probability = 1.0f;
    }
    auto g = make_game(lv);
    int hurt = 0;
    for (int i = 0; i < 5 * 120; ++i) {
        g->step({});
        hurt += count_events(*g, EventType::RobotHurt);
    }
    CHECK(hurt == 0);
    CHECK(g->robots()[0].health == 100.0f);
    CHECK(g->robots()[1].health == 100.0f);
    CHECK(g->player().health < 100.0f - 50.0f); // both robots' shots reached the player
}

TEST_CASE("AI states start the matching clips: alert, shoot pose, shooting, reverse, death") {
    auto lv = flat_level();
    add_robot(lv, Vec3(0, 0, -8));
    auto g = make_game(lv);
    const auto& clips = g->animations().clips;
    g->step({});
    CHECK(g->robots()[0].mode == RobotMode::Alert);
    CHECK(clips.clips[static_cast<std::size_t>(g->robot_animation_clip(0))].name == "alert");
    run_for(*g, 0.8);
    CHECK(g->robots()[0].mode == RobotMode::Aim);
    CHECK(clips.clips[static_cast<std::size_t>(g->robot_animation_clip(0))].name == "shoot_pose");
    run_for(*g, 0.4);
    CHECK(g->robots()[0].mode == RobotMode::Shoot);
    CHECK(clips.clips[static_cast<std::size_t>(g->robot_animation_clip(0))].name == "shooting");
    // The player runs away: shoot pose reverse, chase.
    g->teleport_player(Vec3(0, 0, 10), 0.0f);
    g->step({});
    CHECK(g->robots()[0].mode == RobotMode::Chase);
    CHECK(clips.clips[static_cast<std::size_t>(g->robot_animation_clip(0))].name == "shoot_pose_reverse");
    g->damage_robot(0, 1000.0f, true);
    CHECK(clips.clips[static_cast<std::size_t>(g->robot_animation_clip(0))].name == "death");
}

TEST_CASE("the robot rig takes the model's joint offsets from the glTF; bad models are reported") {
    auto lib = anim::load_animation_library(ks::test::source_dir() / "assets/animations/robot.json");
    REQUIRE(lib.ok());
    auto rig = rig_with_model_offsets(lib->rig, ks::test::source_dir() / "assets/models/robot.gltf");
    if (!rig) FAIL(rig.error().str());
    const int tip = rig->find("hand_r_tip");
    REQUIRE(tip >= 0);
    CHECK(rig->node(tip).rest_position.y == doctest::Approx(-0.72f));
    CHECK(rig->node(rig->find("arm_r")).rest_position.z == doctest::Approx(0.6f));
    // The game uses that rig: a fresh game's clips are bound to it.
    auto g = make_game(flat_level());
    CHECK(g->animations().rig.node(g->animations().rig.find("hand_r_tip")).rest_position.y ==
          doctest::Approx(-0.72f));

    ks::test::ScratchDir dir;
    auto write = [&](const char* name, const char* text) {
        REQUIRE(files::write_atomic(dir / name, text).ok());
        return dir / name;
    };
    auto bad = rig_with_model_offsets(lib->rig, write("a.gltf", "{\"nodes\": 3}"));
    REQUIRE_FALSE(bad.ok());
    CHECK(bad.error().where.file.find("a.gltf") != std::string::npos);
    auto nan = rig_with_model_offsets(
        lib->rig, write("b.gltf", "{\"nodes\": [{\"name\": \"hand_r\", \"translation\": [0, \"x\", 0]}]}"));
    REQUIRE_FALSE(nan.ok());
    CHECK(nan.error().where.path == "nodes[0].translation");
    CHECK_FALSE(rig_with_model_offsets(lib->rig, dir / "missing.gltf").ok());
}

TEST_CASE("follow hysteresis: once alerted a robot keeps following out to the maximum eye radius") {
    auto lv = flat_level();
    auto& r = add_robot(lv, Vec3(0, 0, -15));
    r.as<level::RobotProps>().velocity = 0.0f; // stands, so only the player's distance changes
    r.as<level::RobotProps>().hit_probability = 0.0f;
    r.as<level::RobotProps>().search_time = 0.0f; // the reference: a lost player is forgotten at once
    auto g = make_game(lv);
    run_for(*g, 1.0);
    REQUIRE(g->robots()[0].mode != RobotMode::Idle);
    g->teleport_player(Vec3(0, 0, 7), 0.0f); // 22 away: between 19 and 25
    run_for(*g, 1.0);
    CHECK(g->robots()[0].mode == RobotMode::Chase);
    g->teleport_player(Vec3(0, 0, 12), 0.0f); // 27 away: lost
    run_for(*g, 0.1);
    CHECK(g->robots()[0].mode == RobotMode::Idle);
    g->teleport_player(Vec3(0, 0, 7), 0.0f); // 22 again: not noticed from idle
    run_for(*g, 1.0);
    CHECK(g->robots()[0].mode == RobotMode::Idle);
}

TEST_CASE("idle robots wander: turn, then drive forward at 2.4 fading out; a bump adds 3π/4 to the turn") {
    auto lv = flat_level();
    lv.player_start.position = Vec3(0, 0, 90); // far away
    add_robot(lv, Vec3(0.0f));
    auto g = make_game(lv);
    const Vec3 start = g->robots()[0].feet;
    float max_speed = 0.0f;
    for (int i = 0; i < 10 * 120; ++i) {
        g->step({});
        const Vec3 v = g->world().character(g->robots()[0].body).movement.velocity;
        max_speed = std::max(max_speed, std::sqrt(v.x * v.x + v.z * v.z));
    }
    CHECK(g->robots()[0].mode == RobotMode::Idle);
    CHECK(glm::length(g->robots()[0].feet - start) > 2.0f);
    CHECK(max_speed <= 2.4f + 1e-4f);
    CHECK(max_speed > 2.0f);
}

TEST_CASE("a robot's shot that meets a gas cylinder first sets it off") {
    auto lv = flat_level();
    auto& r = add_robot(lv, Vec3(0, 0, -10));
    r.as<level::RobotProps>().hit_probability = 1.0f;
    r.as<level::RobotProps>().velocity = 0.0f;
    lv.add(level::EntityType::GasCylinder, Vec3(0, 0, -5), "gas"); // in the line of fire
    auto g = make_game(lv);
    run_for(*g, 3.0);
    CHECK(g->cylinders()[0].exploded);
}

// Difficulty (game/difficulty.h): a player standing 8 units in front of a robot, seeds 1-4, 5 s each. Easy
// robots aim longer before their first shot, hit less often and hurt less; Hard ones the other way.
TEST_CASE("difficulty: Easy robots shoot later and hurt less than Normal ones, Hard ones sooner and more") {
    struct Outcome {
        float damage = 0.0f;    // over the seeds
        double first_hit = 0.0; // summed over the seeds: when the first damage came (5 s if none)
    };
    auto lv = flat_level();
    add_robot(lv, Vec3(0, 0, -8));
    auto built = build_robot_navigation(lv); // one mesh for every game
    REQUIRE(built);
    const std::shared_ptr<const nav::NavMesh> mesh = std::move(*built);
    auto play = [&](Difficulty difficulty) {
        Outcome out;
        for (std::uint64_t seed = 1; seed <= 4; ++seed) {
            GameOptions options;
            options.seed = seed;
            options.navigation = mesh;
            options.settings.difficulty = difficulty;
            auto created = Game::create(lv, options);
            REQUIRE(created);
            Game& g = **created;
            double first = 5.0;
            for (int i = 0; i < 5 * 120 && g.phase() == Phase::Playing; ++i) {
                g.step({});
                if (first == 5.0 && count_events(g, EventType::PlayerDamaged) > 0) first = g.time();
            }
            out.damage += g.player().damage_taken;
            out.first_hit += first;
        }
        return out;
    };
    const Outcome easy = play(Difficulty::Easy), normal = play(Difficulty::Normal),
                  hard = play(Difficulty::Hard);
    MESSAGE("damage easy " << easy.damage << " normal " << normal.damage << " hard " << hard.damage
                           << "; first hit " << easy.first_hit << " / " << normal.first_hit << " / "
                           << hard.first_hit);
    CHECK(easy.damage < normal.damage);
    CHECK(normal.damage < hard.damage);
    CHECK(easy.first_hit > normal.first_hit);
    CHECK(normal.first_hit > hard.first_hit);
    // What a hit does: the robot's damage scaled, nothing else (a Normal hit is the level's 10).
    CHECK(difficulty_scale(Difficulty::Normal).damage == 1.0f);
    CHECK(difficulty_scale(Difficulty::Normal).accuracy == 1.0f);
    CHECK(difficulty_scale(Difficulty::Normal).reaction_delay == 0.0f);
}

TEST_CASE("difficulty names: easy, normal, hard read back; anything else is an error naming the three") {
    for (Difficulty d : kDifficulties) {
        auto parsed = parse_difficulty(difficulty_name(d), Location("test"));
        REQUIRE(parsed);
        CHECK(*parsed == d);
    }
    auto bad = parse_difficulty("nightmare", Location("command line", 0, 0, "--difficulty"));
    REQUIRE_FALSE(bad);
    CHECK(bad.error().str().find("nightmare") != std::string::npos);
    CHECK(bad.error().str().find("--difficulty") != std::string::npos);
    CHECK(bad.error().hint == "use easy, normal or hard");
}
