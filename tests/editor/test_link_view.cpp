// The logic UI's window-free parts: what the link rows offer (events, targets, actions, picks), the
// viewport's link arrows (which links get one, their roles, their ends on the boxes) and the logic entities'
// markers.
#include "editor_test_util.h"
#include "level/entity_shapes.h"
#include "view/link_arrows.h"
#include "view/link_options.h"
#include "view/link_problems.h"
#include "view/logic_markers.h"

#include <algorithm>

using namespace ks;
using namespace ks::editor;

using editor_test::all_shown;

namespace {
level::Level logic_hall() {
    auto loaded = level::load_level_file(test::source_dir() / "tests/data/levels/logic_hall.json");
    REQUIRE_MESSAGE(loaded.ok(), (loaded.ok() ? std::string() : loaded.error().str()));
    return *loaded;
}

const level::Entity& named(const level::Level& level, const std::string& name) {
    for (const auto& e : level.entities)
        if (e.name == name) return e;
    FAIL("no entity named " << name);
    return level.entities.front();
}

const LinkArrow* arrow_between(const std::vector<LinkArrow>& arrows, int from, int to) {
    for (const auto& a : arrows)
        if (a.source_id == from && a.target_id == to) return &a;
    return nullptr;
}
} // namespace

TEST_CASE("link targets: objectives, the level, then every entity that takes an action, unnamed ones too") {
    level::Level level = logic_hall();
    level::Entity& light = level.add(level::EntityType::FloorLight, Vec3(5, 0, 5));
    light.name.clear(); // as in a file that names it not
    const auto options = target_options(level);
    REQUIRE(options.size() >= 4);
    CHECK(options[0].kind == level::TargetKind::Objective);
    CHECK(options[0].target == "clear_hall");
    CHECK(options[1].target == "shutdown");
    CHECK(options[2].kind == level::TargetKind::Level);
    CHECK(options[2].target == "level");
    auto find = [&](const std::string& label) {
        return std::find_if(options.begin(), options.end(),
                            [&](const TargetOption& o) { return o.label == label; });
    };
    CHECK(find("Exit door (door)") != options.end());
    CHECK(find("Hall spawner (spawner)") != options.end());
    CHECK(find("Welcome (message)") != options.end());
    CHECK(find("Hall lamp (top_light)") != options.end());
    const auto unnamed = find("floor_light #" + std::to_string(light.id) + " (unnamed)");
    REQUIRE(unnamed != options.end());
    CHECK(unnamed->entity_id == light.id);
    CHECK(unnamed->target.empty());
    // Walls, floors and the control panel take no action: never offered.
    CHECK(find("North wall (wall)") == options.end());
    CHECK(find("Ground (floor)") == options.end());
    CHECK(find("Control panel (control_panel)") == options.end());
}

TEST_CASE("link actions follow the target; a changed target keeps the action it also takes") {
    const level::Level level = logic_hall();
    using K = level::TargetKind;
    CHECK(target_actions(level, K::Entity, "Exit door") ==
          std::vector<std::string>{"open", "close", "toggle", "lock", "unlock"});
    CHECK(target_actions(level, K::Entity, "Hall spawner") == std::vector<std::string>{"spawn"});
    CHECK(target_actions(level, K::Entity, "Hall lamp") == std::vector<std::string>{"on", "off", "toggle"});
    CHECK(target_actions(level, K::Objective, "clear_hall") == std::vector<std::string>{"complete"});
    CHECK(target_actions(level, K::Level, "level") == std::vector<std::string>{"win", "lose"});
    CHECK(target_actions(level, K::Entity, "Nobody").empty());
    CHECK(target_actions(level, K::Entity, "").empty());

    const auto lamp = target_actions(level, K::Entity, "Hall lamp");
    CHECK(action_for_target(lamp, "toggle") == "toggle"); // a door's toggle is a lamp's too
    CHECK(action_for_target(lamp, "open") == "on");       // the lamp's first
    CHECK(action_for_target({}, "open").empty());

    // The kind of an existing link's target comes from its action, else from the name.
    CHECK(link_target_kind(level, {"on_use", "shutdown", "complete"}) == K::Objective);
    CHECK(link_target_kind(level, {"on_use", "level", "win"}) == K::Level);
    CHECK(link_target_kind(level, {"on_use", "Exit door", "open"}) == K::Entity);
    CHECK(link_target_kind(level, {"on_use", "level", ""}) == K::Level);
    CHECK(link_target_kind(level, {"on_use", "clear_hall", "typo"}) == K::Objective);
    CHECK(link_target_kind(level, {"on_use", "Exit door", "typo"}) == K::Entity);

    CHECK(target_label(level, K::Entity, "Exit door") == "Exit door (door)");
    CHECK(target_label(level, K::Entity, "Gone") == "\"Gone\"");
    CHECK(target_label(level, K::Entity, "") == "(no target)");
    CHECK(target_label(level, K::Objective, "clear_hall") == "objective clear_hall");
    CHECK(link_label({"on_enter", "Hall spawner", "spawn"}) == "on_enter -> spawn");
}

TEST_CASE("a pick on something that takes no action is refused with the reason") {
    const level::Level level = logic_hall();
    CHECK_FALSE(pick_refusal(level, named(level, "Exit door").id));
    CHECK_FALSE(pick_refusal(level, named(level, "Welcome").id));
    const auto wall = pick_refusal(level, named(level, "North wall").id);
    REQUIRE(wall);
    CHECK(wall->find("wall 5 (\"North wall\") takes no action") == 0);
    REQUIRE(pick_refusal(level, 999));
    CHECK(pick_refusal(level, 999)->find("does not exist") != std::string::npos);
}

TEST_CASE("link arrows: one per linked pair of entities, roles from the selection, none to objectives") {
    const level::Level level = logic_hall();
    const int trigger = named(level, "Hall trigger").id, spawner = named(level, "Hall spawner").id;
    const int intruders = named(level, "Intruders").id;
    auto arrows = link_arrows(level, {}, all_shown);
    // The trigger's two links name two entities; the control panel's names an objective, the objectives'
    // and the level's own links have no entity source: two arrows.
    REQUIRE(arrows.size() == 2);
    const LinkArrow* to_spawner = arrow_between(arrows, trigger, spawner);
    REQUIRE(to_spawner);
    CHECK(to_spawner->role == ArrowRole::Other);
    CHECK(to_spawner->labels == std::vector<std::string>{"on_enter -> spawn"});
    REQUIRE(arrow_between(arrows, trigger, intruders));

    // The ends sit on the boxes, and the curve rises above the straight line between them.
    const geometry::Obb source_box = entity_obb(named(level, "Hall trigger"));
    const geometry::Obb target_box = entity_obb(named(level, "Hall spawner"));
    CHECK(source_box.contains(to_spawner->from, 1e-3f));
    CHECK_FALSE(source_box.contains(to_spawner->from, -0.05f)); // on the surface, not inside
    CHECK(target_box.contains(to_spawner->to, 1e-3f));
    CHECK_FALSE(target_box.contains(to_spawner->to, -0.05f));
    CHECK(to_spawner->middle().y > (to_spawner->from.y + to_spawner->to.y) * 0.5f + 0.4f);

    arrows = link_arrows(level, {trigger}, all_shown);
    CHECK(arrow_between(arrows, trigger, spawner)->role == ArrowRole::Outgoing);
    CHECK(arrow_between(arrows, trigger, intruders)->role == ArrowRole::Outgoing);
    arrows = link_arrows(level, {spawner}, all_shown);
    CHECK(arrow_between(arrows, trigger, spawner)->role == ArrowRole::Incoming);
    CHECK(arrow_between(arrows, trigger, intruders)->role == ArrowRole::Other);

    // A hidden end hides the arrow.
    arrows = link_arrows(level, {}, [&](const level::Entity& e) { return e.id != spawner; });
    CHECK(arrows.size() == 1);
}

TEST_CASE(
    "link arrows: links to the same target share an arrow; ambiguous, dangling and self links get none") {
    level::Level level = logic_hall();
    level::Entity* trigger = level.find(13);
    REQUIRE(trigger);
    trigger->links.push_back({"on_exit", "Hall spawner", "spawn"});
    trigger->links.push_back({"on_enter", "Nobody", "open"});
    trigger->links.push_back({"on_enter", "Hall trigger", "disable"});
    auto arrows = link_arrows(level, {}, all_shown);
    REQUIRE(arrows.size() == 2);
    CHECK(arrow_between(arrows, 13, 14)->labels ==
          std::vector<std::string>{"on_enter -> spawn", "on_exit -> spawn"});

    level.find(15)->name = "Intruders"; // two messages called "Intruders": the link's target is ambiguous
    arrows = link_arrows(level, {}, all_shown);
    CHECK(arrows.size() == 1);

    // Two entities linking each other: the two curves bend to opposite sides.
    level.find(14)->links.push_back({"on_death", "Hall trigger", "enable"});
    arrows = link_arrows(level, {}, all_shown);
    const LinkArrow* there = arrow_between(arrows, 13, 14);
    const LinkArrow* back = arrow_between(arrows, 14, 13);
    REQUIRE(there);
    REQUIRE(back);
    CHECK(glm::length(there->middle() - back->middle()) > 1.0f);
}

TEST_CASE("an arrow's lines: the curve from end to end, then a head at the target") {
    const level::Level level = logic_hall();
    const auto arrows = link_arrows(level, {}, all_shown);
    REQUIRE_FALSE(arrows.empty());
    const LinkArrow& arrow = arrows.front();
    std::vector<MarkerLine> lines;
    arrow_lines(arrow, 12, lines);
    REQUIRE(lines.size() == 12 + 4);
    CHECK(glm::length(lines.front().a - arrow.from) < 1e-4f);
    CHECK(glm::length(lines[11].b - arrow.to) < 1e-4f);
    for (size_t i = 1; i < 12; ++i) CHECK(glm::length(lines[i].a - lines[i - 1].b) < 1e-4f); // joined
    for (size_t i = 12; i < lines.size(); ++i) {
        CHECK(glm::length(lines[i].a - arrow.to) < 1e-4f);
        const float length = glm::length(lines[i].b - lines[i].a);
        CHECK(length > 0.4f);
        CHECK(length < 2.0f);
    }
}

TEST_CASE("logic markers: a spawner's ring, post and facing; a message's bubble; a trigger's faces") {
    std::vector<MarkerLine> lines;
    const Vec3 feet(4, 1, -2);
    spawner_marker(feet, 90.0f, lines);
    REQUIRE(lines.size() > 20);
    float top = -1e9f;
    for (const auto& l : lines) top = std::max({top, l.a.y, l.b.y});
    CHECK(top == doctest::Approx(feet.y + level::kRobotHeight + level::kRobotRadius * 0.8f));
    // Yaw 90 faces -x: the arrow's tip is the farthest point in -x.
    float west = 1e9f;
    for (const auto& l : lines) west = std::min({west, l.a.x, l.b.x});
    CHECK(west == doctest::Approx(feet.x - level::kRobotRadius * 2.0f - 1.2f));

    lines.clear();
    const Vec3 centre(0, 2, 0), right(1, 0, 0), up(0, 1, 0);
    message_marker(centre, right, up, level::kLogicMarkerHalfSize, lines);
    REQUIRE(lines.size() >= 8);
    for (const auto& l : lines)
        for (const Vec3& p : {l.a, l.b}) {
            CHECK(p.z == doctest::Approx(0.0f)); // in the camera's plane
            CHECK(std::abs(p.x - centre.x) <= level::kLogicMarkerHalfSize + 1e-4f);
            CHECK(std::abs(p.y - centre.y) <= level::kLogicMarkerHalfSize + 1e-4f);
        }

    geometry::Obb box;
    box.center = Vec3(1, 2, 3);
    box.half = Vec3(2, 1, 0.5f);
    const auto faces = box_faces(box);
    for (size_t f = 0; f < faces.size(); ++f) {
        const size_t axis = f / 2;
        const float side = f % 2 == 0 ? -1.0f : 1.0f;
        for (const Vec3& corner : faces[f]) {
            const Vec3 local = corner - box.center;
            CHECK(local[static_cast<int>(axis)] == doctest::Approx(side * box.half[static_cast<int>(axis)]));
            for (int k = 0; k < 3; ++k) CHECK(std::abs(local[k]) == doctest::Approx(box.half[k]));
        }
        // Around the face: consecutive corners differ along one axis.
        for (size_t k = 0; k < 4; ++k) {
            const Vec3 d = faces[f][(k + 1) % 4] - faces[f][k];
            const int moved = (std::abs(d.x) > 1e-4f) + (std::abs(d.y) > 1e-4f) + (std::abs(d.z) > 1e-4f);
            CHECK(moved == 1);
        }
    }
}

TEST_CASE("kill lists take robots and spawners; incoming links list who acts on an entity") {
    level::Level level = logic_hall();
    level::Entity& robot = level.add(level::EntityType::Robot, Vec3(0, 0, -40));
    robot.name.clear();
    const auto options = kill_options(level);
    REQUIRE(options.size() == 2);
    CHECK(options[0].label == "Hall spawner (spawner)");
    CHECK(options[1].label == "robot #" + std::to_string(robot.id) + " (unnamed)");
    CHECK_FALSE(kill_refusal(level, robot.id));
    CHECK_FALSE(kill_refusal(level, named(level, "Hall spawner").id));
    REQUIRE(kill_refusal(level, named(level, "Exit door").id));
    CHECK(*kill_refusal(level, named(level, "Exit door").id) ==
          "door 12 (\"Exit door\") cannot be killed: pick a robot or a spawner");

    const auto door = incoming_links(level, named(level, "Exit door").id);
    REQUIRE(door.size() == 2); // the objective's unlock and open
    CHECK(door[0].source == "objective clear_hall");
    CHECK(door[0].source_entity == 0);
    CHECK(door[0].label == "on_complete -> unlock");
    CHECK(door[1].label == "on_complete -> open");
    const auto spawner = incoming_links(level, named(level, "Hall spawner").id);
    REQUIRE(spawner.size() == 1);
    CHECK(spawner[0].source == "Hall trigger (trigger)");
    CHECK(spawner[0].source_entity == 13);
    const auto welcome = incoming_links(level, named(level, "Welcome").id);
    REQUIRE(welcome.size() == 1);
    CHECK(welcome[0].source == "level");
    CHECK(incoming_links(level, robot.id).empty()); // no name: nothing can name it
}

TEST_CASE("logic problems are found again by the path of the list, link, objective or kill name drawn") {
    level::Level level = logic_hall();
    CHECK(logic_problems(level).empty());
    CHECK(links_path(level, LinkOwner::entity(13)) == "entities[12].links");
    CHECK(links_path(level, LinkOwner::objective("shutdown")) == "objectives[1].links");
    CHECK(links_path(level, LinkOwner::level()) == "links");
    CHECK(links_path(level, LinkOwner::entity(999)).empty());
    CHECK(links_path(level, LinkOwner::objective("nope")).empty());

    level.find(13)->links.push_back({"on_enter", "Nobody", "open"});
    level.objectives[0].kill.push_back("Exit door");
    level.objectives[1].links.push_back({"on_complete", "Welcome", "open"});
    const auto problems = logic_problems(level);
    const auto dangling = problems_at(problems, "entities[12].links[2]");
    REQUIRE(dangling.size() == 1);
    CHECK(dangling[0]->error);
    CHECK(dangling[0]->message.find("no entity named \"Nobody\"") != std::string::npos);
    CHECK(problems_at(problems, "entities[12].links[0]").empty());
    CHECK(problems_at(problems, "entities[12].links").size() == 1); // the list: everything under it
    const auto kill = problems_at(problems, "objectives[0].kill[1]");
    REQUIRE(kill.size() == 1);
    CHECK(kill[0]->message.find("cannot be killed") != std::string::npos);
    const auto wrong_action = problems_at(problems, "objectives[1].links[0]");
    REQUIRE(wrong_action.size() == 1);
    CHECK(wrong_action[0]->message.find("cannot \"open\"") != std::string::npos);
    // A path is a prefix only at a step: objectives[1] is not objectives[10].
    CHECK(problems_at({{"objectives[10].id", "m", "", true}}, "objectives[1]").empty());
    CHECK(problems_at(problems, "").empty());
}
