#pragma once
// The dojo panel's key edits, free of any window so tests drive them: add or remove a node's key in one
// phase of a clip (a phase is a key time on every node's track; a node's key there is its TargetDef), an
// undo/redo history of whole-file snapshots (animation files are a few kilobytes), and a save that
// validates before it writes atomically.
#include "anim/clip.h"
#include "anim/clip_io.h"
#include "core/result.h"

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace ks::editor {

// Adds a key for `node` in phase `phase` of clip `clip`: an absolute rotation (and position, when the clip
// moves the node) at the value the node reaches there now (key_values), so no pose of the clip changes
// until the animator edits the key. Errors (file unchanged) on an index out of range, a node the rig does
// not define, or a node already keyed in that phase.
Result<void> add_node_key(anim::AnimationFile& file, std::size_t clip, std::size_t phase,
                          const std::string& node);
// Removes `node`'s key from that phase; errors (file unchanged) when there is none.
Result<void> remove_node_key(anim::AnimationFile& file, std::size_t clip, std::size_t phase,
                             const std::string& node);
// Rig nodes that have no key in that phase (what "add key" offers), in rig order; empty when out of range.
std::vector<std::string> unkeyed_nodes(const anim::AnimationFile& file, std::size_t clip, std::size_t phase);

// Phase (key time) edits. A phase is one step of the clip: a duration, an easing and its node keys.
// Duplicates phase `phase` right after itself as a pause: absolute keys hold their values, relative ones
// become offsets of zero, so the pose holds for the copy's duration and every later key reaches what it
// did; returns the copy's index. Errors (file unchanged) out of range.
Result<std::size_t> duplicate_phase(anim::AnimationFile& file, std::size_t clip, std::size_t phase);
// Removes a phase; a clip keeps at least one (validation requires it), so removing the last one errors.
Result<void> remove_phase(anim::AnimationFile& file, std::size_t clip, std::size_t phase);
// Swaps a phase with its neighbour (offset -1: earlier, +1: later); returns its new index. Errors (file
// unchanged) when the neighbour does not exist.
Result<std::size_t> move_phase(anim::AnimationFile& file, std::size_t clip, std::size_t phase, int offset);

// Keys hold absolute values (docs/animation.md, "Independent keys"): editing one never moves another.
// The value `node`'s rotation (Euler degrees) or position (offset from rest) reaches at the end of each
// phase of `clip` when the clip plays from the rest pose (the dojo's start and the game's), resolved as
// anim::compile does (absolute, relative to the phase's start, home under the rest rule, or held), in
// double. Empty when the clip or node does not exist.
std::vector<DVec3> key_values(const anim::AnimationFile& file, std::size_t clip, const std::string& node,
                              bool position);
// Makes every relative key (add_rot / add_pos) absolute with the value it reaches (key_values, snapped to
// kValueSteps), so the clips play the same poses from rest. Kept relative, where the format needs them:
// the rig's root nodes (an offset from where the robot stands and faces: the death spin) and a looping
// clip's channel whose pass does not end where it began (each pass carries on from the last). Returns how
// many targets changed. The dojo runs it on every file it opens.
std::size_t make_keys_absolute(anim::AnimationFile& file);

// The grids the dojo keeps values and times on, as steps per unit, so that a file is saved as it was
// typed (0.2, not 0.19999999999999996, nor a float widget's 0.30000001192092896): computed key values to
// 1e-9 (degrees or units), times to a microsecond, the key table's fields to a thousandth of a degree and
// 1e-5 units. snap(v, steps) is the nearest double to round(v * steps) / steps.
constexpr double kValueSteps = 1e9, kTimeSteps = 1e6, kDegreeFieldSteps = 1e3, kUnitFieldSteps = 1e5;
double snap(double value, double steps);
DVec3 snap(const DVec3& value, double steps);

// Unlimited undo/redo of the dojo's edits: record(before) ahead of every edit; a new edit drops the redo
// steps. Continuous edits (a dragged field) record once when the drag starts.
class DojoHistory {
  public:
    void record(const anim::AnimationFile& before, std::string name);
    bool undo(anim::AnimationFile& file); // false when there is nothing to undo
    bool redo(anim::AnimationFile& file);
    bool can_undo() const { return !undo_.empty(); }
    bool can_redo() const { return !redo_.empty(); }
    std::size_t undo_count() const { return undo_.size(); }
    std::size_t redo_count() const { return redo_.size(); }
    const std::string& undo_name() const;
    const std::string& redo_name() const;
    // Every step's name, oldest first: the undo steps, then the redo steps (the History panel's list).
    std::vector<std::string> step_names() const;
    void clear();

  private:
    struct Step {
        anim::AnimationFile file;
        std::string name;
    };
    std::vector<Step> undo_, redo_;
};

// What the dojo checks live and before saving: anim::validate (durations, finite values, events inside their
// clip, ...) and then anim::check_required_clips (the robot's clips the game and the Dojo play).
std::vector<anim::Issue> dojo_file_issues(const anim::AnimationFile& file);

// Checks `file` (dojo_file_issues) and writes it atomically; on issues nothing is written and the error
// names the file, the first issue's JSON path, its message and fix, and how many issues there are.
Result<void> save_dojo_file(const std::filesystem::path& path, const anim::AnimationFile& file);

} // namespace ks::editor
