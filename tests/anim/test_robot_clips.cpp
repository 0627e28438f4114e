// The shipped robot clips against the reference facts (seed-facts.md section 5.8): nodes, targets,
// durations and easings, sampled through the same code path the game uses.
#include "anim/clip_io.h"
#include "anim/player.h"
#include "anim/rotation.h"
#include "anim_test_support.h"

#include <doctest/doctest.h>
#include <numbers>

using namespace ks;
using namespace ks::anim;
using ks::anim::test::robot_library;

namespace {

constexpr float pi = std::numbers::pi_v<float>;

// Samples a clip started from the rest pose.
struct Sampler {
    const AnimationLibrary& lib = robot_library();
    Pose rest, out;
    Sampler() {
        rest.set_rest(lib.rig);
        out.set_rest(lib.rig);
    }
    const Pose& at(const char* clip, double t) {
        int index = lib.clips.find(clip);
        REQUIRE_MESSAGE(index >= 0, clip);
        sample_clip(lib.clips.clips[static_cast<std::size_t>(index)], rest.euler, rest.position, t, out.euler,
                    out.position);
        out.update_rotations();
        return out;
    }
    Vec3 euler(const char* clip, double t, const char* node) {
        int n = lib.rig.find(node);
        REQUIRE_MESSAGE(n >= 0, node);
        return at(clip, t).euler[static_cast<std::size_t>(n)];
    }
};

void check_vec(const Vec3& got, const Vec3& expected, float tolerance = 1e-5f) {
    CHECK(got.x == doctest::Approx(expected.x).epsilon(tolerance).scale(1.0));
    CHECK(got.y == doctest::Approx(expected.y).epsilon(tolerance).scale(1.0));
    CHECK(got.z == doctest::Approx(expected.z).epsilon(tolerance).scale(1.0));
}

} // namespace

TEST_CASE("the robot rig has the model's English node names and hierarchy") {
    const Rig& rig = robot_library().rig;
    const std::pair<const char*, const char*> expected[] = {
        {"robot", ""},          {"wheel_base", "robot"}, {"chest", "wheel_base"},  {"arm_r", "chest"},
        {"forearm_r", "arm_r"}, {"hand_r", "forearm_r"}, {"hand_r_tip", "hand_r"}, {"arm_l", "chest"},
        {"forearm_l", "arm_l"}, {"hand_l", "forearm_l"}, {"head", "chest"},        {"wheels", "wheel_base"},
    };
    CHECK(rig.size() == 12);
    for (auto [name, parent] : expected) {
        int n = rig.find(name);
        REQUIRE_MESSAGE(n >= 0, name);
        const int p = rig.node(n).parent;
        CHECK(std::string(p < 0 ? "" : rig.node(p).name) == parent);
    }
}

TEST_CASE("the six robot clips and reset exist, with the reference durations and loop modes") {
    const ClipSet& clips = robot_library().clips;
    struct Expect {
        const char* name;
        float duration;
        LoopMode loop;
    };
    for (auto e : {Expect{"idle", 1.6f, LoopMode::Loop}, Expect{"alert", 0.6f, LoopMode::Once},
                   Expect{"shoot_pose", 0.3f, LoopMode::Once}, Expect{"shooting", 0.5f, LoopMode::Once},
                   Expect{"shoot_pose_reverse", 0.3f, LoopMode::Once}, Expect{"death", 1.8f, LoopMode::Once},
                   Expect{"reset", 0.0f, LoopMode::Once}}) {
        int i = clips.find(e.name);
        REQUIRE_MESSAGE(i >= 0, e.name);
        CHECK(clips.clips[static_cast<std::size_t>(i)].duration == doctest::Approx(e.duration));
        CHECK(clips.clips[static_cast<std::size_t>(i)].loop == e.loop);
        // The wheels are never animated (reference), and the shot marker only follows the hand.
        for (const Channel& ch : clips.clips[static_cast<std::size_t>(i)].channels) {
            CHECK(robot_library().rig.node(ch.node).name != "wheels");
            CHECK(robot_library().rig.node(ch.node).name != "hand_r_tip");
        }
    }
}

TEST_CASE("alert: chest, head spin 2 pi then 4 pi (linear), arms up, then everything home") {
    Sampler s;
    check_vec(s.euler("alert", 0.3, "chest"), {0, 0, pi / 4});
    check_vec(s.euler("alert", 0.3, "head"), {0, 2 * pi, 0});
    for (const char* arm : {"arm_r", "forearm_r", "arm_l", "forearm_l"})
        check_vec(s.euler("alert", 0.3, arm), {0, 0, 3 * pi / 4});
    // Quadratic.In on the chest, Linear on the head (Tween.js default when no easing is set).
    check_vec(s.euler("alert", 0.15, "chest"), {0, 0, pi / 4 * 0.25f});
    check_vec(s.euler("alert", 0.15, "head"), {0, pi, 0});
    check_vec(s.euler("alert", 0.45, "head"), {0, 3 * pi, 0});
    check_vec(s.euler("alert", 0.45, "chest"), {0, 0, pi / 4 * (1 - 0.25f)}); // back home with Quadratic.In
    check_vec(s.euler("alert", 0.5999, "head"), {0, 4 * pi * (1 - 0.0001f / 0.6f * 2), 0}, 1e-3f);
    // At the end the 0 ms step sets the head to 0: the same rotation as 4 pi, so nothing visible jumps.
    check_vec(s.euler("alert", 0.6, "head"), {0, 0, 0});
    check_vec(s.euler("alert", 0.6, "chest"), {0, 0, 0});
    check_vec(s.euler("alert", 5.0, "arm_r"), {0, 0, 0});
}

TEST_CASE("shoot pose, shooting recoil (once, then holding the shoot pose) and shoot pose reverse") {
    Sampler s;
    check_vec(s.euler("shoot_pose", 0.3, "arm_r"), {0, pi / 8, pi / 3});
    check_vec(s.euler("shoot_pose", 0.3, "forearm_r"), {pi / 8, 0, 0});
    check_vec(s.euler("shoot_pose", 0.3, "hand_r"), {-pi / 4, 0, 0});
    check_vec(s.euler("shoot_pose", 0.3, "arm_l"), {-pi / 4, -0.13f * pi, pi / 6});
    check_vec(s.euler("shoot_pose", 0.3, "forearm_l"), {-pi / 4, 0, 0});
    check_vec(s.euler("shoot_pose", 0.3, "chest"), {0, 0, 0});
    check_vec(s.euler("shoot_pose", 0.15, "arm_r"), Vec3(0, pi / 8, pi / 3) * 0.25f);

    check_vec(s.euler("shooting", 0.2, "chest"), {0, 0, pi / 6});
    check_vec(s.euler("shooting", 0.2, "head"), {0, 0, -pi / 6});
    check_vec(s.euler("shooting", 0.2, "arm_r"), {0, pi / 8, pi / 3});
    check_vec(s.euler("shooting", 0.5, "chest"), {0, 0, 0});
    check_vec(s.euler("shooting", 0.5, "arm_r"), {0, pi / 8, pi / 3});
    // Once per shot, as the reference: after its recoil the robot holds the shoot pose (no second recoil
    // without a muzzle flash).
    check_vec(s.euler("shooting", 0.7, "chest"), {0, 0, 0});
    check_vec(s.euler("shooting", 100.2, "chest"), {0, 0, 0});
    check_vec(s.euler("shooting", 100.2, "arm_r"), {0, pi / 8, pi / 3});

    // Reverse from the shoot pose: everything home over 300 ms, Quadratic.In.
    const ClipSet& clips = robot_library().clips;
    Pose from = s.at("shoot_pose", 1.0), out = from;
    const Clip& reverse = clips.clips[static_cast<std::size_t>(clips.find("shoot_pose_reverse"))];
    sample_clip(reverse, from.euler, from.position, 0.15, out.euler, out.position);
    const int arm = robot_library().rig.find("arm_r");
    check_vec(out.euler[static_cast<std::size_t>(arm)], Vec3(0, pi / 8, pi / 3) * 0.75f);
    sample_clip(reverse, from.euler, from.position, 0.3, out.euler, out.position);
    for (const Vec3& e : out.euler) check_vec(e, {0, 0, 0});
}

TEST_CASE("death: two spins of the root group with Quadratic.InOut, then tipping over with Bounce.InOut") {
    Sampler s;
    check_vec(s.euler("death", 0.9, "robot"), {0, 4 * pi, 0});
    check_vec(s.euler("death", 0.45, "robot"), {0, 2 * pi, 0}); // InOut midpoint
    check_vec(s.euler("death", 0.225, "robot"), {0, 4 * pi * 0.125f, 0});
    check_vec(s.euler("death", 0.9, "wheel_base"), {pi / 8, 0, 0});
    check_vec(s.euler("death", 0.9, "chest"), {-pi / 8, 0, 0});
    check_vec(s.euler("death", 0.9, "arm_r"), {0, -pi / 4, 3 * pi / 4});
    check_vec(s.euler("death", 0.9, "arm_l"), {0, pi / 4, 3 * pi / 4});
    check_vec(s.euler("death", 0.9, "forearm_r"), {0, 0, pi / 4});
    check_vec(s.euler("death", 1.8, "robot"), {0, 4 * pi, -0.95f * pi / 2}); // the spin stays, z tips
    check_vec(s.euler("death", 1.8, "head"), {0, pi / 4, 0});
    check_vec(s.euler("death", 1.8, "arm_r"), {0, -pi / 4, 0.55f * pi});
    check_vec(s.euler("death", 1.8, "arm_l"), {0, pi / 4, 0.55f * pi});
    // Bounce.InOut at a quarter of phase 2: (1 - BounceOut(0.5)) / 2 = 0.1171875.
    check_vec(s.euler("death", 0.9 + 0.225, "robot"), {0, 4 * pi, -0.95f * pi / 2 * 0.1171875f});
    check_vec(s.euler("death", 60.0, "robot"), {0, 4 * pi, -0.95f * pi / 2}); // holds (once)
}

TEST_CASE("death spins relative to the captured root yaw (the Tween.js \"+4pi\" string)") {
    const AnimationLibrary& lib = robot_library();
    Pose start;
    start.set_rest(lib.rig);
    start.euler[0] = Vec3(0, 1.0f, 0);
    Pose out = start;
    const Clip& death = lib.clips.clips[static_cast<std::size_t>(lib.clips.find("death"))];
    sample_clip(death, start.euler, start.position, 0.9, out.euler, out.position);
    check_vec(out.euler[0], {0, 1.0f + 4 * pi, 0});
}

TEST_CASE("reset is immediate; idle is a loop that returns to where it started") {
    Sampler s;
    for (const Vec3& e : s.at("reset", 0.0).euler) check_vec(e, {0, 0, 0});
    const int base = robot_library().rig.find("wheel_base");
    const Vec3 rest_position = robot_library().rig.node(base).rest_position;
    CHECK(s.at("idle", 0.4).position[static_cast<std::size_t>(base)].y ==
          doctest::Approx(rest_position.y + 0.04f));
    CHECK(s.at("idle", 0.8).position[static_cast<std::size_t>(base)].y == doctest::Approx(rest_position.y));
    check_vec(s.euler("idle", 0.4, "arm_r"), {0, 0, 10 * pi / 180});
    check_vec(s.euler("idle", 1.2, "arm_r"), {0, 0, -10 * pi / 180});
    for (double t : {0.1, 0.55, 1.3}) {
        const Pose a = s.at("idle", t);
        const Pose b = s.at("idle", t + 1.6 * 3);
        for (int n = 0; n < a.size(); ++n) CHECK(angle_between(a.rotation[n], b.rotation[n]) < 1e-5f);
    }
}

TEST_CASE("unlisted nodes: 'rest' sends rest nodes home, 'hold' keeps them, the root is never reset") {
    const AnimationLibrary& lib = robot_library();
    AnimationFile file = lib.file;
    Pose start;
    start.set_rest(lib.rig);
    const int chest = lib.rig.find("chest"), root = lib.rig.find("robot");
    start.euler[static_cast<std::size_t>(chest)] = Vec3(0.3f, 0, 0);
    start.euler[static_cast<std::size_t>(root)] = Vec3(0, 0.7f, 0);
    for (UnlistedRule rule : {UnlistedRule::Rest, UnlistedRule::Hold}) {
        for (ClipDef& c : file.clips) c.unlisted = rule;
        auto clips = compile(file, lib.rig);
        REQUIRE(clips.ok());
        const Clip& pose = clips->clips[static_cast<std::size_t>(clips->find("shoot_pose"))];
        Pose out = start;
        sample_clip(pose, start.euler, start.position, 0.3, out.euler, out.position);
        check_vec(out.euler[static_cast<std::size_t>(chest)],
                  rule == UnlistedRule::Rest ? Vec3(0) : Vec3(0.3f, 0, 0));
        check_vec(out.euler[static_cast<std::size_t>(root)], Vec3(0, 0.7f, 0));
    }
}

TEST_CASE("binding to a model that lacks a node is an error naming it") {
    const AnimationLibrary& lib = robot_library();
    std::vector<std::pair<std::string, std::string>> names;
    for (const RigNode& n : lib.rig.nodes())
        if (n.name != "forearm_l")
            names.emplace_back(n.name, n.parent < 0 ? "" : lib.rig.node(n.parent).name);
    for (auto& [name, parent] : names)
        if (parent == "forearm_l") parent = "arm_l";
    auto rig = Rig::from_names(names);
    REQUIRE(rig.ok());
    auto clips = compile(lib.file, *rig);
    REQUIRE_FALSE(clips.ok());
    CHECK(clips.error().str().find("node 'forearm_l' is not in the rig") != std::string::npos);
    CHECK(clips.error().str().find("clip 'alert'") != std::string::npos);
    // A rig from names alone (tests and tools without the model) binds when every node is there.
    std::vector<std::pair<std::string, std::string>> all;
    for (const RigNode& n : lib.rig.nodes())
        all.emplace_back(n.name, n.parent < 0 ? "" : lib.rig.node(n.parent).name);
    auto full = Rig::from_names(all);
    REQUIRE(full.ok());
    CHECK(compile(lib.file, *full).ok());
    CHECK_FALSE(Rig::from_names({{"a", ""}, {"b", "c"}}).ok());
    CHECK_FALSE(Rig::from_names({{"a", ""}, {"a", ""}}).ok());
}

TEST_CASE("world transforms follow the hierarchy: the shot marker moves with the right arm") {
    const AnimationLibrary& lib = robot_library();
    Pose pose;
    pose.set_rest(lib.rig);
    std::vector<Mat4> world(static_cast<std::size_t>(lib.rig.size()));
    const auto tip = static_cast<std::size_t>(lib.rig.find("hand_r_tip"));
    compute_world(lib.rig, pose, world);
    const Vec3 rest_tip = Vec3(world[tip][3]);
    // Sum of rest offsets along robot -> wheel_base -> chest -> arm_r -> forearm_r -> hand_r -> hand_r_tip.
    Vec3 expected(0);
    for (int n = static_cast<int>(tip); n >= 0; n = lib.rig.node(n).parent)
        expected += lib.rig.node(n).rest_position;
    check_vec(rest_tip, expected);
    Player player(lib.clips, lib.rig);
    player.play(lib.clips.find("shoot_pose"), 0.0f);
    player.advance(1.0);
    compute_world(lib.rig, player.pose(), world);
    CHECK(glm::length(Vec3(world[tip][3]) - rest_tip) > 0.1f);
    // The marker stays rigidly attached to the hand, at its rest offset.
    const auto hand = static_cast<std::size_t>(lib.rig.find("hand_r"));
    CHECK(glm::length(Vec3(world[tip][3]) - Vec3(world[hand][3])) ==
          doctest::Approx(glm::length(lib.rig.node(static_cast<int>(tip)).rest_position)).epsilon(1e-5));
}

TEST_CASE("the head is tweened without easing in every clip, even when going home by the rest rule") {
    const AnimationLibrary& lib = robot_library();
    REQUIRE(lib.file.node_ease.size() == 1);
    CHECK(lib.file.node_ease[0].node == "head");
    Pose start;
    start.set_rest(lib.rig);
    const auto head = static_cast<std::size_t>(lib.rig.find("head"));
    const auto chest = static_cast<std::size_t>(lib.rig.find("chest"));
    start.euler[head] = Vec3(0, 0, 0.4f);
    start.euler[chest] = Vec3(0, 0, 0.4f);
    Pose out = start;
    const Clip& pose = lib.clips.clips[static_cast<std::size_t>(lib.clips.find("shoot_pose"))];
    sample_clip(pose, start.euler, start.position, 0.15, out.euler, out.position);
    check_vec(out.euler[head], {0, 0, 0.4f * 0.5f});   // Linear: halfway home
    check_vec(out.euler[chest], {0, 0, 0.4f * 0.75f}); // Quadratic.In: a quarter of the way
}
