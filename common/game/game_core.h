#pragma once
// The state every game system shares (game.h lists the systems): the settings, the seeded Rng (drawn in
// the step's fixed order), the physics World, the step's event list, the phase and the step count. The
// systems hold a reference to it; the Game owns it and clears the events at the start of each step.
#include "core/random.h"
#include "game/game_types.h"
#include "level/level.h"
#include "physics/world.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace ks::game {

// What a physics body belongs to (kept in BodyDesc::user_data as kind << 32 | index into its system's list).
enum class BodyKind : std::uint8_t {
    None,
    Player,
    Robot,
    Cylinder,
    DoorLeaf,
    DoorSensor,
    Pickup,
    Panel,
    Scenery
};
inline std::uint64_t pack_user(BodyKind kind, std::uint32_t index) {
    return static_cast<std::uint64_t>(kind) << 32 | index;
}
inline BodyKind user_kind(std::uint64_t user) {
    return static_cast<BodyKind>(user >> 32);
}
inline std::uint32_t user_index(std::uint64_t user) {
    return static_cast<std::uint32_t>(user);
}

// "robot 12 ("Guard")": how a body's errors name the level entity it was built from.
std::string entity_label(const level::Entity& e);

struct GameCore {
    GameCore(const GameSettings& game_settings, std::uint64_t seed);

    GameSettings settings;
    Rng rng;
    physics::World world;
    std::vector<Event> events; // this step's, in the order they happened
    Phase phase = Phase::Playing;
    double phase_time = 0.0;
    bool paused = false;
    std::int64_t steps = 0;

    bool playing() const { return phase == Phase::Playing; }
    void push(EventType type, Vec3 position = Vec3(0.0f), int entity = -1, float amount = 0.0f,
              Vec3 end = Vec3(0.0f));
    void push_cue(EventType type, Vec3 position, int entity, std::string_view cue);
    // Enters `next` (PlayerDied or Won at the player's feet); the phase clock restarts.
    void set_phase(Phase next, const Vec3& player_feet);
    // Closest shootable hit along a ray, skipping `ignore` and (for robot shots) every robot.
    bool shoot_ray(const geometry::Ray& ray, physics::BodyId ignore, bool skip_robots, physics::RayHit& hit);
    // Whether something that blocks sight lies on the straight line between two points.
    bool line_blocked(const Vec3& from, const Vec3& to) const;
};

} // namespace ks::game
