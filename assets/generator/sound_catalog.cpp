// The sound table: every sound of the audio plan, what it is, and the level it is finished to.
#include "sounds.h"

#include <algorithm>
#include <cmath>

namespace ks::assetgen {
using namespace synth;

const std::vector<SoundRecipe>& sound_recipes() {
    using K = SoundKind;
    static const std::vector<SoundRecipe> recipes = {
        {"rifle_shot", "energy rifle crack: noise snap, falling zap, low punch, short room",
         sounds::rifle_shot, K::OneShot, -1.0},
        {"robot_shot", "the robot's blaster: a lower, buzzier pulse zap", sounds::robot_shot, K::OneShot,
         -1.0},
        {"dry_fire", "empty-magazine click", sounds::dry_fire, K::OneShot, -1.0},
        {"impact", "a shot hitting a wall: spark tick and ricochet", sounds::impact, K::OneShot, -1.0},
        {"robot_alert", "the robot saw you: a rising two-tone chirp", sounds::robot_alert, K::OneShot, -1.0},
        {"robot_hit", "a shot landing on the robot: metal clang and sparks", sounds::robot_hit, K::OneShot,
         -1.0},
        {"robot_death", "the robot powering down: falling whine, sputter, sparks", sounds::robot_death,
         K::OneShot, -1.0},
        {"robot_explosion", "the robot blowing up: boom, crackle, debris", sounds::robot_explosion,
         K::OneShot, -1.0},
        {"cylinder_explosion", "the gas cylinder blowing up: deeper, longer, burning gas",
         sounds::cylinder_explosion, K::OneShot, -1.0},
        {"robot_motor", "loop: the robot's servo whine while it moves", sounds::robot_motor, K::Loop, -14.0},
        {"door_open", "pneumatic hiss, then the leaves sliding open", sounds::door_open, K::OneShot, -1.0},
        {"door_close", "the leaves sliding shut, a clunk, a release hiss", sounds::door_close, K::OneShot,
         -1.0},
        {"light_switch", "a switch snapping", sounds::light_switch, K::OneShot, -1.0},
        {"pickup_health", "warm rising major chime", sounds::pickup_health, K::OneShot, -1.0},
        {"pickup_ammo", "magazine clack and a bright ping", sounds::pickup_ammo, K::OneShot, -1.0},
        {"pickup_shield", "shimmering rising sweep", sounds::pickup_shield, K::OneShot, -1.0},
        {"player_hurt", "dull thud and a grunt", sounds::player_hurt, K::OneShot, -1.0},
        {"shield_hit", "electric crackle on the shield", sounds::shield_hit, K::OneShot, -1.0},
        {"player_death", "a long falling tone", sounds::player_death, K::OneShot, -1.0},
        {"jump", "soft push-off thump", sounds::jump, K::OneShot, -1.0},
        {"land", "heavier landing thump", sounds::land, K::OneShot, -1.0},
        {"footstep_floor", "dry concrete tap", sounds::footstep_floor, K::OneShot, -1.0},
        {"footstep_stairs", "hollow metal step", sounds::footstep_stairs, K::OneShot, -1.0},
        {"ui_hover", "subtle high tick", sounds::ui_hover, K::OneShot, -1.0},
        {"ui_click", "firmer two-part tick", sounds::ui_click, K::OneShot, -1.0},
        {"win_sting", "triumphant arpeggio into a brass chord", sounds::win_sting, K::OneShot, -1.0},
        {"door_locked", "a locked door: the latch rattled, then a low denied buzz", sounds::door_locked,
         K::OneShot, -1.0},
        {"objective_complete", "an objective done: a rising bell fifth", sounds::objective_complete,
         K::OneShot, -1.0},
        {"message_shown", "a message arriving: a breath of static, two quick chirps", sounds::message_shown,
         K::OneShot, -1.0},
        {"ambient_facility", "loop: low drone, air handling, distant machinery", sounds::ambient_facility,
         K::Loop, -12.0},
        {"ambient_dojo", "loop: quiet airy room tone", sounds::ambient_dojo, K::Loop, -16.0},
        {"machine_hum", "loop: transformer hum with a motor", sounds::machine_hum, K::Loop, -12.0},
        {"vent_loop", "loop: air rushing through a duct, a fan", sounds::vent_loop, K::Loop, -14.0},
        {"alarm_loop", "loop: two-tone facility alarm", sounds::alarm_loop, K::Loop, -10.0},
        {"computer_beeps", "loop: console chirps and data warble", sounds::computer_beeps, K::Loop, -16.0},
    };
    return recipes;
}

namespace {
constexpr double kMaxLoopPeakDb = -1.0;

// Cuts what follows the last sample louder than -55 dB of the peak (nothing audible in a game mix), keeping 5
// ms.
void trim_tail(Signal& s) {
    const double floor = peak(s) * db_to_gain(-55.0);
    std::size_t last = 0;
    for (std::size_t i = 0; i < s.size(); ++i)
        if (std::abs(s[i]) > floor) last = i;
    s.resize(std::min(s.size(), last + 1 + frames(0.005)));
}
} // namespace

std::vector<std::int16_t> finish_sound(const SoundRecipe& recipe, Signal signal) {
    if (recipe.kind == SoundKind::OneShot) {
        dc_block(signal);
        trim_tail(signal);
        fade_in(signal, 0.0003);
        // A reverb tail that is still faintly there is eased out over the last fifth, not cut.
        fade_out(signal, std::min(0.3, 0.2 * static_cast<double>(signal.size()) / kSampleRate));
        const double p = peak(signal);
        if (p > 0.0) scale(signal, db_to_gain(recipe.level_db) / p);
    } else {
        process_looped(signal, dc_block);
        const double r = rms(signal);
        if (r > 0.0) scale(signal, db_to_gain(recipe.level_db) / r);
        const double p = peak(signal);
        if (p > db_to_gain(kMaxLoopPeakDb)) scale(signal, db_to_gain(kMaxLoopPeakDb) / p);
    }
    return to_pcm16(signal);
}

} // namespace ks::assetgen
