// The live play-test's rebuild (live_update.h): a new game on the edited level, then the running game's
// state of every entity that still exists carried in by the game and its systems (live_carry.h), with the
// rule the header states.
#include "game/live_update.h"

#include "game/live_carry.h"
#include "nav/nav_mesh.h"

#include <memory>

namespace ks::game {
namespace {

// What the navigation mesh is built from (nav/nav_input.cpp): doors, brushes, models and every entity with
// a solid shape.
bool shapes_navigation(const level::Entity& e) {
    const auto type = e.type();
    return type == level::EntityType::Door || type == level::EntityType::Brush ||
           type == level::EntityType::Model || level::static_solid_shape(e).has_value();
}

// The edit left the mesh's input as it was: the same solids, in the same order, with the same place and
// props (names and links do not matter to it), and the same level settings.
bool same_navigation_input(const level::Level& a, const level::Level& b) {
    if (!(a.settings == b.settings)) return false;
    auto next = [](const level::Level& lv, std::size_t& i) -> const level::Entity* {
        while (i < lv.entities.size() && !shapes_navigation(lv.entities[i])) ++i;
        return i < lv.entities.size() ? &lv.entities[i++] : nullptr;
    };
    std::size_t i = 0, k = 0;
    for (;;) {
        const level::Entity* x = next(a, i);
        const level::Entity* y = next(b, k);
        if (!x || !y) return x == y;
        if (x->id != y->id || x->position != y->position || x->rotation != y->rotation ||
            !(x->props == y->props))
            return false;
    }
}

} // namespace

std::string LiveRebuild::summary() const {
    return std::to_string(kept) + " entities kept their state, " + std::to_string(added) + " added, " +
           std::to_string(removed) + " removed";
}

Result<LiveRebuild> rebuild_for_edit(const Game& running, const level::Level& before,
                                     const level::Level& edited, GameOptions options) {
    // An edit that left the solids alone (robots, lights, links, spawners, triggers...) keeps the mesh:
    // the build copies the running game's (a view of it, not owned: it is copied before create returns).
    // One that moved a wall builds again only the tiles the change touches; the rest are copied.
    if (!options.navigation && running.navigation()) {
        if (same_navigation_input(before, edited)) {
            options.navigation =
                std::shared_ptr<const nav::NavMesh>(std::shared_ptr<void>(), running.navigation());
        } else if (auto rebuilt = nav::NavMesh::rebuild(*running.navigation(), before, edited)) {
            options.navigation = std::move(*rebuilt);
        }
    }
    auto built = Game::create(edited, std::move(options));
    if (!built) return built.error();
    LiveRebuild out;
    out.game = std::move(*built);
    const LevelEdit edit(before, edited);
    out.kept = out.game->carry_from(running, edit);
    for (const level::Entity& e : edited.entities) out.added += edit.existed(e.id) ? 0 : 1;
    for (const level::Entity& e : before.entities) out.removed += edit.remains(e.id) ? 0 : 1;
    return out;
}

} // namespace ks::game
