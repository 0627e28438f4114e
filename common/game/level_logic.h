#pragma once
// The level's logic at run time (docs/game.md, "Level logic"): the link table resolved at Game::create, the
// queue of actions waiting out their delay (in whole fixed steps), "once" links, the objectives, the
// triggers' and message's state. Within the game's step (after everything else has moved) it turns the
// step's events into link events and applies the actions through the other systems' interfaces (doors and
// lights, robots, spawners), so the logic is as deterministic as the rest of the game (logic_build.cpp,
// logic_step.cpp). Work per step is bounded: at most kMaxActionsPerStep actions run in one step (a
// zero-delay loop is cut off there and reported), at most kMaxPending wait.
#include "core/math.h"
#include "game/game_core.h"
#include "game/logic_record.h"
#include "game/spawners.h"
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

class LevelEdit; // live_carry.h
class Interactables;
class PlayerSystem;
class RobotSystem;

// What a resolved link acts on; its index is into the game's array of that kind (doors(), lights(),
// robots(), spawners()) or the logic's (triggers(), messages, sounds, objectives()).
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
    bool fired = false;              // a once link that has fired
    LogicEnd source_end, target_end; // for logic records: the link's owner and what it acts on
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

    // Actions reach the player, robots, doors and lights, and spawners through their systems.
    LevelLogic(GameCore& core, PlayerSystem& player, RobotSystem& robots, Interactables& interactables,
               Spawners& spawners);
    // Resolves the level's links, objectives, triggers, messages and sounds (after the other systems are
    // built: links name their records).
    void build(const level::Level& level);
    // The logic's part of a playing step: due actions, the level's on_start, the message's clock, trigger
    // volumes, then the cascade (this step's events become link events, ready actions run and set off more).
    void step(float dt);
    // Won when every objective is complete (after the spawners had their turn).
    void check_won();
    // Runs a link action now, as a link would (Game::run_action); false when the entity does not take it.
    bool run_action(level::LinkAction action, int target);
    bool complete_objective(std::string_view id);
    // Says a run-time problem once (logged, and kept in problems()).
    void report(std::string problem);
    // The live play-test's rebuild (live_carry.h, after the robots): objectives done, triggers, fired once
    // links, delayed actions still waiting whose link the edit kept, and the message on screen carry over;
    // a carried robot already dead does not die again.
    void carry_from(const LevelLogic& previous, const LevelEdit& edit);

    std::span<const ObjectiveState> objectives() const { return objectives_; }
    // The first objective not yet complete (the one the HUD shows), or -1.
    int current_objective() const;
    bool all_objectives_complete() const;
    std::span<const TriggerState> triggers() const { return triggers_; }
    std::span<const SpawnerState> spawners() const { return spawners_.spawners(); }
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
        // The heap's order: its front is the earliest due action, the first scheduled first.
        static bool later(const Pending& a, const Pending& b) {
            return a.due != b.due ? a.due > b.due : a.sequence > b.sequence;
        }
    };
    std::span<const Pending> pending() const { return pending_; }
    bool uses_locks() const { return uses_locks_; }

    // The observer hook (logic_record.h): this step's events and actions, in order, and any run between
    // steps since. Cleared by Game::step; the game never reads them.
    std::span<const LogicRecord> records() const { return records_; }
    void clear_records() { records_.clear(); }

  private:
    // Schedules every link in `range` whose event is `event`: a zero-delay link runs in this step, the
    // others wait in the queue. A fired once link is skipped.
    void fire(LinkRange range, level::LinkEvent event);
    void fire_entity(int entity_id, level::LinkEvent event);
    // Starts a step: the budget is refilled and the actions due now are ready, in due order.
    void begin_step();
    // Refills the budget with nothing ready (an action run between steps).
    void reset_budget();
    // The next action to run in this step, or false when none is ready or the budget is spent.
    bool next_ready(std::uint32_t& link);
    // Runs ready actions and what they set off until nothing is left (or the step's budget is spent); the
    // game's events from `cursor` on are new to the logic.
    void run_cascade(std::size_t cursor);
    void translate_events(std::size_t& cursor);
    void note_deaths();
    void test_triggers();
    bool trigger_holds(const TriggerState& t) const;
    void apply_action(const LogicLink& link);
    void record_event(LogicEnd source, level::LinkEvent event);
    void record_action(const LogicLink& link, int index);
    void complete_objective_at(std::size_t index);
    void check_kill_objectives();

    GameCore& core_;
    PlayerSystem& player_;
    RobotSystem& robots_;
    Interactables& interactables_;
    Spawners& spawners_;
    std::vector<LogicLink> links_;
    std::unordered_map<int, LinkRange> entity_links_; // by source entity id
    LinkRange level_links_;
    std::vector<ObjectiveState> objectives_;
    std::vector<TriggerState> triggers_;
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
    std::vector<LogicRecord> records_;
    std::vector<bool> robot_dead_; // by robot index: its on_death has been seen (grows with the robots)
    bool started_ = false;
    bool overflow_reported_ = false, pending_full_reported_ = false; // said once, not every step
    bool objectives_dirty_ = false; // a robot died: kill conditions may hold now
    bool uses_locks_ = false;       // a door starts locked or a link locks one: door locks are state
};

} // namespace ks::game
