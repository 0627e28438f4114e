#pragma once
// The level's logic at run time (docs/game.md, "Level logic"): the link table resolved at Game::create, the
// queue of actions waiting out their delay (in whole fixed steps), "once" links, the objectives, the
// triggers', spawners' and message's state. This class is the bookkeeping and the state the HUD and the
// tests read; the Game applies the actions within its step (logic_step.cpp, spawners.cpp), so the logic is
// as deterministic as the rest of the game. Work per step is bounded: at most kMaxActionsPerStep actions
// run in one step (a zero-delay loop is cut off there and reported), at most kMaxPending wait.
#include "core/math.h"
#include "geometry/transform.h"
#include "level/level.h"
#include "level/logic_names.h"

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace ks::game {

// What a resolved link acts on; its index is into the game's array of that kind (doors(), lights(),
// robots()) or the logic's (triggers(), spawners(), messages, sounds, objectives()).
enum class LogicTarget : std::uint8_t {
    Door,
    Light,
    Trigger,
    Robot,
    Spawner,
    Message,
    Sound,
    Objective,
    Level
};

struct LogicLink {
    level::LinkEvent event = level::LinkEvent::OnStart;
    level::LinkAction action = level::LinkAction::Win;
    LogicTarget target = LogicTarget::Level;
    std::uint32_t target_index = 0;
    std::int64_t delay_steps = 0; // the link's delay rounded to whole steps
    bool once = false;
    bool fired = false; // a once link that has fired
};

struct LinkRange {
    std::uint32_t first = 0, count = 0;
};

struct ObjectiveState {
    std::string id, text;
    bool completed = false;
    bool kill_condition = false;              // it lists robots or spawners, all of which resolved
    std::vector<std::uint32_t> kill_robots;   // indices into Game::robots()
    std::vector<std::uint32_t> kill_spawners; // indices into LevelLogic::spawners()
    LinkRange links;                          // on_complete
};

enum class TriggerWho : std::uint8_t { Player, Robots, Both };

struct TriggerState {
    int entity_id = 0;
    geometry::Transform frame; // bottom centre, yaw only
    Vec3 size{0.0f};
    TriggerWho who = TriggerWho::Player;
    bool enabled = true;
    bool occupied = false; // someone it notices was inside at the last test
};

struct SpawnerState {
    int entity_id = 0;
    std::string name;
    level::RobotProps robot;
    Vec3 position{0.0f};
    float yaw_degrees = 0.0f;
    int count = 1, max_alive = 1;
    std::int64_t interval_steps = 0; // the interval rounded to whole steps
    int left = 0;                    // robots still to make in the current wave
    std::int64_t next_step = 0;      // the step from which the next may be made
    bool started = false;
    bool stuck = false; // no navigation mesh, or no walkable ground near it: it can never make a robot
    std::vector<std::uint32_t> robots; // indices into Game::robots() of those it made
};

struct MessageEntity {
    int entity_id = 0;
    std::string text;
    float duration = 0.0f;
};

// The message on screen: its text and how long it stays.
struct ShownMessage {
    int entity_id = -1;
    std::string_view text; // the message entity's, owned by the logic
    float duration = 0.0f;
    float time_left = 0.0f;
    bool visible() const { return time_left > 0.0f; }
};

struct SoundEntity {
    int entity_id = 0;
    std::string sound;
    Vec3 position{0.0f};
    float volume = 1.0f, radius = 40.0f;
};

class LevelLogic {
  public:
    static constexpr int kMaxActionsPerStep = 1024;
    static constexpr std::size_t kMaxPending = 4096;
    static constexpr std::size_t kMaxProblems = 32;
    static constexpr std::size_t kMaxRobots = 1024; // spawners stop making robots past this many in the game

    std::span<const ObjectiveState> objectives() const { return objectives_; }
    // The first objective not yet complete (the one the HUD shows), or -1.
    int current_objective() const;
    bool all_objectives_complete() const;
    std::span<const TriggerState> triggers() const { return triggers_; }
    std::span<const SpawnerState> spawners() const { return spawners_; }
    const ShownMessage& message() const { return message_; }
    std::span<const LogicLink> links() const { return links_; }
    // The links an entity's events fire (empty when it has none) and the level's own (on_start); an
    // objective's on_complete links are in its ObjectiveState. The bot reads these backward: which event
    // of which entity completes an objective, unlocks a door, starts a spawner.
    LinkRange entity_links(int entity_id) const {
        const auto it = entity_links_.find(entity_id);
        return it == entity_links_.end() ? LinkRange{} : it->second;
    }
    LinkRange level_links() const { return level_links_; }
    // Actions that were dropped: past kMaxActionsPerStep in one step (a zero-delay loop) or kMaxPending.
    std::int64_t dropped_actions() const { return dropped_; }
    // What went wrong at run time, each said once: dangling links in a level that was not validated, a
    // spawner with no ground to spawn on, a loop cut off.
    std::span<const std::string> problems() const { return problems_; }

    // Pending delayed actions (a heap on (due step, sequence)), for the state hash.
    struct Pending {
        std::int64_t due = 0;
        std::uint32_t sequence = 0, link = 0;
    };
    std::span<const Pending> pending() const { return pending_; }
    bool uses_locks() const { return uses_locks_; }

  private:
    friend class Game;

    // Schedules every link in `range` whose event is `event`: a zero-delay link runs in this step, the
    // others wait in the queue. A fired once link is skipped.
    void fire(LinkRange range, level::LinkEvent event, std::int64_t step);
    void fire_entity(int entity_id, level::LinkEvent event, std::int64_t step);
    // Starts a step: the budget is refilled and the actions due by `step` are ready, in due order.
    void begin_step(std::int64_t step);
    // Refills the budget with nothing ready (an action run between steps).
    void reset_budget();
    // The next action to run in this step, or false when none is ready or the budget is spent.
    bool next_ready(std::uint32_t& link);
    void report(std::string problem);

    std::vector<LogicLink> links_;
    std::unordered_map<int, LinkRange> entity_links_; // by source entity id
    LinkRange level_links_;
    std::vector<ObjectiveState> objectives_;
    std::vector<TriggerState> triggers_;
    std::vector<SpawnerState> spawners_;
    std::vector<MessageEntity> messages_;
    std::vector<SoundEntity> sounds_;
    ShownMessage message_;
    std::vector<Pending> pending_;
    std::vector<std::uint32_t> ready_;
    std::size_t ready_head_ = 0;
    int spent_ = 0; // actions run in this step
    std::uint32_t sequence_ = 0;
    std::int64_t dropped_ = 0;
    std::vector<std::string> problems_;
    std::vector<bool> robot_dead_; // by robot index: its on_death has been seen
    bool started_ = false;
    bool overflow_reported_ = false, pending_full_reported_ = false; // said once, not every step
    bool objectives_dirty_ = false; // a robot died: kill conditions may hold now
    bool uses_locks_ = false;       // a door starts locked or a link locks one: door locks are state
    int next_robot_id_ = 1;         // entity ids of spawned robots, after the level's
};

} // namespace ks::game
