#include "model/dojo_curves.h"

#include "anim/player.h"
#include "jsonio/number_text.h"
#include "model/dojo_edit_support.h"
#include "model/dojo_keys.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ks::editor {
namespace {
using dojo_support::clip_at;
using dojo_support::seconds_text;

constexpr const char* kChannelNames[] = {"rot.x", "rot.y", "rot.z", "pos.x", "pos.y", "pos.z"};

Result<anim::PhaseDef*> phase_at(anim::AnimationFile& file, std::size_t clip, std::size_t phase) {
    auto found = clip_at(file, clip);
    if (!found) return found.error();
    auto& phases = (*found)->phases;
    if (phase >= phases.size())
        return Error("clip '" + (*found)->name + "' has no key " + std::to_string(phase + 1), {},
                     "it has " + std::to_string(phases.size()) + " keys");
    return &phases[phase];
}

const anim::TargetDef* target_for(const anim::PhaseDef& phase, const std::string& node) {
    for (const anim::TargetDef& t : phase.targets)
        if (t.node == node) return &t;
    return nullptr;
}

// The channel's value as the curve shows it: degrees, or the offset from the rest position.
double shown(CurveChannel channel, const Vec3& value, const anim::RigNode& node) {
    const int c = component(channel);
    return is_position(channel) ? static_cast<double>(value[c] - node.rest_position[c])
                                : static_cast<double>(value[c]) * kDegreesPerRadian;
}

// The easing of the segment ending at this phase for `node` (anim::compile's rule).
anim::Ease segment_ease(const anim::AnimationFile& file, const anim::PhaseDef& phase,
                        const std::string& node) {
    if (const anim::TargetDef* t = target_for(phase, node); t && t->ease) return *t->ease;
    for (const anim::NodeEase& ne : file.node_ease)
        if (ne.node == node) return ne.ease;
    return phase.ease;
}

const anim::Channel* find_channel(const anim::Clip& clip, int node, bool position) {
    for (const anim::Channel& ch : clip.channels)
        if (ch.node == node && ch.is_position == position) return &ch;
    return nullptr;
}

void fill_keys(const anim::AnimationFile& file, const anim::ClipDef& def, const anim::Clip& compiled,
               const anim::RigNode& rig_node, int node, CurveChannel channel, const Vec3& start,
               ClipCurve& curve) {
    const bool position = is_position(channel);
    const anim::Channel* ch = find_channel(compiled, node, position);
    double time = 0;
    for (std::size_t p = 0; p < def.phases.size(); ++p) {
        const anim::PhaseDef& phase = def.phases[p];
        time += phase.duration;
        CurveKey key;
        key.phase = p;
        key.time = time;
        key.ease = segment_ease(file, phase, rig_node.name);
        Vec3 value = start;
        if (ch) { // compiled keys: [first_key] is the start, then one per phase
            const anim::Key& k = compiled.keys[ch->first_key + 1 + p];
            value = k.mode == anim::KeyMode::Absolute ? k.value : start + k.value;
        }
        key.value = shown(channel, value, rig_node);
        if (const anim::TargetDef* t = target_for(phase, rig_node.name)) {
            const auto& absolute = position ? t->pos : t->rot;
            const auto& relative = position ? t->add_pos : t->add_rot;
            key.keyed = absolute || relative;
            key.relative = !absolute && relative;
            if (key.keyed) key.target_value = (absolute ? *absolute : *relative)[component(channel)];
        }
        curve.keys.push_back(key);
    }
}

// The file compiled on its own rig, with the rest pose clips start from and the node's index.
struct CompiledClips {
    anim::Rig rig;
    anim::ClipSet clips;
    anim::Pose rest;
    int node = -1;
    mutable std::vector<Vec3> euler, position; // sampling scratch

    double sample(std::size_t clip, CurveChannel channel, double t) const {
        anim::sample_clip(clips.clips[clip], rest.euler, rest.position, t, euler, position);
        const auto n = static_cast<std::size_t>(node);
        return shown(channel, is_position(channel) ? position[n] : euler[n], rig.node(node));
    }
};

Result<int> node_index(const anim::Rig& rig, const std::string& node) {
    const int index = rig.find(node);
    if (index >= 0) return index;
    std::string names;
    for (const anim::RigNode& n : rig.nodes()) names += (names.empty() ? "" : ", ") + n.name;
    return Error("node '" + node + "' is not in the rig", {}, "nodes: " + names);
}

Result<CompiledClips> compile_for(const anim::AnimationFile& file, std::size_t clip,
                                  const std::string& node) {
    if (auto found = clip_at(file, clip); !found) return found.error();
    auto rig = anim::build_rig(file);
    if (!rig) return rig.error();
    CompiledClips out;
    auto index = node_index(*rig, node);
    if (!index) return index.error();
    out.node = *index;
    auto clips = anim::compile(file, *rig);
    if (!clips) return clips.error();
    out.clips = std::move(clips).value();
    out.rig = std::move(rig).value();
    out.rest.set_rest(out.rig);
    out.euler = out.rest.euler;
    out.position = out.rest.position;
    return out;
}

} // namespace

void keep_later_keys(anim::AnimationFile& file, std::size_t clip, std::size_t phase, const std::string& node,
                     CurveChannel channel, double delta) {
    anim::ClipDef& def = file.clips[clip];
    const bool rest_rule =
        def.unlisted == anim::UnlistedRule::Rest &&
        std::find(file.rest_nodes.begin(), file.rest_nodes.end(), node) != file.rest_nodes.end();
    const bool position = is_position(channel);
    for (std::size_t p = phase + 1; p < def.phases.size(); ++p) {
        anim::TargetDef* t = nullptr;
        for (anim::TargetDef& candidate : def.phases[p].targets)
            if (candidate.node == node) t = &candidate;
        if (!t) {
            if (rest_rule) return; // home again: what follows does not depend on the edited key
            continue;              // held
        }
        if (position ? t->pos : t->rot) return;
        auto& offset = position ? t->add_pos : t->add_rot;
        if (!offset) continue; // keyed for the other kind only: this channel holds
        (*offset)[component(channel)] -= delta;
        return;
    }
}

const char* curve_channel_name(CurveChannel c) {
    return kChannelNames[static_cast<int>(c)];
}

std::optional<CurveChannel> curve_channel_from_name(std::string_view name) {
    for (int i = 0; i < 6; ++i)
        if (name == kChannelNames[i]) return static_cast<CurveChannel>(i);
    return std::nullopt;
}

namespace {
ClipCurve sampled_curve(const anim::AnimationFile& file, std::size_t clip, const CompiledClips* compiled,
                        CurveChannel channel, int samples);
} // namespace

Result<ClipCurve> clip_curve(const anim::AnimationFile& file, std::size_t clip, const std::string& node,
                             CurveChannel channel, int samples) {
    auto compiled = compile_for(file, clip, node);
    if (!compiled) return compiled.error();
    return sampled_curve(file, clip, &*compiled, channel, samples);
}

Result<std::vector<ClipCurve>> clip_curves(const anim::AnimationFile& file, std::size_t clip,
                                           std::span<const NodeChannel> channels, int samples) {
    std::vector<ClipCurve> curves;
    if (channels.empty()) {
        if (auto found = clip_at(file, clip); !found) return found.error();
        return curves;
    }
    auto compiled = compile_for(file, clip, channels.front().node);
    if (!compiled) return compiled.error();
    for (const NodeChannel& channel : channels) {
        auto index = node_index(compiled->rig, channel.node);
        if (!index) return index.error();
        compiled->node = *index;
        curves.push_back(sampled_curve(file, clip, &*compiled, channel.channel, samples));
    }
    return curves;
}

namespace {
ClipCurve sampled_curve(const anim::AnimationFile& file, std::size_t clip, const CompiledClips* compiled,
                        CurveChannel channel, int samples) {
    const anim::Clip& c = compiled->clips.clips[clip];
    const anim::RigNode& rig_node = compiled->rig.node(compiled->node);
    const auto n = static_cast<std::size_t>(compiled->node);
    ClipCurve curve;
    curve.duration = c.duration;
    const Vec3 start = is_position(channel) ? compiled->rest.position[n] : compiled->rest.euler[n];
    curve.start_value = shown(channel, start, rig_node);
    const int count = c.duration > 0 ? std::clamp(samples, 2, 4096) : 1;
    for (int i = 0; i < count; ++i) {
        const double t = count == 1 ? 0.0 : c.duration * i / (count - 1);
        curve.points.push_back({t, compiled->sample(clip, channel, t)});
    }
    fill_keys(file, file.clips[clip], c, rig_node, compiled->node, channel, start, curve);
    return curve;
}
} // namespace

Result<double> curve_value(const anim::AnimationFile& file, std::size_t clip, const std::string& node,
                           CurveChannel channel, double seconds) {
    if (!std::isfinite(seconds)) return Error("time is not a number", {}, "seconds from the clip's start");
    auto compiled = compile_for(file, clip, node);
    if (!compiled) return compiled.error();
    return compiled->sample(clip, channel, seconds);
}

Result<void> move_key_time(anim::AnimationFile& file, std::size_t clip, std::size_t phase, double seconds) {
    auto found = phase_at(file, clip, phase);
    if (!found) return found.error();
    const auto& phases = file.clips[clip].phases;
    if (!std::isfinite(seconds))
        return Error("key time is not a number", {}, "seconds from the clip's start");
    double previous_end = 0;
    for (std::size_t p = 0; p < phase; ++p) previous_end += phases[p].duration;
    const double end = previous_end + phases[phase].duration;
    const bool has_next = phase + 1 < phases.size();
    const double next_end = has_next ? end + phases[phase + 1].duration : 0;
    const std::string key = "key " + std::to_string(phase + 1);
    if (seconds < previous_end)
        return Error(key + " cannot move to " + seconds_text(seconds) + ": " +
                         (phase == 0 ? std::string("that is before the clip's start")
                                     : "it would pass key " + std::to_string(phase) + " at " +
                                           seconds_text(previous_end)),
                     {},
                     has_next
                         ? "a time in [" + seconds_text(previous_end) + ", " + seconds_text(next_end) + "]"
                         : "a time of " + seconds_text(previous_end) + " or later");
    if (has_next && seconds > next_end)
        return Error(key + " cannot move to " + seconds_text(seconds) + ": it would pass key " +
                         std::to_string(phase + 2) + " at " + seconds_text(next_end),
                     {}, "a time in [" + seconds_text(previous_end) + ", " + seconds_text(next_end) + "]");
    anim::AnimationFile edited = file;
    auto& edited_phases = edited.clips[clip].phases;
    // On the time grid, so the file holds 0.2 where 0.75 - 0.55 gives 0.19999999999999996.
    edited_phases[phase].duration = snap(seconds - previous_end, kTimeSteps);
    if (has_next) edited_phases[phase + 1].duration = snap(next_end - seconds, kTimeSteps);
    if (auto valid = dojo_support::no_new_clip_issues(file, edited, clip); !valid)
        return Error(key + " cannot move to " + seconds_text(seconds) + ": " + valid.error().message, {},
                     valid.error().hint);
    file = std::move(edited);
    return ok();
}

Result<void> set_key_value(anim::AnimationFile& file, std::size_t clip, std::size_t phase,
                           const std::string& node, CurveChannel channel, double value) {
    auto found = phase_at(file, clip, phase);
    if (!found) return found.error();
    if (!target_for(**found, node))
        return Error("node '" + node + "' has no key in key " + std::to_string(phase + 1) + " of '" +
                         file.clips[clip].name + "'",
                     {}, "add a key for it there first");
    if (!std::isfinite(value)) return Error("key value is not a number", {}, "a finite number");
    anim::AnimationFile edited = file;
    anim::TargetDef* target = nullptr;
    for (anim::TargetDef& t : edited.clips[clip].phases[phase].targets)
        if (t.node == node) target = &t;
    const bool position = is_position(channel);
    auto& absolute = position ? target->pos : target->rot;
    auto& relative = position ? target->add_pos : target->add_rot;
    if (!absolute && !relative) // keyed for the other kind only: an absolute key where the node is now
        absolute = snap(key_values(file, clip, node, position)[phase], kValueSteps);
    auto& edited_value = absolute ? absolute : relative;
    const double delta = value - (*edited_value)[component(channel)];
    (*edited_value)[component(channel)] = value;
    if (!absolute) keep_later_keys(edited, clip, phase, node, channel, delta);
    if (auto valid = dojo_support::no_new_clip_issues(file, edited, clip); !valid)
        return Error("cannot set " + node + " " + curve_channel_name(channel) + " to " +
                         jsonio::shortest_text(value) + ": " + valid.error().message,
                     {}, valid.error().hint);
    file = std::move(edited);
    return ok();
}

} // namespace ks::editor
