#include "anim/clip.h"

#include <algorithm>
#include <numbers>

namespace ks::anim {
namespace {

Vec3 to_radians(const DVec3& degrees) {
    constexpr double k = std::numbers::pi / 180.0;
    return Vec3(static_cast<float>(degrees.x * k), static_cast<float>(degrees.y * k),
                static_cast<float>(degrees.z * k));
}
Vec3 to_float(const DVec3& v) {
    return Vec3(v);
}

const TargetDef* find_target(const PhaseDef& phase, const std::string& node) {
    for (const TargetDef& t : phase.targets)
        if (t.node == node) return &t;
    return nullptr;
}

struct Resolved {
    KeyMode mode = KeyMode::FromStart;
    Vec3 value{0};
};

} // namespace

double ClipDef::duration() const {
    double total = 0;
    for (const PhaseDef& p : phases) total += p.duration;
    return total;
}

const ClipDef* AnimationFile::find_clip(const std::string& name) const {
    for (const ClipDef& c : clips)
        if (c.name == name) return &c;
    return nullptr;
}

int ClipSet::find(std::string_view name) const {
    for (std::size_t i = 0; i < clips.size(); ++i)
        if (clips[i].name == name) return static_cast<int>(i);
    return -1;
}

float ClipSet::blend_time(int from, int to) const {
    const int n = static_cast<int>(clips.size());
    if (from < 0 || to < 0 || from >= n || to >= n) return default_blend_;
    return blend_[static_cast<std::size_t>(from * n + to)];
}

Result<Rig> build_rig(const AnimationFile& file) {
    std::vector<RigNode> nodes;
    std::vector<Error> errors;
    for (const RigNodeDef& def : file.rig) {
        RigNode n;
        n.name = def.name;
        n.rest_position = to_float(def.position);
        n.rest_euler = to_radians(def.rotation);
        if (!def.parent.empty()) {
            for (std::size_t j = 0; j < nodes.size(); ++j)
                if (nodes[j].name == def.parent) n.parent = static_cast<int>(j);
            if (n.parent < 0)
                errors.emplace_back("rig node '" + def.name + "': parent '" + def.parent +
                                    "' is not listed before it");
        }
        nodes.push_back(std::move(n));
    }
    if (!errors.empty()) return combine_errors(errors);
    return Rig::create(std::move(nodes));
}

Result<ClipSet> compile(const AnimationFile& file, const Rig& rig) {
    std::vector<Error> errors;
    auto need_node = [&](const std::string& name, const std::string& context) {
        int index = rig.find(name);
        if (index < 0)
            errors.emplace_back(context + ": node '" + name + "' is not in the rig", Location{},
                                "the model must have every node the clips animate");
        return index;
    };
    for (const NodeEase& ne : file.node_ease) need_node(ne.node, "node_ease");
    std::vector<int> rest_nodes;
    for (const std::string& name : file.rest_nodes) {
        int index = need_node(name, "rest_nodes");
        if (index >= 0) rest_nodes.push_back(index);
    }

    ClipSet set;
    set.wrap_captured_angles = file.wrap_captured_angles;
    set.node_count_ = rig.size();
    for (const ClipDef& def : file.clips) {
        Clip clip;
        clip.name = def.name;
        clip.loop = def.loop;
        clip.events = def.events;
        std::stable_sort(clip.events.begin(), clip.events.end(),
                         [](const ClipEvent& a, const ClipEvent& b) { return a.time < b.time; });
        clip.duration = def.duration();

        // Which channels the clip has: every node it names, plus the rest nodes when unlisted ones go home.
        std::vector<char> has_rot(static_cast<std::size_t>(rig.size()), 0), has_pos(has_rot);
        if (def.unlisted == UnlistedRule::Rest)
            for (int n : rest_nodes) has_rot[static_cast<std::size_t>(n)] = 1;
        for (std::size_t p = 0; p < def.phases.size(); ++p)
            for (const TargetDef& t : def.phases[p].targets) {
                int n = need_node(t.node, "clip '" + def.name + "' phase " + std::to_string(p));
                if (n < 0) continue;
                if (t.rot || t.add_rot) has_rot[static_cast<std::size_t>(n)] = 1;
                if (t.pos || t.add_pos) has_pos[static_cast<std::size_t>(n)] = 1;
            }
        const bool rest_rule = def.unlisted == UnlistedRule::Rest;
        auto is_rest_node = [&](int n) {
            return rest_rule && std::find(rest_nodes.begin(), rest_nodes.end(), n) != rest_nodes.end();
        };

        for (int n = 0; n < rig.size(); ++n)
            for (int kind = 0; kind < 2; ++kind) {
                const bool position = kind == 1;
                if (!(position ? has_pos : has_rot)[static_cast<std::size_t>(n)]) continue;
                const std::string& name = rig.node(n).name;
                const Ease* node_ease = nullptr;
                for (const NodeEase& ne : file.node_ease)
                    if (ne.node == name) node_ease = &ne.ease;
                Channel ch;
                ch.node = n;
                ch.is_position = position;
                ch.first_key = static_cast<std::uint32_t>(clip.keys.size());
                clip.keys.push_back(Key{0.0, Vec3(0), KeyMode::FromStart, Ease::linear()});
                Resolved current;
                double time = 0;
                for (const PhaseDef& phase : def.phases) {
                    time += phase.duration;
                    const TargetDef* t = find_target(phase, name);
                    Key key;
                    key.time = time;
                    key.ease = t && t->ease ? *t->ease : node_ease ? *node_ease : phase.ease;
                    const auto& absolute =
                        position ? (t ? t->pos : std::nullopt) : (t ? t->rot : std::nullopt);
                    const auto& relative =
                        position ? (t ? t->add_pos : std::nullopt) : (t ? t->add_rot : std::nullopt);
                    if (absolute) {
                        current.mode = KeyMode::Absolute;
                        current.value = position ? rig.node(n).rest_position + to_float(*absolute)
                                                 : to_radians(*absolute);
                    } else if (relative) {
                        current.value += position ? to_float(*relative) : to_radians(*relative);
                    } else if (!t && is_rest_node(n)) {
                        current.mode = KeyMode::Absolute;
                        current.value = position ? rig.node(n).rest_position : rig.node(n).rest_euler;
                    } // else: hold the previous value
                    key.mode = current.mode;
                    key.value = current.value;
                    clip.keys.push_back(key);
                }
                ch.key_count = static_cast<std::uint32_t>(clip.keys.size()) - ch.first_key;
                clip.channels.push_back(ch);
            }
        set.clips.push_back(std::move(clip));
    }

    const int n = static_cast<int>(set.clips.size());
    for (int i = 0; i < n; ++i) {
        const ClipDef& def = file.clips[static_cast<std::size_t>(i)];
        if (def.loop != LoopMode::Next) continue;
        set.clips[static_cast<std::size_t>(i)].next = set.find(def.next);
        if (set.clips[static_cast<std::size_t>(i)].next < 0)
            errors.emplace_back("clip '" + def.name + "': next clip '" + def.next + "' does not exist");
    }
    set.default_blend_ = static_cast<float>(file.default_blend);
    set.blend_.assign(static_cast<std::size_t>(n * n), set.default_blend_);
    // "*" matches every clip; pairs naming both clips exactly win over wildcard ones, whatever their order.
    for (int pass = 0; pass < 2; ++pass)
        for (const BlendPair& pair : file.blends) {
            const bool wildcard = pair.from == "*" || pair.to == "*";
            if (wildcard != (pass == 0)) continue;
            int from = set.find(pair.from), to = set.find(pair.to);
            if ((from < 0 && pair.from != "*") || (to < 0 && pair.to != "*")) {
                errors.emplace_back("blend pair " + pair.from + " -> " + pair.to + " names an unknown clip");
                continue;
            }
            for (int f = 0; f < n; ++f)
                for (int t = 0; t < n; ++t)
                    if ((from < 0 || f == from) && (to < 0 || t == to))
                        set.blend_[static_cast<std::size_t>(f * n + t)] = static_cast<float>(pair.time);
        }
    if (!errors.empty()) return combine_errors(errors);
    return set;
}

} // namespace ks::anim
