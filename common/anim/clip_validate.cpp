#include "anim/clip_io.h"

#include "anim/clip_issues.h"
#include "jsonio/number_text.h"
#include "jsonio/suggest.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace ks::anim {
namespace {

// Limits that catch typos (an angle in radians written as degrees is fine; 1e9 is not).
constexpr double kMaxDuration = 600.0; // seconds per phase
constexpr double kMaxBlend = 10.0;     // seconds
constexpr double kMaxAngle = 36000.0;  // degrees: 100 turns
constexpr double kMaxOffset = 10000.0; // world units
// A clip's frame rate (frames per second): film's 24 to high-speed 1000; 0 or a negative rate has no grid.
constexpr double kMinFrameRate = 1.0, kMaxFrameRate = 1000.0;
// Events per clip: a walk cycle's footsteps, a burst's shots. Each event acts (a muzzle_flash is a shot), so
// thousands are a mistake, not a clip.
constexpr std::size_t kMaxClipEvents = 64;

// The semantic checks of validate(), in the order their issues are listed: rig, node references, blends,
// clips, then chains of 'next' clips.
class Validator {
  public:
    explicit Validator(const AnimationFile& file) : file_(file) {}

    std::vector<Issue> run() {
        check_rig();
        check_node_references();
        for (const ClipDef& c : file_.clips) clip_names_.push_back(c.name);
        known_clips_ = "known clips: " + jsonio::join(clip_names_);
        check_blends();
        check_clips();
        check_next_chains();
        return std::move(issues_);
    }

  private:
    const AnimationFile& file_;
    std::vector<Issue> issues_;
    const JsonPath top_;
    std::vector<std::string> node_names_, clip_names_;
    std::string known_nodes_, known_clips_;

    void problem(const JsonPath& path, std::string message, std::string hint = {}) {
        issues_.push_back({path, std::move(message), std::move(hint)});
    }
    bool is_node(const std::string& name) const {
        return std::find(node_names_.begin(), node_names_.end(), name) != node_names_.end();
    }
    bool is_clip(const std::string& name) const { return file_.find_clip(name) != nullptr; }

    void check_components(const DVec3& v, const JsonPath& path, double limit, const std::string& what,
                          const char* unit) {
        for (int c = 0; c < 3; ++c)
            if (!std::isfinite(v[c]) || std::abs(v[c]) > limit)
                problem(path[static_cast<std::size_t>(c)],
                        what + " component " + jsonio::shortest_text(v[c]) + " is out of range",
                        "finite, |value| <= " + jsonio::shortest_text(limit) + unit);
    }

    void check_rig() {
        std::set<std::string> seen;
        if (file_.rig.empty())
            problem(top_ / "rig", "the rig has no nodes", "list the model's nodes, root first");
        for (std::size_t i = 0; i < file_.rig.size(); ++i) {
            const RigNodeDef& n = file_.rig[i];
            const JsonPath p = (top_ / "rig")[i];
            if (n.name.empty())
                problem(p / "name", "rig node name is empty");
            else if (!seen.insert(n.name).second)
                problem(p / "name", "duplicate rig node " + quoted_name(n.name), "names must be unique");
            if (!n.parent.empty() && !is_node(n.parent))
                problem(p / "parent",
                        "parent " + quoted_name(n.parent) + " is not a node listed before " +
                            quoted_name(n.name),
                        node_names_.empty() ? "the first node is the root and has no parent"
                                            : "earlier nodes: " + jsonio::join(node_names_));
            check_components(n.position, p / "position", kMaxOffset, "position", "");
            check_components(n.rotation, p / "rotation", kMaxAngle, "rotation", "");
            node_names_.push_back(n.name);
        }
        known_nodes_ = "known nodes: " + jsonio::join(node_names_);
    }

    void check_node_references() {
        for (std::size_t i = 0; i < file_.rest_nodes.size(); ++i)
            if (!is_node(file_.rest_nodes[i]))
                problem((top_ / "rest_nodes")[i], "unknown node " + quoted_name(file_.rest_nodes[i]),
                        did_you_mean(file_.rest_nodes[i], node_names_) + known_nodes_);
        for (const NodeEase& ne : file_.node_ease) {
            const JsonPath p = top_ / "node_ease" / ne.node;
            if (!is_node(ne.node))
                problem(p, "unknown node " + quoted_name(ne.node),
                        did_you_mean(ne.node, node_names_) + known_nodes_);
            if (std::string why = validate_ease(ne.ease); !why.empty()) problem(p, why);
        }
    }

    void check_blends() {
        const double default_blend = file_.default_blend;
        if (!std::isfinite(default_blend) || default_blend < 0 || default_blend > kMaxBlend)
            problem(top_ / "blend" / "default",
                    "default blend time " + jsonio::shortest_text(default_blend) + " s is out of range",
                    "seconds in [0, " + jsonio::shortest_text(kMaxBlend) + "]");
        for (std::size_t i = 0; i < file_.blends.size(); ++i) {
            const BlendPair& b = file_.blends[i];
            const JsonPath p = (top_ / "blend" / "pairs")[i];
            if (b.from != "*" && !is_clip(b.from))
                problem(p / "from", "unknown clip " + quoted_name(b.from), known_clips_ + ", or * for any");
            if (b.to != "*" && !is_clip(b.to))
                problem(p / "to", "unknown clip " + quoted_name(b.to), known_clips_ + ", or * for any");
            if (!std::isfinite(b.time) || b.time < 0 || b.time > kMaxBlend)
                problem(p / "time", "blend time " + jsonio::shortest_text(b.time) + " s is out of range",
                        "seconds in [0, " + jsonio::shortest_text(kMaxBlend) + "]");
        }
    }

    void check_clips() {
        std::set<std::string> seen;
        if (file_.clips.empty()) problem(top_ / "clips", "the file has no clips");
        for (std::size_t ci = 0; ci < file_.clips.size(); ++ci) {
            const ClipDef& c = file_.clips[ci];
            const JsonPath cp = (top_ / "clips")[ci];
            if (c.name.empty())
                problem(cp / "name", "clip name is empty");
            else if (!seen.insert(c.name).second)
                problem(cp / "name", "duplicate clip " + quoted_name(c.name), "clip names must be unique");
            check_loop(c, cp);
            check_frame_rate(c, cp);
            if (c.phases.empty())
                problem(cp / "phases", "clip " + quoted_name(c.name) + " has no phases",
                        "at least one phase");
            if ((c.loop == LoopMode::Loop || c.loop == LoopMode::PingPong) && !(c.duration() > 0))
                problem(cp / "phases",
                        std::string(c.loop == LoopMode::Loop ? "looping" : "ping-pong") + " clip " +
                            quoted_name(c.name) + " has zero length",
                        "give a phase a duration > 0");
            for (std::size_t pi = 0; pi < c.phases.size(); ++pi)
                check_phase(c.phases[pi], (cp / "phases")[pi]);
            if (c.events.size() > kMaxClipEvents) {
                problem(cp / "events",
                        "clip " + quoted_name(c.name) + " has " + std::to_string(c.events.size()) +
                            " events; at most " + std::to_string(kMaxClipEvents),
                        "each event acts when the clip passes it (a muzzle_flash is a shot): keep the ones "
                        "that mean something");
                continue;
            }
            for (std::size_t ei = 0; ei < c.events.size(); ++ei) {
                check_event(c, c.events[ei], (cp / "events")[ei]);
                check_event_repeated(c, ei, cp / "events");
            }
        }
    }

    void check_event(const ClipDef& c, const ClipEvent& e, const JsonPath& ep) {
        const double length = c.duration();
        if (!std::isfinite(e.time) || e.time < 0 || e.time > length)
            problem(ep / "time",
                    "event time " + jsonio::shortest_text(e.time) + " s is outside clip " +
                        quoted_name(c.name) + " (0.." + jsonio::shortest_text(length) + " s)",
                    "put the event inside the clip");
        if (e.name.empty()) problem(ep / "name", "event name is empty", "e.g. \"muzzle_flash\"");
        if (!e.sound.empty() && !is_sound_name(e.sound))
            problem(ep / "sound",
                    "sound name " + quoted_name(e.sound) + " has characters other than a-z, 0-9 and _",
                    "name a file of assets/sounds/ without its .wav");
    }

    // The same event twice at the same moment acts twice (two muzzle_flash events are two shots, double
    // damage): refused, naming the first.
    void check_event_repeated(const ClipDef& c, std::size_t index, const JsonPath& events) {
        const ClipEvent& e = c.events[index];
        for (std::size_t k = 0; k < index; ++k) {
            const ClipEvent& first = c.events[k];
            if (first.name != e.name || !(std::fabs(first.time - e.time) <= kSameEventTime)) continue;
            problem(events[index],
                    "event " + quoted_name(e.name) + " is listed twice at " + jsonio::shortest_text(e.time) +
                        " s in clip " + quoted_name(c.name) + " (also events[" + std::to_string(k) + "])",
                    "remove one: each acts when the clip passes it (two muzzle_flash events are two shots)");
            return;
        }
    }
    static constexpr double kSameEventTime = 1e-6; // seconds: closer than any frame

    static bool is_sound_name(const std::string& s) {
        for (char ch : s)
            if (!((ch >= 'a' && ch <= 'z') || (ch >= '0' && ch <= '9') || ch == '_')) return false;
        return true;
    }

    void check_loop(const ClipDef& c, const JsonPath& cp) {
        if (c.loop == LoopMode::Next) {
            if (c.next.empty())
                problem(cp, "loop mode 'next' needs a \"next\" clip", known_clips_);
            else if (!is_clip(c.next))
                problem(cp / "next", "unknown clip " + quoted_name(c.next),
                        did_you_mean(c.next, clip_names_) + known_clips_);
        } else if (!c.next.empty()) {
            problem(cp / "next", "\"next\" is only used with \"loop\": \"next\"",
                    "remove it or set the loop mode");
        }
    }

    void check_frame_rate(const ClipDef& c, const JsonPath& cp) {
        if (!c.frame_rate) return;
        const double fps = *c.frame_rate;
        if (std::isfinite(fps) && fps >= kMinFrameRate && fps <= kMaxFrameRate) return;
        problem(cp / "frame_rate",
                "frame rate " + jsonio::shortest_text(fps) + " of clip " + quoted_name(c.name) + " is " +
                    (fps <= 0 ? "not positive" : "out of range"),
                "frames per second in [" + jsonio::shortest_text(kMinFrameRate) + ", " +
                    jsonio::shortest_text(kMaxFrameRate) +
                    "], e.g. 24, 30 or 60; remove \"frame_rate\" to work in seconds");
    }

    void check_phase(const PhaseDef& ph, const JsonPath& pp) {
        if (!std::isfinite(ph.duration) || ph.duration < 0 || ph.duration > kMaxDuration)
            problem(pp / "duration",
                    "duration " + jsonio::shortest_text(ph.duration) + " s is " +
                        (ph.duration < 0 ? "negative" : "out of range"),
                    "seconds in [0, " + jsonio::shortest_text(kMaxDuration) +
                        "]; 0 sets the targets instantly");
        if (std::string why = validate_ease(ph.ease); !why.empty()) problem(pp / "ease", why);
        for (const TargetDef& t : ph.targets) check_target(t, pp / "targets" / t.node);
    }

    void check_target(const TargetDef& t, const JsonPath& tp) {
        if (!is_node(t.node)) {
            problem(tp, "unknown node " + quoted_name(t.node),
                    did_you_mean(t.node, node_names_) + known_nodes_);
            return;
        }
        if (t.rot && t.add_rot)
            problem(tp, "both \"rot\" and \"add_rot\"", "a target is absolute or relative, not both");
        if (t.pos && t.add_pos)
            problem(tp, "both \"pos\" and \"add_pos\"", "a target is absolute or relative, not both");
        if (!t.rot && !t.add_rot && !t.pos && !t.add_pos)
            problem(tp, "target sets nothing", "give \"rot\", \"add_rot\", \"pos\" or \"add_pos\"");
        const struct {
            const std::optional<DVec3>& value;
            const char* key;
            double limit;
            const char* unit;
        } channels[] = {{t.rot, "rot", kMaxAngle, " degrees"},
                        {t.add_rot, "add_rot", kMaxAngle, " degrees"},
                        {t.pos, "pos", kMaxOffset, " units"},
                        {t.add_pos, "add_pos", kMaxOffset, " units"}};
        for (const auto& channel : channels)
            if (channel.value)
                check_components(*channel.value, tp / channel.key, channel.limit, channel.key, channel.unit);
        if (t.ease)
            if (std::string why = validate_ease(*t.ease); !why.empty()) problem(tp / "ease", why);
    }

    // A chain of Next clips that returns to itself without taking time would hand over forever.
    void check_next_chains() {
        for (std::size_t ci = 0; ci < file_.clips.size(); ++ci) {
            const ClipDef* c = &file_.clips[ci];
            double total = 0;
            for (int steps = 0;
                 c && c->loop == LoopMode::Next && steps <= static_cast<int>(file_.clips.size()); ++steps) {
                total += c->duration();
                c = file_.find_clip(c->next);
                if (c == &file_.clips[ci] && !(total > 0)) {
                    problem((top_ / "clips")[ci] / "next",
                            "clip " + quoted_name(c->name) + " returns to itself through 'next' in zero time",
                            "give a clip in the chain a duration > 0");
                    break;
                }
            }
        }
    }
};

} // namespace

std::vector<Issue> validate(const AnimationFile& file) {
    return Validator(file).run();
}

} // namespace ks::anim
