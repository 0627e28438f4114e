// Independent keys (docs/animation.md, "Independent keys"; model/dojo_keys.h, dojo_curves.h): adding,
// editing, dragging or duplicating one key never moves another; relative keys are made absolute on load
// with the same poses (the root's offsets and a looping motion kept); times and values saved exactly.
#include "anim/player.h"
#include "dojo_test_util.h"
#include "model/dojo_curves.h"
#include "model/dojo_keys.h"

#include <cmath>
#include <string>
#include <vector>

using namespace ks;
using namespace ks::editor;

namespace {

anim::TargetDef rotate(const std::string& node, DVec3 degrees, bool relative) {
    anim::TargetDef t;
    t.node = node;
    (relative ? t.add_rot : t.rot) = degrees;
    return t;
}

// robot > chest > head, chest and head going home under the rest rule. "turn" (once, unlisted hold): key 1
// at 0.3 s turns the head +30 and the chest +10 and the root +90 (all relative); key 2 at 0.6 s the head
// +30 more; key 3 at 1 s the head -60 (back to 0) and the chest to 5 absolutely. "settle" (once, the rest
// rule): key 1 turns the head +40 relatively, key 2 leaves it unkeyed (it eases home). "spin" (loop): the
// head +90 each pass (a motion that carries on).
anim::AnimationFile relative_file() {
    anim::AnimationFile f = ks::dojo_test::nod_file();
    f.clips.clear();
    const anim::Ease ease = anim::Ease::named(anim::EaseFamily::Quadratic, anim::EaseMode::InOut);
    anim::ClipDef turn;
    turn.name = "turn";
    turn.unlisted = anim::UnlistedRule::Hold;
    turn.phases = {
        {0.3,
         ease,
         {rotate("head", DVec3(0, 30, 0), true), rotate("chest", DVec3(0, 0, 10), true),
          rotate("robot", DVec3(0, 90, 0), true)}},
        {0.3, ease, {rotate("head", DVec3(0, 30, 0), true)}},
        {0.4, ease, {rotate("head", DVec3(0, -60, 0), true), rotate("chest", DVec3(0, 0, 5), false)}}};
    anim::ClipDef settle;
    settle.name = "settle";
    settle.phases = {{0.5, ease, {rotate("head", DVec3(40, 0, 0), true)}}, {0.5, ease, {}}};
    anim::ClipDef spin;
    spin.name = "spin";
    spin.loop = anim::LoopMode::Loop;
    spin.phases = {{0.5, anim::Ease::linear(), {rotate("head", DVec3(0, 90, 0), true)}}};
    f.clips = {turn, settle, spin};
    REQUIRE(anim::validate(f).empty());
    return f;
}

std::size_t clip_of(const anim::AnimationFile& file, const std::string& name) {
    return ks::dojo_test::index_of(file, name);
}

// Every node's Euler angles and position at `samples` times over the clip's first pass, played from rest.
std::vector<Vec3> poses(const anim::AnimationFile& file, std::size_t clip, int samples = 41) {
    auto rig = anim::build_rig(file);
    REQUIRE(rig.ok());
    auto clips = anim::compile(file, *rig);
    REQUIRE_MESSAGE(clips.ok(), (clips.ok() ? std::string() : clips.error().str()));
    anim::Pose rest;
    rest.set_rest(*rig);
    std::vector<Vec3> euler = rest.euler, position = rest.position, out;
    const anim::Clip& c = clips->clips[clip];
    for (int i = 0; i < samples; ++i) {
        anim::sample_clip(c, rest.euler, rest.position, c.duration * i / (samples - 1), euler, position);
        out.insert(out.end(), euler.begin(), euler.end());
        out.insert(out.end(), position.begin(), position.end());
    }
    return out;
}

float largest_difference(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
    REQUIRE(a.size() == b.size());
    float worst = 0;
    for (std::size_t i = 0; i < a.size(); ++i) worst = std::max(worst, glm::length(a[i] - b[i]));
    return worst;
}

// Each node's rotation and position at every key, as key_values gives them.
std::vector<DVec3> all_key_values(const anim::AnimationFile& file, std::size_t clip) {
    std::vector<DVec3> out;
    for (const anim::RigNodeDef& node : file.rig)
        for (bool position : {false, true}) {
            const auto values = key_values(file, clip, node.name, position);
            out.insert(out.end(), values.begin(), values.end());
        }
    return out;
}

std::vector<double> key_times(const anim::ClipDef& clip) {
    std::vector<double> out;
    double t = 0;
    for (const anim::PhaseDef& phase : clip.phases) out.push_back(t += phase.duration);
    return out;
}

} // namespace

TEST_CASE("independent keys: key_values resolves relative, absolute, rest and held keys from rest") {
    const anim::AnimationFile file = relative_file();
    const std::size_t turn = clip_of(file, "turn"), settle = clip_of(file, "settle");
    CHECK(key_values(file, turn, "head", false) ==
          std::vector<DVec3>{DVec3(0, 30, 0), DVec3(0, 60, 0), DVec3(0, 0, 0)});
    CHECK(key_values(file, turn, "chest", false) ==
          std::vector<DVec3>{DVec3(0, 0, 10), DVec3(0, 0, 10), DVec3(0, 0, 5)}); // held, then absolute
    CHECK(key_values(file, settle, "head", false) == std::vector<DVec3>{DVec3(40, 0, 0), DVec3(0, 0, 0)});
    CHECK(key_values(file, turn, "no_such_node", false).empty());
    CHECK(key_values(file, file.clips.size(), "head", false).empty());
}

TEST_CASE("independent keys: relative keys made absolute on load play the same poses; the root's and a "
          "looping motion's stay relative") {
    anim::AnimationFile file = relative_file();
    std::vector<std::vector<Vec3>> before;
    for (std::size_t c = 0; c < file.clips.size(); ++c) before.push_back(poses(file, c));

    CHECK(make_keys_absolute(file) == 5); // head x3 and chest in turn, head in settle
    CHECK(anim::validate(file).empty());
    for (std::size_t c = 0; c < file.clips.size(); ++c)
        CHECK(largest_difference(poses(file, c), before[c]) < 1e-6f);
    const anim::ClipDef& turn = file.clips[clip_of(file, "turn")];
    CHECK(*turn.phases[1].targets[0].rot == DVec3(0, 60, 0));
    CHECK_FALSE(turn.phases[1].targets[0].add_rot);
    CHECK(*turn.phases[0].targets[2].add_rot == DVec3(0, 90, 0)); // the root: an offset from where it is
    CHECK(file.clips[clip_of(file, "spin")].phases[0].targets[0].add_rot); // each pass carries on
    CHECK(make_keys_absolute(file) == 0);                                  // nothing left to migrate
}

TEST_CASE("independent keys: editing a relative key's value leaves every later key where it was") {
    anim::AnimationFile file = relative_file(); // not migrated: the format's relative keys, as in old files
    const std::size_t turn = clip_of(file, "turn");
    REQUIRE(set_key_value(file, turn, 0, "head", CurveChannel::RotY, 45));
    CHECK(key_values(file, turn, "head", false) ==
          std::vector<DVec3>{DVec3(0, 45, 0), DVec3(0, 60, 0), DVec3(0, 0, 0)});
    // The root's relative key: only that key moves.
    REQUIRE(set_key_value(file, turn, 0, "robot", CurveChannel::RotY, 120));
    CHECK(key_values(file, turn, "robot", false).back() == DVec3(0, 120, 0));
    CHECK(key_values(file, turn, "head", false)[1] == DVec3(0, 60, 0));
}

TEST_CASE("independent keys: dragging a key in time and value on the curve moves no other key") {
    anim::AnimationFile file = relative_file();
    make_keys_absolute(file);
    const std::size_t turn = clip_of(file, "turn");
    const std::vector<double> times = key_times(file.clips[turn]);
    const std::vector<DVec3> values = all_key_values(file, turn);
    // What the curve view's drag does each frame: the time, then the value.
    REQUIRE(move_key_time(file, turn, 0, 0.45));
    REQUIRE(set_key_value(file, turn, 0, "head", CurveChannel::RotY, -39.3));
    const std::vector<double> moved = key_times(file.clips[turn]);
    CHECK(moved[0] == doctest::Approx(0.45));
    CHECK(moved[1] == doctest::Approx(times[1]));
    CHECK(moved[2] == doctest::Approx(times[2]));
    const std::vector<DVec3> after = all_key_values(file, turn);
    const std::size_t keys = times.size();
    std::size_t changed = 0;
    for (std::size_t i = 0; i < after.size(); ++i)
        if (after[i] != values[i]) {
            ++changed;
            CHECK(i == keys * 2 * 2); // head (third node), rotation, key 1
            CHECK(after[i] == DVec3(0, -39.3, 0));
        }
    CHECK(changed == 1);
}

TEST_CASE("independent keys: adding a key or duplicating one changes no pose of the clip") {
    anim::AnimationFile file = relative_file(); // relative keys, as in an old file
    const std::size_t settle = clip_of(file, "settle"), turn = clip_of(file, "turn");
    // The head eases home in settle's key 2 (the rest rule): a key added there keeps it doing so.
    const auto settle_poses = poses(file, settle);
    REQUIRE(add_node_key(file, settle, 1, "head"));
    CHECK(*file.clips[settle].phases[1].targets[0].rot == DVec3(0, 0, 0));
    CHECK(largest_difference(poses(file, settle), settle_poses) < 1e-6f);
    // The chest holds in turn's key 2: a key added there holds it too.
    const auto turn_poses = poses(file, turn);
    REQUIRE(add_node_key(file, turn, 1, "chest"));
    CHECK(*file.clips[turn].phases[1].targets.back().rot == DVec3(0, 0, 10));
    CHECK(largest_difference(poses(file, turn), turn_poses) < 1e-6f);

    // A duplicated key is a pause: it holds the key's pose, and every later key reaches what it did.
    const auto head = key_values(file, turn, "head", false);
    REQUIRE(duplicate_phase(file, turn, 0));
    CHECK(key_values(file, turn, "head", false) == std::vector<DVec3>{head[0], head[0], head[1], head[2]});
    CHECK(key_values(file, turn, "robot", false)[1] == key_values(file, turn, "robot", false)[0]);
}

TEST_CASE("independent keys: times and values are saved exactly and load back the same") {
    CHECK(snap(0.75 - 0.55, kTimeSteps) == 0.2);
    CHECK(snap(static_cast<double>(0.3f), kTimeSteps) == 0.3);
    CHECK(snap(static_cast<double>(12.3f), kDegreeFieldSteps) == 12.3);
    CHECK(snap(0.1 + 0.2, kValueSteps) == 0.3);
    CHECK(snap(1e300, kValueSteps) == 1e300); // no finer grid: left alone

    anim::AnimationFile file = relative_file();
    make_keys_absolute(file);
    const std::size_t turn = clip_of(file, "turn");
    file.clips[turn].phases[1].duration = 0.25; // keys at 0.3, 0.55, 0.95
    REQUIRE(move_key_time(file, turn, 2, 0.75));
    CHECK(file.clips[turn].phases[2].duration == 0.2);
    const std::string text = anim::save_animation_string(file);
    CHECK(text.find("0.19999999999999996") == std::string::npos);
    auto loaded = anim::load_animation_string(text, "turn.json");
    REQUIRE(loaded.ok());
    CHECK(anim::save_animation_string(*loaded) == text);
    CHECK(loaded->clips[turn].phases[2].duration == 0.2);
    CHECK(all_key_values(*loaded, turn) == all_key_values(file, turn));
}
