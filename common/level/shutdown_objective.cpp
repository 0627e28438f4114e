#include "level/shutdown_objective.h"

#include <algorithm>

namespace ks::level {

Link shutdown_link() {
    Link link;
    link.event = "on_use";
    link.target = kShutdownObjective;
    link.action = "complete";
    return link;
}

bool add_shutdown_objective(Level& level) {
    bool added = false, panel = false;
    const Link link = shutdown_link();
    for (Entity& e : level.entities) {
        if (e.type() != EntityType::ControlPanel) continue;
        panel = true;
        if (std::find(e.links.begin(), e.links.end(), link) != e.links.end()) continue;
        e.links.push_back(link);
        added = true;
    }
    if (!panel) return false; // nothing could complete it
    const bool has = std::any_of(level.objectives.begin(), level.objectives.end(),
                                 [](const Objective& o) { return o.id == kShutdownObjective; });
    if (!has) {
        level.objectives.push_back({kShutdownObjective, kShutdownObjectiveText, {}, {}});
        added = true;
    }
    return added;
}

} // namespace ks::level
