// The dojo's curve view: a node's channel over the clip's time with its keys and easings, and the key edits
// made on it (a key dragged in time keeps the other keys in place; a key's value sets the target's
// component, or a relative key's offset). Each edit is one undo step; refusals leave the file unchanged.
#include "dojo_test_util.h"
#include "model/dojo_curves.h"

#include <cmath>

using namespace ks;
using namespace ks::editor;
using ks::dojo_test::nod_file;
using ks::dojo_test::text;

namespace {

ClipCurve curve(const anim::AnimationFile& file, const std::string& node, CurveChannel channel,
                int samples = 11) {
    auto c = clip_curve(file, 0, node, channel, samples);
    REQUIRE_MESSAGE(c.ok(), (c.ok() ? std::string() : c.error().str()));
    return *c;
}

template <class Edit>
void refused_curve(anim::AnimationFile& file, Edit&& edit, const std::string& expected) {
    const std::string before = text(file);
    DojoHistory history;
    auto result = apply_dojo_edit(file, history, "refused", [&] { return edit(); });
    REQUIRE_FALSE(result.ok());
    INFO(result.error().str());
    CHECK(result.error().str().find(expected) != std::string::npos);
    CHECK(text(file) == before);
    CHECK(history.undo_count() == 0);
}

} // namespace

TEST_CASE("dojo curves: samples, keys, easings and key kinds of a node's channel") {
    const anim::AnimationFile file = nod_file();
    const ClipCurve chest = curve(file, "chest", CurveChannel::RotZ);
    CHECK(chest.duration == 1.0);
    CHECK(chest.start_value == 0);
    REQUIRE(chest.points.size() == 11);
    CHECK(chest.points[0].value == doctest::Approx(0));
    CHECK(chest.points[2].time == doctest::Approx(0.2));
    CHECK(chest.points[2].value == doctest::Approx(15).epsilon(1e-5));             // linear to 30 at 0.4 s
    CHECK(chest.points[7].value == doctest::Approx(30 - 20 * 0.25).epsilon(1e-5)); // Quadratic.In, halfway
    CHECK(chest.points[10].value == doctest::Approx(10).epsilon(1e-5));
    REQUIRE(chest.keys.size() == 2);
    CHECK(chest.keys[0].time == doctest::Approx(0.4));
    CHECK(chest.keys[0].value == doctest::Approx(30).epsilon(1e-5));
    CHECK(chest.keys[0].ease == anim::Ease::linear());
    CHECK(chest.keys[0].keyed);
    CHECK_FALSE(chest.keys[0].relative);
    CHECK(chest.keys[0].target_value == 30);
    CHECK(chest.keys[1].ease == anim::Ease::named(anim::EaseFamily::Quadratic, anim::EaseMode::In));

    // The head is not keyed in key 1 (the rest rule holds it home), then turns 90 degrees relatively.
    const ClipCurve head = curve(file, "head", CurveChannel::RotY);
    CHECK_FALSE(head.keys[0].keyed);
    CHECK(head.keys[0].value == doctest::Approx(0));
    CHECK(head.keys[1].keyed);
    CHECK(head.keys[1].relative);
    CHECK(head.keys[1].target_value == 90);
    CHECK(head.keys[1].value == doctest::Approx(90).epsilon(1e-5));

    // A channel nothing animates is flat at its rest value (positions as offsets from rest).
    const ClipCurve lift = curve(file, "chest", CurveChannel::PosY);
    CHECK(lift.start_value == 0);
    for (const CurvePoint& p : lift.points) CHECK(p.value == doctest::Approx(0));

    CHECK_FALSE(clip_curve(file, 0, "tail", CurveChannel::RotX).ok());
    CHECK(clip_curve(file, 0, "tail", CurveChannel::RotX).error().hint.find("chest") != std::string::npos);
    CHECK_FALSE(clip_curve(file, 3, "chest", CurveChannel::RotX).ok());
    for (int c = 0; c < 6; ++c) {
        const auto channel = static_cast<CurveChannel>(c);
        CHECK(curve_channel_from_name(curve_channel_name(channel)) == channel);
    }
    CHECK_FALSE(curve_channel_from_name("rot.w").has_value());
}

TEST_CASE("dojo curves: curve_value follows the loop mode past the clip's end") {
    anim::AnimationFile file = nod_file();
    auto at = [&](double t) {
        auto v = curve_value(file, 0, "chest", CurveChannel::RotZ, t);
        REQUIRE(v.ok());
        return *v;
    };
    CHECK(at(0.2) == doctest::Approx(15).epsilon(1e-5));
    CHECK(at(1.5) == doctest::Approx(10).epsilon(1e-5)); // once: holds
    file.clips[0].events.clear();
    REQUIRE(set_loop_mode(file, 0, anim::LoopMode::PingPong));
    CHECK(at(1.8) == doctest::Approx(at(0.2)).epsilon(1e-5)); // 2d - t
    CHECK(at(2.2) == doctest::Approx(at(0.2)).epsilon(1e-5)); // and again from the start
    CHECK_FALSE(curve_value(file, 0, "chest", CurveChannel::RotZ, std::nan("")).ok());
}

TEST_CASE("dojo curves: moving a key in time keeps the others in place; crossing a neighbour is refused") {
    anim::AnimationFile file = nod_file();
    DojoHistory history;
    const std::string original = text(file);
    REQUIRE(apply_dojo_edit(file, history, "key time", [&] { return move_key_time(file, 0, 0, 0.5); }));
    CHECK(file.clips[0].phases[0].duration == 0.5);
    CHECK(file.clips[0].phases[1].duration == doctest::Approx(0.5));
    CHECK(curve(file, "chest", CurveChannel::RotZ).keys[1].time == doctest::Approx(1.0));
    CHECK(curve(file, "chest", CurveChannel::RotZ).keys[0].time == doctest::Approx(0.5));
    // Meeting a neighbour is allowed (a zero-length phase sets its keys at once); passing it is not.
    REQUIRE(move_key_time(file, 0, 0, 1.0));
    CHECK(file.clips[0].phases[1].duration == 0);
    refused_curve(
        file, [&] { return move_key_time(file, 0, 0, 1.2); }, "it would pass key 2 at 1 s");
    refused_curve(
        file, [&] { return move_key_time(file, 0, 0, -0.1); }, "before the clip's start");
    refused_curve(
        file, [&] { return move_key_time(file, 0, 1, 0.9); }, "it would pass key 1 at 1 s");
    refused_curve(
        file, [&] { return move_key_time(file, 0, 0, std::nan("")); }, "not a number");
    refused_curve(
        file, [&] { return move_key_time(file, 0, 2, 0.5); }, "clip 'nod' has no key 3");
    REQUIRE(history.undo(file));
    CHECK(text(file) == original); // the direct edit after it went with the snapshot
    CHECK(file.clips[0].phases[0].duration == 0.4);

    // The last key sets the clip's length; it may not leave an event behind or make a loop empty.
    file = nod_file();
    REQUIRE(move_key_time(file, 0, 1, 1.5));
    CHECK(file.clips[0].duration() == doctest::Approx(1.5));
    refused_curve(
        file, [&] { return move_key_time(file, 0, 1, 0.6); }, "event time 0.9 s is outside clip 'nod'");
    file.clips[0].events.clear();
    REQUIRE(move_key_time(file, 0, 1, 0.6));
    REQUIRE(move_key_time(file, 0, 0, 0));
    REQUIRE(set_loop_mode(file, 0, anim::LoopMode::Loop));
    refused_curve(
        file, [&] { return move_key_time(file, 0, 1, 0); }, "looping clip 'nod' has zero length");
}

TEST_CASE("dojo curves: a key's value sets the target's component, a relative key's offset") {
    anim::AnimationFile file = nod_file();
    DojoHistory history;
    REQUIRE(apply_dojo_edit(file, history, "value",
                            [&] { return set_key_value(file, 0, 0, "chest", CurveChannel::RotZ, 45); }));
    CHECK(*file.clips[0].phases[0].targets[0].rot == DVec3(0, 0, 45));
    CHECK(curve(file, "chest", CurveChannel::RotZ).keys[0].value == doctest::Approx(45).epsilon(1e-5));
    REQUIRE(set_key_value(file, 0, 1, "head", CurveChannel::RotY, 120));
    CHECK(*file.clips[0].phases[1].targets[1].add_rot == DVec3(0, 120, 0));
    CHECK_FALSE(file.clips[0].phases[1].targets[1].rot.has_value());
    // The head is keyed for rotation only: a position value makes an absolute position key where the
    // head is (at rest: no offset) with that component set.
    REQUIRE(set_key_value(file, 0, 1, "head", CurveChannel::PosX, 0.25));
    CHECK(*file.clips[0].phases[1].targets[1].pos == DVec3(0.25, 0, 0));
    CHECK_FALSE(file.clips[0].phases[1].targets[1].add_pos.has_value());
    CHECK(curve(file, "head", CurveChannel::PosX).keys[1].value == doctest::Approx(0.25).epsilon(1e-5));
    CHECK(anim::validate(file).empty()); // (not the robot's file: it has no required clips)

    refused_curve(
        file, [&] { return set_key_value(file, 0, 0, "head", CurveChannel::RotY, 1); },
        "node 'head' has no key in key 1 of 'nod'");
    refused_curve(
        file, [&] { return set_key_value(file, 0, 0, "chest", CurveChannel::RotX, std::nan("")); },
        "not a number");
    refused_curve(
        file, [&] { return set_key_value(file, 0, 0, "chest", CurveChannel::RotX, 1e9); }, "out of range");
    REQUIRE(history.undo(file));
    CHECK(*file.clips[0].phases[0].targets[0].rot == DVec3(0, 0, 30));
}
