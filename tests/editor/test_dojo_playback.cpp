// The dojo's playback (model/dojo_playback.h): the transition test, played frame by frame, hands over from
// its `from` clip to its `to` clip at the switch time and reaches the same pose as scrubbing to that time
// (it once stayed on `from` forever while playing); a clip alone plays the same either way.
#include "anim/player.h"
#include "dojo_test_util.h"
#include "model/dojo_playback.h"

#include <algorithm>
#include <vector>

using namespace ks;
using namespace ks::editor;
using ks::dojo_test::shipped_clips;

namespace {

float largest_difference(const anim::Pose& a, const anim::Pose& b) {
    float worst = 0;
    for (std::size_t i = 0; i < a.euler.size(); ++i)
        worst = std::max(
            {worst, glm::length(a.euler[i] - b.euler[i]), glm::length(a.position[i] - b.position[i])});
    return worst;
}

struct Compiled {
    anim::AnimationFile file = shipped_clips();
    anim::Rig rig;
    anim::ClipSet clips;
    Compiled() {
        auto built = anim::build_rig(file);
        REQUIRE(built.ok());
        rig = *built;
        auto compiled = anim::compile(file, rig);
        REQUIRE(compiled.ok());
        clips = std::move(*compiled);
    }
};

} // namespace

TEST_CASE("dojo playback: the transition test played by frames switches to its `to` clip at the switch "
          "time and matches scrubbing there") {
    const Compiled c;
    DojoPlayPlan plan;
    plan.transition = true;
    plan.from = c.clips.find("idle");
    plan.to = c.clips.find("alert");
    REQUIRE(plan.from >= 0);
    REQUIRE(plan.to >= 0);
    plan.switch_at = 0.5;
    plan.blend = 0.25f;

    anim::Player played(c.clips, c.rig);
    dojo_restart_at(played, plan, 0.0);
    const double frame = 1.0 / 60.0;
    double now = 0.0;
    bool was_blending = false;
    for (int i = 0; i < 90; ++i) { // 1.5 s: before, across and after the switch and its blend
        dojo_advance(played, plan, now, frame);
        now += frame;
        CHECK(played.current_clip() == (now > plan.switch_at ? plan.to : plan.from));
        if (now > plan.switch_at && now < plan.switch_at + plan.blend - frame)
            was_blending = was_blending || played.blending();
        anim::Player scrubbed(c.clips, c.rig);
        dojo_restart_at(scrubbed, plan, now);
        CHECK(largest_difference(played.pose(), scrubbed.pose()) < 1e-4f);
    }
    CHECK(was_blending); // the hand-over is a blend, not a cut
    CHECK_FALSE(played.blending());
}

TEST_CASE("dojo playback: a step that ends exactly at the switch time hands over on the next step") {
    const Compiled c;
    DojoPlayPlan plan;
    plan.transition = true;
    plan.from = c.clips.find("idle");
    plan.to = c.clips.find("alert");
    plan.switch_at = 0.25;
    anim::Player player(c.clips, c.rig);
    dojo_restart_at(player, plan, 0.0);
    dojo_advance(player, plan, 0.0, 0.25);
    CHECK(player.current_clip() == plan.from);
    dojo_advance(player, plan, 0.25, 0.125);
    CHECK(player.current_clip() == plan.to);
}

TEST_CASE("dojo playback: events fired on both sides of a split step are all reported") {
    const Compiled c;
    const int shooting = c.clips.find("shooting");
    REQUIRE(shooting >= 0);
    DojoPlayPlan plan;
    plan.transition = true;
    plan.from = shooting;
    plan.to = shooting;
    plan.switch_at = c.clips.clips[static_cast<std::size_t>(shooting)].duration; // from's whole pass
    plan.blend = 0.0f;
    anim::Player player(c.clips, c.rig);
    dojo_restart_at(player, plan, 0.0);
    int fired = 0, advances = 0;
    // One step over the whole of `from` and a whole pass of `to`: every event of the clip, twice.
    dojo_advance(player, plan, 0.0, plan.switch_at * 2.0 - 1e-6, [&](const anim::Player& p) {
        ++advances;
        fired += static_cast<int>(p.fired_events().size());
    });
    CHECK(advances == 2);
    const auto events = c.file.clips[static_cast<std::size_t>(shooting)].events.size();
    REQUIRE(events > 0);
    CHECK(fired == static_cast<int>(2 * events));
}

TEST_CASE("dojo playback: a clip alone plays the same by frames as by scrubbing") {
    const Compiled c;
    DojoPlayPlan plan;
    plan.clip = c.clips.find("idle");
    anim::Player played(c.clips, c.rig);
    dojo_restart_at(played, plan, 0.0);
    double now = 0.0;
    for (int i = 0; i < 60; ++i) {
        dojo_advance(played, plan, now, 1.0 / 30.0);
        now += 1.0 / 30.0;
    }
    anim::Player scrubbed(c.clips, c.rig);
    dojo_restart_at(scrubbed, plan, now);
    CHECK(largest_difference(played.pose(), scrubbed.pose()) < 1e-4f);
    CHECK(played.current_clip() == plan.clip);
}

TEST_CASE("dojo playback: the pass time of a loop wraps, a ping-pong folds back, a once clip holds its end") {
    CHECK(dojo_pass_time(anim::LoopMode::Loop, 1.0, 2.25) == doctest::Approx(0.25));
    CHECK(dojo_pass_time(anim::LoopMode::PingPong, 1.0, 1.25) == doctest::Approx(0.75));
    CHECK(dojo_pass_time(anim::LoopMode::PingPong, 1.0, 2.25) == doctest::Approx(0.25));
    CHECK(dojo_pass_time(anim::LoopMode::Once, 1.0, 3.0) == 1.0);
    CHECK(dojo_pass_time(anim::LoopMode::Next, 1.0, 0.5) == 0.5);
    CHECK(dojo_pass_time(anim::LoopMode::Loop, 0.0, 0.5) == 0.0); // no length: no pass
}

TEST_CASE("dojo playback: the keys around the playhead are the clip's start and phase ends either side") {
    const anim::AnimationFile file = ks::dojo_test::nod_file(); // keys at 0.4 s and 1 s
    const anim::ClipDef& nod = file.clips[0];
    auto around = dojo_keys_around(nod, 0.0);
    CHECK(around.previous == -1.0);
    CHECK(around.next == doctest::Approx(0.4));
    around = dojo_keys_around(nod, 0.6);
    CHECK(around.previous == doctest::Approx(0.4));
    CHECK(around.next == doctest::Approx(1.0));
    around = dojo_keys_around(nod, 0.4); // on a key: the keys either side of it
    CHECK(around.previous == 0.0);
    CHECK(around.next == doctest::Approx(1.0));
    around = dojo_keys_around(nod, 5.0); // a once clip held at its end
    CHECK(around.previous == doctest::Approx(0.4));
    CHECK(around.next == -1.0);
}

TEST_CASE("dojo playback: DojoPlayback shows clips, tests transitions, loops a once clip and keeps its "
          "choices in range when the clips change") {
    const Compiled c;
    DojoPlayback playback;
    playback.set_rig(c.rig);
    CHECK_FALSE(playback.has_clips());
    playback.set_clips(c.clips);
    REQUIRE(playback.has_clips());
    const int alert = c.clips.find("alert"), idle = c.clips.find("idle");
    CHECK_FALSE(playback.show_clip(-1));
    CHECK_FALSE(playback.show_clip(static_cast<int>(c.clips.clips.size())));
    REQUIRE(playback.show_clip(alert));
    CHECK(playback.clip() == alert);
    CHECK(playback.playing());
    CHECK(playback.time() == 0.0);
    const double length = c.clips.clips[static_cast<std::size_t>(alert)].duration;
    CHECK(playback.timeline_length() == doctest::Approx(length));

    // Playing: speed scales dt; a once clip starts over (Loop on) when a step would pass its end.
    playback.set_speed(2.0f);
    playback.advance(0.1);
    CHECK(playback.time() == doctest::Approx(0.2));
    playback.advance(length); // past the end
    CHECK(playback.time() == 0.0);
    playback.set_loop(false);
    playback.advance(length);
    CHECK(playback.time() == doctest::Approx(2.0 * length));
    playback.set_playing(false);
    playback.advance(0.1);
    CHECK(playback.time() == doctest::Approx(2.0 * length));

    // The transition test takes the file's blend for the pair and starts over.
    REQUIRE(playback.test_transition(idle, alert));
    CHECK(playback.transition());
    CHECK(playback.plan().blend == c.clips.blend_time(idle, alert));
    CHECK(playback.time() == 0.0);
    CHECK(playback.timeline_length() ==
          doctest::Approx(playback.plan().switch_at + playback.plan().blend + length));
    REQUIRE(playback.show_clip(idle)); // leaves the test
    CHECK_FALSE(playback.transition());

    // Fewer clips (after an edit): the choices are kept in range and the playhead kept.
    playback.restart_at(0.3);
    anim::ClipSet fewer = c.clips;
    fewer.clips.resize(1);
    playback.choose_clip(static_cast<int>(c.clips.clips.size()) - 1);
    playback.set_clips(fewer);
    CHECK(playback.clip() == 0);
    CHECK(playback.plan().from == 0);
    CHECK(playback.plan().to == 0);
    CHECK(playback.time() == doctest::Approx(0.3));
}
