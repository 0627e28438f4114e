#include "game/game_core.h"

#include <cmath>

namespace ks::game {

std::string entity_label(const level::Entity& e) {
    return std::string(level::type_name(e.type())) + " " + std::to_string(e.id) +
           (e.name.empty() ? std::string() : " (\"" + e.name + "\")");
}

GameCore::GameCore(const GameSettings& game_settings, std::uint64_t seed)
    : settings(game_settings), rng(seed), world(physics::WorldSettings{game_settings.step, 240}) {}

void GameCore::push(EventType type, Vec3 position, int entity, float amount, Vec3 end) {
    events.push_back({type, position, end, entity, amount, {}});
}

void GameCore::push_cue(EventType type, Vec3 position, int entity, std::string_view cue) {
    events.push_back({type, position, Vec3(0.0f), entity, 0.0f, cue});
}

void GameCore::set_phase(Phase next, const Vec3& player_feet) {
    if (phase == next) return;
    phase = next;
    phase_time = 0.0;
    if (next == Phase::Dead) push(EventType::PlayerDied, player_feet);
    if (next == Phase::Won) push(EventType::Won, player_feet);
}

bool GameCore::shoot_ray(const geometry::Ray& ray, physics::BodyId ignore, bool skip_robots,
                         physics::RayHit& hit) {
    physics::RayFilter filter(physics::layer::kShootable, ignore);
    if (skip_robots)
        filter.accept_user_data = [](std::uint64_t user) { return user_kind(user) != BodyKind::Robot; };
    return world.ray_closest(ray, hit, filter);
}

bool GameCore::line_blocked(const Vec3& from, const Vec3& to) const {
    const Vec3 d = to - from;
    const float len = glm::length(d);
    if (!(len > 1e-4f) || !std::isfinite(len)) return false;
    return world.ray_any({from, d / len, len}, physics::RayFilter(physics::layer::kBlocksSight));
}

} // namespace ks::game
