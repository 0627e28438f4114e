#pragma once
// The game's sound effects (assets/sounds/<name>.wav, the names of the audio plan): a render function per
// sound in sound_<group>.cpp, and the table saying what each is and how loud it is finished.
#include "synth.h"

#include <cstdint>
#include <vector>

namespace ks::assetgen {

enum class SoundKind { OneShot, Loop };

struct SoundRecipe {
    const char* name;
    const char* what;
    synth::Signal (*render)();
    SoundKind kind;
    // One-shots: the peak in dBFS. Loops: the RMS in dBFS (their peaks held at or below -1 dBFS).
    double level_db;
};

const std::vector<SoundRecipe>& sound_recipes();

// One-shots lose any DC, their inaudible tail (below -55 dB of the peak) and get short fades so they start
// and end at zero; loops are levelled without touching their seam. Then 16-bit PCM.
std::vector<std::int16_t> finish_sound(const SoundRecipe& recipe, synth::Signal signal);

namespace sounds {
// sound_weapons.cpp
synth::Signal rifle_shot();
synth::Signal robot_shot();
synth::Signal dry_fire();
synth::Signal impact();
// sound_robots.cpp
synth::Signal robot_alert();
synth::Signal robot_hit();
synth::Signal robot_death();
synth::Signal robot_motor();
// sound_explosions.cpp
synth::Signal robot_explosion();
synth::Signal cylinder_explosion();
// sound_world.cpp
synth::Signal door_open();
synth::Signal door_close();
synth::Signal light_switch();
synth::Signal pickup_health();
synth::Signal pickup_ammo();
synth::Signal pickup_shield();
// sound_player.cpp
synth::Signal player_hurt();
synth::Signal shield_hit();
synth::Signal player_death();
synth::Signal jump();
synth::Signal land();
synth::Signal footstep_floor();
synth::Signal footstep_stairs();
// sound_ui.cpp
synth::Signal ui_hover();
synth::Signal ui_click();
synth::Signal win_sting();
// sound_logic.cpp
synth::Signal door_locked();
synth::Signal objective_complete();
synth::Signal message_shown();
// sound_ambience.cpp
synth::Signal ambient_facility();
synth::Signal ambient_dojo();
synth::Signal machine_hum();
synth::Signal vent_loop();
synth::Signal alarm_loop();
synth::Signal computer_beeps();
} // namespace sounds

} // namespace ks::assetgen
