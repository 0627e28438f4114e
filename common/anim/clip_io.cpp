#include "anim/clip_io.h"

#include "core/files.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

namespace ks::anim {
namespace {

using Json = nlohmann::ordered_json;

// Limits that catch typos (an angle in radians written as degrees is fine; 1e9 is not).
constexpr double kMaxDuration = 600.0; // seconds per phase
constexpr double kMaxBlend = 10.0;     // seconds
constexpr double kMaxAngle = 36000.0;  // degrees: 100 turns
constexpr double kMaxOffset = 10000.0; // world units

std::string join(const std::vector<std::string>& items, const char* separator = ", ") {
    std::string out;
    for (const std::string& s : items) out += (out.empty() ? "" : separator) + s;
    return out;
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            std::size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diagonal = up;
        }
    }
    return row[b.size()];
}

// "did you mean 'x'? " for a near miss (a typo), else "".
std::string suggestion(std::string_view given, const std::vector<std::string>& candidates) {
    const std::string* best = nullptr;
    std::size_t best_distance = std::max<std::size_t>(2, given.size() / 3) + 1;
    for (const std::string& c : candidates) {
        std::size_t d = edit_distance(given, c);
        if (d < best_distance) {
            best_distance = d;
            best = &c;
        }
    }
    return best ? "did you mean '" + *best + "'? " : "";
}

const char* json_type(const Json& j) {
    switch (j.type()) {
    case Json::value_t::null:
        return "null";
    case Json::value_t::boolean:
        return "a boolean";
    case Json::value_t::string:
        return "a string";
    case Json::value_t::array:
        return "an array";
    case Json::value_t::object:
        return "an object";
    case Json::value_t::discarded:
        return "invalid";
    default:
        return "a number";
    }
}

const char* loop_name(LoopMode m) {
    switch (m) {
    case LoopMode::Once:
        return "once";
    case LoopMode::Loop:
        return "loop";
    case LoopMode::Next:
        return "next";
    }
    return "once";
}
const char* mode_name(EaseMode m) {
    return m == EaseMode::In ? "In" : m == EaseMode::Out ? "Out" : "InOut";
}

// Reads the parsed document into an AnimationFile, recording type and shape problems.
class Reader {
  public:
    std::vector<Issue> issues;

    void problem(const JsonPath& path, std::string message, std::string hint = {}) {
        issues.push_back({path, std::move(message), std::move(hint)});
    }

    bool is_object(const Json& j, const JsonPath& path, const char* what) {
        if (j.is_object()) return true;
        problem(path, std::string(what) + " must be an object, not " + json_type(j));
        return false;
    }
    bool is_array(const Json& j, const JsonPath& path, const char* what) {
        if (j.is_array()) return true;
        problem(path, std::string(what) + " must be an array, not " + json_type(j));
        return false;
    }
    void known_keys(const Json& j, const JsonPath& path, std::initializer_list<const char*> allowed) {
        for (auto it = j.begin(); it != j.end(); ++it) {
            bool ok = false;
            for (const char* a : allowed) ok = ok || it.key() == a;
            if (ok) continue;
            std::vector<std::string> names;
            for (const char* a : allowed) names.emplace_back(a);
            problem(path / it.key(), "unknown key '" + it.key() + "'",
                    suggestion(it.key(), names) + "known keys: " + join(names));
        }
    }
    bool string(const Json& j, const JsonPath& path, std::string& out) {
        if (j.is_string()) {
            out = j.get<std::string>();
            return true;
        }
        problem(path, std::string("must be a string, not ") + json_type(j));
        return false;
    }
    bool number(const Json& j, const JsonPath& path, double& out) {
        if (!j.is_number()) {
            problem(path, std::string("must be a number, not ") + json_type(j));
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
            problem(path, std::string("must be an array of 3 numbers [x, y, z], not ") +
                              (j.is_array() ? "an array of " + std::to_string(j.size()) : json_type(j)));
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
                    path, "unknown easing '" + j.get<std::string>() + "'",
                    suggestion(j.get<std::string>(), known_ease_names()) +
                        "known: " + join(known_ease_names()) +
                        "; or {\"power\": p, \"mode\": \"In|Out|InOut\"} or {\"bezier\": [x1, y1, x2, y2]}");
                return false;
            }
            out = *parsed;
            return true;
        }
        if (!j.is_object()) {
            problem(path, std::string("easing must be a name or an object, not ") + json_type(j),
                    "e.g. \"Quadratic.In\"");
            return false;
        }
        if (j.contains("power")) {
            known_keys(j, path, {"power", "mode"});
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
                    problem(path / "mode", "unknown mode '" + m + "'", "one of In, Out, InOut");
                    return false;
                }
            }
            out = Ease::power(static_cast<float>(p), mode);
            return true;
        }
        if (j.contains("bezier")) {
            known_keys(j, path, {"bezier"});
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
        known_keys(root, top,
                   {"format", "version", "rig", "rest_nodes", "node_ease", "blend", "wrap_captured_angles",
                    "clips"});
        std::string format;
        if (!root.contains("format"))
            problem(top, "missing \"format\"", std::string("\"format\": \"") + kAnimationFormat + "\"");
        else if (string(root["format"], top / "format", format) && format != kAnimationFormat)
            problem(top / "format", "format is '" + format + "'",
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
            known_keys(b, bp, {"default", "pairs"});
            if (b.contains("default")) number(b["default"], bp / "default", file.default_blend);
            if (b.contains("pairs") && is_array(b["pairs"], bp / "pairs", "blend pairs"))
                for (std::size_t i = 0; i < b["pairs"].size(); ++i) {
                    const Json& pj = b["pairs"][i];
                    const JsonPath pp = (bp / "pairs")[i];
                    if (!is_object(pj, pp, "a blend pair")) continue;
                    known_keys(pj, pp, {"from", "to", "time"});
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
                problem(top / "wrap_captured_angles",
                        std::string("must be true or false, not ") + json_type(root["wrap_captured_angles"]));
        }

        if (!root.contains("clips"))
            problem(top, "missing \"clips\"", "a list of clips: [{\"name\": ..., \"phases\": [...]}]");
        else if (is_array(root["clips"], top / "clips", "clips"))
            for (std::size_t i = 0; i < root["clips"].size(); ++i)
                read_clip(root["clips"][i], (top / "clips")[i], file);
    }

    void read_rig_node(const Json& j, const JsonPath& path, AnimationFile& file) {
        if (!is_object(j, path, "a rig node")) return;
        known_keys(j, path, {"name", "parent", "position", "rotation"});
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
        known_keys(j, path, {"name", "loop", "next", "unlisted", "phases"});
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
                else
                    problem(path / "loop", "unknown loop mode '" + loop + "'", "one of once, loop, next");
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
                    problem(path / "unlisted", "unknown rule '" + rule + "'", "one of rest, hold");
            }
        }
        if (!j.contains("phases"))
            problem(path, "clip has no \"phases\"", "at least one {\"duration\": s, \"targets\": {...}}");
        else if (is_array(j["phases"], path / "phases", "phases"))
            for (std::size_t i = 0; i < j["phases"].size(); ++i)
                clip.phases.push_back(read_phase(j["phases"][i], (path / "phases")[i]));
        file.clips.push_back(std::move(clip));
    }

    PhaseDef read_phase(const Json& j, const JsonPath& path) {
        PhaseDef phase;
        if (!is_object(j, path, "a phase")) return phase;
        known_keys(j, path, {"duration", "ease", "targets"});
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
                known_keys(tj, tp, {"rot", "add_rot", "pos", "add_pos", "ease"});
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

// --- writing ----------------------------------------------------------------------------------------------

std::string number_text(double v) {
    if (v == 0) return "0"; // also -0
    char buf[32];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, end);
}
std::string number_text(float v) {
    if (v == 0) return "0";
    char buf[32];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, end);
}
std::string quoted(const std::string& s) {
    return Json(s).dump();
}
std::string vec_text(const DVec3& v) {
    return "[" + number_text(v.x) + ", " + number_text(v.y) + ", " + number_text(v.z) + "]";
}
std::string ease_text(const Ease& e) {
    switch (e.family) {
    case EaseFamily::Power:
        return "{\"power\": " + number_text(e.params[0]) + ", \"mode\": \"" + mode_name(e.mode) + "\"}";
    case EaseFamily::CubicBezier:
        return "{\"bezier\": [" + number_text(e.params[0]) + ", " + number_text(e.params[1]) + ", " +
               number_text(e.params[2]) + ", " + number_text(e.params[3]) + "]}";
    default:
        return quoted(ease_name(e));
    }
}

} // namespace

std::vector<Issue> validate(const AnimationFile& file) {
    std::vector<Issue> issues;
    auto problem = [&](const JsonPath& p, std::string m, std::string h = {}) {
        issues.push_back({p, std::move(m), std::move(h)});
    };
    const JsonPath top;
    std::vector<std::string> node_names;
    std::set<std::string> seen;
    if (file.rig.empty()) problem(top / "rig", "the rig has no nodes", "list the model's nodes, root first");
    for (std::size_t i = 0; i < file.rig.size(); ++i) {
        const RigNodeDef& n = file.rig[i];
        const JsonPath p = (top / "rig")[i];
        if (n.name.empty())
            problem(p / "name", "rig node name is empty");
        else if (!seen.insert(n.name).second)
            problem(p / "name", "duplicate rig node '" + n.name + "'", "names must be unique");
        if (!n.parent.empty() &&
            std::find(node_names.begin(), node_names.end(), n.parent) == node_names.end())
            problem(p / "parent", "parent '" + n.parent + "' is not a node listed before '" + n.name + "'",
                    node_names.empty() ? "the first node is the root and has no parent"
                                       : "earlier nodes: " + join(node_names));
        auto check_vec = [&](const DVec3& v, const JsonPath& vp, double limit, const char* what) {
            for (int c = 0; c < 3; ++c)
                if (!std::isfinite(v[c]) || std::abs(v[c]) > limit)
                    problem(vp[static_cast<std::size_t>(c)],
                            std::string(what) + " component " + number_text(v[c]) + " is out of range",
                            "finite, |value| <= " + number_text(limit));
        };
        check_vec(n.position, p / "position", kMaxOffset, "position");
        check_vec(n.rotation, p / "rotation", kMaxAngle, "rotation");
        node_names.push_back(n.name);
    }
    const std::string known_nodes = "known nodes: " + join(node_names);
    auto is_node = [&](const std::string& name) {
        return std::find(node_names.begin(), node_names.end(), name) != node_names.end();
    };
    for (std::size_t i = 0; i < file.rest_nodes.size(); ++i)
        if (!is_node(file.rest_nodes[i]))
            problem((top / "rest_nodes")[i], "unknown node '" + file.rest_nodes[i] + "'",
                    suggestion(file.rest_nodes[i], node_names) + known_nodes);

    for (const NodeEase& ne : file.node_ease) {
        const JsonPath p = top / "node_ease" / ne.node;
        if (!is_node(ne.node))
            problem(p, "unknown node '" + ne.node + "'", suggestion(ne.node, node_names) + known_nodes);
        if (std::string why = validate_ease(ne.ease); !why.empty()) problem(p, why);
    }

    std::vector<std::string> clip_names;
    for (const ClipDef& c : file.clips) clip_names.push_back(c.name);
    const std::string known_clips = "known clips: " + join(clip_names);
    auto is_clip = [&](const std::string& name) { return file.find_clip(name) != nullptr; };

    if (!std::isfinite(file.default_blend) || file.default_blend < 0 || file.default_blend > kMaxBlend)
        problem(top / "blend" / "default",
                "default blend time " + number_text(file.default_blend) + " s is out of range",
                "seconds in [0, " + number_text(kMaxBlend) + "]");
    for (std::size_t i = 0; i < file.blends.size(); ++i) {
        const BlendPair& b = file.blends[i];
        const JsonPath p = (top / "blend" / "pairs")[i];
        if (b.from != "*" && !is_clip(b.from))
            problem(p / "from", "unknown clip '" + b.from + "'", known_clips + ", or * for any");
        if (b.to != "*" && !is_clip(b.to))
            problem(p / "to", "unknown clip '" + b.to + "'", known_clips + ", or * for any");
        if (!std::isfinite(b.time) || b.time < 0 || b.time > kMaxBlend)
            problem(p / "time", "blend time " + number_text(b.time) + " s is out of range",
                    "seconds in [0, " + number_text(kMaxBlend) + "]");
    }

    std::set<std::string> seen_clips;
    if (file.clips.empty()) problem(top / "clips", "the file has no clips");
    for (std::size_t ci = 0; ci < file.clips.size(); ++ci) {
        const ClipDef& c = file.clips[ci];
        const JsonPath cp = (top / "clips")[ci];
        if (c.name.empty())
            problem(cp / "name", "clip name is empty");
        else if (!seen_clips.insert(c.name).second)
            problem(cp / "name", "duplicate clip '" + c.name + "'", "clip names must be unique");
        if (c.loop == LoopMode::Next) {
            if (c.next.empty())
                problem(cp, "loop mode 'next' needs a \"next\" clip", known_clips);
            else if (!is_clip(c.next))
                problem(cp / "next", "unknown clip '" + c.next + "'",
                        suggestion(c.next, clip_names) + known_clips);
        } else if (!c.next.empty()) {
            problem(cp / "next", "\"next\" is only used with \"loop\": \"next\"",
                    "remove it or set the loop mode");
        }
        if (c.phases.empty())
            problem(cp / "phases", "clip '" + c.name + "' has no phases", "at least one phase");
        if (c.loop == LoopMode::Loop && !(c.duration() > 0))
            problem(cp / "phases", "looping clip '" + c.name + "' has zero length",
                    "give a phase a duration > 0");
        for (std::size_t pi = 0; pi < c.phases.size(); ++pi) {
            const PhaseDef& ph = c.phases[pi];
            const JsonPath pp = (cp / "phases")[pi];
            if (!std::isfinite(ph.duration) || ph.duration < 0 || ph.duration > kMaxDuration)
                problem(pp / "duration",
                        "duration " + number_text(ph.duration) + " s is " +
                            (ph.duration < 0 ? "negative" : "out of range"),
                        "seconds in [0, " + number_text(kMaxDuration) + "]; 0 sets the targets instantly");
            if (std::string why = validate_ease(ph.ease); !why.empty()) problem(pp / "ease", why);
            for (const TargetDef& t : ph.targets) {
                const JsonPath tp = pp / "targets" / t.node;
                if (!is_node(t.node)) {
                    problem(tp, "unknown node '" + t.node + "'",
                            suggestion(t.node, node_names) + known_nodes);
                    continue;
                }
                if (t.rot && t.add_rot)
                    problem(tp, "both \"rot\" and \"add_rot\"", "a target is absolute or relative, not both");
                if (t.pos && t.add_pos)
                    problem(tp, "both \"pos\" and \"add_pos\"", "a target is absolute or relative, not both");
                if (!t.rot && !t.add_rot && !t.pos && !t.add_pos)
                    problem(tp, "target sets nothing", "give \"rot\", \"add_rot\", \"pos\" or \"add_pos\"");
                auto check = [&](const std::optional<DVec3>& v, const char* key, double limit,
                                 const char* unit) {
                    if (!v) return;
                    for (int k = 0; k < 3; ++k)
                        if (!std::isfinite((*v)[k]) || std::abs((*v)[k]) > limit)
                            problem((tp / key)[static_cast<std::size_t>(k)],
                                    std::string(key) + " component " + number_text((*v)[k]) +
                                        " is out of range",
                                    "finite, |value| <= " + number_text(limit) + unit);
                };
                check(t.rot, "rot", kMaxAngle, " degrees");
                check(t.add_rot, "add_rot", kMaxAngle, " degrees");
                check(t.pos, "pos", kMaxOffset, " units");
                check(t.add_pos, "add_pos", kMaxOffset, " units");
                if (t.ease)
                    if (std::string why = validate_ease(*t.ease); !why.empty()) problem(tp / "ease", why);
            }
        }
    }
    // A chain of Next clips that returns to itself without taking time would hand over forever.
    for (std::size_t ci = 0; ci < file.clips.size(); ++ci) {
        const ClipDef* c = &file.clips[ci];
        double total = 0;
        for (int steps = 0; c && c->loop == LoopMode::Next && steps <= static_cast<int>(file.clips.size());
             ++steps) {
            total += c->duration();
            c = file.find_clip(c->next);
            if (c == &file.clips[ci] && !(total > 0)) {
                problem((top / "clips")[ci] / "next",
                        "clip '" + c->name + "' returns to itself through 'next' in zero time",
                        "give a clip in the chain a duration > 0");
                break;
            }
        }
    }
    return issues;
}

Result<AnimationFile> load_animation_string(std::string_view text, const std::string& file_name) {
    if (text.find_first_not_of(" \t\r\n") == std::string_view::npos)
        return Error("the animation file is empty", Location(file_name, 1, 1),
                     std::string("expected a JSON object with \"format\": \"") + kAnimationFormat +
                         "\", \"version\", \"rig\" and \"clips\"");
    Json root;
    try {
        root = Json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        // e.byte is 1-based, pointing just past the offending character.
        const std::size_t offset = e.byte > 0 ? e.byte - 1 : 0;
        TextPosition pos = line_column(text, offset);
        std::string hint = "fix the JSON syntax";
        const std::string_view near = text.substr(offset >= 8 ? offset - 8 : 0, 16);
        for (const char* bad : {"NaN", "nan", "Infinity", "inf"})
            if (near.find(bad) != std::string_view::npos)
                hint = "JSON has no NaN or Infinity: write a finite number";
        std::string what = e.what();
        if (auto p = what.find("parse error"); p != std::string::npos) what = what.substr(p);
        return Error(what, Location(file_name, pos.line, pos.column), hint);
    } catch (const nlohmann::json::exception& e) {
        // Number overflow (1e999) is reported without a position: find the quoted token in the text.
        std::string what = e.what();
        TextPosition pos{};
        auto open = what.find('\''), close = what.rfind('\'');
        if (open != std::string::npos && close > open) {
            auto at = text.find(what.substr(open + 1, close - open - 1));
            if (at != std::string_view::npos) pos = line_column(text, at);
        }
        return Error(what.substr(what.find(']') + 2) + ": number is not finite",
                     Location(file_name, pos.line, pos.column), "write a finite number");
    }

    Reader reader;
    AnimationFile file;
    reader.read(root, file);
    std::vector<Issue> issues = std::move(reader.issues);
    // Semantic checks run on what could be read, so one pass reports everything; a semantic issue on a
    // value the reader already rejected (or inside it) would only repeat that problem and is left out.
    auto related = [](const std::string& a, const std::string& b) {
        const std::string& shorter = a.size() < b.size() ? a : b;
        const std::string& longer = a.size() < b.size() ? b : a;
        return longer.compare(0, shorter.size(), shorter) == 0 &&
               (longer.size() == shorter.size() || shorter.empty() || longer[shorter.size()] == '.' ||
                longer[shorter.size()] == '[');
    };
    const std::size_t read_issues = issues.size();
    for (Issue& semantic : validate(file)) {
        bool repeat = false;
        for (std::size_t i = 0; i < read_issues && !repeat; ++i)
            repeat = related(issues[i].path.str(), semantic.path.str());
        if (!repeat) issues.push_back(std::move(semantic));
    }
    if (issues.empty()) return file;

    std::vector<Error> errors;
    for (const Issue& issue : issues) {
        TextPosition pos = locate(text, issue.path);
        errors.emplace_back(issue.message, Location(file_name, pos.line, pos.column, issue.path.str()),
                            issue.hint);
    }
    std::stable_sort(errors.begin(), errors.end(), [](const Error& a, const Error& b) {
        return std::pair(a.where.line, a.where.column) < std::pair(b.where.line, b.where.column);
    });
    return combine_errors(errors);
}

Result<AnimationFile> load_animation_file(const std::filesystem::path& path) {
    auto text = files::read_text(path);
    if (!text) {
        Error e = text.error();
        if (e.hint.empty()) e.hint = "animation files live in assets/animations/";
        return e;
    }
    return load_animation_string(*text, path.string());
}

std::string save_animation_string(const AnimationFile& file) {
    std::string out;
    out += "{\n";
    out += "  \"format\": " + quoted(kAnimationFormat) + ",\n";
    out += "  \"version\": " + std::to_string(kAnimationVersion) + ",\n";
    out += "  \"rig\": [\n";
    for (std::size_t i = 0; i < file.rig.size(); ++i) {
        const RigNodeDef& n = file.rig[i];
        out += "    {\"name\": " + quoted(n.name);
        if (!n.parent.empty()) out += ", \"parent\": " + quoted(n.parent);
        if (n.position != DVec3(0)) out += ", \"position\": " + vec_text(n.position);
        if (n.rotation != DVec3(0)) out += ", \"rotation\": " + vec_text(n.rotation);
        out += i + 1 < file.rig.size() ? "},\n" : "}\n";
    }
    out += "  ],\n  \"rest_nodes\": [";
    for (std::size_t i = 0; i < file.rest_nodes.size(); ++i)
        out += (i ? ", " : "") + quoted(file.rest_nodes[i]);
    out += "],\n";
    if (!file.node_ease.empty()) {
        out += "  \"node_ease\": {";
        for (std::size_t i = 0; i < file.node_ease.size(); ++i)
            out +=
                (i ? ", " : "") + quoted(file.node_ease[i].node) + ": " + ease_text(file.node_ease[i].ease);
        out += "},\n";
    }
    out += "  \"blend\": {\n    \"default\": " + number_text(file.default_blend) + ",\n    \"pairs\": [";
    for (std::size_t i = 0; i < file.blends.size(); ++i) {
        const BlendPair& b = file.blends[i];
        out += (i ? ",\n" : "\n");
        out += "      {\"from\": " + quoted(b.from) + ", \"to\": " + quoted(b.to) +
               ", \"time\": " + number_text(b.time) + "}";
    }
    out += file.blends.empty() ? "]\n  },\n" : "\n    ]\n  },\n";
    out +=
        std::string("  \"wrap_captured_angles\": ") + (file.wrap_captured_angles ? "true" : "false") + ",\n";
    out += "  \"clips\": [";
    for (std::size_t ci = 0; ci < file.clips.size(); ++ci) {
        const ClipDef& c = file.clips[ci];
        out += ci ? ",\n" : "\n";
        out += "    {\n      \"name\": " + quoted(c.name) + ",\n";
        out += std::string("      \"loop\": \"") + loop_name(c.loop) + "\",\n";
        if (!c.next.empty()) out += "      \"next\": " + quoted(c.next) + ",\n";
        out += std::string("      \"unlisted\": \"") + (c.unlisted == UnlistedRule::Rest ? "rest" : "hold") +
               "\",\n";
        out += "      \"phases\": [";
        for (std::size_t pi = 0; pi < c.phases.size(); ++pi) {
            const PhaseDef& ph = c.phases[pi];
            out += pi ? ",\n" : "\n";
            out += "        {\n          \"duration\": " + number_text(ph.duration) + ",\n";
            out += "          \"ease\": " + ease_text(ph.ease) + ",\n";
            out += "          \"targets\": {";
            for (std::size_t ti = 0; ti < ph.targets.size(); ++ti) {
                const TargetDef& t = ph.targets[ti];
                out += ti ? ",\n" : "\n";
                out += "            " + quoted(t.node) + ": {";
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
        out += c.phases.empty() ? "]\n" : "\n      ]\n";
        out += "    }";
    }
    out += file.clips.empty() ? "]\n}\n" : "\n  ]\n}\n";
    return out;
}

Result<void> save_animation_file(const std::filesystem::path& path, const AnimationFile& file) {
    return files::write_atomic(path, save_animation_string(file));
}

Result<AnimationLibrary> load_animation_library(const std::filesystem::path& path) {
    auto file = load_animation_file(path);
    if (!file) return file.error();
    auto rig = build_rig(*file);
    if (!rig) return Error(rig.error().message, Location(path.string()), rig.error().hint);
    auto clips = compile(*file, *rig);
    if (!clips) return Error(clips.error().message, Location(path.string()), clips.error().hint);
    return AnimationLibrary{std::move(*file), std::move(*rig), std::move(*clips)};
}

} // namespace ks::anim
