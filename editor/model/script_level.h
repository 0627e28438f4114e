#pragma once
// The script language's level steps: files, selection, entity edits, fields and settings, patrols,
// history, editing aids (script_level_edits.cpp) and the level's expectations (script_level_expect.cpp).
// Each step is what its command's parser read, typed; its `run` applies it to the script's Editor.
#include "model/edit_selection.h"
#include "model/edit_transforms.h"
#include "model/validation.h"

#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace ks::editor {

struct ScriptContext;

namespace steps {

// ---- files and recovery -------------------------------------------------------------------------------
struct New {
    Result<void> run(ScriptContext& c) const;
};
struct Open {
    std::string path;
    Result<void> run(ScriptContext& c) const;
};
struct Save {
    Result<void> run(ScriptContext& c) const;
};
struct SaveAs {
    std::string path;
    bool overwrite = false;
    Result<void> run(ScriptContext& c) const;
};
struct Recover {
    bool accept = false;
    Result<void> run(ScriptContext& c) const;
};
struct CampaignAdd {
    std::string campaign, title; // title empty: the level's name
    Result<void> run(ScriptContext& c) const;
};

// ---- selection ----------------------------------------------------------------------------------------
struct Select {
    std::vector<int> ids; // kPlayerStartId for the player start
    SelectMode mode = SelectMode::Replace;
    Result<void> run(ScriptContext& c) const;
};
struct SelectAll {
    Result<void> run(ScriptContext& c) const;
};
struct SelectType {
    level::EntityType type = level::EntityType::Wall;
    Result<void> run(ScriptContext& c) const;
};
struct SelectNone {
    Result<void> run(ScriptContext& c) const;
};
struct SelectBox {
    Vec3 a{0.0f}, b{0.0f}; // opposite corners
    Result<void> run(ScriptContext& c) const;
};

// ---- entity edits -------------------------------------------------------------------------------------
struct Place {
    level::EntityType type = level::EntityType::Wall;
    Vec3 position{0.0f};
    float yaw = 0.0f;
    std::string name;
    Result<void> run(ScriptContext& c) const;
};
struct Move {
    Vec3 delta{0.0f};
    bool snap = false;
    Result<void> run(ScriptContext& c) const;
};
struct Nudge {
    int axis = 0;      // 0 x, 1 y, 2 z
    int direction = 1; // +1 or -1
    Result<void> run(ScriptContext& c) const;
};
struct Rotate {
    int axis = 1; // 0 x, 1 y, 2 z
    float degrees = 0.0f;
    RotationSpace space = RotationSpace::World;
    Result<void> run(ScriptContext& c) const;
};
struct Scale {
    Vec3 factors{1.0f};
    Result<void> run(ScriptContext& c) const;
};
struct Delete {
    Result<void> run(ScriptContext& c) const;
};
struct Duplicate {
    std::optional<Vec3> offset; // none: one grid step
    Result<void> run(ScriptContext& c) const;
};
struct Copy {
    Result<void> run(ScriptContext& c) const;
};
struct Paste {
    Result<void> run(ScriptContext& c) const;
};

// ---- fields, level settings and quick fixes -----------------------------------------------------------
struct Set {
    std::string field, value;
    Result<void> run(ScriptContext& c) const;
};
struct Reset {
    std::string field;
    Result<void> run(ScriptContext& c) const;
};
struct Setting {
    std::string field, value;
    Result<void> run(ScriptContext& c) const;
};
struct PlayerStart {
    Vec3 position{0.0f};
    float yaw = 0.0f;
    Result<void> run(ScriptContext& c) const;
};
struct LevelName {
    std::string name;
    Result<void> run(ScriptContext& c) const;
};
struct Fix {
    Rule rule = Rule::Format;
    Result<void> run(ScriptContext& c) const;
};

// ---- a robot's patrol route (points count from 0) -----------------------------------------------------
struct PatrolAdd {
    int robot = 0;
    Vec3 point{0.0f};
    std::optional<int> after; // none: at the end; -1: first
    Result<void> run(ScriptContext& c) const;
};
struct PatrolMove {
    int robot = 0, index = 0;
    Vec3 point{0.0f};
    Result<void> run(ScriptContext& c) const;
};
struct PatrolRemove {
    int robot = 0, index = 0;
    Result<void> run(ScriptContext& c) const;
};
struct PatrolMode {
    int robot = 0;
    std::string mode; // loop or ping_pong
    Result<void> run(ScriptContext& c) const;
};
struct PatrolWait {
    int robot = 0;
    float seconds = 0.0f;
    Result<void> run(ScriptContext& c) const;
};

// ---- history (count -1: all) --------------------------------------------------------------------------
struct Undo {
    int count = 1;
    Result<void> run(ScriptContext& c) const;
};
struct Redo {
    int count = 1;
    Result<void> run(ScriptContext& c) const;
};
struct Begin {
    std::string name;
    Result<void> run(ScriptContext& c) const;
};
struct Commit {
    Result<void> run(ScriptContext& c) const;
};
struct Cancel {
    Result<void> run(ScriptContext& c) const;
};

// ---- editing aids: grid, snapping, locking and hiding -------------------------------------------------
struct Grid {
    float step = 1.0f, rotation_step = 15.0f;
    Result<void> run(ScriptContext& c) const;
};
struct Snap {
    bool on = true;
    Result<void> run(ScriptContext& c) const;
};
struct SetLocked {
    std::vector<int> ids;
    bool locked = true;
    Result<void> run(ScriptContext& c) const;
};
struct SetHidden {
    std::vector<int> ids;
    bool hidden = true;
    Result<void> run(ScriptContext& c) const;
};

// ---- expectations -------------------------------------------------------------------------------------
struct ExpectCount {
    level::EntityType type = level::EntityType::Wall;
    int count = 0;
    Result<void> run(ScriptContext& c) const;
};
struct ExpectValid {
    Result<void> run(ScriptContext& c) const;
};
struct ExpectIssue {
    Rule rule = Rule::Format;
    int entity_id = 0;  // 0: any
    bool wanted = true; // false: `expect no_issue`
    Result<void> run(ScriptContext& c) const;
};
struct ExpectSelected {
    int count = 0;
    Result<void> run(ScriptContext& c) const;
};
struct ExpectField {
    int entity_id = 0;
    std::string field, value;
    Result<void> run(ScriptContext& c) const;
};
struct ExpectPatrol {
    int robot = 0, points = 0;
    Result<void> run(ScriptContext& c) const;
};
struct ExpectDirty {
    bool dirty = true; // false: `expect clean`
    Result<void> run(ScriptContext& c) const;
};
struct ExpectCampaign {
    std::string campaign;
    int levels = 0;
    Result<void> run(ScriptContext& c) const;
};
struct ExpectPlayerStart {
    Vec3 position{0.0f};
    std::optional<float> yaw;
    Result<void> run(ScriptContext& c) const;
};

} // namespace steps

struct LevelStep {
    std::variant<steps::New, steps::Open, steps::Save, steps::SaveAs, steps::Recover, steps::CampaignAdd,
                 steps::Select, steps::SelectAll, steps::SelectType, steps::SelectNone, steps::SelectBox,
                 steps::Place, steps::Move, steps::Nudge, steps::Rotate, steps::Scale, steps::Delete,
                 steps::Duplicate, steps::Copy, steps::Paste, steps::Set, steps::Reset, steps::Setting,
                 steps::PlayerStart, steps::LevelName, steps::Fix, steps::PatrolAdd, steps::PatrolMove,
                 steps::PatrolRemove, steps::PatrolMode, steps::PatrolWait, steps::Undo, steps::Redo,
                 steps::Begin, steps::Commit, steps::Cancel, steps::Grid, steps::Snap, steps::SetLocked,
                 steps::SetHidden, steps::ExpectCount, steps::ExpectValid, steps::ExpectIssue,
                 steps::ExpectSelected, steps::ExpectField, steps::ExpectPatrol, steps::ExpectDirty,
                 steps::ExpectCampaign, steps::ExpectPlayerStart>
        step;
    Result<void> run(ScriptContext& c) const;
};

} // namespace ks::editor
