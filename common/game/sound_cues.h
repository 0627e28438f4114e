#pragma once
// What the player should hear of one game step: each event becomes zero or more sound cues (a sound name,
// where, how loud, how important). The game stays headless: the runtime hands these to the audio engine, the
// tests read them directly. Continuous sounds (robot motors, ambience, level emitters) are not events; the
// runtime keeps those from the game's state.
#include "game/game.h"

#include <span>
#include <string_view>
#include <vector>

namespace ks::game {

// How much a voice matters when the voice limit is reached (higher steals lower).
enum class SoundPriority : int { Footstep = 0, Detail = 1, Combat = 2, Critical = 3 };

struct SoundCue {
    std::string_view sound; // a name in assets/sounds/ (static storage or the game's clip set)
    Vec3 position{0.0f};
    bool positional = true; // false: the player's own sounds, centred on the listener
    int entity = -1;        // level entity id, -1 for the player or the world
    float volume = 1.0f;    // 0..1
    float pitch = 1.0f;
    SoundPriority priority = SoundPriority::Detail;
    float reference_distance = 8.0f; // full volume within this many level units, then inverse-distance
};

// Appends the cues of one step's events (game.events()) to `out` (cleared first). Deterministic: the pitch
// jitter of footsteps comes from the game's step count, not a clock or a global RNG.
void sound_cues(const Game& game, std::span<const Event> events, std::vector<SoundCue>& out);

// Every sound name the game can ask for through events (not counting clip cues), for tests and validation.
std::span<const std::string_view> event_sound_names();

} // namespace ks::game
