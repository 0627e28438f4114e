#pragma once
// A validation issue's quick fix (validation.h): a label for its button and a typed action, one struct per
// kind of fix. apply_quick_fix applies each kind by its own function (quick_fix.cpp), as one undo step. A
// new kind of fix is a struct here, joined to FixAction, and its apply_fix overload in quick_fix.cpp.
#include "core/math.h"
#include "level/level.h"
#include "model/field_access.h"
#include "model/logic_edit.h"

#include <string>
#include <variant>

namespace ks::editor::fixes {

// The issue's entity to `position`.
struct MoveEntity {
    Vec3 position{0.0f};
};
// The player start to `position` (its yaw kept).
struct MovePlayerStart {
    Vec3 position{0.0f};
};
// The issue's entity deleted.
struct DeleteEntity {};
// A field of the issue's entity.
struct SetField {
    std::string field;
    FieldValue value;
};
// Point `index` of the issue's robot's patrol to `position`.
struct MovePatrolPoint {
    int index = 0;
    Vec3 position{0.0f};
};
// A level setting.
struct SetSetting {
    std::string field;
    FieldValue value;
};
// Link `index` of `owner` replaced by `link` (as the fix leaves it).
struct SetLink {
    LinkOwner owner;
    int index = 0;
    level::Link link;
};
// Link `index` of `owner` removed.
struct RemoveLink {
    LinkOwner owner;
    int index = 0;
};
// `link` appended to `owner`'s links.
struct AddLink {
    LinkOwner owner;
    level::Link link;
};
// Objective `objective`'s kill-list name `kill_index` becomes `name`.
struct SetKillName {
    int objective = 0, kill_index = 0;
    std::string name;
};
// Objective `objective`'s kill-list name `kill_index` removed.
struct RemoveKillName {
    int objective = 0, kill_index = 0;
};
// The objective "shutdown", completed by using the control panel (v1's win).
struct AddShutdownObjective {};
// Group `group` (a prefab instance) becomes a plain group.
struct UnlinkPrefab {
    int group = 0;
};

} // namespace ks::editor::fixes

namespace ks::editor {

// std::monostate: the issue has no quick fix.
using FixAction = std::variant<std::monostate, fixes::MoveEntity, fixes::MovePlayerStart, fixes::DeleteEntity,
                               fixes::SetField, fixes::MovePatrolPoint, fixes::SetSetting, fixes::SetLink,
                               fixes::RemoveLink, fixes::AddLink, fixes::SetKillName, fixes::RemoveKillName,
                               fixes::AddShutdownObjective, fixes::UnlinkPrefab>;

struct QuickFix {
    std::string label; // "Drop to floor", shown on the button
    FixAction action;

    bool available() const { return !std::holds_alternative<std::monostate>(action); }
    template <class Fix>
    bool is() const {
        return std::holds_alternative<Fix>(action);
    }
};

class Editor;
struct Issue;
// The issue's fix as one undo step through the editor's operations (edit_*.h).
// Tests: tests/editor/test_validation.cpp and the rules' own test files.
Result<void> apply_quick_fix(Editor& editor, const Issue& issue);

} // namespace ks::editor
