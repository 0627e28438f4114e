#include "model/dojo_playback.h"

#include <algorithm>

namespace ks::editor {

void dojo_restart_at(anim::Player& player, const DojoPlayPlan& plan, double seconds) {
    if (!plan.transition) {
        player.play(plan.clip, 0.0f);
        player.advance(seconds);
        return;
    }
    player.play(plan.from, 0.0f);
    player.advance(std::min(seconds, plan.switch_at));
    if (seconds > plan.switch_at) {
        player.play(plan.to, plan.blend);
        player.advance(seconds - plan.switch_at);
    }
}

void dojo_advance(anim::Player& player, const DojoPlayPlan& plan, double now, double step,
                  const std::function<void(const anim::Player&)>& after_advance) {
    auto advance = [&](double dt) {
        player.advance(dt);
        if (after_advance) after_advance(player);
    };
    // The same rule as dojo_restart_at: `to` starts once the time is past the switch, not at it.
    if (plan.transition && now <= plan.switch_at && now + step > plan.switch_at) {
        advance(plan.switch_at - now);
        player.play(plan.to, plan.blend);
        advance(now + step - plan.switch_at);
        return;
    }
    advance(step);
}

} // namespace ks::editor
