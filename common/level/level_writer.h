#pragma once
// Level -> JSON in the one key order the format defines (see docs/level-format.md): format, version, name,
// settings, player_start, next_id, objectives, links, entities; each entity id, type, name, position,
// rotation, props, links; props in their visit() order. Every field is written, defaults included, so a file
// never depends on today's defaults -- but for the fields added after version 1 (marked omitted_at_default)
// and the logic's lists, which are left out while default or empty.
#include "level/level.h"

#include <nlohmann/json.hpp>

namespace ks::level {

nlohmann::ordered_json write_level(const Level& level);
nlohmann::ordered_json write_entity(const Entity& entity);
// Settings::sun_direction is kept unit length: scaled to length 1 only when it is off by more than 1e-4, so
// normalising twice changes nothing and load -> save -> load -> save stays byte-identical. Zero and
// non-finite vectors are returned unchanged (validation reports them).
Vec3 normalized_direction(Vec3 direction);
// "#rrggbb", components clamped to 0..1 and rounded to 8 bits.
std::string color_to_hex(const Color& color);

} // namespace ks::level
