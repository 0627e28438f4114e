#pragma once
// The viewport's link arrows, window-free: one arrow from each entity to each entity its links name (several
// links between the same two entities share it and list their labels), drawn as a curve lifted above the
// straight line from the source's box to the target's (two entities linking each other get two curves, one to
// each side) with a head at the target. Links to objectives and the level are not drawn (the inspector lists
// them); a target that names no entity, or several, has no arrow, nor does a link from an entity to itself.
#include "level/level.h"
#include "view/sound_marker.h"

#include <functional>
#include <string>
#include <vector>

namespace ks::editor {

// How an arrow stands to the selection: leaving a selected entity, arriving at one, or neither (faint).
enum class ArrowRole { Other, Outgoing, Incoming };

struct LinkArrow {
    int source_id = 0, target_id = 0;
    ArrowRole role = ArrowRole::Other;
    std::vector<std::string> labels; // "on_enter -> spawn", one per link, in the source's link order
    Vec3 from{0.0f}, to{0.0f};       // where the curve leaves the source's box and enters the target's
    Vec3 control{0.0f};              // the quadratic curve's control point
    Vec3 point_at(float t) const;    // on the curve, t in 0 .. 1
    Vec3 middle() const { return point_at(0.5f); }
};

// Every arrow between two entities that `shown` accepts; `selected` decides the roles.
std::vector<LinkArrow> link_arrows(const level::Level& level, const std::vector<int>& selected,
                                   const std::function<bool(const level::Entity&)>& shown);

// The arrow's lines: the curve in `segments` pieces, then a four-line head whose tip is `to`.
void arrow_lines(const LinkArrow& arrow, int segments, std::vector<MarkerLine>& out);

} // namespace ks::editor
