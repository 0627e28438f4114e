// The script language's dojo lines run on a DojoDocument (script_dojo.h): each edit through
// DojoDocument::edit (one undo step), each expectation checked against the file.
#include "core/paths.h"
#include "jsonio/number_text.h"
#include "model/dojo_curves.h"
#include "model/script_dojo.h"

#include <cmath>

namespace ks::editor {
namespace fs = std::filesystem;
namespace {

constexpr double kFileTolerance = 1e-9;  // a file's doubles, and sums of its durations
constexpr double kCurveTolerance = 1e-3; // sampled in float: degrees or units

template <class T>
Result<void> done(const Result<T>& r) {
    if (!r) return r.error();
    return ok();
}

std::string number_text(double v) {
    return jsonio::shortest_text(v);
}

class DojoRunner {
  public:
    DojoRunner(DojoDocument& dojo, const fs::path& base_dir, ScriptReport& report)
        : dojo_(dojo), base_dir_(base_dir), report_(report) {}

    Result<void> run(const DojoStep& s) {
        if (s.op == DojoOp::Open) return open(s);
        if (!dojo_.is_open())
            return Error("no clip file is open", {},
                         "start the dojo lines with 'dojo open' (the robot's clips) or 'dojo open FILE'");
        if (s.op == DojoOp::Save) return save(s);
        if (s.op == DojoOp::Undo || s.op == DojoOp::Redo) return undo_or_redo(s);
        if (s.op >= DojoOp::ExpectClipExists) return expectation(s);
        if (s.op <= DojoOp::ClipLoop) return clip_edit(s);
        if (s.op <= DojoOp::BlendClear) return blend_edit(s);
        if (s.op <= DojoOp::EventRemove) return event_edit(s);
        return key_edit(s);
    }

  private:
    // ---- files and history ----------------------------------------------------------------------------

    fs::path resolve(const std::string& p) const {
        fs::path path(p);
        return path.is_absolute() || base_dir_.empty() ? path : base_dir_ / path;
    }
    Result<void> open(const DojoStep& s) {
        return dojo_.open(s.words.empty() ? paths::asset("animations/robot.json") : resolve(s.words[0]));
    }
    Result<void> save(const DojoStep& s) {
        if (auto saved = dojo_.save(s.words.empty() ? fs::path() : resolve(s.words[0])); !saved) return saved;
        report_.saved.push_back(dojo_.path());
        return ok();
    }
    Result<void> undo_or_redo(const DojoStep& s) {
        const bool undo = s.op == DojoOp::Undo;
        for (int i = 0; s.index < 0 || i < s.index; ++i) {
            if (undo ? dojo_.undo() : dojo_.redo()) continue;
            if (s.index < 0) break;
            return Error(std::string("nothing to ") + (undo ? "undo" : "redo") + " in the dojo (step " +
                         std::to_string(i + 1) + " of " + std::to_string(s.index) + ")");
        }
        return ok();
    }

    Result<std::size_t> clip(const std::string& name) const { return find_clip_index(dojo_.file(), name); }
    static std::size_t nth(const DojoStep& s) { return static_cast<std::size_t>(s.index - 1); }
    // The line's words from the first on, joined: the history step's name.
    static std::string step_name(const char* verb, const DojoStep& s) {
        std::string name = verb;
        for (const std::string& w : s.words) name += " " + w;
        return name;
    }

    // ---- edits ----------------------------------------------------------------------------------------

    Result<void> clip_edit(const DojoStep& s) {
        if (s.op == DojoOp::ClipNew) return new_clip_step(s);
        auto index = clip(s.words[0]);
        if (!index) return index.error();
        const std::size_t c = *index;
        switch (s.op) {
        case DojoOp::ClipDuplicate:
            return done(
                dojo_.edit(step_name("duplicate clip", s), [&](auto& f) { return duplicate_clip(f, c); }));
        case DojoOp::ClipRename:
            return dojo_.edit(step_name("rename clip", s),
                              [&](auto& f) { return rename_clip(f, c, s.words[1]); });
        case DojoOp::ClipDelete:
            return dojo_.edit(step_name("delete clip", s), [&](auto& f) { return delete_clip(f, c); });
        default: {
            const auto mode = loop_mode_from_name(s.words[1]);
            if (!mode) return mode.error();
            const std::string next = s.words.size() > 2 ? s.words[2] : std::string();
            return dojo_.edit(step_name("loop", s),
                              [&](auto& f) { return set_loop_mode(f, c, *mode, next); });
        }
        }
    }
    // clip new NAME [from CLIP [SECONDS]]: the pose CLIP reaches then (its end by default).
    Result<void> new_clip_step(const DojoStep& s) {
        std::vector<NodePoseValue> pose;
        if (s.words.size() > 1) {
            auto source = clip(s.words[1]);
            if (!source) return source.error();
            const double at = s.has_number ? s.number : dojo_.file().clips[*source].duration();
            auto values = clip_pose_values(dojo_.file(), *source, at);
            if (!values) return values.error();
            pose = std::move(values).value();
        }
        return done(
            dojo_.edit(step_name("new clip", s), [&](auto& f) { return new_clip(f, s.words[0], pose); }));
    }

    Result<void> blend_edit(const DojoStep& s) {
        if (s.op == DojoOp::BlendDefault)
            return dojo_.edit("default blend " + number_text(s.number),
                              [&](auto& f) { return set_default_blend(f, s.number); });
        if (s.op == DojoOp::BlendClear)
            return dojo_.edit(step_name("clear blend", s),
                              [&](auto& f) { return clear_blend(f, s.words[0], s.words[1]); });
        return dojo_.edit(step_name("blend", s) + " " + number_text(s.number),
                          [&](auto& f) { return set_blend(f, s.words[0], s.words[1], s.number); });
    }

    Result<void> event_edit(const DojoStep& s) {
        auto index = clip(s.words[0]);
        if (!index) return index.error();
        const std::size_t c = *index, e = nth(s);
        switch (s.op) {
        case DojoOp::EventAdd: {
            const std::string sound = s.words.size() > 2 ? s.words[2] : std::string();
            return done(dojo_.edit(step_name("add event", s),
                                   [&](auto& f) { return add_event(f, c, s.number, s.words[1], sound); }));
        }
        case DojoOp::EventMove:
            return done(dojo_.edit(step_name("move event", s),
                                   [&](auto& f) { return move_event(f, c, e, s.number); }));
        case DojoOp::EventRename:
            return dojo_.edit(step_name("rename event", s),
                              [&](auto& f) { return rename_event(f, c, e, s.words[1]); });
        case DojoOp::EventSound: {
            const std::string sound = s.words[1] == "none" ? std::string() : s.words[1];
            return dojo_.edit(step_name("event sound", s),
                              [&](auto& f) { return set_event_sound(f, c, e, sound); });
        }
        default:
            return dojo_.edit(step_name("remove event", s), [&](auto& f) { return remove_event(f, c, e); });
        }
    }

    Result<void> key_edit(const DojoStep& s) {
        auto index = clip(s.words[0]);
        if (!index) return index.error();
        const std::size_t c = *index, k = nth(s);
        switch (s.op) {
        case DojoOp::KeyTime:
            return dojo_.edit(step_name("key time", s),
                              [&](auto& f) { return move_key_time(f, c, k, s.number); });
        case DojoOp::KeyValue: {
            const CurveChannel channel = *curve_channel_from_name(s.words[2]);
            return dojo_.edit(step_name("key value", s),
                              [&](auto& f) { return set_key_value(f, c, k, s.words[1], channel, s.number); });
        }
        case DojoOp::KeyAdd:
            return dojo_.edit(step_name("add key", s),
                              [&](auto& f) { return add_node_key(f, c, k, s.words[1]); });
        default:
            return dojo_.edit(step_name("remove key", s),
                              [&](auto& f) { return remove_node_key(f, c, k, s.words[1]); });
        }
    }

    // ---- expectations ---------------------------------------------------------------------------------

    Result<void> expect(bool condition, const std::string& message) {
        ++report_.expectations_checked;
        if (!condition) return Error("expectation failed: " + message);
        return ok();
    }
    static bool close(double a, double b, double tolerance) { return std::abs(a - b) <= tolerance; }

    Result<void> expectation(const DojoStep& s) {
        const anim::AnimationFile& file = dojo_.file();
        switch (s.op) {
        case DojoOp::ExpectValid: {
            const auto issues = dojo_file_issues(file);
            return expect(issues.empty(), "the clip file has " + std::to_string(issues.size()) + " issue(s)" +
                                              issue_list(issues));
        }
        case DojoOp::ExpectIssue: {
            const auto issues = dojo_file_issues(file);
            bool found = false;
            for (const anim::Issue& i : issues)
                found = found || i.message.find(s.words[0]) != std::string::npos;
            return expect(found,
                          "no clip file issue mentions '" + s.words[0] + "'; issues:" + issue_list(issues));
        }
        case DojoOp::ExpectDirty:
            return expect(dojo_.dirty(), "the clip file has no unsaved edits");
        case DojoOp::ExpectClean:
            return expect(!dojo_.dirty(), "the clip file has unsaved edits");
        case DojoOp::ExpectClipExists:
        case DojoOp::ExpectClipMissing: {
            const bool exists = file.find_clip(s.words[0]) != nullptr;
            const bool wanted = s.op == DojoOp::ExpectClipExists;
            return expect(exists == wanted,
                          "clip '" + s.words[0] + "' " + (exists ? "exists" : "is missing"));
        }
        default:
            break;
        }
        auto index = clip(s.words[0]);
        if (!index) return index.error();
        return clip_expectation(s, *index);
    }

    static std::string issue_list(const std::vector<anim::Issue>& issues) {
        std::string out;
        for (const anim::Issue& i : issues) out += "\n  " + i.path.str() + ": " + i.message;
        return out;
    }

    Result<void> clip_expectation(const DojoStep& s, std::size_t c) {
        const anim::AnimationFile& file = dojo_.file();
        const anim::ClipDef& def = file.clips[c];
        const std::string name = "clip '" + def.name + "'";
        switch (s.op) {
        case DojoOp::ExpectClipLoop: {
            const std::string next = s.words.size() > 2 ? s.words[2] : std::string();
            const std::string actual =
                std::string(loop_mode_name(def.loop)) + (def.next.empty() ? "" : " " + def.next);
            return expect(s.words[1] == loop_mode_name(def.loop) && next == def.next,
                          name + " loops '" + actual + "', expected '" + s.words[1] +
                              (next.empty() ? "" : " " + next) + "'");
        }
        case DojoOp::ExpectClipDuration:
            return expect(close(def.duration(), s.number, kFileTolerance),
                          name + " lasts " + number_text(def.duration()) + " s, expected " +
                              number_text(s.number));
        case DojoOp::ExpectBlend: {
            auto to = clip(s.words[1]);
            if (!to) return to.error();
            const double actual = blend_grid(file).at(c, *to).seconds;
            return expect(close(actual, s.number, kFileTolerance),
                          "blend " + s.words[0] + " -> " + s.words[1] + " is " + number_text(actual) +
                              " s, expected " + number_text(s.number));
        }
        case DojoOp::ExpectEvents:
            return expect(def.events.size() == static_cast<std::size_t>(s.index),
                          name + " has " + std::to_string(def.events.size()) + " events, expected " +
                              std::to_string(s.index));
        case DojoOp::ExpectEvent:
            return expect_event(s, def);
        default:
            return key_expectation(s, c);
        }
    }

    Result<void> expect_event(const DojoStep& s, const anim::ClipDef& def) {
        const std::size_t e = nth(s);
        if (e >= def.events.size())
            return expect(false, "clip '" + def.name + "' has no event " + std::to_string(s.index) +
                                     " (it has " + std::to_string(def.events.size()) + ")");
        const anim::ClipEvent& ev = def.events[e];
        bool match = close(ev.time, s.number, kFileTolerance);
        if (s.words.size() > 1) match = match && ev.name == s.words[1];
        if (s.words.size() > 2)
            match = match && ev.sound == (s.words[2] == "none" ? std::string() : s.words[2]);
        return expect(match, "event " + std::to_string(s.index) + " of clip '" + def.name + "' is " +
                                 number_text(ev.time) + " s '" + ev.name + "'" +
                                 (ev.sound.empty() ? "" : " sound '" + ev.sound + "'"));
    }

    Result<void> key_expectation(const DojoStep& s, std::size_t c) {
        const anim::AnimationFile& file = dojo_.file();
        const anim::ClipDef& def = file.clips[c];
        if (s.op == DojoOp::ExpectCurve) {
            const CurveChannel channel = *curve_channel_from_name(s.words[2]);
            auto value = curve_value(file, c, s.words[1], channel, s.number);
            if (!value) return value.error();
            return expect(close(*value, s.number2, kCurveTolerance),
                          "clip '" + def.name + "' " + s.words[1] + " " + s.words[2] + " at " +
                              number_text(s.number) + " s is " + number_text(*value) + ", expected " +
                              number_text(s.number2));
        }
        const std::size_t k = nth(s);
        if (k >= def.phases.size())
            return expect(false, "clip '" + def.name + "' has no key " + std::to_string(s.index) +
                                     " (it has " + std::to_string(def.phases.size()) + ")");
        if (s.op == DojoOp::ExpectKeyTime) {
            double end = 0;
            for (std::size_t p = 0; p <= k; ++p) end += def.phases[p].duration;
            return expect(close(end, s.number, kFileTolerance),
                          "key " + std::to_string(s.index) + " of clip '" + def.name + "' is at " +
                              number_text(end) + " s, expected " + number_text(s.number));
        }
        const CurveChannel channel = *curve_channel_from_name(s.words[2]);
        auto curve = clip_curve(file, c, s.words[1], channel, 2);
        if (!curve) return curve.error();
        const CurveKey& key = curve->keys[k];
        if (!key.keyed)
            return expect(false, s.words[1] + " has no " + s.words[2] + " key in key " +
                                     std::to_string(s.index) + " of clip '" + def.name + "'");
        return expect(close(key.target_value, s.number, kFileTolerance),
                      s.words[1] + " " + s.words[2] + " in key " + std::to_string(s.index) + " of clip '" +
                          def.name + "' is " + number_text(key.target_value) + ", expected " +
                          number_text(s.number));
    }

    DojoDocument& dojo_;
    const fs::path& base_dir_;
    ScriptReport& report_;
};

} // namespace

Result<void> run_dojo_step(const DojoStep& step, DojoDocument& dojo, const fs::path& base_dir,
                           ScriptReport& report) {
    return DojoRunner(dojo, base_dir, report).run(step);
}

} // namespace ks::editor
