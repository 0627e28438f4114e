// The script language's level commands for fields and settings, patrols, history and editing aids
// (script_level.h): each command's parser, its steps' `run`, and the table entry that registers it
// (script_command.h).
#include "model/edit_entities.h"
#include "model/edit_layers.h"
#include "model/edit_patrols.h"
#include "model/quick_fix.h"
#include "model/script_level_words.h"

#include <optional>

namespace ks::editor {
namespace {
using namespace script_tokens;
using namespace level_words;

// lock|unlock|hide|show ID...: the step's flag (locked or hidden) set to `value`.
template <class T>
Result<ScriptStep> ids_argument(const LineWords& w, const char* usage, bool value) {
    T step;
    if (auto r = ids_from(w, usage, 1, step.ids); !r) return r.error();
    if constexpr (requires { step.locked; })
        step.locked = value;
    else
        step.hidden = value;
    return level_step(std::move(step));
}

template <class T>
Result<ScriptStep> field_and_value(const LineWords& w, const char* usage) {
    if (w.size() < 3) return w.fail(0, "expected a field and a value", usage);
    return level_step(T{w.word(1), w.rest(2)});
}

// undo|redo [N|all]: count -1 for all.
template <class T>
Result<ScriptStep> step_count(const LineWords& w, const char* usage) {
    if (auto r = w.need(1, 2, usage); !r) return r.error();
    T step;
    if (w.size() == 2) {
        const std::string word = w.word(0);
        if (w.text(1) == "all")
            step.count = -1;
        else if (!to_int(w.text(1), step.count) || step.count < 1)
            return w.fail(1, "expected a count of steps", word + " 3, or " + word + " all");
    }
    return level_step(step);
}

// ---- level settings, editing aids, transactions and quick fixes ---------------------------------------

constexpr const char* kPlayerStartUsage = "player_start X,Y,Z [yaw D]";
constexpr const char* kGridUsage = "grid STEP [ROTATION_STEP]";

Result<ScriptStep> parse_reset(const LineWords& w) {
    if (auto r = w.need(2, 2, "reset FIELD"); !r) return r.error();
    return level_step(steps::Reset{w.word(1)});
}

Result<ScriptStep> parse_level_name(const LineWords& w) {
    if (w.size() < 2) return w.fail(0, "expected a name", "level_name Two Rooms");
    return level_step(steps::LevelName{w.rest(1)});
}

Result<ScriptStep> parse_player_start(const LineWords& w) {
    steps::PlayerStart step;
    if (w.size() != 2 && w.size() != 4) return w.fail(0, "wrong number of words", kPlayerStartUsage);
    if (auto r = w.vec(1, step.position); !r) return r.error();
    if (w.size() == 4) {
        if (w.text(2) != "yaw") return w.fail(2, "expected 'yaw'", kPlayerStartUsage);
        if (!to_float(w.text(3), step.yaw)) return w.fail(3, "expected degrees", "yaw 90");
    }
    return level_step(step);
}

Result<ScriptStep> parse_grid(const LineWords& w) {
    steps::Grid step;
    if (auto r = w.need(2, 3, kGridUsage); !r) return r.error();
    if (!to_float(w.text(1), step.step) || step.step <= 0)
        return w.fail(1, "expected a positive grid step", "grid 0.5");
    if (w.size() == 3 && (!to_float(w.text(2), step.rotation_step) || step.rotation_step <= 0))
        return w.fail(2, "expected a positive rotation step in degrees", "grid 1 15");
    return level_step(step);
}

Result<ScriptStep> parse_snap(const LineWords& w) {
    if (auto r = w.need(2, 2, "snap on|off"); !r) return r.error();
    if (w.text(1) != "on" && w.text(1) != "off") return w.fail(1, "expected on or off", "snap off");
    return level_step(steps::Snap{w.text(1) == "on"});
}

Result<ScriptStep> parse_begin(const LineWords& w) {
    return level_step(steps::Begin{w.size() > 1 ? w.rest(1) : "Script transaction"});
}

Result<ScriptStep> parse_fix(const LineWords& w) {
    steps::Fix step;
    if (auto r = w.need(2, 2, "fix RULE"); !r) return r.error();
    if (auto r = rule(w, 1, step.rule); !r) return r.error();
    return level_step(step);
}

// ---- robot patrols ------------------------------------------------------------------------------------

constexpr const char* kPatrolUsage =
    "patrol ID add X,Y,Z [after INDEX] | patrol ID move INDEX X,Y,Z | patrol ID remove INDEX | "
    "patrol ID mode loop|ping_pong | patrol ID wait SECONDS";

Result<ScriptStep> parse_patrol_point_edit(const LineWords& w, int robot, std::string_view action) {
    const size_t words = action == "move" ? 5 : 4;
    if (auto r = w.need(words, words, kPatrolUsage); !r) return r.error();
    int index = 0;
    if (!to_int(w.text(3), index) || index < 0)
        return w.fail(3, "expected a point index (0 is the first)", kPatrolUsage);
    if (action == "remove") return level_step(steps::PatrolRemove{robot, index});
    steps::PatrolMove step{robot, index, Vec3(0.0f)};
    if (auto r = w.vec(4, step.point); !r) return r.error();
    return level_step(step);
}

Result<ScriptStep> parse_patrol(const LineWords& w) {
    if (w.size() < 3) return w.fail(w.size(), "missing words", kPatrolUsage);
    int robot = 0;
    if (!to_int(w.text(1), robot) || robot < 1) return w.fail(1, "expected the robot's id", kPatrolUsage);
    const std::string_view action = w.text(2);
    if (action == "add") {
        steps::PatrolAdd step{robot, Vec3(0.0f), std::nullopt};
        if (w.size() != 4 && w.size() != 6) return w.fail(w.size(), "wrong number of words", kPatrolUsage);
        if (auto r = w.vec(3, step.point); !r) return r.error();
        if (w.size() == 6) {
            int after = 0;
            if (w.text(4) != "after") return w.fail(4, "expected 'after'", kPatrolUsage);
            if (!to_int(w.text(5), after) || after < -1)
                return w.fail(5, "expected a point index (-1 puts the point first)", kPatrolUsage);
            step.after = after;
        }
        return level_step(step);
    }
    if (action == "move" || action == "remove") return parse_patrol_point_edit(w, robot, action);
    if (action == "mode") {
        if (auto r = w.need(4, 4, kPatrolUsage); !r) return r.error();
        const std::string mode = w.word(3);
        if (mode != "loop" && mode != "ping_pong")
            return w.fail(3, "unknown patrol mode '" + mode + "'", "modes: loop, ping_pong");
        return level_step(steps::PatrolMode{robot, mode});
    }
    if (action == "wait") {
        steps::PatrolWait step{robot, 0.0f};
        if (auto r = w.need(4, 4, kPatrolUsage); !r) return r.error();
        if (!to_float(w.text(3), step.seconds) || step.seconds < 0)
            return w.fail(3, "expected seconds (0 or more)", kPatrolUsage);
        return level_step(step);
    }
    return w.fail(2, "unknown patrol action '" + std::string(action) + "'",
                  "actions: add, move, remove, mode, wait");
}

constexpr CommandSpec kCommands[] = {
    {"set", false, "set FIELD VALUE", "set a property on the selection (VALUE: the rest of the line)",
     [](const LineWords& w) { return field_and_value<steps::Set>(w, "set FIELD VALUE"); }},
    {"setting", false, "setting FIELD VALUE", "set a level setting",
     [](const LineWords& w) { return field_and_value<steps::Setting>(w, "setting FIELD VALUE"); }},
    {"reset", false, "reset FIELD", "revert a property on the selection", parse_reset},
    {"player_start", false, kPlayerStartUsage, "place the player start", parse_player_start},
    {"level_name", false, "level_name TEXT", "rename the level", parse_level_name},
    {"undo", false, "undo [N|all]", "undo steps",
     [](const LineWords& w) { return step_count<steps::Undo>(w, "undo [N|all]"); }},
    {"redo", false, "redo [N|all]", "redo steps",
     [](const LineWords& w) { return step_count<steps::Redo>(w, "redo [N|all]"); }},
    {"grid", false, kGridUsage, "the grid step and rotation step", parse_grid},
    {"snap", false, "snap on|off", "snapping to the grid", parse_snap},
    {"lock", false, "lock ID...", "lock entities",
     [](const LineWords& w) { return ids_argument<steps::SetLocked>(w, "lock ID...", true); }},
    {"unlock", false, "unlock ID...", "unlock entities",
     [](const LineWords& w) { return ids_argument<steps::SetLocked>(w, "unlock ID...", false); }},
    {"hide", false, "hide ID...", "hide entities",
     [](const LineWords& w) { return ids_argument<steps::SetHidden>(w, "hide ID...", true); }},
    {"show", false, "show ID...", "show hidden entities",
     [](const LineWords& w) { return ids_argument<steps::SetHidden>(w, "show ID...", false); }},
    {"begin", false, "begin [NAME]", "start a transaction (one undo step)", parse_begin},
    {"commit", false, "commit", "end the transaction", no_arguments<steps::Commit>},
    {"cancel", false, "cancel", "revert the transaction", no_arguments<steps::Cancel>},
    {"fix", false, "fix RULE", "apply every available quick fix of a rule", parse_fix},
    {"patrol", false, kPatrolUsage, "edit a robot's patrol route (points count from 0)", parse_patrol},
};

} // namespace

std::span<const CommandSpec> level_setting_commands() {
    return kCommands;
}

// ---- running ------------------------------------------------------------------------------------------

namespace steps {

Result<void> Set::run(ScriptContext& c) const {
    return set_field_text(c.editor, field, value);
}
Result<void> Reset::run(ScriptContext& c) const {
    return revert_field(c.editor, field);
}
Result<void> Setting::run(ScriptContext& c) const {
    return set_setting_text(c.editor, field, value);
}
Result<void> PlayerStart::run(ScriptContext& c) const {
    return set_player_start(c.editor, {position, yaw});
}
Result<void> LevelName::run(ScriptContext& c) const {
    return rename_level(c.editor, name);
}
// Every quick fix of the rule, re-validating after each (a fix may resolve other issues).
Result<void> Fix::run(ScriptContext& c) const {
    for (int guard = 0; guard < 10000; ++guard) {
        std::optional<Issue> next;
        for (const auto& i : c.editor.issues())
            if (i.rule == rule && i.fix.available()) {
                next = i;
                break;
            }
        if (!next) return ok();
        if (auto r = apply_quick_fix(c.editor, *next); !r) return r;
    }
    return Error(std::string("fix ") + rule_name(rule) + ": the fixes do not settle");
}

Result<void> PatrolAdd::run(ScriptContext& c) const {
    return patrol_add(c.editor, robot, point, after);
}
Result<void> PatrolMove::run(ScriptContext& c) const {
    return patrol_move(c.editor, robot, index, point);
}
Result<void> PatrolRemove::run(ScriptContext& c) const {
    return patrol_remove(c.editor, robot, index);
}
Result<void> PatrolMode::run(ScriptContext& c) const {
    return patrol_set_mode(c.editor, robot, mode);
}
Result<void> PatrolWait::run(ScriptContext& c) const {
    return patrol_set_wait(c.editor, robot, seconds);
}

namespace {
// count < 0 means "all": stop quietly when history runs out.
Result<void> undo_or_redo(Editor& editor, bool undo, int count) {
    for (int i = 0; count < 0 || i < count; ++i) {
        if (undo ? editor.undo() : editor.redo()) continue;
        if (count < 0) break;
        return Error(std::string("nothing to ") + (undo ? "undo" : "redo") + " (step " +
                     std::to_string(i + 1) + " of " + std::to_string(count) + ")");
    }
    return ok();
}
} // namespace

Result<void> Undo::run(ScriptContext& c) const {
    return undo_or_redo(c.editor, true, count);
}
Result<void> Redo::run(ScriptContext& c) const {
    return undo_or_redo(c.editor, false, count);
}
Result<void> Begin::run(ScriptContext& c) const {
    c.editor.begin_transaction(name);
    return ok();
}
Result<void> Commit::run(ScriptContext& c) const {
    if (!c.editor.history().in_transaction()) return Error("commit without begin");
    c.editor.commit_transaction();
    return ok();
}
Result<void> Cancel::run(ScriptContext& c) const {
    if (!c.editor.history().in_transaction()) return Error("cancel without begin");
    c.editor.cancel_transaction();
    return ok();
}

Result<void> Grid::run(ScriptContext& c) const {
    c.editor.grid().step = step;
    c.editor.grid().rotation_step = rotation_step;
    return ok();
}
Result<void> Snap::run(ScriptContext& c) const {
    c.editor.grid().snap = on;
    return ok();
}
Result<void> SetLocked::run(ScriptContext& c) const {
    for (int id : ids) {
        if (!c.editor.level().find(id)) return Error("no entity with id " + std::to_string(id));
        if (auto done = set_locked(c.editor, id, locked); !done) return done;
    }
    return ok();
}
Result<void> SetHidden::run(ScriptContext& c) const {
    for (int id : ids) {
        if (!c.editor.level().find(id)) return Error("no entity with id " + std::to_string(id));
        if (auto done = set_hidden(c.editor, id, hidden); !done) return done;
    }
    return ok();
}

} // namespace steps
} // namespace ks::editor
