#pragma once
// Scripted mode: a line-based language that drives the same Editor operations the UI dispatches, for tests
// and automation (`killswitch-editor --script FILE`). The whole script is parsed first, so a typo on line 40
// is reported before line 1 changes anything; errors read "file:line:column: message (hint)".
// The language is documented in docs/editor.md.
#include "core/result.h"
#include "model/editor.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace ks::editor {

enum class ScriptOp {
    New,
    Open,
    Save,
    SaveAs,
    Place,
    Select,
    SelectAll,
    SelectType,
    SelectNone,
    SelectBox,
    Move,
    Nudge,
    Rotate,
    Scale,
    Set,
    Reset,
    Setting,
    PlayerStart,
    LevelName,
    Delete,
    Duplicate,
    Copy,
    Paste,
    Undo,
    Redo,
    Grid,
    Snap,
    Lock,
    Unlock,
    Hide,
    Show,
    Begin,
    Commit,
    Cancel,
    Fix,
    Patrol,
    Recover,
    CampaignAdd,
    ExpectCount,
    ExpectValid,
    ExpectIssue,
    ExpectNoIssue,
    ExpectSelected,
    ExpectField,
    ExpectPatrol,
    ExpectDirty,
    ExpectClean,
    ExpectCampaign,
    ExpectPlayerStart,
    Dojo,      // a command on the clip file (ScriptStep::dojo): see DojoOp
    Logic,     // a link, objective or naming command (ScriptStep::logic): see LogicOp
    Structure, // a group, layer or prefab command (ScriptStep::structure): see StructureOp
};

// The dojo context: commands on an animation clip file (`dojo open`, `clip ...`, `blend ...`, `event ...`,
// `key ...`) and its expectations, run on the script's DojoDocument (script_dojo_parser.cpp,
// script_dojo_runner.cpp). Kept in groups in this order (files, clips, blends, events, keys, expectations):
// the runner sends each group to its own function by range.
enum class DojoOp {
    Open,
    Save,
    Undo,
    Redo,
    ClipNew,
    ClipDuplicate,
    ClipRename,
    ClipDelete,
    ClipLoop,
    BlendDefault,
    BlendSet,
    BlendClear,
    EventAdd,
    EventMove,
    EventRename,
    EventSound,
    EventRemove,
    KeyTime,
    KeyValue,
    KeyAdd,
    KeyRemove,
    ExpectClipExists,
    ExpectClipMissing,
    ExpectClipLoop,
    ExpectClipDuration,
    ExpectBlend,
    ExpectEvents,
    ExpectEvent,
    ExpectKeyTime,
    ExpectKeyValue,
    ExpectCurve,
    ExpectValid,
    ExpectIssue,
    ExpectDirty,
    ExpectClean,
};

// One dojo line: `words` holds the names in the order the line gives them (clips, nodes, channel, loop mode,
// event name and sound, file path), `number` the seconds or value, `index` the key or event (counted from 1,
// as the panel shows them) or the undo/redo count (-1: all).
struct DojoStep {
    DojoOp op = DojoOp::Open;
    std::vector<std::string> words;
    double number = 0, number2 = 0;
    bool has_number = false;
    int index = 0;
};

// The level-logic lines (script_logic.h): `name`, `link`, `objective` and their expectations.
enum class LogicOp {
    Name,
    LinkAdd,
    LinkSet,
    LinkRemove,
    ObjectiveAdd,
    ObjectiveText,
    ObjectiveKill,
    ObjectiveRemove,
    ObjectiveMove,
    ExpectLinks,
    ExpectLink,
    ExpectObjectives,
};

// One logic line. `owner` is the SOURCE of link lines; `index` a link or the objective position, counted
// from 0 (scripts count from 1); `words` the kill list; `text` the name, objective id or link field,
// `value` the objective text or the link field's value; `link` the link added or expected.
struct LogicStep {
    LogicOp op = LogicOp::Name;
    LinkOwner owner;
    int entity_id = 0;
    int index = 0;
    int count = 0;
    std::string text, value;
    std::vector<std::string> words;
    level::Link link;
};

// Groups, layers and prefabs (script_structure.h) and their expectations.
enum class StructureOp {
    Group,
    Ungroup,
    Enter,
    Exit,
    Pick,
    LayerAdd,
    LayerRename,
    LayerRemove,
    LayerShow,
    LayerHide,
    LayerLock,
    LayerUnlock,
    LayerActive,
    LayerMove,
    PrefabFolder,
    PrefabSave,
    PrefabPlace,
    PrefabApply,
    PrefabUpdate,
    PrefabRevert,
    PrefabUnlink,
    ExpectGroups,
    ExpectGroup,
    ExpectLayers,
    ExpectLayer,
    ExpectInstance,
    ExpectOverride,
    ExpectNoOverride,
    ExpectHidden,
    ExpectShown,
    ExpectOpenGroup,
};

// One structure line. `layer` names a layer by name or index (resolved when the line runs); `id` is a
// group id (or the entity of `pick`), `entity_id` a member; `name` a group, layer or prefab name, `text` a
// title, field or path; `count` what an expectation counts; `state` a layer's expected visible/locked
// words ("visible", "hidden", "locked", "unlocked").
struct StructureStep {
    StructureOp op = StructureOp::Group;
    std::string layer, name, text;
    std::vector<std::string> state;
    int id = 0, entity_id = 0, count = 0;
    Vec3 position{0.0f};
    float yaw = 0.0f;
    bool replace = false;
    SelectMode mode = SelectMode::Replace;
};

// One parsed line. Which members matter depends on op (see script_parser.cpp).
struct ScriptStep {
    ScriptOp op = ScriptOp::New;
    int line = 0;
    level::EntityType type = level::EntityType::Wall;
    Vec3 vec{0.0f}, vec2{0.0f};
    bool has_vec = false;
    float number = 0.0f;
    bool has_number = false;
    int count = 0;
    std::vector<int> ids;
    SelectMode mode = SelectMode::Replace;
    std::string text, text2; // field names, values, paths, names
    DojoStep dojo;           // ScriptOp::Dojo
    LogicStep logic;         // ScriptOp::Logic
    StructureStep structure; // ScriptOp::Structure
};

struct Script {
    std::string file_name;
    std::filesystem::path base_dir; // relative paths in the script resolve against it
    std::vector<ScriptStep> steps;
};

struct ScriptReport {
    int lines_run = 0;
    int expectations_checked = 0;
    std::vector<std::filesystem::path> saved; // every file written by `save` and `dojo save`, in order
};

// Parses every line; all syntax errors at once, one per line of the combined Error.
Result<Script> parse_script(std::string_view text, const std::string& file_name);
// Runs a parsed script on `editor`; stops at the first failing line.
Result<ScriptReport> run_parsed_script(const Script& script, Editor& editor);
// Reads, parses and runs a script file on a fresh editor (paths relative to the script's folder).
Result<ScriptReport> run_script(const std::filesystem::path& path);
// The same on an existing editor, for tests and a script console.
Result<ScriptReport> run_script_text(std::string_view text, const std::string& file_name,
                                     const std::filesystem::path& base_dir, Editor& editor);

} // namespace ks::editor
