#pragma once
// The feedback's muzzle flashes (runtime/model/feedback.h) as the renderer's lights: dynamic point lights
// (not in the light map: the fast path adds them to baked walls per pixel), put at the front of the frame's
// lights, as the renderer keeps the first lights in view when there are too many. Inline, like
// event_particles.h, because tests/runtime/test_play_feedback.cpp checks it and the tests link no
// runtime/app object.
#include "render/scene.h"
#include "runtime/model/feedback.h"

#include <array>
#include <vector>

namespace ks::runtime {

// A muzzle flash's light as a render::Light.
inline render::Light point_light(const feedback::MuzzleLight& m) {
    render::Light l;
    l.type = render::Light::Type::Point;
    l.position = m.position;
    l.color = m.color;
    l.intensity = m.intensity;
    l.range = m.range;
    l.dynamic = true; // not in the light map: the fast path adds it to baked walls per pixel
    return l;
}

// Puts the live muzzle lights at the front of `lights`; allocates nothing once `lights` has room.
inline void add_muzzle_lights(const feedback::Feedback& feedback, std::vector<render::Light>& lights,
                              float extra) {
    std::array<feedback::MuzzleLight, feedback::Feedback::kMaxLights> live;
    const std::size_t n = feedback.muzzle_lights(live, extra);
    lights.insert(lights.begin(), n, render::Light{});
    for (std::size_t i = 0; i < n; ++i) lights[i] = point_light(live[i]);
}

} // namespace ks::runtime
