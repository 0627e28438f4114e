#include "level/level.h"

#include "brush/brush_build.h"

#include <algorithm>
#include <utility>

namespace ks::level {
namespace {

constexpr std::array<std::string_view, static_cast<size_t>(EntityType::Count)> kTypeNames = {
    "wall",         "floor",         "stair", "door",    "floor_light", "top_light", "robot", "pickup",
    "gas_cylinder", "control_panel", "sound", "trigger", "spawner",     "message",   "brush", "model",
};

// Builds the variant alternative whose index is `index` (the EntityType order is the variant order).
template <size_t... I>
Props props_for_index(size_t index, std::index_sequence<I...>) {
    Props result;
    ((index == I ? (result = Props(std::in_place_index<I>), 0) : 0), ...);
    return result;
}

} // namespace

static_assert(std::variant_size_v<Props> == static_cast<size_t>(EntityType::Count),
              "every EntityType needs a props struct in the Props variant, in the same order");

std::string_view type_name(EntityType type) {
    const auto index = static_cast<size_t>(type);
    return index < kTypeNames.size() ? kTypeNames[index] : std::string_view("unknown");
}

bool type_from_name(std::string_view name, EntityType& out) {
    for (size_t i = 0; i < kTypeNames.size(); ++i) {
        if (kTypeNames[i] == name) {
            out = static_cast<EntityType>(i);
            return true;
        }
    }
    return false;
}

const std::array<EntityType, static_cast<size_t>(EntityType::Count)>& all_types() {
    static const auto types = [] {
        std::array<EntityType, static_cast<size_t>(EntityType::Count)> list{};
        for (size_t i = 0; i < list.size(); ++i) list[i] = static_cast<EntityType>(i);
        return list;
    }();
    return types;
}

Props default_props(EntityType type) {
    return props_for_index(static_cast<size_t>(type), std::make_index_sequence<std::variant_size_v<Props>>{});
}

const brush::Brush& default_brush() {
    static const brush::Brush box = [] {
        brush::FaceAttributes attributes;
        attributes.material = std::string(kDefaultBrushMaterial);
        const double h = kDefaultBrushHalfSize;
        return brush::make_box({-h, 0.0, -h}, {h, 2.0 * h, h}, attributes).value();
    }();
    return box;
}

Entity* Level::find(int id) {
    auto it = std::find_if(entities.begin(), entities.end(), [id](const Entity& e) { return e.id == id; });
    return it == entities.end() ? nullptr : &*it;
}

const Entity* Level::find(int id) const {
    return const_cast<Level*>(this)->find(id);
}

Entity& Level::add(EntityType type, Vec3 position, std::string name) {
    // next_id may lag behind ids that were set by hand; never hand out an id that is already taken.
    for (const Entity& e : entities) next_id = std::max(next_id, e.id + 1);
    Entity entity;
    entity.id = next_id++;
    entity.name =
        name.empty() ? std::string(type_name(type)) + " " + std::to_string(entity.id) : std::move(name);
    entity.position = position;
    entity.props = default_props(type);
    entities.push_back(std::move(entity));
    return entities.back();
}

} // namespace ks::level
