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
