// A level's scenery and its comparison (scenery.h).
#include "level/scenery.h"

namespace ks::level {
namespace {

// The props with the switches the game sets every frame put at one value.
Props without_switches(const Props& props) {
    Props out = props;
    if (auto* door = std::get_if<DoorProps>(&out)) {
        door->open = false;
        door->locked = false;
    } else if (auto* floor_light = std::get_if<FloorLightProps>(&out)) {
        floor_light->light.on = true;
    } else if (auto* top_light = std::get_if<TopLightProps>(&out)) {
        top_light->light.on = true;
    }
    return out;
}

bool same_scenery_entity(const Entity& a, const Entity& b) {
    if (a.id != b.id || a.position != b.position || a.rotation != b.rotation || a.type() != b.type())
        return false;
    if (a.props == b.props) return true;
    return without_switches(a.props) == without_switches(b.props);
}

// What render::environment_from_settings reads: light and fog (not gravity, not the ambient sound).
bool same_light_settings(const Settings& a, const Settings& b) {
    return a.ambient_color == b.ambient_color && a.ambient_intensity == b.ambient_intensity &&
           a.fog_color == b.fog_color && a.fog_density == b.fog_density &&
           a.sun_direction == b.sun_direction && a.sun_color == b.sun_color &&
           a.sun_intensity == b.sun_intensity;
}

} // namespace

bool is_scenery(EntityType type) {
    switch (type) {
    case EntityType::Wall:
    case EntityType::Floor:
    case EntityType::Stair:
    case EntityType::Door:
    case EntityType::FloorLight:
    case EntityType::TopLight:
    case EntityType::ControlPanel:
    case EntityType::Brush:
    case EntityType::Model:
        return true;
    case EntityType::Robot:
    case EntityType::Pickup:
    case EntityType::GasCylinder:
    case EntityType::Sound:
    case EntityType::Trigger:
    case EntityType::Spawner:
    case EntityType::Message:
    case EntityType::Count:
        return false;
    }
    return false;
}

bool same_scenery(const Level& a, const Level& b) {
    if (!same_light_settings(a.settings, b.settings)) return false;
    auto next = [](const Level& level, std::size_t& i) -> const Entity* {
        while (i < level.entities.size() && !is_scenery(level.entities[i].type())) ++i;
        return i < level.entities.size() ? &level.entities[i++] : nullptr;
    };
    std::size_t i = 0, k = 0;
    for (;;) {
        const Entity* x = next(a, i);
        const Entity* y = next(b, k);
        if (!x || !y) return x == y;
        if (!same_scenery_entity(*x, *y)) return false;
    }
}

} // namespace ks::level
