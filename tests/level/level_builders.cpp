#include "level_builders.h"

#include "brush/brush_build.h"
#include "level/level_io.h"
#include "level/logic_names.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace ks::test {
namespace {

using namespace ks::level;

// A float inside [lo, hi] with a random number of significant digits, or a full-precision one, or a tiny
// one: the shapes that shortest round-trip printing has to get right.
float random_float(Rng& rng, double lo, double hi) {
    const double span = hi - lo;
    switch (rng.below(4)) {
    case 0:
        return static_cast<float>(lo + span * rng.uniform_double()); // all 24 bits
    case 1: {                                                        // a short decimal such as 0.8 or 12.25
        const double scale = std::pow(10.0, rng.below(4));
        const double v = std::round((lo + span * rng.uniform_double()) * scale) / scale;
        return static_cast<float>(std::clamp(v, lo, hi));
    }
    case 2: { // small magnitudes near the low end of the range
        const double v =
            lo + span * std::pow(10.0, -static_cast<double>(rng.below(8))) * rng.uniform_double();
        return static_cast<float>(std::clamp(v, lo, hi));
    }
    default:
        return static_cast<float>(rng.chance(0.5f) ? lo : hi); // the range's own ends
    }
}

std::string random_name(Rng& rng) {
    static const char* const kPieces[] = {"Wall", "robot", "\"quoted\"",  "back\\slash", "tab\there",
                                          "Café", "Ä-ß",   "line\nbreak", "  spaces  ",  "{brace}",
                                          "",     "数字",  "#1"};
    std::string name;
    const int parts = static_cast<int>(rng.below(4));
    for (int i = 0; i < parts; ++i) name += kPieces[rng.below(std::size(kPieces))];
    return name;
}

class RandomFiller {
  public:
    explicit RandomFiller(Rng& rng) : rng_(rng) {}
    void field(float& v, const FieldInfo& info) { v = random_float(rng_, info.min, info.max); }
    void field(int& v, const FieldInfo& info) {
        v = static_cast<int>(info.min) +
            static_cast<int>(rng_.below(static_cast<std::uint32_t>(info.max - info.min) + 1));
    }
    void field(bool& v, const FieldInfo&) { v = rng_.chance(0.5f); }
    void field(std::string& v, const FieldInfo& info) {
        static const char* const kTextures[] = {"concrete", "wood", "tiles", "ceiling", "metal"};
        static const char* const kModels[] = {"door.gltf", "robot.gltf", "pickup_ammo.gltf"};
        v = std::string_view(info.name) == "texture" ? kTextures[rng_.below(5)]
            : std::string_view(info.name) == "file"  ? kModels[rng_.below(3)] // a shipped model
                                                     : random_name(rng_);
        if (v.empty() && info.min >= 1) v = "text"; // a message needs some
    }
    void field(Vec2& v, const FieldInfo& info) {
        for (int i = 0; i < 2; ++i) v[i] = random_float(rng_, info.min, info.max);
    }
    void field(Vec3& v, const FieldInfo& info) {
        for (int i = 0; i < 3; ++i) v[i] = random_float(rng_, info.min, info.max);
    }
    void field(Color& c, const FieldInfo&) {
        c = {static_cast<float>(rng_.below(256)) / 255.0f, static_cast<float>(rng_.below(256)) / 255.0f,
             static_cast<float>(rng_.below(256)) / 255.0f};
    }
    void field(Choice& v, const FieldInfo&) {
        v.value = v.options[rng_.below(static_cast<std::uint32_t>(v.options.size()))];
    }
    // A spelling the format accepts; "" (no sound) where the field allows it.
    void field(SoundName& v, const FieldInfo& info) {
        static const std::string kNames[] = {
            "machine_hum",  "vent_loop", "alarm_loop", "computer_beeps",
            "ambient_dojo", "x",         "a_2",        std::string(kMaxSoundNameLength, 'z')};
        v.value = info.min == 0 && rng_.chance(0.2f) ? "" : kNames[rng_.below(std::size(kNames))];
    }
    // Points are offsets from the robot (random_level adds its position): a patrol stays near its robot.
    // No points is no patrol, which the file leaves out whole: mode and wait then keep their defaults.
    void field(Patrol& v, const FieldInfo&) {
        v = {};
        v.points.resize(rng_.below(4));
        if (v.points.empty()) return;
        for (Vec3& p : v.points) p = {random_float(rng_, -20, 20), 0.0f, random_float(rng_, -20, 20)};
        field(v.mode, {"mode", ""});
        v.wait = random_float(rng_, 0, 5);
    }

    // A box of random size, often cut by a slanted plane of a random whole-number direction (normalised,
    // so its components are full-precision doubles), with random materials and mappings per face.
    void field(brush::Brush& v, const FieldInfo&) {
        static const char* const kMaterials[] = {"concrete", "wood", "tiles", "ceiling", "metal"};
        const double w = 0.5 + rng_.below(40) * 0.25, h = 0.5 + rng_.below(40) * 0.25;
        std::vector<brush::Face> faces = brush::make_box({-w, 0, -w}, {w, h, w}).value().faces();
        if (rng_.chance(0.6f)) {
            const DVec3 n = glm::normalize(DVec3(static_cast<double>(rng_.below(7)) - 3.0, 4.0,
                                                 static_cast<double>(rng_.below(7)) - 3.0));
            faces.push_back({{n, h * 0.75 * n.y}, {}});
        }
        for (brush::Face& f : faces) {
            f.attributes.material = kMaterials[rng_.below(5)];
            f.attributes.offset = {random_float(rng_, -8, 8), rng_.uniform_double() * 3};
            f.attributes.scale = {random_float(rng_, 0.25, 8), rng_.chance(0.5f) ? 1.0 : -2.5};
            f.attributes.rotation_degrees = rng_.chance(0.5f) ? 0.0 : random_float(rng_, -180, 180);
        }
        v = brush::Brush::from_faces(std::move(faces), brush::RedundantPlanes::drop).value();
    }

  private:
    Rng& rng_;
};

// Links between random entities, each to a target that takes its action: targets get unique names (a link
// target's name must be unique), and a locked door is always freed by some link.
void add_random_links(Rng& rng, Level& level) {
    std::vector<std::pair<size_t, LinkAction>> targets;
    for (size_t i = 0; i < level.entities.size(); ++i) {
        const auto actions = entity_actions(level.entities[i].type());
        const auto* robot = level.entities[i].try_as<RobotProps>();
        const auto* door = level.entities[i].try_as<DoorProps>();
        const bool must = door && door->locked; // else the checks warn that it can never open
        if (actions.empty() || (robot && robot->dummy) || (!must && !rng.chance(0.6f))) continue;
        level.entities[i].name = "target " + std::to_string(level.entities[i].id);
        targets.emplace_back(i, actions[rng.below(static_cast<std::uint32_t>(actions.size()))]);
    }
    for (auto& [i, action] : targets)
        if (auto* door = level.entities[i].try_as<DoorProps>(); door && door->locked)
            action = LinkAction::Unlock;
    if (targets.empty()) return;
    for (const auto& [i, action] : targets) {
        Link link{"on_start", level.entities[i].name, std::string(action_name(action)),
                  static_cast<float>(rng.below(8)) * 0.25f, rng.chance(0.5f)};
        // From the level, or from an entity that emits events (its first event).
        std::vector<size_t> sources;
        for (size_t k = 0; k < level.entities.size(); ++k)
            if (!entity_events(level.entities[k].type()).empty()) sources.push_back(k);
        if (sources.empty() || rng.chance(0.3f)) {
            level.links.push_back(std::move(link));
            continue;
        }
        Entity& source = level.entities[sources[rng.below(static_cast<std::uint32_t>(sources.size()))]];
        link.event = std::string(event_name(entity_events(source.type()).front()));
        source.links.push_back(std::move(link));
    }
}

} // namespace

Level level_with_every_type() {
    Level level;
    level.name = "Every type";
    level.settings.ambient_color = {1, 204 / 255.0f, 128 / 255.0f};
    level.settings.fog_density = 0.01f;
    level.settings.sun_direction = {0, -1, 0};
    level.settings.gravity = -9.81f;
    level.player_start = {{1.5f, 0.25f, -3}, 45};

    auto& wall = level.add(EntityType::Wall, {1, 2, 3}, "Wall").as<WallProps>();
    wall = {{7.5f, 11, 0.25f}, "wood", 3.3f};
    auto& floor = level.add(EntityType::Floor, {0, 16, 0}, "Ceiling").as<FloorProps>();
    floor = {{120, 200}, 0.75f, true, "ceiling", 1.5f};
    auto& stair = level.add(EntityType::Stair, {8, 0, -84}, "Stair").as<StairProps>();
    stair = {{12, 6, 12}, 12, "metal"};
    auto& door = level.add(EntityType::Door, {0, 0, -30}, "Door").as<DoorProps>();
    door = {6, 5.5f, true, 2.1f, 0.8f, true};
    auto& floor_light = level.add(EntityType::FloorLight, {7, 0, -6}, "Floor light").as<FloorLightProps>();
    floor_light = {{{1, 204 / 255.0f, 128 / 255.0f}, 0.8f, 20, false}, 40, 3.8f};
    auto& top_light = level.add(EntityType::TopLight, {0, 16, 20}, "Top light").as<TopLightProps>();
    top_light = {{{128 / 255.0f, 1, 1}, 1.25f, 30, true}, 1.5f};
    auto& robot = level.add(EntityType::Robot, {54, 6, -37}, "Robot").as<RobotProps>();
    robot = {150, 9, 7, 12, 18, 26, 0.8f, 0.65f, 12, 15, true, 6.5f, 24, {}};
    robot.patrol.points = {{54, 6, -37}, {60, 6, -37}, {60, 6, -31.5f}};
    robot.patrol.mode.value = "ping_pong";
    robot.patrol.wait = 1.5f;
    robot.dormant = true;
    auto& pickup = level.add(EntityType::Pickup, {-2, 6, -82}, "Pickup").as<PickupProps>();
    pickup.kind.value = "shield";
    pickup.amount = 25;
    auto& gas = level.add(EntityType::GasCylinder, {-5, 0, 12}, "Gas").as<GasCylinderProps>();
    gas = {0.6f, 2.2f, 35, 7.5f, 30};
    auto& panel = level.add(EntityType::ControlPanel, {90, 0, 50}, "Panel").as<ControlPanelProps>();
    panel.size = {3, 4.5f, 5};
    auto& sound = level.add(EntityType::Sound, {0, 14, -60}, "Vent").as<SoundProps>();
    sound = {{"vent_loop"}, 0.35f, 22.5f, false};
    level.settings.ambient_sound.value = "ambient_dojo";
    auto& trigger = level.add(EntityType::Trigger, {0, 0, -20}, "Hall trigger").as<TriggerProps>();
    trigger.size = {10, 5, 6.5f};
    trigger.who.value = "both";
    trigger.enabled = false;
    auto& spawner = level.add(EntityType::Spawner, {40, 0, -60}, "Hall spawner").as<SpawnerProps>();
    spawner.count = 5;
    spawner.interval = 1.5f;
    spawner.max_alive = 2;
    spawner.robot.health = 60;
    spawner.robot.hearing_radius = 45;
    level.add(EntityType::Message, {0, 2, 0}, "Welcome").as<MessageProps>() = {"Clear the \"hall\"", 6.5f};
    { // a ramp: a box cut by a slope of direction (0, 2, 1), faces with their own materials and mappings
        std::vector<brush::Face> faces = brush::make_box({-3, 0, -4}, {3, 4, 4}).value().faces();
        const DVec3 slope = glm::normalize(DVec3(0, 2, 1));
        faces.push_back({{slope, 4.0 * slope.y}, {}}); // through y = 4 over z = 0: down to y = 2 at z = 4
        for (size_t i = 0; i < faces.size(); ++i)
            faces[i].attributes = {
                i % 2 ? "metal" : "wood", {0.5 * double(i), -0.25}, {2, 0.75}, 15.0 * double(i)};
        level.add(EntityType::Brush, {-30, 0, 40}, "Ramp").as<BrushProps>().brush =
            brush::Brush::from_faces(std::move(faces)).value();
    }
    auto& model = level.add(EntityType::Model, {12, 0, -30}, "Console").as<ModelProps>();
    model.file = "floor_light.gltf";
    model.scale = 1.5f;
    model.collision.value = "box";
    int yaw = -144;
    for (Entity& e : level.entities) e.rotation = {static_cast<float>(yaw += 37), 0.5f, -1.25f};

    // Links on every kind of source, every kind of target; two objectives.
    auto link = [](const char* event, const char* target, const char* action, float delay = 0,
                   bool once = false) {
        return Link{event, target, action, delay, once};
    };
    auto named = [&](const char* name) -> Entity& {
        for (Entity& e : level.entities)
            if (e.name == name) return e;
        FAIL("no entity " << name);
        return level.entities.front();
    };
    named("Hall trigger").links = {link("on_enter", "Hall spawner", "spawn", 0.5f, true),
                                   link("on_exit", "Door", "close", 2.25f)};
    named("Robot").links = {link("on_death", "Welcome", "show"), link("on_alert", "Hall trigger", "disable")};
    named("Door").links = {link("on_open", "Floor light", "on")};
    named("Floor light").links = {link("on_use", "Top light", "toggle")};
    named("Panel").links = {link("on_use", "shutdown", "complete")};
    named("Pickup").links = {link("on_pickup", "Vent", "play", 1)};
    level.links = {link("on_start", "Hall trigger", "enable"), link("on_start", "Welcome", "show", 3, true)};
    level.objectives = {
        {"clear", "Clear the hall", {"Hall spawner"}, {link("on_complete", "Door", "unlock")}},
        {"shutdown", "Shut down the simulation", {}, {link("on_complete", "level", "win", 2)}}};
    return level;
}

Level random_level(Rng& rng, int entity_count) {
    Level level;
    level.name = random_name(rng);
    RandomFiller filler(rng);
    level.settings.visit(filler);
    // Unit length within 1e-4 (as the loader keeps it), never zero.
    Vec3 sun(random_float(rng, -1, 1), -0.5f - rng.uniform(), random_float(rng, -1, 1));
    level.settings.sun_direction = sun / glm::length(sun);
    level.player_start = {
        {random_float(rng, -1000, 1000), random_float(rng, -10, 50), random_float(rng, -1000, 1000)},
        random_float(rng, -360, 360)};

    std::vector<int> ids(static_cast<size_t>(entity_count));
    for (int i = 0; i < entity_count; ++i)
        ids[static_cast<size_t>(i)] = 1 + i * 3 + static_cast<int>(rng.below(3));
    for (size_t i = ids.size(); i > 1; --i)
        std::swap(ids[i - 1], ids[rng.below(static_cast<std::uint32_t>(i))]);

    for (int i = 0; i < entity_count; ++i) {
        Entity e;
        e.id = ids[static_cast<size_t>(i)];
        e.name = random_name(rng);
        e.position = {random_float(rng, -1e4, 1e4), random_float(rng, -100, 100),
                      random_float(rng, -1e4, 1e4)};
        e.rotation = {random_float(rng, -720, 720), random_float(rng, -90, 90), random_float(rng, -180, 180)};
        e.props =
            default_props(static_cast<EntityType>(rng.below(static_cast<std::uint32_t>(EntityType::Count))));
        std::visit([&](auto& props) { props.visit(filler); }, e.props);
        auto* spawner = e.try_as<SpawnerProps>();
        if (spawner) spawner->robot.dummy = false; // a spawner makes fighting robots
        RobotProps* robot = spawner ? &spawner->robot : e.try_as<RobotProps>();
        if (robot) // near the robot (or the spawner's robots): a patrol far outside the level is an error
            for (Vec3& p : robot->patrol.points) p += e.position;
        if (robot && robot->eye_radius_min > robot->eye_radius_max)
            std::swap(robot->eye_radius_min, robot->eye_radius_max);
        // A shipped model (3 to 9 units across) scaled into what validation calls a sensible size.
        if (auto* model = e.try_as<ModelProps>()) model->scale = std::clamp(model->scale, 0.1f, 100.0f);
        level.entities.push_back(std::move(e));
    }
    add_random_links(rng, level);
    // A disabled trigger with links that nothing enables is a warning (its links never fire).
    for (Entity& e : level.entities)
        if (auto* trigger = e.try_as<TriggerProps>(); trigger && !e.links.empty()) trigger->enabled = true;
    level.next_id = entity_count * 3 + 1 + static_cast<int>(rng.below(5));
    return level;
}

} // namespace ks::test

TEST_CASE("test builders: every type is present and off its defaults; random levels are valid and seeded") {
    using namespace ks::level;
    const Level every = ks::test::level_with_every_type();
    REQUIRE(every.entities.size() == all_types().size());
    for (size_t i = 0; i < every.entities.size(); ++i) {
        CHECK(every.entities[i].type() == all_types()[i]);
        CHECK_FALSE(every.entities[i].props == default_props(all_types()[i]));
    }
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        ks::Rng a(seed), b(seed);
        const Level first = ks::test::random_level(a, 30);
        CHECK(first == ks::test::random_level(b, 30));
        CHECK_MESSAGE(validate(first).diagnostics.empty(), validate(first).str());
    }
}
