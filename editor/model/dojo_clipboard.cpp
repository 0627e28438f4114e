#include "model/dojo_clipboard.h"

#include <algorithm>
#include <array>
#include <utility>

namespace ks::editor {

namespace {

DVec3 mirrored_rotation(const DVec3& r) {
    return {r.x == 0 ? 0.0 : -r.x, r.y == 0 ? 0.0 : -r.y, r.z}; // no "-0" written to the file
}
DVec3 mirrored_offset(const DVec3& p) {
    return {p.x, p.y, p.z == 0 ? 0.0 : -p.z};
}

bool in_rig(const anim::AnimationFile& file, const std::string& node) {
    return std::any_of(file.rig.begin(), file.rig.end(),
                       [&](const anim::RigNodeDef& n) { return n.name == node; });
}

} // namespace

Result<DojoKeyClipboard> copy_key(const anim::AnimationFile& file, std::size_t clip, std::size_t key) {
    if (clip >= file.clips.size())
        return Error("there is no clip " + std::to_string(clip + 1), {}, "pick a clip");
    const anim::ClipDef& def = file.clips[clip];
    if (key >= def.phases.size())
        return Error("clip '" + def.name + "' has no key " + std::to_string(key + 1), {},
                     "keys 1 to " + std::to_string(def.phases.size()));
    return DojoKeyClipboard{def.phases[key].targets};
}

DojoKeyClipboard copy_pose(std::span<const NodePoseValue> pose) {
    DojoKeyClipboard out;
    for (const NodePoseValue& v : pose) {
        anim::TargetDef t;
        t.node = v.node;
        t.rot = v.rot;
        t.pos = v.pos;
        out.targets.push_back(std::move(t));
    }
    return out;
}

std::string mirror_node_name(const std::string& name) {
    static constexpr std::array<std::pair<const char*, const char*>, 5> kSides{
        {{"_l", "_r"}, {"_L", "_R"}, {".l", ".r"}, {".L", ".R"}, {"left", "right"}}};
    for (const auto& [a, b] : kSides)
        for (const auto& [from, to] :
             {std::pair{std::string(a), std::string(b)}, std::pair{std::string(b), std::string(a)}})
            if (name.size() > from.size() && name.compare(name.size() - from.size(), from.size(), from) == 0)
                return name.substr(0, name.size() - from.size()) + to;
    for (const auto& [from, to] : {std::pair{std::string("_l_"), std::string("_r_")},
                                   std::pair{std::string("_r_"), std::string("_l_")}})
        if (const std::size_t at = name.find(from); at != std::string::npos)
            return name.substr(0, at) + to + name.substr(at + from.size()); // hand_r_tip
    for (const auto& [from, to] : {std::pair{std::string("left"), std::string("right")},
                                   std::pair{std::string("right"), std::string("left")}})
        if (name.rfind(from, 0) == 0) return to + name.substr(from.size());
    return name;
}

DojoKeyClipboard mirrored(const DojoKeyClipboard& clipboard, const anim::AnimationFile& file) {
    DojoKeyClipboard out = clipboard;
    for (anim::TargetDef& t : out.targets) {
        const std::string other = mirror_node_name(t.node);
        if (in_rig(file, other)) t.node = other;
        if (t.rot) t.rot = mirrored_rotation(*t.rot);
        if (t.add_rot) t.add_rot = mirrored_rotation(*t.add_rot);
        if (t.pos) t.pos = mirrored_offset(*t.pos);
        if (t.add_pos) t.add_pos = mirrored_offset(*t.add_pos);
    }
    return out;
}

Result<void> paste_key(anim::AnimationFile& file, std::size_t clip, std::size_t key,
                       const DojoKeyClipboard& clipboard) {
    if (clip >= file.clips.size())
        return Error("there is no clip " + std::to_string(clip + 1), {}, "pick a clip");
    anim::ClipDef& def = file.clips[clip];
    if (key >= def.phases.size())
        return Error("clip '" + def.name + "' has no key " + std::to_string(key + 1), {},
                     "keys 1 to " + std::to_string(def.phases.size()));
    if (clipboard.targets.empty())
        return Error("nothing to paste", {}, "copy a key or a pose first (Ctrl+C)");
    for (const anim::TargetDef& t : clipboard.targets)
        if (!in_rig(file, t.node))
            return Error("the copied node '" + t.node + "' is not in this file's rig", {},
                         "copy from a clip of the same rig");
    std::vector<anim::TargetDef>& targets = def.phases[key].targets;
    for (const anim::TargetDef& t : clipboard.targets) {
        const auto same = std::find_if(targets.begin(), targets.end(),
                                       [&](const anim::TargetDef& o) { return o.node == t.node; });
        if (same != targets.end())
            *same = t;
        else
            targets.push_back(t);
    }
    return ok();
}

} // namespace ks::editor
