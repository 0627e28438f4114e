#pragma once
// How loud a sound is at a distance, in level units (the player is 3 units tall, a wall 16). The engine
// computes this itself (OpenAL's own distance model is off) so the gain it applies is exactly the gain the
// voice limit compares, and a sound beyond its max distance is truly silent.
//
// Inverse distance, clamped: full volume up to `ref_distance`, then ref / distance (-6 dB per doubling),
// faded linearly to silence over the last quarter before `max_distance`. A rifle shot (ref 8, max 150) is
// -6 dB at 16 units, -18 dB at 64, -25 dB at 120 and silent past 150; the defaults (ref 4, max 64) suit
// footsteps, doors and pickups.
#include "core/math.h"

#include <algorithm>
#include <cmath>

namespace ks::audio {

inline constexpr float kDefaultRefDistance = 4.0f;
inline constexpr float kDefaultMaxDistance = 64.0f;
inline constexpr float kFadeStart = 0.75f; // fraction of max_distance where the fade to silence begins

inline float distance_gain(float distance, float ref_distance, float max_distance) {
    if (!std::isfinite(distance)) return 0.0f;
    const float ref = std::max(ref_distance, 0.01f);
    const float max = std::max(max_distance, ref);
    if (distance >= max) return 0.0f;
    const float inverse = ref / std::max(distance, ref);
    const float fade_from = kFadeStart * max;
    const float fade = distance <= fade_from ? 1.0f : (max - distance) / (max - fade_from);
    return inverse * fade;
}

// The back of the head: a sound behind the listener loses highs (head shadow), so front and back, which
// stereo panning alone cannot tell apart, sound different. The multiplier of the highs (the low-pass
// filter's GAINHF): 1 anywhere in front, falling with the angle to kRearGainHf straight behind.
inline constexpr float kRearGainHf = 0.6f;

// `forward`: the listener's unit view direction; `to_source`: from the listener to the sound.
inline float rear_highs(const Vec3& forward, const Vec3& to_source) {
    const float len = glm::length(to_source);
    if (!(len > 1e-4f) || !std::isfinite(len)) return 1.0f;
    const float cosine = glm::dot(forward, to_source) / len;
    return 1.0f - (1.0f - kRearGainHf) * std::clamp(-cosine, 0.0f, 1.0f);
}

} // namespace ks::audio
