// The bot's choice of goal (game/autoplay_goals.h) on small levels built in code: it chains backward from the
// first objective not complete to something it can walk to (a trigger, a panel, a floor light, a robot, a
// pickup, a door), works around locked doors (what unlocks them, or waiting beside them while a delayed link
// runs), and then plays each level through to the win.
#include "game/autoplay.h"
#include "game_test_levels.h"

using namespace ks;
using namespace ks::game;
using namespace ks::game_test;

namespace {

// A 96 x 88 floor (x -48..48, z -52..36), the player at z 20 facing -z: small, so both meshes build fast.
level::Level arena() {
    level::Level lv;
    lv.name = "arena";
    auto& floor = lv.add(level::EntityType::Floor, Vec3(0.0f, 0.0f, -8.0f), "ground");
    floor.as<level::FloorProps>().size = Vec2(96.0f, 88.0f);
    lv.player_start.position = Vec3(0.0f, 0.0f, 20.0f);
    return lv;
}

level::Objective objective(const char* id, std::vector<std::string> kill = {}) {
    level::Objective o;
    o.id = id;
    o.text = id;
    o.kill = std::move(kill);
    return o;
}

// A robot that stands still and never fights back, so a run's outcome depends on the bot alone.
level::Entity& add_harmless_robot(level::Level& lv, const char* name, Vec3 feet) {
    auto& r = add_robot(lv, feet);
    r.name = name;
    auto& props = r.as<level::RobotProps>();
    props.dormant = true;
    props.hit_probability = 0.0f;
    return r;
}

// 60 x 80 ground (z -40..40), the player at z 30 facing -z, a wall across z 0 whose only way through is a
// door in the middle ("Gate", id returned through `door`), and a control panel beyond it at z -25.
level::Level divided_level(bool locked, int& door, int& panel) {
    level::Level lv;
    lv.name = "divided";
    lv.add(level::EntityType::Floor, Vec3(0.0f), "ground").as<level::FloorProps>().size = Vec2(60.0f, 80.0f);
    lv.player_start.position = Vec3(0.0f, 0.0f, 30.0f);
    add_wall(lv, Vec3(-16.25f, 0, 0), Vec3(27.5f, 16, 0.5f));
    add_wall(lv, Vec3(16.25f, 0, 0), Vec3(27.5f, 16, 0.5f));
    add_wall(lv, Vec3(0, 5, 0), Vec3(5, 11, 0.5f));
    auto& d = lv.add(level::EntityType::Door, Vec3(0.0f), "Gate");
    d.as<level::DoorProps>().locked = locked;
    door = d.id;
    auto& p = lv.add(level::EntityType::ControlPanel, Vec3(0, 0, -25), "Panel");
    p.links = {link("on_use", "shutdown", "complete")};
    panel = p.id;
    lv.objectives.push_back(objective("shutdown"));
    return lv;
}

struct Played {
    std::unique_ptr<Game> game;
    std::unique_ptr<Autoplay> bot;
};

Played start(const level::Level& lv, std::uint64_t seed = 1) {
    auto g = make_game(lv, seed);
    auto bot = Autoplay::create(lv, *g, seed);
    if (!bot) FAIL(bot.error().str());
    Played p{std::move(g), std::make_unique<Autoplay>(std::move(*bot))};
    p.game->step(p.bot->decide(*p.game)); // the first decision chooses the goal
    return p;
}

// Plays on until the game ends or `seconds` pass; returns whether it was won.
bool play(Played& p, double seconds) {
    const auto steps = static_cast<int>(seconds * 120);
    for (int i = 0; i < steps && p.game->phase() == Phase::Playing; ++i) p.game->step(p.bot->decide(*p.game));
    return p.game->phase() == Phase::Won;
}

void check_goal(const Autoplay& bot, BotGoalKind kind, int entity) {
    CAPTURE(goal_kind_name(bot.goal().kind));
    CAPTURE(bot.goal().entity_id);
    CHECK(bot.goal().kind == kind);
    CHECK(bot.goal().entity_id == entity);
}

} // namespace

TEST_CASE("the bot walks into the trigger whose on_enter completes the objective") {
    auto lv = arena();
    const int gate = add_trigger(lv, "Gate", Vec3(10, 0, -10), Vec3(4, 4, 4)).id;
    lv.entities.back().links = {link("on_enter", "reach", "complete")};
    lv.add(level::EntityType::ControlPanel, Vec3(-10, 0, 0), "Decoy panel"); // completes nothing
    lv.objectives.push_back(objective("reach"));
    auto p = start(lv);
    check_goal(*p.bot, BotGoalKind::Enter, gate);
    CHECK(play(p, 10.0));
    CHECK(p.game->time() < 4.0); // straight there (34 units at 15 units/s), no detour to the panel
}

TEST_CASE(
    "a kill list's spawner that has not spawned: the bot enters the trigger that spawns it, then hunts") {
    auto lv = arena();
    const int gate = add_trigger(lv, "Gate", Vec3(0, 0, 0), Vec3(8, 4, 4)).id;
    lv.entities.back().links = {link("on_enter", "Pit", "spawn", 0.5f, true)};
    auto& spawner = lv.add(level::EntityType::Spawner, Vec3(0, 0, -30), "Pit");
    auto& props = spawner.as<level::SpawnerProps>();
    props.count = 2;
    props.interval = 1.0f;
    props.robot.hit_probability = 0.0f;
    lv.objectives.push_back(objective("clear", {"Pit"}));
    auto p = start(lv);
    check_goal(*p.bot, BotGoalKind::Enter, gate);
    // Inside the trigger the spawn is due in 0.5 s: the bot waits for it, then goes after the robots.
    bool waited = false;
    for (int i = 0; i < 120 * 10 && p.game->phase() == Phase::Playing; ++i) {
        p.game->step(p.bot->decide(*p.game));
        waited = waited || p.bot->goal().kind == BotGoalKind::Wait;
    }
    CHECK(waited);
    CHECK(p.game->phase() == Phase::Won);
    REQUIRE(p.game->robots().size() == 2);
    for (const Robot& r : p.game->robots()) CHECK_FALSE(r.alive()); // won as the last one fell
}

TEST_CASE("a panel behind a locked door: the bot uses the floor light that unlocks it, then the panel") {
    int door = 0, panel = 0;
    auto lv = divided_level(true, door, panel);
    auto& lamp = lv.add(level::EntityType::FloorLight, Vec3(20, 0, 25), "Switch");
    lamp.links = {link("on_use", "Gate", "unlock")};
    auto p = start(lv);
    check_goal(*p.bot, BotGoalKind::Use, lamp.id);
    bool went_for_panel = false;
    for (int i = 0; i < 120 * 20 && p.game->phase() == Phase::Playing; ++i) {
        p.game->step(p.bot->decide(*p.game));
        if (p.bot->goal().kind == BotGoalKind::Use && p.bot->goal().entity_id == panel) {
            went_for_panel = true;
            CHECK_FALSE(p.game->doors()[0].locked);
        }
    }
    CHECK(went_for_panel);
    CHECK(p.game->phase() == Phase::Won);
    CHECK(p.game->doors()[0].progress > 0.0f); // it opened the door with E on the way
}

TEST_CASE("a locked door with a delayed unlock under way: the bot waits in front of it on its own side") {
    int door = 0, panel = 0;
    auto lv = divided_level(true, door, panel);
    lv.links = {link("on_start", "Gate", "unlock", 4.0f), link("on_start", "Gate", "open", 4.0f)};
    auto p = start(lv);
    p.game->step(p.bot->decide(*p.game)); // the level's on_start ran in the first step: now it is due
    CHECK(p.bot->goal().kind == BotGoalKind::Wait);
    CHECK(p.bot->goal().point.z > 0.0f); // the player's side of the wall
    CHECK(p.bot->goal().point.z < 5.0f);
    CHECK(std::abs(p.bot->goal().point.x) < 2.0f);
    for (int i = 0; i < 120 * 3; ++i) p.game->step(p.bot->decide(*p.game));
    CHECK(p.game->doors()[0].locked);
    CHECK(p.game->player().feet.z > 0.0f); // still waiting, not pressing E at a locked door
    CHECK(count_events(*p.game, EventType::LockedDoorUsed) == 0);
    CHECK(play(p, 10.0));
    CHECK(p.game->time() > 4.0);
}

TEST_CASE("a locked door nothing opens: the bot waits beside it and never presses E there") {
    int door = 0, panel = 0;
    auto lv = divided_level(true, door, panel);
    auto p = start(lv);
    CHECK(p.bot->goal().kind == BotGoalKind::Wait);
    int locked_uses = 0;
    for (int i = 0; i < 120 * 8; ++i) {
        p.game->step(p.bot->decide(*p.game));
        locked_uses += count_events(*p.game, EventType::LockedDoorUsed);
    }
    CHECK(locked_uses == 0);
    CHECK(p.game->phase() == Phase::Playing);
    CHECK(glm::length(Vec2(p.game->player().feet.x, p.game->player().feet.z - 3.0f)) < 1.5f);
}

TEST_CASE("an unlocked door whose on_open completes the objective: the bot opens it") {
    int door = 0, panel = 0;
    auto lv = divided_level(false, door, panel);
    lv.entities[static_cast<std::size_t>(door - 1)].links = {link("on_open", "opened", "complete")};
    lv.objectives.insert(lv.objectives.begin(), objective("opened"));
    auto p = start(lv);
    check_goal(*p.bot, BotGoalKind::OpenDoor, door);
    CHECK(play(p, 20.0));
    CHECK(p.game->logic().objectives()[0].completed);
}

TEST_CASE("a robot's on_death completes the objective: the bot hunts that robot, not the nearer one") {
    auto lv = arena();
    add_harmless_robot(lv, "Bystander", Vec3(-44, 0, 20)); // farther than the bot engages
    const int target = add_harmless_robot(lv, "Target", Vec3(30, 0, -40)).id;
    lv.entities.back().links = {link("on_death", "kill", "complete")};
    lv.objectives.push_back(objective("kill"));
    auto p = start(lv);
    check_goal(*p.bot, BotGoalKind::Hunt, target);
    CHECK(play(p, 20.0));
}

TEST_CASE("a pickup's on_pickup completes the objective; a disabled trigger is enabled by the panel first") {
    auto lv = arena();
    auto& medkit = lv.add(level::EntityType::Pickup, Vec3(15, 0, 0), "Medkit");
    medkit.as<level::PickupProps>().kind.value = "shield"; // taken: the player starts without a shield
    medkit.links = {link("on_pickup", "take", "complete")};
    const int medkit_id = medkit.id;
    auto& gate = add_trigger(lv, "Gate", Vec3(-15, 0, -15), Vec3(4, 4, 4));
    gate.as<level::TriggerProps>().enabled = false;
    gate.links = {link("on_enter", "reach", "complete")};
    const int gate_id = gate.id;
    auto& panel = lv.add(level::EntityType::ControlPanel, Vec3(0, 0, -30), "Panel");
    panel.links = {link("on_use", "Gate", "enable")};
    const int panel_id = panel.id;
    lv.objectives = {objective("take"), objective("reach")};
    auto p = start(lv);
    check_goal(*p.bot, BotGoalKind::Pickup, medkit_id);
    bool used_panel = false, entered = false;
    for (int i = 0; i < 120 * 20 && p.game->phase() == Phase::Playing; ++i) {
        p.game->step(p.bot->decide(*p.game));
        used_panel =
            used_panel || (p.bot->goal().kind == BotGoalKind::Use && p.bot->goal().entity_id == panel_id);
        entered = entered || (p.bot->goal().kind == BotGoalKind::Enter && p.bot->goal().entity_id == gate_id);
    }
    CHECK(used_panel);
    CHECK(entered);
    CHECK(p.game->phase() == Phase::Won);
}

TEST_CASE("objectives that complete only each other: the bot stops looking and falls back to the panel") {
    auto lv = arena();
    auto a = objective("a"), b = objective("b");
    a.links = {link("on_complete", "b", "complete")};
    b.links = {link("on_complete", "a", "complete")};
    lv.objectives = {a, b};
    const int panel = lv.add(level::EntityType::ControlPanel, Vec3(0, 0, -10), "Panel").id;
    auto p = start(lv);
    check_goal(*p.bot, BotGoalKind::Use, panel);
    CHECK_FALSE(play(p, 3.0)); // the panel completes nothing here
}

TEST_CASE("a health pickup at full health cannot be taken, so it is no goal until the player is hurt") {
    auto lv = arena();
    auto& medkit = lv.add(level::EntityType::Pickup, Vec3(15, 0, 0), "Medkit");
    medkit.links = {link("on_pickup", "heal", "complete")};
    const int medkit_id = medkit.id;
    lv.objectives.push_back(objective("heal"));
    auto p = start(lv);
    CHECK(p.bot->goal().kind == BotGoalKind::None);
    p.game->damage_player(30.0f);
    for (int i = 0; i < 130; ++i) p.game->step(p.bot->decide(*p.game)); // the next choice, within a second
    check_goal(*p.bot, BotGoalKind::Pickup, medkit_id);
    CHECK(play(p, 10.0));
}

TEST_CASE("a floor lamp beside a door that E would reach first: the bot steps up to the door and opens it") {
    // Found building levels/lockdown.json: in the door's sensor, 8 from the door, E's target was the lamp
    // 5 away, so the bot stood waiting to face a door it could not use.
    int door = 0, panel = 0;
    auto lv = divided_level(false, door, panel);
    lv.add(level::EntityType::FloorLight, Vec3(-5, 0, 5), "Lamp beside the door").rotation.x = -30.0f;
    auto p = start(lv);
    check_goal(*p.bot, BotGoalKind::Use, panel);
    int lamp_toggles = 0;
    for (int i = 0; i < 120 * 15 && p.game->phase() == Phase::Playing; ++i) {
        p.game->step(p.bot->decide(*p.game));
        lamp_toggles += count_events(*p.game, EventType::LightToggled);
    }
    CHECK(p.game->phase() == Phase::Won);
    CHECK(lamp_toggles == 0);
}
