#pragma once
// The HUD's hit feedback over the crosshair: the hit marker when a shot hits a robot, and the red arcs on a
// ring round the crosshair pointing where damage came from (feedback::Feedback::damage_arcs).
#include "runtime/model/feedback.h"

#include <span>

struct ImDrawList;

namespace ks::runtime {

// Four short diagonal strokes round the crosshair, white with a dark edge so they read on any background,
// a little larger at the hit and fading with `strength` (0..1).
void draw_hit_marker(ImDrawList* draw, float strength, float w, float h);
// One red arc per source, centred on its angle (clockwise from up), with a notch pointing outward.
void draw_damage_arcs(ImDrawList* draw, std::span<const feedback::DamageArc> arcs, float w, float h);

} // namespace ks::runtime
