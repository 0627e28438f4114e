#pragma once
// What the autoplay bot does next (docs/game.md, "Autoplay bot"). It reads the level's logic backward from
// the first objective not yet complete: an objective completes by a `complete` link from some entity's
// event, or by its kill list; an event happens when the bot does something (uses a panel or floor light,
// walks into a trigger, kills a robot, takes a pickup, opens a door) or when another link acts (a spawner
// spawns, a door unlocks, a trigger is enabled), which it chains back the same way. Every way found ends in
// a goal the bot can walk to; the nearest along the mesh wins, and waiting (for a delayed link, a spawner's
// next robot) only when nothing can be done. The bot's mesh has every door open, so a goal behind a locked
// door becomes what unlocks or opens that door, or a wait beside it. It reads only the game's state.
#include "game/game.h"
#include "nav/nav_mesh.h"

#include <cstdint>
#include <span>
#include <vector>

namespace ks::game {

enum class BotGoalKind : std::uint8_t {
    None,     // nothing to do
    Use,      // walk to a control panel or floor light and press E on it
    Enter,    // walk into a trigger's box
    Hunt,     // walk toward a robot; the bot shoots it once it is in sight
    Pickup,   // walk onto a pickup
    OpenDoor, // walk to a closed, unlocked door and press E
    Wait,     // walk to `point` and stand: what is needed is under way, or nothing can be done
};
const char* goal_kind_name(BotGoalKind kind);

struct BotGoal {
    BotGoalKind kind = BotGoalKind::None;
    int entity_id = -1; // what the goal acts on; -1 for a wait
    Vec3 point{0.0f};   // where to walk, on the bot's mesh
    // A goal that moves (a hunted robot) stays the same goal: the bot does not drop its plan for it.
    bool same_target(const BotGoal& other) const {
        return kind == other.kind && entity_id == other.entity_id;
    }
};

// A door the bot cannot pass: closed or closing, and locked, so E does nothing (a link may still open it).
bool door_blocks(const Door& door);
// Sets the bot mesh's doors as the game has them for the bot: blocking doors closed, every other open (it
// opens those with E). Returns whether any door blocks.
bool close_blocking_doors(const Game& game, nav::NavMesh& mesh);

class GoalPlanner {
  public:
    // Indexes which entity's event (or which objective's completion, or the level's start) fires each of
    // the game's links. The links never change after Game::create, so this holds for the whole game.
    explicit GoalPlanner(const Game& game);

    // The goal for now. Leaves the mesh's doors as close_blocking_doors sets them.
    BotGoal choose(const Game& game, nav::NavMesh& mesh);

  private:
    enum class SourceKind : std::uint8_t {
        None,
        Door,
        Light,
        Panel,
        Pickup,
        Robot,
        Trigger,
        Objective,
        Level
    };
    struct Source {
        SourceKind kind = SourceKind::None;
        std::uint32_t index = 0; // into the game's (or the logic's) array of that kind
    };
    struct Search; // one choose(): the game, the mesh, the best goal so far

    void objective(Search& s, std::size_t index, int depth) const;
    // Ways to make a link do one of `actions` to the target; `wait_at` is where to wait when one is due.
    void action_on(Search& s, LogicTarget target, std::uint32_t index,
                   std::span<const level::LinkAction> actions, const Vec3& wait_at, int depth) const;
    void cause(Search& s, const Source& source, level::LinkEvent event, int depth) const;
    void hunt(Search& s, std::uint32_t robot, int depth) const;
    // A goal at a point: kept when the bot can walk there, else what opens the locked door in the way.
    void consider(Search& s, BotGoal goal, int depth) const;
    void door_in_the_way(Search& s, const BotGoal& goal, int depth) const;
    // Where to wait for a locked door to open: in front of it, on the side of `from`.
    Vec3 door_wait_point(Search& s, const Door& door, const Vec3& from) const;
    void offer(Search& s, const BotGoal& goal, float cost) const;

    std::vector<Source> sources_; // parallel to LevelLogic::links()
    // Scratch kept between choices, so choosing allocates nothing once they have grown.
    std::vector<std::uint64_t> expanded_;
    std::vector<Vec3> path_;
};

} // namespace ks::game
