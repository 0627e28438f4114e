#include "anim/clip_reader.h"

#include "anim/clip_issues.h"
#include "jsonio/describe.h"
#include "jsonio/object_reader.h"
#include "jsonio/suggest.h"

#include <algorithm>
#include <cmath>

namespace ks::anim {
namespace {

using Json = nlohmann::ordered_json;

class Reader {
  public:
    std::vector<Issue> issues;

    void problem(const JsonPath& path, std::string message, std::string hint = {}) {
        issues.push_back({path, std::move(message), std::move(hint)});
    }

    bool is_object(const Json& j, const JsonPath& path, const char* what) {
        if (j.is_object()) return true;
        problem(path, std::string(what) + " must be an object, not " + jsonio::type_name(j));
        return false;
    }
    bool is_array(const Json& j, const JsonPath& path, const char* what) {
        if (j.is_array()) return true;
        problem(path, std::string(what) + " must be an array, not " + jsonio::type_name(j));
        return false;
    }
    void known_keys(const Json& j, const JsonPath& path, std::initializer_list<const char*> allowed,
                    const char* what) {
        const std::vector<std::string> names(allowed.begin(), allowed.end());
        for (auto it = j.begin(); it != j.end(); ++it) {
            if (std::find(names.begin(), names.end(), it.key()) != names.end()) continue;
            issues.push_back({path / it.key(), jsonio::unknown_field_message(it.key()),
                              jsonio::unknown_field_hint(it.key(), names, what), true});
        }
    }
    bool string(const Json& j, const JsonPath& path, std::string& out) {
        if (j.is_string()) {
            out = j.get<std::string>();
            return true;
        }
        problem(path, std::string("must be a string, not ") + jsonio::type_name(j));
        return false;
    }
    bool number(const Json& j, const JsonPath& path, double& out) {
        if (!j.is_number()) {
            problem(path, std::string("must be a number, not ") + jsonio::type_name(j));
            return false;
        }
        out = j.get<double>();
        if (!std::isfinite(out)) {
            problem(path, "number is not finite", "write a finite number");
            return false;
        }
        return true;
    }
    bool vec3(const Json& j, const JsonPath& path, DVec3& out) {
        if (!j.is_array() || j.size() != 3) {
            problem(path,
                    std::string("must be an array of 3 numbers [x, y, z], not ") +
                        (j.is_array() ? "an array of " + std::to_string(j.size()) : jsonio::type_name(j)));
            return false;
        }
        bool ok = true;
        for (std::size_t i = 0; i < 3; ++i) ok = number(j[i], path[i], out[static_cast<int>(i)]) && ok;
        return ok;
    }
    bool ease(const Json& j, const JsonPath& path, Ease& out) {
        if (j.is_string()) {
            auto parsed = parse_ease_name(j.get<std::string>());
            if (!parsed) {
                problem(
                    path, "unknown easing " + quoted_name(j.get<std::string>()),
                    did_you_mean(j.get<std::string>(), known_ease_names()) +
                        "known: " + jsonio::join(known_ease_names()) +
                        "; or {\"power\": p, \"mode\": \"In|Out|InOut\"} or {\"bezier\": [x1, y1, x2, y2]}");
                return false;
            }
            out = *parsed;
            return true;
        }
        if (!j.is_object()) {
            problem(path, std::string("easing must be a name or an object, not ") + jsonio::type_name(j),
                    "e.g. \"Quadratic.In\"");
            return false;
        }
        if (j.contains("power")) {
            known_keys(j, path, {"power", "mode"}, "easing");
            double p = 0;
            if (!number(j["power"], path / "power", p)) return false;
            EaseMode mode = EaseMode::In;
            if (j.contains("mode")) {
                std::string m;
                if (!string(j["mode"], path / "mode", m)) return false;
                if (m == "In")
                    mode = EaseMode::In;
                else if (m == "Out")
                    mode = EaseMode::Out;
                else if (m == "InOut")
                    mode = EaseMode::InOut;
                else {
                    problem(path / "mode", "unknown mode " + quoted_name(m), "one of In, Out, InOut");
                    return false;
                }
            }
            out = Ease::power(static_cast<float>(p), mode);
            return true;
        }
        if (j.contains("bezier")) {
            known_keys(j, path, {"bezier"}, "easing");
            const Json& b = j["bezier"];
            if (!b.is_array() || b.size() != 4) {
                problem(path / "bezier", "must be 4 numbers [x1, y1, x2, y2]");
                return false;
            }
            double v[4];
            bool ok = true;
            for (std::size_t i = 0; i < 4; ++i) ok = number(b[i], (path / "bezier")[i], v[i]) && ok;
            if (!ok) return false;
            out = Ease::bezier(float(v[0]), float(v[1]), float(v[2]), float(v[3]));
            return true;
        }
        problem(path, "easing object needs \"power\" or \"bezier\"",
                "{\"power\": 2.5, \"mode\": \"InOut\"} or {\"bezier\": [0.25, 0.1, 0.25, 1]}");
        return false;
    }

    void read(const Json& root, AnimationFile& file) {
        const JsonPath top;
        if (!is_object(root, top, "the document")) return;
        known_keys(
            root, top,
            {"format", "version", "rig", "rest_nodes", "node_ease", "blend", "wrap_captured_angles", "clips"},
            "animation file");
        std::string format;
        if (!root.contains("format"))
            problem(top, "missing \"format\"", std::string("\"format\": \"") + kAnimationFormat + "\"");
        else if (string(root["format"], top / "format", format) && format != kAnimationFormat)
            problem(top / "format", "format is " + quoted_name(format),
                    std::string("expected '") + kAnimationFormat + "'");
        if (!root.contains("version"))
            problem(top, "missing \"version\"", "\"version\": 1");
        else if (!root["version"].is_number_integer() ||
                 root["version"].get<long long>() != kAnimationVersion)
            problem(top / "version", "unsupported version " + root["version"].dump(),
                    "this build reads version 1");

        if (!root.contains("rig"))
            problem(top, "missing \"rig\"", "a list of nodes: [{\"name\": \"robot\"}, ...]");
        else if (is_array(root["rig"], top / "rig", "rig"))
            for (std::size_t i = 0; i < root["rig"].size(); ++i)
                read_rig_node(root["rig"][i], (top / "rig")[i], file);

        if (root.contains("rest_nodes") && is_array(root["rest_nodes"], top / "rest_nodes", "rest_nodes"))
            for (std::size_t i = 0; i < root["rest_nodes"].size(); ++i) {
                std::string name;
                if (string(root["rest_nodes"][i], (top / "rest_nodes")[i], name))
                    file.rest_nodes.push_back(name);
            }

        if (root.contains("blend") && is_object(root["blend"], top / "blend", "blend")) {
            const Json& b = root["blend"];
            const JsonPath bp = top / "blend";
            known_keys(b, bp, {"default", "pairs"}, "blend");
            if (b.contains("default")) number(b["default"], bp / "default", file.default_blend);
            if (b.contains("pairs") && is_array(b["pairs"], bp / "pairs", "blend pairs"))
                for (std::size_t i = 0; i < b["pairs"].size(); ++i) {
                    const Json& pj = b["pairs"][i];
                    const JsonPath pp = (bp / "pairs")[i];
                    if (!is_object(pj, pp, "a blend pair")) continue;
                    known_keys(pj, pp, {"from", "to", "time"}, "blend pair");
                    BlendPair pair;
                    for (const char* key : {"from", "to", "time"})
                        if (!pj.contains(key)) problem(pp, std::string("missing \"") + key + "\"");
                    if (pj.contains("from")) string(pj["from"], pp / "from", pair.from);
                    if (pj.contains("to")) string(pj["to"], pp / "to", pair.to);
                    if (pj.contains("time")) number(pj["time"], pp / "time", pair.time);
                    file.blends.push_back(pair);
                }
        }
        if (root.contains("node_ease") && is_object(root["node_ease"], top / "node_ease", "node_ease"))
            for (auto it = root["node_ease"].begin(); it != root["node_ease"].end(); ++it) {
                NodeEase ne{it.key(), Ease::linear()};
                if (ease(it.value(), top / "node_ease" / it.key(), ne.ease)) file.node_ease.push_back(ne);
            }
        if (root.contains("wrap_captured_angles")) {
            if (root["wrap_captured_angles"].is_boolean())
                file.wrap_captured_angles = root["wrap_captured_angles"].get<bool>();
            else
                problem(top / "wrap_captured_angles", std::string("must be true or false, not ") +
                                                          jsonio::type_name(root["wrap_captured_angles"]));
        }

        if (!root.contains("clips"))
            problem(top, "missing \"clips\"", "a list of clips: [{\"name\": ..., \"phases\": [...]}]");
        else if (is_array(root["clips"], top / "clips", "clips"))
            for (std::size_t i = 0; i < root["clips"].size(); ++i)
                read_clip(root["clips"][i], (top / "clips")[i], file);
    }

    void read_rig_node(const Json& j, const JsonPath& path, AnimationFile& file) {
        if (!is_object(j, path, "a rig node")) return;
        known_keys(j, path, {"name", "parent", "position", "rotation"}, "rig node");
        RigNodeDef node;
        if (!j.contains("name"))
            problem(path, "rig node has no \"name\"");
        else
            string(j["name"], path / "name", node.name);
        if (j.contains("parent")) string(j["parent"], path / "parent", node.parent);
        if (j.contains("position")) vec3(j["position"], path / "position", node.position);
        if (j.contains("rotation")) vec3(j["rotation"], path / "rotation", node.rotation);
        file.rig.push_back(std::move(node));
    }

    void read_clip(const Json& j, const JsonPath& path, AnimationFile& file) {
        ClipDef clip;
        if (!is_object(j, path, "a clip")) {
            file.clips.push_back(std::move(clip));
            return;
        }
        known_keys(j, path, {"name", "loop", "next", "unlisted", "frame_rate", "phases", "events"}, "clip");
        if (!j.contains("name"))
            problem(path, "clip has no \"name\"");
        else
            string(j["name"], path / "name", clip.name);
        if (j.contains("loop")) {
            std::string loop;
            if (string(j["loop"], path / "loop", loop)) {
                if (loop == "once")
                    clip.loop = LoopMode::Once;
                else if (loop == "loop")
                    clip.loop = LoopMode::Loop;
                else if (loop == "next")
                    clip.loop = LoopMode::Next;
                else if (loop == "ping_pong")
                    clip.loop = LoopMode::PingPong;
                else
                    problem(path / "loop", "unknown loop mode " + quoted_name(loop),
                            did_you_mean(loop, {"once", "loop", "ping_pong", "next"}) +
                                "one of once, loop, ping_pong, next");
            }
        }
        if (j.contains("next")) string(j["next"], path / "next", clip.next);
        if (j.contains("unlisted")) {
            std::string rule;
            if (string(j["unlisted"], path / "unlisted", rule)) {
                if (rule == "rest")
                    clip.unlisted = UnlistedRule::Rest;
                else if (rule == "hold")
                    clip.unlisted = UnlistedRule::Hold;
                else
                    problem(path / "unlisted", "unknown rule " + quoted_name(rule), "one of rest, hold");
            }
        }
        if (double fps = 0; j.contains("frame_rate") && number(j["frame_rate"], path / "frame_rate", fps))
            clip.frame_rate = fps; // its range is validate()'s
        if (!j.contains("phases"))
            problem(path, "clip has no \"phases\"", "at least one {\"duration\": s, \"targets\": {...}}");
        else if (is_array(j["phases"], path / "phases", "phases"))
            for (std::size_t i = 0; i < j["phases"].size(); ++i)
                clip.phases.push_back(read_phase(j["phases"][i], (path / "phases")[i]));
        if (j.contains("events") && is_array(j["events"], path / "events", "events"))
            for (std::size_t i = 0; i < j["events"].size(); ++i)
                read_event(j["events"][i], (path / "events")[i], clip);
        file.clips.push_back(std::move(clip));
    }

    void read_event(const Json& j, const JsonPath& path, ClipDef& clip) {
        ClipEvent event;
        if (!is_object(j, path, "an event")) return;
        known_keys(j, path, {"time", "name", "sound"}, "event");
        if (!j.contains("time"))
            problem(path, "event has no \"time\"", "seconds from the clip's start, e.g. \"time\": 0.1");
        else
            number(j["time"], path / "time", event.time);
        if (!j.contains("name"))
            problem(path, "event has no \"name\"", "e.g. \"name\": \"muzzle_flash\"");
        else
            string(j["name"], path / "name", event.name);
        if (j.contains("sound")) string(j["sound"], path / "sound", event.sound);
        clip.events.push_back(std::move(event));
    }

    PhaseDef read_phase(const Json& j, const JsonPath& path) {
        PhaseDef phase;
        if (!is_object(j, path, "a phase")) return phase;
        known_keys(j, path, {"duration", "ease", "targets"}, "phase");
        if (!j.contains("duration"))
            problem(path, "phase has no \"duration\"", "seconds, e.g. \"duration\": 0.3");
        else if (!number(j["duration"], path / "duration", phase.duration))
            phase.duration = 0;
        if (j.contains("ease")) ease(j["ease"], path / "ease", phase.ease);
        if (j.contains("targets") && is_object(j["targets"], path / "targets", "targets"))
            for (auto it = j["targets"].begin(); it != j["targets"].end(); ++it) {
                const JsonPath tp = path / "targets" / it.key();
                TargetDef t;
                t.node = it.key();
                if (!is_object(it.value(), tp, "a target")) {
                    phase.targets.push_back(std::move(t));
                    continue;
                }
                const Json& tj = it.value();
                known_keys(tj, tp, {"rot", "add_rot", "pos", "add_pos", "ease"}, "target");
                DVec3 v;
                if (tj.contains("rot") && vec3(tj["rot"], tp / "rot", v)) t.rot = v;
                if (tj.contains("add_rot") && vec3(tj["add_rot"], tp / "add_rot", v)) t.add_rot = v;
                if (tj.contains("pos") && vec3(tj["pos"], tp / "pos", v)) t.pos = v;
                if (tj.contains("add_pos") && vec3(tj["add_pos"], tp / "add_pos", v)) t.add_pos = v;
                Ease e;
                if (tj.contains("ease") && ease(tj["ease"], tp / "ease", e)) t.ease = e;
                phase.targets.push_back(std::move(t));
            }
        return phase;
    }
};

} // namespace

std::vector<Issue> read_animation_json(const Json& root, AnimationFile& file) {
    Reader reader;
    reader.read(root, file);
    return std::move(reader.issues);
}

} // namespace ks::anim
