#pragma once
// The script language's dojo steps: commands on an animation clip file (`dojo open`, `clip ...`,
// `blend ...`, `event ...`, `key ...`) and its expectations, parsed and registered by
// script_dojo_parser.cpp and run on the script's DojoDocument by script_dojo_runner.cpp (every step but
// `dojo open` needs an open file). Clips and nodes are named; keys and events count from 1, as the panel
// shows them; a channel is its name (rot.x ... pos.z), checked when parsed.
#include "core/result.h"

#include <optional>
#include <string>
#include <variant>

namespace ks::editor {

struct ScriptContext;

namespace steps {

// ---- the file and its history (count -1: all) ---------------------------------------------------------
struct DojoOpen {
    std::string path; // empty: the robot's clips
    Result<void> run(ScriptContext& c) const;
};
struct DojoSave {
    std::string path; // empty: the opened file
    Result<void> run(ScriptContext& c) const;
};
// glTF for Blender (dojo_gltf.h): every clip, or the one named, written with the file's rig; a glTF's node
// animations read into clips (what did not map goes to the log).
struct DojoExport {
    std::string path, clip; // clip empty: every clip
    Result<void> run(ScriptContext& c) const;
};
struct DojoImport {
    std::string path;
    Result<void> run(ScriptContext& c) const;
};
struct DojoUndo {
    int count = 1;
    Result<void> run(ScriptContext& c) const;
};
struct DojoRedo {
    int count = 1;
    Result<void> run(ScriptContext& c) const;
};

// ---- clips --------------------------------------------------------------------------------------------
struct ClipNew {
    std::string name, from;        // from empty: an empty key
    std::optional<double> seconds; // the pose `from` reaches then (default: its end)
    Result<void> run(ScriptContext& c) const;
};
struct ClipDuplicate {
    std::string clip;
    Result<void> run(ScriptContext& c) const;
};
struct ClipRename {
    std::string clip, name;
    Result<void> run(ScriptContext& c) const;
};
struct ClipDelete {
    std::string clip;
    Result<void> run(ScriptContext& c) const;
};
struct ClipLoop {
    std::string clip, mode, next; // next: with mode next only
    Result<void> run(ScriptContext& c) const;
};

// ---- the blend table ----------------------------------------------------------------------------------
struct BlendDefault {
    double seconds = 0;
    Result<void> run(ScriptContext& c) const;
};
struct BlendSet {
    std::string from, to;
    double seconds = 0;
    Result<void> run(ScriptContext& c) const;
};
struct BlendClear {
    std::string from, to;
    Result<void> run(ScriptContext& c) const;
};

// ---- events -------------------------------------------------------------------------------------------
struct EventAdd {
    std::string clip;
    double time = 0;
    std::string name, sound; // sound empty: none
    Result<void> run(ScriptContext& c) const;
};
struct EventMove {
    std::string clip;
    int event = 1;
    double time = 0;
    Result<void> run(ScriptContext& c) const;
};
struct EventRename {
    std::string clip;
    int event = 1;
    std::string name;
    Result<void> run(ScriptContext& c) const;
};
struct EventSound {
    std::string clip;
    int event = 1;
    std::string sound; // "none" clears it
    Result<void> run(ScriptContext& c) const;
};
struct EventRemove {
    std::string clip;
    int event = 1;
    Result<void> run(ScriptContext& c) const;
};

// ---- keys ---------------------------------------------------------------------------------------------
struct KeyTime {
    std::string clip;
    int key = 1;
    double seconds = 0;
    Result<void> run(ScriptContext& c) const;
};
struct KeyValue {
    std::string clip;
    int key = 1;
    std::string node, channel;
    double value = 0;
    Result<void> run(ScriptContext& c) const;
};
struct KeyAdd {
    std::string clip;
    int key = 1;
    std::string node;
    Result<void> run(ScriptContext& c) const;
};
struct KeyRemove {
    std::string clip;
    int key = 1;
    std::string node;
    Result<void> run(ScriptContext& c) const;
};

// ---- expectations -------------------------------------------------------------------------------------
struct ExpectClipExists {
    std::string clip;
    bool exists = true; // false: `missing`
    Result<void> run(ScriptContext& c) const;
};
struct ExpectClipLoop {
    std::string clip, mode, next;
    Result<void> run(ScriptContext& c) const;
};
struct ExpectClipDuration {
    std::string clip;
    double seconds = 0;
    Result<void> run(ScriptContext& c) const;
};
struct ExpectBlend {
    std::string from, to;
    double seconds = 0;
    Result<void> run(ScriptContext& c) const;
};
struct ExpectEvents {
    std::string clip;
    int count = 0;
    Result<void> run(ScriptContext& c) const;
};
struct ExpectEvent {
    std::string clip;
    int event = 1;
    double time = 0;
    std::optional<std::string> name, sound; // sound "none": no sound
    Result<void> run(ScriptContext& c) const;
};
struct ExpectKeyTime {
    std::string clip;
    int key = 1;
    double seconds = 0;
    Result<void> run(ScriptContext& c) const;
};
struct ExpectKeyValue {
    std::string clip;
    int key = 1;
    std::string node, channel;
    double value = 0;
    Result<void> run(ScriptContext& c) const;
};
struct ExpectCurve {
    std::string clip, node, channel;
    double time = 0, value = 0;
    Result<void> run(ScriptContext& c) const;
};
struct ExpectDojoValid {
    Result<void> run(ScriptContext& c) const;
};
struct ExpectDojoIssue {
    std::string text; // a part of the issue's message
    Result<void> run(ScriptContext& c) const;
};
struct ExpectDojoDirty {
    bool dirty = true; // false: `clean`
    Result<void> run(ScriptContext& c) const;
};

} // namespace steps

struct DojoStep {
    std::variant<steps::DojoOpen, steps::DojoSave, steps::DojoExport, steps::DojoImport, steps::DojoUndo,
                 steps::DojoRedo, steps::ClipNew, steps::ClipDuplicate, steps::ClipRename, steps::ClipDelete,
                 steps::ClipLoop, steps::BlendDefault, steps::BlendSet, steps::BlendClear, steps::EventAdd,
                 steps::EventMove, steps::EventRename, steps::EventSound, steps::EventRemove, steps::KeyTime,
                 steps::KeyValue, steps::KeyAdd, steps::KeyRemove, steps::ExpectClipExists,
                 steps::ExpectClipLoop, steps::ExpectClipDuration, steps::ExpectBlend, steps::ExpectEvents,
                 steps::ExpectEvent, steps::ExpectKeyTime, steps::ExpectKeyValue, steps::ExpectCurve,
                 steps::ExpectDojoValid, steps::ExpectDojoIssue, steps::ExpectDojoDirty>
        step;
    // Every step but DojoOpen refuses to run before a clip file is open.
    Result<void> run(ScriptContext& c) const;
};

} // namespace ks::editor
