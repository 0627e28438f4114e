#include "model/dojo_keys.h"

#include "anim/clip_io.h"
#include "anim/required_clips.h"

#include <algorithm>
#include <cmath>

namespace ks::editor {
namespace {

Result<anim::PhaseDef*> find_phase(anim::AnimationFile& file, std::size_t clip, std::size_t phase) {
    if (clip >= file.clips.size())
        return Error("clip " + std::to_string(clip) + " does not exist", {},
                     "the file has " + std::to_string(file.clips.size()) + " clips");
    auto& def = file.clips[clip];
    if (phase >= def.phases.size())
        return Error("clip '" + def.name + "' has no key " + std::to_string(phase + 1), {},
                     "it has " + std::to_string(def.phases.size()) + " keys");
    return &def.phases[phase];
}

auto keyed(const std::string& node) {
    return [&node](const anim::TargetDef& t) { return t.node == node; };
}

const anim::TargetDef* target_of(const anim::PhaseDef& phase, const std::string& node) {
    const auto it = std::find_if(phase.targets.begin(), phase.targets.end(), keyed(node));
    return it == phase.targets.end() ? nullptr : &*it;
}

const anim::RigNodeDef* rig_node(const anim::AnimationFile& file, const std::string& node) {
    const auto it = std::find_if(file.rig.begin(), file.rig.end(),
                                 [&](const anim::RigNodeDef& n) { return n.name == node; });
    return it == file.rig.end() ? nullptr : &*it;
}

// The clip moves the node's position somewhere (so its position is a channel of the clip).
bool moves_position(const anim::ClipDef& clip, const std::string& node) {
    for (const anim::PhaseDef& phase : clip.phases)
        if (const anim::TargetDef* t = target_of(phase, node); t && (t->pos || t->add_pos)) return true;
    return false;
}

// The start of a channel played from rest: the rest rotation, or no offset.
DVec3 rest_value(const anim::RigNodeDef& node, bool position) {
    return position ? DVec3(0.0) : node.rotation;
}

// One channel made absolute in one clip; how many targets changed.
std::size_t absolute_channel(anim::AnimationFile& file, std::size_t clip, const anim::RigNodeDef& node,
                             bool position) {
    anim::ClipDef& def = file.clips[clip];
    bool relative = false;
    for (const anim::PhaseDef& phase : def.phases)
        if (const anim::TargetDef* t = target_of(phase, node.name))
            relative = relative || (position ? t->add_pos : t->add_rot).has_value();
    if (!relative) return 0;
    const std::vector<DVec3> reached = key_values(file, clip, node.name, position);
    if (def.loop == anim::LoopMode::Loop && !reached.empty() &&
        glm::length(reached.back() - rest_value(node, position)) > 1.0 / kValueSteps)
        return 0; // each pass carries on from the last: the offsets are the motion
    std::size_t changed = 0;
    for (std::size_t p = 0; p < def.phases.size(); ++p)
        for (anim::TargetDef& t : def.phases[p].targets) {
            if (t.node != node.name) continue;
            auto& absolute = position ? t.pos : t.rot;
            auto& offset = position ? t.add_pos : t.add_rot;
            if (!offset) continue;
            absolute = snap(reached[p], kValueSteps);
            offset.reset();
            ++changed;
        }
    return changed;
}

} // namespace

double snap(double value, double steps) {
    const double scaled = value * steps;
    if (!std::isfinite(scaled) || std::abs(scaled) > 0x1p52) return value; // no finer grid to snap to
    return std::round(scaled) / steps;
}

DVec3 snap(const DVec3& value, double steps) {
    return DVec3(snap(value.x, steps), snap(value.y, steps), snap(value.z, steps));
}

std::vector<DVec3> key_values(const anim::AnimationFile& file, std::size_t clip, const std::string& node,
                              bool position) {
    std::vector<DVec3> out;
    const anim::RigNodeDef* def = rig_node(file, node);
    if (clip >= file.clips.size() || !def) return out;
    const anim::ClipDef& c = file.clips[clip];
    const bool rest_rule =
        c.unlisted == anim::UnlistedRule::Rest &&
        std::find(file.rest_nodes.begin(), file.rest_nodes.end(), node) != file.rest_nodes.end();
    const DVec3 rest = rest_value(*def, position);
    DVec3 value = rest;
    for (const anim::PhaseDef& phase : c.phases) {
        const anim::TargetDef* t = target_of(phase, node);
        const auto& absolute = position ? (t ? t->pos : std::nullopt) : (t ? t->rot : std::nullopt);
        const auto& offset = position ? (t ? t->add_pos : std::nullopt) : (t ? t->add_rot : std::nullopt);
        if (absolute)
            value = *absolute;
        else if (offset)
            value += *offset;
        else if (!t && rest_rule)
            value = rest;
        out.push_back(value);
    }
    return out;
}

std::size_t make_keys_absolute(anim::AnimationFile& file) {
    std::size_t changed = 0;
    for (std::size_t clip = 0; clip < file.clips.size(); ++clip)
        for (const anim::RigNodeDef& node : file.rig) {
            if (node.parent.empty()) continue; // the root: its offsets are its meaning
            changed += absolute_channel(file, clip, node, false) + absolute_channel(file, clip, node, true);
        }
    return changed;
}

Result<void> add_node_key(anim::AnimationFile& file, std::size_t clip, std::size_t phase,
                          const std::string& node) {
    auto found = find_phase(file, clip, phase);
    if (!found) return found.error();
    if (std::none_of(file.rig.begin(), file.rig.end(),
                     [&](const anim::RigNodeDef& n) { return n.name == node; }))
        return Error("node '" + node + "' is not in the rig", {}, "pick one of the rig's nodes");
    anim::PhaseDef& p = **found;
    if (std::any_of(p.targets.begin(), p.targets.end(), keyed(node)))
        return Error("node '" + node + "' already has a key here", {}, "edit or remove the existing key");
    anim::TargetDef target;
    target.node = node;
    target.rot = snap(key_values(file, clip, node, false)[phase], kValueSteps);
    if (moves_position(file.clips[clip], node))
        target.pos = snap(key_values(file, clip, node, true)[phase], kValueSteps);
    p.targets.push_back(std::move(target));
    return {};
}

Result<void> remove_node_key(anim::AnimationFile& file, std::size_t clip, std::size_t phase,
                             const std::string& node) {
    auto found = find_phase(file, clip, phase);
    if (!found) return found.error();
    auto& targets = (*found)->targets;
    const auto it = std::find_if(targets.begin(), targets.end(), keyed(node));
    if (it == targets.end()) return Error("node '" + node + "' has no key here", {}, "nothing to remove");
    targets.erase(it);
    return {};
}

std::vector<std::string> unkeyed_nodes(const anim::AnimationFile& file, std::size_t clip, std::size_t phase) {
    std::vector<std::string> out;
    if (clip >= file.clips.size() || phase >= file.clips[clip].phases.size()) return out;
    const auto& targets = file.clips[clip].phases[phase].targets;
    for (const auto& n : file.rig)
        if (std::none_of(targets.begin(), targets.end(), keyed(n.name))) out.push_back(n.name);
    return out;
}

Result<std::size_t> duplicate_phase(anim::AnimationFile& file, std::size_t clip, std::size_t phase) {
    auto found = find_phase(file, clip, phase);
    if (!found) return found.error();
    auto& phases = file.clips[clip].phases;
    anim::PhaseDef copy = **found;
    for (anim::TargetDef& t : copy.targets) { // a pause: relative keys hold where the phase ended
        if (t.add_rot) t.add_rot = DVec3(0.0);
        if (t.add_pos) t.add_pos = DVec3(0.0);
    }
    phases.insert(phases.begin() + static_cast<std::ptrdiff_t>(phase) + 1, std::move(copy));
    return phase + 1;
}

Result<void> remove_phase(anim::AnimationFile& file, std::size_t clip, std::size_t phase) {
    auto found = find_phase(file, clip, phase);
    if (!found) return found.error();
    auto& def = file.clips[clip];
    if (def.phases.size() == 1)
        return Error("clip '" + def.name + "' has only this key", {},
                     "a clip needs at least one key: edit this one or add another first");
    def.phases.erase(def.phases.begin() + static_cast<std::ptrdiff_t>(phase));
    return {};
}

Result<std::size_t> move_phase(anim::AnimationFile& file, std::size_t clip, std::size_t phase, int offset) {
    auto found = find_phase(file, clip, phase);
    if (!found) return found.error();
    if (offset != -1 && offset != 1) return Error("a key moves one place at a time", {}, "use -1 or +1");
    auto& phases = file.clips[clip].phases;
    if ((offset < 0 && phase == 0) || (offset > 0 && phase + 1 >= phases.size()))
        return Error(std::string("key ") + std::to_string(phase + 1) + " is already the " +
                         (offset < 0 ? "first" : "last"),
                     {}, "nothing to move");
    const std::size_t to = offset < 0 ? phase - 1 : phase + 1;
    std::swap(phases[phase], phases[to]);
    return to;
}

void DojoHistory::record(const anim::AnimationFile& before, std::string name) {
    undo_.push_back({before, std::move(name)});
    redo_.clear();
}

bool DojoHistory::undo(anim::AnimationFile& file) {
    if (undo_.empty()) return false;
    Step step = std::move(undo_.back());
    undo_.pop_back();
    std::swap(step.file, file);
    redo_.push_back(std::move(step));
    return true;
}

bool DojoHistory::redo(anim::AnimationFile& file) {
    if (redo_.empty()) return false;
    Step step = std::move(redo_.back());
    redo_.pop_back();
    std::swap(step.file, file);
    undo_.push_back(std::move(step));
    return true;
}

const std::string& DojoHistory::undo_name() const {
    static const std::string none;
    return undo_.empty() ? none : undo_.back().name;
}

const std::string& DojoHistory::redo_name() const {
    static const std::string none;
    return redo_.empty() ? none : redo_.back().name;
}

std::vector<std::string> DojoHistory::step_names() const {
    std::vector<std::string> names;
    for (const auto& s : undo_) names.push_back(s.name);
    for (auto it = redo_.rbegin(); it != redo_.rend(); ++it) names.push_back(it->name);
    return names;
}

void DojoHistory::clear() {
    undo_.clear();
    redo_.clear();
}

std::vector<anim::Issue> dojo_file_issues(const anim::AnimationFile& file) {
    auto issues = anim::validate(file);
    for (anim::Issue& issue : anim::check_required_clips(file)) issues.push_back(std::move(issue));
    return issues;
}

Result<void> save_dojo_file(const std::filesystem::path& path, const anim::AnimationFile& file) {
    const auto issues = dojo_file_issues(file);
    if (!issues.empty()) {
        const auto& first = issues.front();
        return Error(
            "not saved: " + first.message +
                (issues.size() > 1 ? " (and " + std::to_string(issues.size() - 1) + " more issues)" : ""),
            Location(path.string(), 0, 0, first.path.str()),
            first.hint.empty() ? "fix the issues listed in the dojo panel" : first.hint);
    }
    return anim::save_animation_file(path, file);
}

} // namespace ks::editor
