#include "anim/clip_io.h"

#include "jsonio/json_writer.h"
#include "jsonio/number_text.h"

namespace ks::anim {
namespace {

const char* loop_name(LoopMode m) {
    switch (m) {
    case LoopMode::Once:
        return "once";
    case LoopMode::Loop:
        return "loop";
    case LoopMode::Next:
        return "next";
    case LoopMode::PingPong:
        return "ping_pong";
    }
    return "once";
}

const char* mode_name(EaseMode m) {
    return m == EaseMode::In ? "In" : m == EaseMode::Out ? "Out" : "InOut";
}

std::string vec_text(const DVec3& v) {
    return "[" + jsonio::shortest_text(v.x) + ", " + jsonio::shortest_text(v.y) + ", " +
           jsonio::shortest_text(v.z) + "]";
}
std::string ease_text(const Ease& e) {
    switch (e.family) {
    case EaseFamily::Power:
        return "{\"power\": " + jsonio::shortest_text(e.params[0]) + ", \"mode\": \"" + mode_name(e.mode) +
               "\"}";
    case EaseFamily::CubicBezier:
        return "{\"bezier\": [" + jsonio::shortest_text(e.params[0]) + ", " +
               jsonio::shortest_text(e.params[1]) + ", " + jsonio::shortest_text(e.params[2]) + ", " +
               jsonio::shortest_text(e.params[3]) + "]}";
    default:
        return jsonio::json_string(ease_name(e));
    }
}

} // namespace

std::string save_animation_string(const AnimationFile& file) {
    std::string out;
    out += "{\n";
    out += "  \"format\": " + jsonio::json_string(kAnimationFormat) + ",\n";
    out += "  \"version\": " + std::to_string(kAnimationVersion) + ",\n";
    out += "  \"rig\": [\n";
    for (std::size_t i = 0; i < file.rig.size(); ++i) {
        const RigNodeDef& n = file.rig[i];
        out += "    {\"name\": " + jsonio::json_string(n.name);
        if (!n.parent.empty()) out += ", \"parent\": " + jsonio::json_string(n.parent);
        if (n.position != DVec3(0)) out += ", \"position\": " + vec_text(n.position);
        if (n.rotation != DVec3(0)) out += ", \"rotation\": " + vec_text(n.rotation);
        out += i + 1 < file.rig.size() ? "},\n" : "}\n";
    }
    out += "  ],\n  \"rest_nodes\": [";
    for (std::size_t i = 0; i < file.rest_nodes.size(); ++i)
        out += (i ? ", " : "") + jsonio::json_string(file.rest_nodes[i]);
    out += "],\n";
    if (!file.node_ease.empty()) {
        out += "  \"node_ease\": {";
        for (std::size_t i = 0; i < file.node_ease.size(); ++i)
            out += (i ? ", " : "") + jsonio::json_string(file.node_ease[i].node) + ": " +
                   ease_text(file.node_ease[i].ease);
        out += "},\n";
    }
    out += "  \"blend\": {\n    \"default\": " + jsonio::shortest_text(file.default_blend) +
           ",\n    \"pairs\": [";
    for (std::size_t i = 0; i < file.blends.size(); ++i) {
        const BlendPair& b = file.blends[i];
        out += (i ? ",\n" : "\n");
        out += "      {\"from\": " + jsonio::json_string(b.from) + ", \"to\": " + jsonio::json_string(b.to) +
               ", \"time\": " + jsonio::shortest_text(b.time) + "}";
    }
    out += file.blends.empty() ? "]\n  },\n" : "\n    ]\n  },\n";
    out +=
        std::string("  \"wrap_captured_angles\": ") + (file.wrap_captured_angles ? "true" : "false") + ",\n";
    out += "  \"clips\": [";
    for (std::size_t ci = 0; ci < file.clips.size(); ++ci) {
        const ClipDef& c = file.clips[ci];
        out += ci ? ",\n" : "\n";
        out += "    {\n      \"name\": " + jsonio::json_string(c.name) + ",\n";
        out += std::string("      \"loop\": \"") + loop_name(c.loop) + "\",\n";
        if (!c.next.empty()) out += "      \"next\": " + jsonio::json_string(c.next) + ",\n";
        out += std::string("      \"unlisted\": \"") + (c.unlisted == UnlistedRule::Rest ? "rest" : "hold") +
               "\",\n";
        if (c.frame_rate) out += "      \"frame_rate\": " + jsonio::shortest_text(*c.frame_rate) + ",\n";
        out += "      \"phases\": [";
        for (std::size_t pi = 0; pi < c.phases.size(); ++pi) {
            const PhaseDef& ph = c.phases[pi];
            out += pi ? ",\n" : "\n";
            out += "        {\n          \"duration\": " + jsonio::shortest_text(ph.duration) + ",\n";
            out += "          \"ease\": " + ease_text(ph.ease) + ",\n";
            out += "          \"targets\": {";
            for (std::size_t ti = 0; ti < ph.targets.size(); ++ti) {
                const TargetDef& t = ph.targets[ti];
                out += ti ? ",\n" : "\n";
                out += "            " + jsonio::json_string(t.node) + ": {";
                std::string fields;
                auto field = [&](const char* key, const std::string& value) {
                    fields += (fields.empty() ? "\"" : ", \"") + std::string(key) + "\": " + value;
                };
                if (t.rot) field("rot", vec_text(*t.rot));
                if (t.add_rot) field("add_rot", vec_text(*t.add_rot));
                if (t.pos) field("pos", vec_text(*t.pos));
                if (t.add_pos) field("add_pos", vec_text(*t.add_pos));
                if (t.ease) field("ease", ease_text(*t.ease));
                out += fields + "}";
            }
            out += ph.targets.empty() ? "}\n" : "\n          }\n";
            out += "        }";
        }
        out += c.phases.empty() ? "]" : "\n      ]";
        if (!c.events.empty()) {
            out += ",\n      \"events\": [";
            for (std::size_t ei = 0; ei < c.events.size(); ++ei) {
                const ClipEvent& e = c.events[ei];
                out += ei ? ",\n" : "\n";
                out += "        {\"time\": " + jsonio::shortest_text(e.time) +
                       ", \"name\": " + jsonio::json_string(e.name);
                if (!e.sound.empty()) out += ", \"sound\": " + jsonio::json_string(e.sound);
                out += "}";
            }
            out += "\n      ]";
        }
        out += "\n    }";
    }
    out += file.clips.empty() ? "]\n}\n" : "\n  ]\n}\n";
    return out;
}

} // namespace ks::anim
