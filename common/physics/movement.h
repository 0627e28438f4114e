#pragma once
// The movement engine: integration of one body's motion over a fixed step. Constant acceleration over a
// step is integrated exactly (x += v·dt + a·dt²/2, v += a·dt), so a jump's apex and landing do not depend
// on the step size beyond sampling; the render frame rate never enters (see World::advance).
#include "core/math.h"

namespace ks::physics {

struct MovementState {
    Vec3 velocity{0.0f};
    Vec3 acceleration{0.0f}; // besides gravity (e.g. an explosion's push), world units/s²
    float gravity = -25.0f;  // along y, the reference's value for player and robots
    float max_speed =
        1e4f; // cap on |velocity| (horizontal and vertical separately), keeps absurd input finite
};

// Advances velocity by one step and returns the displacement for that step.
Vec3 integrate(MovementState& state, float dt);

// Sanitises a state: non-finite components become 0 (a NaN from game code must not reach the world).
bool sanitize(MovementState& state);

} // namespace ks::physics
