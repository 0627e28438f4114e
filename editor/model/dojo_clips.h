#pragma once
// The dojo panel's whole-clip edits, free of any window so tests and scripts drive them: clip management
// (new, duplicate, rename, delete, loop mode), the blend table and clip events. Each function edits an
// AnimationFile in place and leaves it unchanged when it returns an error (the message says why and how to
// fix it). Undo: wrap a call in apply_dojo_edit, which records the file before a successful edit in the
// DojoHistory as one step (dojo_keys.h).
//
// Clips are addressed by index (as dojo_keys.h does); find_clip_index turns a name into one. Blend pairs and
// `next` name clips, so rename and delete keep them in step. The clips the game needs
// (anim::required_robot_clips) cannot be deleted or renamed.
#include "anim/clip.h"
#include "anim/rig.h"
#include "core/result.h"
#include "model/dojo_keys.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace ks::editor {

// ---- undo --------------------------------------------------------------------------------------------

// Runs `edit()` (which edits `file`); when it succeeds, the file as it was before goes into `history` as one
// step named `name`. On an error nothing is recorded (the edit functions leave the file unchanged then).
template <class Edit>
auto apply_dojo_edit(anim::AnimationFile& file, DojoHistory& history, std::string name, Edit&& edit)
    -> decltype(edit()) {
    anim::AnimationFile before = file;
    auto result = edit();
    if (result) history.record(before, std::move(name));
    return result;
}

// ---- clips -------------------------------------------------------------------------------------------

// The index of the clip named `name`; the error lists the clips (with a did-you-mean for a typo).
Result<std::size_t> find_clip_index(const anim::AnimationFile& file, std::string_view name);

// A clip name is letters, digits, '_' and '-' (script words are split at spaces, and "*" is the blend
// table's wildcard). OK when `name` is such a name and no clip has it.
Result<void> check_new_clip_name(const anim::AnimationFile& file, const std::string& name);

// Why clip `clip` cannot be deleted or renamed ("the game plays 'death' when a robot dies"), or "" when it
// can (the UI disables its Delete and Rename with this as the tooltip). Deleting is also refused while
// another clip's `next` names it: delete_clip's error says which.
std::string clip_protection(const anim::AnimationFile& file, std::size_t clip);

// One node's value in a pose, as a clip target spells it: Euler XYZ degrees and the offset from the node's
// rest position.
struct NodePoseValue {
    std::string node;
    DVec3 rot{0};
    DVec3 pos{0};
};
// A Player's pose on `rig` (the editor's: the model's rig) as target values, one per rig node.
std::vector<NodePoseValue> pose_values(const anim::Rig& rig, const anim::Pose& pose);
// The pose clip `clip` of `file` reaches `seconds` after it starts from the rest pose (compiled on the
// file's own rig), as target values: what "new clip from pose" offers a script.
Result<std::vector<NodePoseValue>> clip_pose_values(const anim::AnimationFile& file, std::size_t clip,
                                                    double seconds);

inline constexpr double kNewClipSeconds = 0.5;
// Appends a clip `name` (loop "once", unlisted "rest") of one kNewClipSeconds phase; returns its index.
// With no pose the phase has no targets (the rest nodes ease home); with a pose it has one target per entry,
// setting `rot` and `pos` (every node must be in the file's rig, values finite and in range).
Result<std::size_t> new_clip(anim::AnimationFile& file, const std::string& name,
                             std::span<const NodePoseValue> pose = {});
// Inserts a copy of clip `clip` right after it, named by copy_clip_name; returns the copy's index. The copy
// has no blend pairs of its own (it blends by the wildcard pairs and the default).
Result<std::size_t> duplicate_clip(anim::AnimationFile& file, std::size_t clip);
// "idle_copy", then "idle_copy_2", "idle_copy_3", ...: the first name no clip has.
std::string copy_clip_name(const anim::AnimationFile& file, const std::string& name);
// Renames the clip and every blend pair's from/to and every clip's `next` that named it. Refused for a
// required clip and for a name check_new_clip_name refuses.
Result<void> rename_clip(anim::AnimationFile& file, std::size_t clip, const std::string& new_name);
// Removes the clip and the blend pairs naming it. Refused for a required clip, for a clip another clip's
// `next` names (the error names them), and for the file's only clip.
Result<void> delete_clip(anim::AnimationFile& file, std::size_t clip);
// Sets the loop mode; `next` (the clip played after, LoopMode::Next only, must exist) is cleared for the
// other modes. Loop and PingPong are refused for a clip of zero length.
Result<void> set_loop_mode(anim::AnimationFile& file, std::size_t clip, anim::LoopMode mode,
                           const std::string& next = {});

// "once", "loop", "ping_pong", "next" (the file's spelling) and back.
const char* loop_mode_name(anim::LoopMode mode);
Result<anim::LoopMode> loop_mode_from_name(std::string_view name);

// ---- blend table -------------------------------------------------------------------------------------

inline constexpr double kMaxBlendSeconds = 10.0;
// Each time must be finite and in [0, kMaxBlendSeconds].
Result<void> set_default_blend(anim::AnimationFile& file, double seconds);
// Sets the from -> to cell: updates the pair naming exactly from and to, else appends one. Either name may
// be "*" (any clip); otherwise it must be a clip of the file.
Result<void> set_blend(anim::AnimationFile& file, const std::string& from, const std::string& to,
                       double seconds);
// Removes the pair naming exactly from and to: the cell falls back to a wildcard pair or the default. An
// error when there is none (the hint says where the cell's time comes from).
Result<void> clear_blend(anim::AnimationFile& file, const std::string& from, const std::string& to);

// The blend time the game uses for every from -> to pair of clips (anim::compile's rule: a pair naming both
// clips beats wildcard pairs, a later pair beats an earlier one of the same kind), and where it comes from.
struct BlendCell {
    enum class Source : std::uint8_t { Default, Wildcard, Explicit };
    double seconds = 0;
    Source source = Source::Default;
};
struct BlendGrid {
    std::vector<std::string> clips; // the file's clips, in order: rows (from) and columns (to)
    std::vector<BlendCell> cells;   // clips.size()^2, row-major
    double default_seconds = 0;
    const BlendCell& at(std::size_t from, std::size_t to) const { return cells[from * clips.size() + to]; }
};
BlendGrid blend_grid(const anim::AnimationFile& file);
// The grid's column headers: a name that fits `max_chars` (at least 3) stays whole; a longer one keeps its
// start and its end around a '.' ("shoot_pose_reverse" at 8: "shoo.rse"), since clip names often differ
// at the end; names whose cuts would still read the same get their row number instead ("#4").
std::vector<std::string> short_clip_labels(const std::vector<std::string>& names, std::size_t max_chars);

// ---- clip events -------------------------------------------------------------------------------------

// Events are kept sorted by time (equal times keep their order); each edit returns the event's index after
// sorting. Names are non-empty; sounds are empty (none) or a-z, 0-9 and _ (a file of assets/sounds/).
// Adds an event at `seconds` (inside the clip: 0..duration).
Result<std::size_t> add_event(anim::AnimationFile& file, std::size_t clip, double seconds,
                              const std::string& name, const std::string& sound = {});
// Moves an event to `seconds`, clamped into the clip (a drag past the end stops at it).
Result<std::size_t> move_event(anim::AnimationFile& file, std::size_t clip, std::size_t event,
                               double seconds);
Result<void> rename_event(anim::AnimationFile& file, std::size_t clip, std::size_t event,
                          const std::string& name);
Result<void> set_event_sound(anim::AnimationFile& file, std::size_t clip, std::size_t event,
                             const std::string& sound);
Result<void> remove_event(anim::AnimationFile& file, std::size_t clip, std::size_t event);

} // namespace ks::editor
