#include "model/dojo_clips.h"

#include "anim/clip_issues.h"
#include "anim/player.h"
#include "anim/required_clips.h"
#include "model/dojo_edit_support.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ks::editor {
namespace {
using dojo_support::clip_at;
using dojo_support::clip_list;

std::vector<std::string> clip_names(const anim::AnimationFile& file) {
    std::vector<std::string> names;
    for (const anim::ClipDef& c : file.clips) names.push_back(c.name);
    return names;
}

bool is_name_char(char ch) {
    return (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') || ch == '_' ||
           ch == '-';
}

// Clips whose `next` names `name` (other than the clip itself), quoted and comma-separated; "" for none.
std::string clips_leading_to(const anim::AnimationFile& file, const std::string& name) {
    std::string out;
    for (const anim::ClipDef& c : file.clips)
        if (c.loop == anim::LoopMode::Next && c.next == name && c.name != name)
            out += (out.empty() ? "'" : ", '") + c.name + "'";
    return out;
}

} // namespace

Result<std::size_t> find_clip_index(const anim::AnimationFile& file, std::string_view name) {
    for (std::size_t i = 0; i < file.clips.size(); ++i)
        if (file.clips[i].name == name) return i;
    return Error("no clip '" + std::string(name) + "'", {},
                 anim::did_you_mean(name, clip_names(file)) + clip_list(file));
}

Result<void> check_new_clip_name(const anim::AnimationFile& file, const std::string& name) {
    if (name.empty()) return Error("a clip needs a name", {}, "e.g. wave_hello");
    if (!std::all_of(name.begin(), name.end(), is_name_char))
        return Error("clip name '" + name + "' has characters other than letters, digits, _ and -", {},
                     "e.g. wave_hello (no spaces; * is the blend table's 'any clip')");
    if (file.find_clip(name))
        return Error("a clip named '" + name + "' already exists", {},
                     "pick another name, e.g. '" + copy_clip_name(file, name) + "'");
    return ok();
}

std::string clip_protection(const anim::AnimationFile& file, std::size_t clip) {
    if (clip >= file.clips.size()) return {};
    const anim::RequiredClip* required = anim::find_required_clip(file.clips[clip].name);
    return required ? required->reason : std::string();
}

std::vector<NodePoseValue> pose_values(const anim::Rig& rig, const anim::Pose& pose) {
    std::vector<NodePoseValue> out;
    for (int i = 0; i < rig.size() && i < pose.size(); ++i) {
        const auto n = static_cast<std::size_t>(i);
        NodePoseValue v;
        v.node = rig.node(i).name;
        v.rot = DVec3(pose.euler[n]) * kDegreesPerRadian;
        v.pos = DVec3(pose.position[n] - rig.node(i).rest_position);
        out.push_back(std::move(v));
    }
    return out;
}

Result<std::vector<NodePoseValue>> clip_pose_values(const anim::AnimationFile& file, std::size_t clip,
                                                    double seconds) {
    if (auto found = clip_at(file, clip); !found) return found.error();
    if (!std::isfinite(seconds) || seconds < 0)
        return Error("pose time " + dojo_support::seconds_text(seconds) + " is not a time in the clip", {},
                     "seconds from the clip's start, 0 or more");
    auto rig = anim::build_rig(file);
    if (!rig) return rig.error();
    auto clips = anim::compile(file, *rig);
    if (!clips) return clips.error();
    anim::Pose pose;
    pose.set_rest(*rig);
    const std::vector<Vec3> rest_euler = pose.euler, rest_position = pose.position;
    anim::sample_clip(clips->clips[clip], rest_euler, rest_position, seconds, pose.euler, pose.position);
    return pose_values(*rig, pose);
}

Result<std::size_t> new_clip(anim::AnimationFile& file, const std::string& name,
                             std::span<const NodePoseValue> pose) {
    if (auto r = check_new_clip_name(file, name); !r) return r.error();
    anim::ClipDef clip;
    clip.name = name;
    anim::PhaseDef phase;
    phase.duration = kNewClipSeconds;
    for (const NodePoseValue& v : pose) {
        if (std::any_of(phase.targets.begin(), phase.targets.end(),
                        [&](const anim::TargetDef& t) { return t.node == v.node; }))
            return Error("the pose lists node '" + v.node + "' twice", {}, "one value per node");
        anim::TargetDef target;
        target.node = v.node;
        target.rot = v.rot;
        target.pos = v.pos;
        phase.targets.push_back(std::move(target));
    }
    clip.phases.push_back(std::move(phase));
    anim::AnimationFile edited = file;
    edited.clips.push_back(std::move(clip));
    if (auto valid = dojo_support::no_new_clip_issues(file, edited, edited.clips.size() - 1); !valid)
        return Error("cannot make clip '" + name + "' from this pose: " + valid.error().message, {},
                     valid.error().hint);
    file = std::move(edited);
    return file.clips.size() - 1;
}

std::string copy_clip_name(const anim::AnimationFile& file, const std::string& name) {
    std::string candidate = name + "_copy";
    for (int n = 2; file.find_clip(candidate); ++n) candidate = name + "_copy_" + std::to_string(n);
    return candidate;
}

Result<std::size_t> duplicate_clip(anim::AnimationFile& file, std::size_t clip) {
    auto found = clip_at(file, clip);
    if (!found) return found.error();
    anim::ClipDef copy = **found;
    copy.name = copy_clip_name(file, copy.name);
    file.clips.insert(file.clips.begin() + static_cast<std::ptrdiff_t>(clip) + 1, std::move(copy));
    return clip + 1;
}

Result<void> rename_clip(anim::AnimationFile& file, std::size_t clip, const std::string& new_name) {
    auto found = clip_at(file, clip);
    if (!found) return found.error();
    const std::string old_name = (*found)->name;
    if (new_name == old_name) return ok();
    if (const anim::RequiredClip* required = anim::find_required_clip(old_name))
        return Error("cannot rename '" + old_name + "': " + required->reason, {},
                     "duplicate it and rename the copy instead");
    if (auto r = check_new_clip_name(file, new_name); !r) return r;
    (*found)->name = new_name;
    for (anim::ClipDef& c : file.clips)
        if (c.next == old_name) c.next = new_name;
    for (anim::BlendPair& pair : file.blends) {
        if (pair.from == old_name) pair.from = new_name;
        if (pair.to == old_name) pair.to = new_name;
    }
    return ok();
}

Result<void> delete_clip(anim::AnimationFile& file, std::size_t clip) {
    auto found = clip_at(file, clip);
    if (!found) return found.error();
    const std::string name = (*found)->name;
    if (const anim::RequiredClip* required = anim::find_required_clip(name))
        return Error("cannot delete '" + name + "': " + required->reason, {},
                     "the robot needs it; edit its keys instead");
    if (const std::string leading = clips_leading_to(file, name); !leading.empty())
        return Error("cannot delete '" + name + "': " + leading + " play" +
                         (leading.find(',') == std::string::npos ? "s" : "") + " it next",
                     {}, "set their loop mode to something else first");
    if (file.clips.size() == 1)
        return Error("cannot delete '" + name + "': it is the file's only clip", {},
                     "add another clip first");
    file.clips.erase(file.clips.begin() + static_cast<std::ptrdiff_t>(clip));
    std::erase_if(file.blends, [&](const anim::BlendPair& p) { return p.from == name || p.to == name; });
    return ok();
}

Result<void> set_loop_mode(anim::AnimationFile& file, std::size_t clip, anim::LoopMode mode,
                           const std::string& next) {
    auto found = clip_at(file, clip);
    if (!found) return found.error();
    anim::ClipDef& c = **found;
    if (mode == anim::LoopMode::Next) {
        if (next.empty()) return Error("loop mode 'next' needs the clip to play next", {}, clip_list(file));
        if (auto target = find_clip_index(file, next); !target) return target.error();
    } else if (!next.empty()) {
        return Error("only loop mode 'next' plays another clip after this one", {},
                     "leave the next clip out, or choose 'next'");
    }
    if ((mode == anim::LoopMode::Loop || mode == anim::LoopMode::PingPong) && !(c.duration() > 0))
        return Error("clip '" + c.name + "' has zero length, so it cannot " +
                         (mode == anim::LoopMode::Loop ? "loop" : "ping-pong"),
                     {}, "give a key a duration > 0 first");
    anim::AnimationFile edited = file;
    edited.clips[clip].loop = mode;
    edited.clips[clip].next = mode == anim::LoopMode::Next ? next : std::string();
    if (auto valid = dojo_support::no_new_clip_issues(file, edited, clip); !valid) return valid;
    file = std::move(edited);
    return ok();
}

const char* loop_mode_name(anim::LoopMode mode) {
    switch (mode) {
    case anim::LoopMode::Once:
        return "once";
    case anim::LoopMode::Loop:
        return "loop";
    case anim::LoopMode::Next:
        return "next";
    case anim::LoopMode::PingPong:
        return "ping_pong";
    }
    return "once";
}

Result<anim::LoopMode> loop_mode_from_name(std::string_view name) {
    for (anim::LoopMode m :
         {anim::LoopMode::Once, anim::LoopMode::Loop, anim::LoopMode::PingPong, anim::LoopMode::Next})
        if (name == loop_mode_name(m)) return m;
    return Error("unknown loop mode '" + std::string(name) + "'", {},
                 anim::did_you_mean(name, {"once", "loop", "ping_pong", "next"}) +
                     "one of once, loop, ping_pong, next");
}

} // namespace ks::editor
