// Editing level logic in the editor's model: links of entities, objectives and the level, and objectives
// themselves, each one undo step that undoes exactly; failures change nothing; renaming an entity or an
// objective takes the links and kill lists that named it along; names for link targets.
#include "editor_test_util.h"
#include "model/edit_entities.h"
#include "model/edit_files.h"
#include "model/edit_layers.h"
#include "model/edit_logic.h"
#include "model/edit_selection.h"
#include "model/logic_edit.h"

#include <limits>

using namespace ks;
using namespace ks::editor;
using namespace ks::editor_test;
using level::EntityType;

namespace {

// A hall: a named door and robot, an unnamed door, a trigger and a control panel; one objective.
struct Hall {
    Editor ed;
    int door = 0, robot = 0, other_door = 0, trigger = 0, panel = 0;
    Hall() {
        door = *place(ed, EntityType::Door, {0, 0, 0}, 0, "Gate");
        robot = *place(ed, EntityType::Robot, {5, 0, -5}, 0, "Guard");
        other_door = *place(ed, EntityType::Door, {10, 0, 0});
        trigger = *place(ed, EntityType::Trigger, {0, 0, 5}, 0, "Hall trigger");
        panel = *place(ed, EntityType::ControlPanel, {0, 0, -15}, 0, "Panel");
        REQUIRE(objective_add(ed, {"clear", "Clear the hall", {"Guard"}, {}}).ok());
    }
};

level::Link link(std::string event, std::string target, std::string action, float delay = 0,
                 bool once = false) {
    return {std::move(event), std::move(target), std::move(action), delay, once};
}

// The whole level and the history's length: what a failed edit must leave as it was.
struct Snapshot {
    std::string text;
    size_t steps;
    explicit Snapshot(const Editor& ed) : text(text_of(ed)), steps(ed.history().undo_count()) {}
    bool same(const Editor& ed) const { return text == text_of(ed) && steps == ed.history().undo_count(); }
};

} // namespace

TEST_CASE("links of an entity, an objective and the level: add, set, remove, one undo step each") {
    Hall h;
    Editor& ed = h.ed;
    const std::string before = text_of(ed);
    const size_t steps = ed.history().undo_count();
    const LinkOwner trigger = LinkOwner::entity(h.trigger), objective = LinkOwner::objective("clear"),
                    whole = LinkOwner::level();

    CHECK(*link_add(ed, trigger, link("on_enter", "Gate", "open")) == 0);
    CHECK(*link_add(ed, trigger, link("on_exit", "Gate", "close", 1.5f)) == 1);
    CHECK(*link_add(ed, objective, link("on_complete", "Gate", "unlock")) == 0);
    CHECK(*link_add(ed, whole, link("on_start", "Gate", "lock", 0, true)) == 0);
    REQUIRE(link_set(ed, trigger, 1, link("on_exit", "Gate", "close", 2.0f, true)).ok());
    REQUIRE(link_remove(ed, trigger, 0).ok());
    CHECK(ed.history().undo_count() == steps + 6);

    REQUIRE(links_of(ed, trigger));
    CHECK(*links_of(ed, trigger) == std::vector{link("on_exit", "Gate", "close", 2.0f, true)});
    CHECK(ed.level().objectives[0].links == std::vector{link("on_complete", "Gate", "unlock")});
    CHECK(ed.level().links == std::vector{link("on_start", "Gate", "lock", 0, true)});
    CHECK(links_of(ed, whole) == &ed.level().links);
    CHECK(links_of(ed, LinkOwner::entity(999)) == nullptr);
    CHECK(links_of(ed, LinkOwner::objective("nope")) == nullptr);
    CHECK(ed.history().undo_name().find("Remove link") == 0);

    const std::string edited = text_of(ed);
    for (int i = 0; i < 6; ++i) REQUIRE(ed.undo());
    CHECK(text_of(ed) == before);
    for (int i = 0; i < 6; ++i) REQUIRE(ed.redo());
    CHECK(text_of(ed) == edited);

    // The edits survive the file: save -> load gives the same level.
    auto reloaded = level::load_level_string(edited, "hall.json");
    REQUIRE_MESSAGE(reloaded.ok(), (reloaded.ok() ? std::string() : reloaded.error().str()));
    CHECK(*reloaded == ed.level());
}

TEST_CASE("a link or objective edited with a merge key (a drag, typing) is one undo step") {
    Hall h;
    Editor& ed = h.ed;
    const LinkOwner trigger = LinkOwner::entity(h.trigger);
    REQUIRE(link_add(ed, trigger, link("on_enter", "Gate", "open")).ok());
    const size_t steps = ed.history().undo_count();
    for (float delay : {0.5f, 1.0f, 1.5f})
        REQUIRE(link_set(ed, trigger, 0, link("on_enter", "Gate", "open", delay), "delay drag").ok());
    CHECK(ed.history().undo_count() == steps + 1);
    for (const char* text : {"C", "Cl", "Clear it"}) {
        level::Objective o = ed.level().objectives[0];
        o.text = text;
        REQUIRE(objective_set(ed, 0, o, "objective text").ok());
    }
    CHECK(ed.history().undo_count() == steps + 2);
    CHECK(ed.level().objectives[0].text == "Clear it");
    REQUIRE(ed.undo());
    CHECK(ed.level().objectives[0].text == "Clear the hall");
    REQUIRE(ed.undo());
    CHECK(links_of(ed, trigger)->at(0).delay == 0.0f);
    // Unchanged edits make no step.
    REQUIRE(link_set(ed, trigger, 0, link("on_enter", "Gate", "open")).ok());
    CHECK(ed.history().undo_count() == steps);
}

TEST_CASE("objectives: add, edit, move and remove, each one undo step") {
    Hall h;
    Editor& ed = h.ed;
    const std::string before = text_of(ed);
    const size_t steps = ed.history().undo_count();
    REQUIRE(objective_add(ed, {"panel", "Use the panel", {}, {link("on_complete", "level", "win")}}).ok());
    REQUIRE(objective_add(ed, {"escape", "Escape", {}, {}}).ok());
    REQUIRE(objective_move(ed, 2, 0).ok());
    auto ids = [&] {
        std::vector<std::string> out;
        for (const auto& o : ed.level().objectives) out.push_back(o.id);
        return out;
    };
    CHECK(ids() == std::vector<std::string>{"escape", "clear", "panel"});
    level::Objective edited = ed.level().objectives[1];
    edited.kill = {"Guard", "Guard"};
    REQUIRE(objective_set(ed, 1, edited).ok());
    REQUIRE(objective_remove(ed, 0).ok());
    CHECK(ids() == std::vector<std::string>{"clear", "panel"});
    CHECK(ed.level().objectives[0].kill == std::vector<std::string>{"Guard", "Guard"});
    CHECK(ed.history().undo_count() == steps + 5);
    REQUIRE(ed.undo());
    CHECK(ids() == std::vector<std::string>{"escape", "clear", "panel"});
    for (int i = 0; i < 4; ++i) REQUIRE(ed.undo());
    CHECK(text_of(ed) == before);
    // Moving to where it is changes nothing.
    REQUIRE(objective_move(ed, 0, 0).ok());
    CHECK(ed.history().undo_count() == steps);
}

TEST_CASE("failed link and objective edits change nothing and say what is wrong") {
    Hall h;
    Editor& ed = h.ed;
    const LinkOwner trigger = LinkOwner::entity(h.trigger);
    REQUIRE(link_add(ed, trigger, link("on_enter", "Gate", "open")).ok());
    const Snapshot snapshot(ed);
    auto fails = [&](const auto& result, const char* message_part, const char* hint_part = "") {
        REQUIRE_FALSE(result.ok());
        INFO(result.error().str());
        CHECK(result.error().message.find(message_part) != std::string::npos);
        CHECK(result.error().hint.find(hint_part) != std::string::npos);
        CHECK(snapshot.same(ed));
    };
    fails(link_add(ed, trigger, link("on_entr", "Gate", "open")), "unknown event \"on_entr\"",
          "did you mean \"on_enter\"?");
    fails(link_add(ed, trigger, link("on_death", "Gate", "open")), "does not emit \"on_death\"",
          "on_enter, on_exit");
    fails(link_add(ed, trigger, link("on_enter", "Gate", "opne")), "unknown action \"opne\"",
          "did you mean \"open\"?");
    fails(link_add(ed, trigger, link("on_enter", "Gate", "open", -1)), "out of range", "0 .. 3600");
    fails(link_add(ed, trigger, link("on_enter", "Gate", "open", std::numeric_limits<float>::quiet_NaN())),
          "not a finite number");
    fails(link_add(ed, LinkOwner::objective("clear"), link("on_enter", "Gate", "open")), "does not emit",
          "on_complete");
    fails(link_add(ed, LinkOwner::level(), link("on_use", "Gate", "open")), "does not emit", "on_start");
    fails(link_add(ed, LinkOwner::entity(999), link("on_enter", "Gate", "open")), "no entity with id 999");
    fails(link_add(ed, LinkOwner::objective("nope"), link("on_complete", "Gate", "open")),
          "no objective \"nope\"", "clear");
    const int wall = *place(ed, EntityType::Wall, {0, 0, 20});
    const Snapshot with_wall(ed);
    auto wall_links = link_add(ed, LinkOwner::entity(wall), link("on_use", "Gate", "open"));
    REQUIRE_FALSE(wall_links.ok());
    CHECK(wall_links.error().message.find("emits no events") != std::string::npos);
    CHECK(with_wall.same(ed));
    REQUIRE(ed.undo()); // the wall
    fails(link_set(ed, trigger, 1, link("on_enter", "Gate", "open")), "no link 1", "valid: 0 .. 0");
    fails(link_set(ed, trigger, 0, link("on_enter", "Gate", "explode")), "link 0: unknown action");
    fails(link_remove(ed, trigger, -1), "no link -1");
    fails(link_remove(ed, LinkOwner::level(), 0), "no link 0", "has none");
    REQUIRE(set_locked(ed, h.trigger, true).ok()); // a step of its own (saved in the level's editor section)
    {
        const Snapshot locked(ed);
        auto refused = link_add(ed, trigger, link("on_enter", "Gate", "close"));
        REQUIRE_FALSE(refused.ok());
        CHECK(refused.error().message.find("locked") != std::string::npos);
        CHECK(refused.error().hint.find("unlock") != std::string::npos);
        CHECK(locked.same(ed));
    }
    REQUIRE(ed.undo()); // the lock

    fails(objective_add(ed, {"clear", "Again", {}, {}}), "already an objective \"clear\"");
    fails(objective_add(ed, {"", "No id", {}, {}}), "needs an id");
    fails(objective_add(ed, {"long", std::string(level::kMaxMessageLength + 1, 'x'), {}, {}}), "too long");
    fails(objective_add(ed, {"bad_link", "Text", {}, {link("on_start", "level", "win")}}),
          "link 0: an objective does not emit \"on_start\"");
    REQUIRE(objective_add(ed, {"second", "Second", {}, {}}).ok());
    const Snapshot two(ed);
    auto renamed_onto = objective_set(ed, 1, {"clear", "Second", {}, {}});
    REQUIRE_FALSE(renamed_onto.ok());
    CHECK(two.same(ed));
    CHECK_FALSE(objective_set(ed, 2, {"third", "x", {}, {}}).ok());
    CHECK_FALSE(objective_remove(ed, 5).ok());
    CHECK_FALSE(objective_move(ed, 0, 2).ok());
    CHECK_FALSE(objective_move(ed, -1, 0).ok());
    CHECK(two.same(ed));
}

TEST_CASE("renaming an entity re-targets the links and kill lists that named it, in the same undo step") {
    Hall h;
    Editor& ed = h.ed;
    REQUIRE(link_add(ed, LinkOwner::entity(h.trigger), link("on_enter", "Gate", "open")).ok());
    REQUIRE(link_add(ed, LinkOwner::entity(h.door), link("on_open", "Gate", "lock", 1)).ok()); // its own
    REQUIRE(link_add(ed, LinkOwner::level(), link("on_start", "Guard", "activate")).ok());
    REQUIRE(link_add(ed, LinkOwner::objective("clear"), link("on_complete", "Gate", "unlock")).ok());
    const std::string before = text_of(ed);
    const size_t steps = ed.history().undo_count();

    REQUIRE(rename(ed, h.door, "North gate").ok());
    CHECK(ed.history().undo_count() == steps + 1);
    CHECK(links_of(ed, LinkOwner::entity(h.trigger))->at(0).target == "North gate");
    CHECK(links_of(ed, LinkOwner::entity(h.door))->at(0).target == "North gate");
    CHECK(ed.level().objectives[0].links[0].target == "North gate");
    CHECK(ed.level().links[0].target == "Guard"); // another name: untouched

    // Through the inspector's path: set_field("name") on the selection.
    REQUIRE(select(ed, {h.robot}).ok());
    REQUIRE(set_field(ed, "name", FieldValue(std::string("Captain"))).ok());
    CHECK(ed.level().links[0].target == "Captain");
    CHECK(ed.level().objectives[0].kill == std::vector<std::string>{"Captain"});
    CHECK(ed.history().undo_count() == steps + 2);

    REQUIRE(ed.undo());
    CHECK(ed.level().links[0].target == "Guard");
    CHECK(ed.level().objectives[0].kill == std::vector<std::string>{"Guard"});
    REQUIRE(ed.undo());
    CHECK(text_of(ed) == before);
    REQUIRE(ed.redo());
    CHECK(links_of(ed, LinkOwner::entity(h.trigger))->at(0).target == "North gate");
}

TEST_CASE("a rename leaves links alone when the old name was shared, the new one is empty, or the link "
          "names an objective") {
    Hall h;
    Editor& ed = h.ed;
    REQUIRE(objective_add(ed, {"Gate", "An objective named like the door", {}, {}}).ok());
    REQUIRE(link_add(ed, LinkOwner::entity(h.trigger), link("on_enter", "Gate", "open")).ok());
    REQUIRE(link_add(ed, LinkOwner::entity(h.trigger), link("on_exit", "Gate", "complete")).ok());
    REQUIRE(rename(ed, h.door, "Door A").ok());
    const auto& links = *links_of(ed, LinkOwner::entity(h.trigger));
    CHECK(links[0].target == "Door A");
    CHECK(links[1].target == "Gate"); // completes the objective "Gate"

    REQUIRE(rename(ed, h.other_door, "Door A").ok()); // now two doors share the name
    REQUIRE(rename(ed, h.door, "Door B").ok());
    CHECK(links_of(ed, LinkOwner::entity(h.trigger))->at(0).target == "Door A");

    REQUIRE(rename(ed, h.other_door, "Door C").ok()); // "Door A" is unique again: its owner is other_door
    CHECK(links_of(ed, LinkOwner::entity(h.trigger))->at(0).target == "Door C");
    REQUIRE(
        rename(ed, h.other_door, "").ok()); // no name: the link keeps naming "Door C" (validation says so)
    CHECK(links_of(ed, LinkOwner::entity(h.trigger))->at(0).target == "Door C");
}

TEST_CASE("renaming an objective re-targets the links that complete it, in the same undo step") {
    Hall h;
    Editor& ed = h.ed;
    REQUIRE(link_add(ed, LinkOwner::entity(h.panel), link("on_use", "clear", "complete")).ok());
    REQUIRE(link_add(ed, LinkOwner::entity(h.trigger), link("on_enter", "clear", "open")).ok()); // an entity
    const size_t steps = ed.history().undo_count();
    level::Objective renamed = ed.level().objectives[0];
    renamed.id = "clear_hall";
    REQUIRE(objective_set(ed, 0, renamed).ok());
    CHECK(ed.history().undo_count() == steps + 1);
    CHECK(links_of(ed, LinkOwner::entity(h.panel))->at(0).target == "clear_hall");
    CHECK(links_of(ed, LinkOwner::entity(h.trigger))->at(0).target == "clear");
    CHECK(links_of(ed, LinkOwner::objective("clear_hall")) != nullptr);
    REQUIRE(ed.undo());
    CHECK(links_of(ed, LinkOwner::entity(h.panel))->at(0).target == "clear");
    CHECK(ed.level().objectives[0].id == "clear");
}

TEST_CASE("ensure_link_name gives an entity a unique one-word name when it has none or shares one") {
    Hall h;
    Editor& ed = h.ed;
    const size_t steps = ed.history().undo_count();
    auto gate = ensure_link_name(ed, h.door);
    REQUIRE(gate.ok());
    CHECK(*gate == "Gate");
    CHECK(ed.history().undo_count() == steps); // already named uniquely: no step

    const int third = *place(ed, EntityType::Door, {20, 0, 0}, 0, "door_1");
    const size_t placed = ed.history().undo_count();
    auto unnamed = ensure_link_name(ed, h.other_door);
    REQUIRE(unnamed.ok());
    CHECK(*unnamed == "door_2"); // door_1 is taken
    CHECK(ed.level().find(h.other_door)->name == "door_2");
    CHECK(ed.history().undo_count() == placed + 1);

    REQUIRE(rename(ed, third, "Hall trigger").ok()); // shares the trigger's name
    auto shared = ensure_link_name(ed, h.trigger);
    REQUIRE(shared.ok());
    CHECK(*shared == "Hall_trigger_1");
    CHECK(ed.level().find(third)->name == "Hall trigger");
    REQUIRE(ed.undo());
    CHECK(ed.level().find(h.trigger)->name == "Hall trigger");

    CHECK_FALSE(ensure_link_name(ed, 999).ok());
    REQUIRE(set_locked(ed, h.other_door, true).ok());
    REQUIRE(rename(ed, h.other_door, "").ok() == false);
    CHECK(ensure_link_name(ed, h.other_door).ok()); // named uniquely already: nothing to change
}

TEST_CASE("deleting a link's target: validation names the dangling target and nothing crashes") {
    Hall h;
    Editor& ed = h.ed;
    REQUIRE(link_add(ed, LinkOwner::entity(h.trigger), link("on_enter", "Gate", "open")).ok());
    REQUIRE(link_add(ed, LinkOwner::level(), link("on_start", "Guard", "activate", 2)).ok());
    REQUIRE(delete_entities(ed, {h.door, h.robot}).ok());
    bool gate = false, guard = false;
    for (const Issue& issue : ed.issues()) {
        gate |= issue.message.find("no entity named \"Gate\"") != std::string::npos;
        guard |= issue.message.find("\"Guard\"") != std::string::npos;
    }
    CHECK(gate);
    CHECK(guard);
    // The links still edit, and undo brings the targets back.
    REQUIRE(link_set(ed, LinkOwner::level(), 0, link("on_start", "Guard", "alert", 2)).ok());
    REQUIRE(ed.undo());
    REQUIRE(ed.undo());
    CHECK(ed.level().find(h.door) != nullptr);
    for (const Issue& issue : ed.issues()) CHECK(issue.message.find("no entity named") == std::string::npos);
}

TEST_CASE("recovering an autosave restores the objectives and the level's links too") {
    Hall h;
    Editor& ed = h.ed;
    REQUIRE(link_add(ed, LinkOwner::level(), link("on_start", "Gate", "open")).ok());
    const level::Level saved = ed.level();
    const ks::test::ScratchDir dir;
    const auto autosave = dir / "hall.autosave.json";
    REQUIRE(level::save_level_file(autosave, saved).ok());
    Editor fresh;
    fresh.offer_recovery({dir / "hall.json", autosave});
    REQUIRE(accept_recovery(fresh).ok());
    CHECK(fresh.level().objectives == saved.objectives);
    CHECK(fresh.level().links == saved.links);
    REQUIRE(fresh.undo());
    CHECK(fresh.level().objectives.empty());
    CHECK(fresh.level().links.empty());
}
