#pragma once
// Live design checks on a level, beyond the format's own ranges: things a level can be saved with (as a
// draft) but should not ship with. Each issue names the entity it is about, so the validation panel can
// select it, and carries a quick fix where the fix is obvious.
#include "model/bounds.h"
#include "model/field_access.h"
#include "model/logic_edit.h"
#include "model/quick_fix.h"

#include <optional>
#include <string>
#include <vector>

namespace ks::editor {

enum class Rule {
    Format,       // a range / NaN / id problem that level_io::validate reports
    PlayerStart,  // the player start is not on a floor, or is inside a wall
    ControlPanel, // missing, or more than one
    WallOverlap,  // a gameplay entity intersects a wall
    Support,      // floating above, sunk into, or outside any floor
    StairSlope,   // steeper than the character can climb
    DoorGap,      // a door that does not sit in a gap between walls
    Reachability, // the control panel cannot be walked to from the player start
    Patrol,       // a robot's patrol point is not on a floor or stair surface
    RobotReach,   // a robot that can never walk to where the player starts
    Sound,        // a sound emitter or the level's ambient_sound names no file in assets/sounds
    // Level logic (logic_validation.cpp; the level's own checks, level/logic_checks.h, find them):
    LinkTarget,   // a link target or kill-list name that names nothing
    LogicLoop,    // a zero-delay loop of door links
    TriggerReach, // a trigger whose box no one it notices can walk into (reachability.cpp)
    Objective,    // an objective that can never complete, or a level with no objectives and no win link
    LockedDoor,   // a locked door that no link unlocks or opens
    Texture,      // a texture field naming no surface material in assets/textures (level/texture_names.h)
    Prefab,       // a prefab instance whose prefab file is missing or broken (prefab_validation.cpp)
    StartAmbush,  // a robot that sees the player start and can shoot within seconds (ambush_validation.cpp)
};
const char* rule_name(Rule rule);

enum class IssueSeverity { Warning, Error };

struct Issue {
    Rule rule = Rule::Format;
    IssueSeverity severity = IssueSeverity::Error;
    int entity_id = 0; // 0: the level itself or its player start
    std::string message;
    QuickFix fix;
    // Logic rules: whose links (or which objective) the issue is about and which link (-1: none), so the
    // inspector can show it; select_issue selects the owner when it is an entity.
    std::optional<LinkOwner> owner{};
    int link_index = -1;
};

struct ValidationOptions {
    CharacterLimits character;
    float support_tolerance = 0.05f; // how far above/below a surface still counts as standing on it
    float sink_limit = 1.0f;         // deeper than this under a surface, the entity belongs to a lower one
    bool check_reachability = true;
    // Cell size of the reachability check's navigation mesh, units: the bot's (nav::NavSettings). Coarser
    // cells build faster but refuse steep stairs (Recast's ledge filter) and close gaps near 2r.
    float walk_cell = 0.2f;
    // The editor window runs the walk check in a background thread on a copy of the level, so an edit never
    // waits for the mesh build; its issue shows when the check finishes (the previous result until then).
    // Scripts and tests leave it off and get the answer at once.
    bool background_reachability = false;
    // The sound names the sound rule accepts. Unset: the *.wav files in assets/sounds (core/paths), listed at
    // each validation, so a file a designer drops into the folder counts at once. An empty list (no folder,
    // no files) skips the rule: nothing to check against is no reason to fail a level.
    std::optional<std::vector<std::string>> sound_names;
};

std::vector<Issue> validate_design(const level::Level& level, const ValidationOptions& options = {});
int count_errors(const std::vector<Issue>& issues);

} // namespace ks::editor
