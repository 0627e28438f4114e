// Keying a pose at the playhead (dojo_pose_keys.h).
#include "model/dojo_pose_keys.h"

#include "model/dojo_clips.h"
#include "model/dojo_edit_support.h"
#include "model/dojo_keys.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ks::editor {

namespace {
using dojo_support::clip_at;
using dojo_support::seconds_text;

const NodePoseValue* value_of(const std::vector<NodePoseValue>& pose, const std::string& node) {
    const auto it =
        std::find_if(pose.begin(), pose.end(), [&](const NodePoseValue& v) { return v.node == node; });
    return it == pose.end() ? nullptr : &*it;
}

bool differs(const DVec3& a, const DVec3& b) {
    return glm::length(a - b) > 1e-9;
}

// Splits phase `phase` (from `start` to its end) at `seconds`: a new phase before it ends there, keying every
// node the phase moves to its value then; returns nothing, the new phase takes index `phase`.
Result<void> split_phase(anim::AnimationFile& file, std::size_t clip, std::size_t phase, double start,
                         double seconds) {
    auto at_start = clip_pose_values(file, clip, start);
    auto at_split = clip_pose_values(file, clip, seconds);
    if (!at_start) return at_start.error();
    if (!at_split) return at_split.error();
    anim::ClipDef& def = file.clips[clip];
    anim::PhaseDef second = def.phases[phase];
    anim::PhaseDef first;
    first.duration = snap(seconds - start, kTimeSteps);
    first.ease = second.ease;
    second.duration = snap(second.duration - first.duration, kTimeSteps);
    for (anim::TargetDef& target : second.targets) {
        const NodePoseValue* from = value_of(*at_start, target.node);
        const NodePoseValue* here = value_of(*at_split, target.node);
        if (!from || !here) return Error("node '" + target.node + "' is not in the rig", {}, "");
        anim::TargetDef half;
        half.node = target.node;
        half.ease = target.ease;
        if (target.rot) half.rot = snap(here->rot, kValueSteps);
        if (target.add_rot) {
            half.add_rot = snap(here->rot - from->rot, kValueSteps);
            target.add_rot = snap(*target.add_rot - *half.add_rot, kValueSteps);
        }
        if (target.pos) half.pos = snap(here->pos, kValueSteps);
        if (target.add_pos) {
            half.add_pos = snap(here->pos - from->pos, kValueSteps);
            target.add_pos = snap(*target.add_pos - *half.add_pos, kValueSteps);
        }
        first.targets.push_back(std::move(half));
    }
    // Nodes the phase does not name but still moves (the rest rule easing them home) are held at the split.
    for (const NodePoseValue& here : *at_split) {
        const bool named = std::any_of(second.targets.begin(), second.targets.end(),
                                       [&](const anim::TargetDef& t) { return t.node == here.node; });
        const NodePoseValue* from = value_of(*at_start, here.node);
        if (named || !from || (!differs(from->rot, here.rot) && !differs(from->pos, here.pos))) continue;
        anim::TargetDef hold;
        hold.node = here.node;
        hold.rot = snap(here.rot, kValueSteps);
        if (differs(from->pos, here.pos)) hold.pos = snap(here.pos, kValueSteps);
        first.targets.push_back(std::move(hold));
    }
    def.phases[phase] = std::move(second);
    def.phases.insert(def.phases.begin() + static_cast<std::ptrdiff_t>(phase), std::move(first));
    return {};
}

// The phase whose end is at `seconds`, after splitting the one that holds it when none ends there.
Result<std::size_t> key_phase_at(anim::AnimationFile& file, std::size_t clip, double seconds) {
    const anim::ClipDef& def = file.clips[clip];
    double start = 0.0;
    for (std::size_t p = 0; p < def.phases.size(); ++p) {
        const double end = start + def.phases[p].duration;
        if (std::abs(end - seconds) <= kKeyTimeTolerance) return p;
        if (seconds < end) {
            if (auto split = split_phase(file, clip, p, start, seconds); !split) return split.error();
            return p;
        }
        start = end;
    }
    return Error("no key time at " + seconds_text(seconds), {}, "");
}

anim::TargetDef* target_of(anim::PhaseDef& phase, const std::string& node) {
    const auto it = std::find_if(phase.targets.begin(), phase.targets.end(),
                                 [&](const anim::TargetDef& t) { return t.node == node; });
    return it == phase.targets.end() ? nullptr : &*it;
}
} // namespace

Result<std::size_t> key_rotations_at(anim::AnimationFile& file, std::size_t clip, double seconds,
                                     std::span<const NodeRotation> rotations) {
    auto found = clip_at(file, clip);
    if (!found) return found.error();
    const double duration = (*found)->duration();
    if (rotations.empty()) return Error("nothing to key", {}, "select a node (click its joint) first");
    if (!std::isfinite(seconds) || seconds < -kKeyTimeTolerance || seconds > duration + kKeyTimeTolerance)
        return Error("the playhead (" + seconds_text(seconds) + ") is outside clip '" + (*found)->name + "'",
                     {}, "move it into the clip (0.." + seconds_text(duration) + ")");
    if (seconds <= kKeyTimeTolerance)
        return Error("the clip's start is not a key: a clip starts from the pose it is entered in", {},
                     "move the playhead to a key or between two keys");
    for (const NodeRotation& r : rotations) {
        if (std::none_of(file.rig.begin(), file.rig.end(),
                         [&](const anim::RigNodeDef& n) { return n.name == r.node; }))
            return Error("node '" + r.node + "' is not in the rig", {}, "pick one of the rig's nodes");
        if (!std::isfinite(r.degrees.x) || !std::isfinite(r.degrees.y) || !std::isfinite(r.degrees.z))
            return Error("node '" + r.node + "' has a rotation that is not a number", {}, "");
    }
    anim::AnimationFile edited = file;
    auto phase = key_phase_at(edited, clip, snap(std::min(seconds, duration), kTimeSteps));
    if (!phase) return phase.error();
    // A relative key's offset is counted from the value at its phase's start (the previous key's value).
    double start = 0.0;
    for (std::size_t p = 0; p < *phase; ++p) start += edited.clips[clip].phases[p].duration;
    auto before = clip_pose_values(edited, clip, start);
    if (!before) return before.error();
    anim::PhaseDef& key = edited.clips[clip].phases[*phase];
    for (const NodeRotation& r : rotations) {
        const DVec3 value = snap(r.degrees, kValueSteps);
        anim::TargetDef* target = target_of(key, r.node);
        if (!target) {
            anim::TargetDef made;
            made.node = r.node;
            made.rot = value;
            key.targets.push_back(std::move(made));
        } else if (target->add_rot) {
            const NodePoseValue* from = value_of(*before, r.node);
            target->add_rot = snap(value - (from ? from->rot : DVec3(0.0)), kValueSteps);
        } else {
            target->rot = value;
        }
    }
    if (auto r = dojo_support::no_new_clip_issues(file, edited, clip); !r) return r.error();
    file = std::move(edited);
    return *phase;
}

std::string key_step_name(std::span<const NodeRotation> rotations, double seconds) {
    char at[48];
    std::snprintf(at, sizeof(at), " at %.2f s", seconds);
    if (rotations.size() == 1) return "Key " + rotations.front().node + at;
    return "Key " + std::to_string(rotations.size()) + " nodes" + at;
}

} // namespace ks::editor
