// The script language's dojo steps run on the script's DojoDocument (script_dojo.h): each edit through
// DojoDocument::edit (one undo step, named after the line's words), each expectation checked against the
// file.
#include "core/log.h"
#include "core/paths.h"
#include "jsonio/number_text.h"
#include "model/dojo_curves.h"
#include "model/dojo_gltf.h"
#include "model/script_command.h"

#include <cmath>

namespace ks::editor {
namespace {

constexpr double kFileTolerance = 1e-9;  // a file's doubles, and sums of its durations
constexpr double kCurveTolerance = 1e-3; // sampled in float: degrees or units

template <class T>
Result<void> dojo_step_done(const Result<T>& r) { // named apart from the other runners' done (unity batches)
    if (!r) return r.error();
    return ok();
}

std::string number_text(double v) {
    return jsonio::shortest_text(v);
}

bool close(double a, double b, double tolerance) {
    return std::abs(a - b) <= tolerance;
}

Result<std::size_t> clip_index(const ScriptContext& c, const std::string& name) {
    return find_clip_index(c.dojo.file(), name);
}

// Runs `edit(file, clip index)` as one history step named `name` on clip `clip`.
template <class Edit>
Result<void> edit_clip(ScriptContext& c, const std::string& clip, const std::string& name, Edit edit) {
    auto index = clip_index(c, clip);
    if (!index) return index.error();
    return dojo_step_done(c.dojo.edit(name, [&](auto& f) { return edit(f, *index); }));
}

// count < 0 means "all": stop quietly when history runs out.
Result<void> undo_or_redo(DojoDocument& dojo, bool undo, int count) {
    for (int i = 0; count < 0 || i < count; ++i) {
        if (undo ? dojo.undo() : dojo.redo()) continue;
        if (count < 0) break;
        return Error(std::string("nothing to ") + (undo ? "undo" : "redo") + " in the dojo (step " +
                     std::to_string(i + 1) + " of " + std::to_string(count) + ")");
    }
    return ok();
}

std::string issue_list(const std::vector<anim::Issue>& issues) {
    std::string out;
    for (const anim::Issue& i : issues) out += "\n  " + i.path.str() + ": " + i.message;
    return out;
}

} // namespace

Result<void> DojoStep::run(ScriptContext& c) const {
    if (!std::holds_alternative<steps::DojoOpen>(step) && !c.dojo.is_open())
        return Error("no clip file is open", {},
                     "start the dojo lines with 'dojo open' (the robot's clips) or 'dojo open FILE'");
    return std::visit([&](const auto& s) { return s.run(c); }, step);
}

namespace steps {

// ---- the file and its history -------------------------------------------------------------------------

Result<void> DojoOpen::run(ScriptContext& c) const {
    return c.dojo.open(path.empty() ? paths::asset("animations/robot.json") : c.resolve(path));
}
Result<void> DojoSave::run(ScriptContext& c) const {
    if (auto saved = c.dojo.save(path.empty() ? std::filesystem::path() : c.resolve(path)); !saved)
        return saved;
    c.report.saved.push_back(c.dojo.path());
    return ok();
}
Result<void> DojoExport::run(ScriptContext& c) const {
    auto rig = anim::build_rig(c.dojo.file());
    if (!rig) return rig.error();
    std::vector<std::size_t> clips;
    if (!clip.empty()) {
        auto index = clip_index(c, clip);
        if (!index) return index.error();
        clips.push_back(*index);
    }
    if (auto written = export_clips_gltf(c.dojo.file(), *rig, clips, c.resolve(path)); !written)
        return written;
    c.report.saved.push_back(c.resolve(path));
    return ok();
}
Result<void> DojoImport::run(ScriptContext& c) const {
    auto rig = anim::build_rig(c.dojo.file());
    if (!rig) return rig.error();
    auto report = c.dojo.edit("import glTF " + path,
                              [&](auto& f) { return import_clips_gltf(f, *rig, c.resolve(path)); });
    if (!report) return report.error();
    log::info(c.file_name + ":" + std::to_string(c.line) + ": " + report->summary());
    return ok();
}
Result<void> DojoUndo::run(ScriptContext& c) const {
    return undo_or_redo(c.dojo, true, count);
}
Result<void> DojoRedo::run(ScriptContext& c) const {
    return undo_or_redo(c.dojo, false, count);
}

// ---- clips --------------------------------------------------------------------------------------------

// A new clip, empty or set to the pose `from` reaches at `seconds` (its end by default).
Result<void> ClipNew::run(ScriptContext& c) const {
    std::vector<NodePoseValue> pose;
    if (!from.empty()) {
        auto source = clip_index(c, from);
        if (!source) return source.error();
        const double at = seconds ? *seconds : c.dojo.file().clips[*source].duration();
        auto values = clip_pose_values(c.dojo.file(), *source, at);
        if (!values) return values.error();
        pose = std::move(values).value();
    }
    const std::string step = "new clip " + name + (from.empty() ? "" : " " + from);
    return dojo_step_done(c.dojo.edit(step, [&](auto& f) { return new_clip(f, name, pose); }));
}
Result<void> ClipDuplicate::run(ScriptContext& c) const {
    return edit_clip(c, clip, "duplicate clip " + clip,
                     [&](auto& f, std::size_t i) { return duplicate_clip(f, i); });
}
Result<void> ClipRename::run(ScriptContext& c) const {
    return edit_clip(c, clip, "rename clip " + clip + " " + name,
                     [&](auto& f, std::size_t i) { return rename_clip(f, i, name); });
}
Result<void> ClipDelete::run(ScriptContext& c) const {
    return edit_clip(c, clip, "delete clip " + clip,
                     [&](auto& f, std::size_t i) { return delete_clip(f, i); });
}
Result<void> ClipLoop::run(ScriptContext& c) const {
    auto index = clip_index(c, clip);
    if (!index) return index.error();
    const auto loop = loop_mode_from_name(mode);
    if (!loop) return loop.error();
    return c.dojo.edit("loop " + clip + " " + mode + (next.empty() ? "" : " " + next),
                       [&](auto& f) { return set_loop_mode(f, *index, *loop, next); });
}

// ---- the blend table ----------------------------------------------------------------------------------

Result<void> BlendDefault::run(ScriptContext& c) const {
    return c.dojo.edit("default blend " + number_text(seconds),
                       [&](auto& f) { return set_default_blend(f, seconds); });
}
Result<void> BlendSet::run(ScriptContext& c) const {
    return c.dojo.edit("blend " + from + " " + to + " " + number_text(seconds),
                       [&](auto& f) { return set_blend(f, from, to, seconds); });
}
Result<void> BlendClear::run(ScriptContext& c) const {
    return c.dojo.edit("clear blend " + from + " " + to, [&](auto& f) { return clear_blend(f, from, to); });
}

// ---- events (numbered from 1) -------------------------------------------------------------------------

Result<void> EventAdd::run(ScriptContext& c) const {
    return edit_clip(c, clip, "add event " + clip + " " + name + (sound.empty() ? "" : " " + sound),
                     [&](auto& f, std::size_t i) { return add_event(f, i, time, name, sound); });
}
Result<void> EventMove::run(ScriptContext& c) const {
    return edit_clip(c, clip, "move event " + clip, [&](auto& f, std::size_t i) {
        return move_event(f, i, static_cast<std::size_t>(event - 1), time);
    });
}
Result<void> EventRename::run(ScriptContext& c) const {
    return edit_clip(c, clip, "rename event " + clip + " " + name, [&](auto& f, std::size_t i) {
        return rename_event(f, i, static_cast<std::size_t>(event - 1), name);
    });
}
Result<void> EventSound::run(ScriptContext& c) const {
    const std::string file_sound = sound == "none" ? std::string() : sound;
    return edit_clip(c, clip, "event sound " + clip + " " + sound, [&](auto& f, std::size_t i) {
        return set_event_sound(f, i, static_cast<std::size_t>(event - 1), file_sound);
    });
}
Result<void> EventRemove::run(ScriptContext& c) const {
    return edit_clip(c, clip, "remove event " + clip, [&](auto& f, std::size_t i) {
        return remove_event(f, i, static_cast<std::size_t>(event - 1));
    });
}

// ---- keys (numbered from 1) ---------------------------------------------------------------------------

Result<void> KeyTime::run(ScriptContext& c) const {
    return edit_clip(c, clip, "key time " + clip, [&](auto& f, std::size_t i) {
        return move_key_time(f, i, static_cast<std::size_t>(key - 1), seconds);
    });
}
Result<void> KeyValue::run(ScriptContext& c) const {
    const CurveChannel which = *curve_channel_from_name(channel);
    return edit_clip(c, clip, "key value " + clip + " " + node + " " + channel, [&](auto& f, std::size_t i) {
        return set_key_value(f, i, static_cast<std::size_t>(key - 1), node, which, value);
    });
}
Result<void> KeyAdd::run(ScriptContext& c) const {
    return edit_clip(c, clip, "add key " + clip + " " + node, [&](auto& f, std::size_t i) {
        return add_node_key(f, i, static_cast<std::size_t>(key - 1), node);
    });
}
Result<void> KeyRemove::run(ScriptContext& c) const {
    return edit_clip(c, clip, "remove key " + clip + " " + node, [&](auto& f, std::size_t i) {
        return remove_node_key(f, i, static_cast<std::size_t>(key - 1), node);
    });
}

// ---- expectations -------------------------------------------------------------------------------------

Result<void> ExpectDojoValid::run(ScriptContext& c) const {
    const auto issues = dojo_file_issues(c.dojo.file());
    return c.expect(issues.empty(),
                    "the clip file has " + std::to_string(issues.size()) + " issue(s)" + issue_list(issues));
}
Result<void> ExpectDojoIssue::run(ScriptContext& c) const {
    const auto issues = dojo_file_issues(c.dojo.file());
    bool found = false;
    for (const anim::Issue& i : issues) found = found || i.message.find(text) != std::string::npos;
    return c.expect(found, "no clip file issue mentions '" + text + "'; issues:" + issue_list(issues));
}
Result<void> ExpectDojoDirty::run(ScriptContext& c) const {
    if (dirty) return c.expect(c.dojo.dirty(), "the clip file has no unsaved edits");
    return c.expect(!c.dojo.dirty(), "the clip file has unsaved edits");
}
Result<void> ExpectClipExists::run(ScriptContext& c) const {
    const bool found = c.dojo.file().find_clip(clip) != nullptr;
    return c.expect(found == exists, "clip '" + clip + "' " + (found ? "exists" : "is missing"));
}

Result<void> ExpectClipLoop::run(ScriptContext& c) const {
    auto index = clip_index(c, clip);
    if (!index) return index.error();
    const anim::ClipDef& def = c.dojo.file().clips[*index];
    const std::string actual =
        std::string(loop_mode_name(def.loop)) + (def.next.empty() ? "" : " " + def.next);
    return c.expect(mode == loop_mode_name(def.loop) && next == def.next,
                    "clip '" + def.name + "' loops '" + actual + "', expected '" + mode +
                        (next.empty() ? "" : " " + next) + "'");
}
Result<void> ExpectClipDuration::run(ScriptContext& c) const {
    auto index = clip_index(c, clip);
    if (!index) return index.error();
    const anim::ClipDef& def = c.dojo.file().clips[*index];
    return c.expect(close(def.duration(), seconds, kFileTolerance),
                    "clip '" + def.name + "' lasts " + number_text(def.duration()) + " s, expected " +
                        number_text(seconds));
}
Result<void> ExpectBlend::run(ScriptContext& c) const {
    auto index = clip_index(c, from);
    if (!index) return index.error();
    auto to_index = clip_index(c, to);
    if (!to_index) return to_index.error();
    const double actual = blend_grid(c.dojo.file()).at(*index, *to_index).seconds;
    return c.expect(close(actual, seconds, kFileTolerance), "blend " + from + " -> " + to + " is " +
                                                                number_text(actual) + " s, expected " +
                                                                number_text(seconds));
}
Result<void> ExpectEvents::run(ScriptContext& c) const {
    auto index = clip_index(c, clip);
    if (!index) return index.error();
    const anim::ClipDef& def = c.dojo.file().clips[*index];
    return c.expect(def.events.size() == static_cast<std::size_t>(count),
                    "clip '" + def.name + "' has " + std::to_string(def.events.size()) +
                        " events, expected " + std::to_string(count));
}
Result<void> ExpectEvent::run(ScriptContext& c) const {
    auto index = clip_index(c, clip);
    if (!index) return index.error();
    const anim::ClipDef& def = c.dojo.file().clips[*index];
    const std::size_t e = static_cast<std::size_t>(event - 1);
    if (e >= def.events.size())
        return c.expect(false, "clip '" + def.name + "' has no event " + std::to_string(event) + " (it has " +
                                   std::to_string(def.events.size()) + ")");
    const anim::ClipEvent& ev = def.events[e];
    bool match = close(ev.time, time, kFileTolerance);
    if (name) match = match && ev.name == *name;
    if (sound) match = match && ev.sound == (*sound == "none" ? std::string() : *sound);
    return c.expect(match, "event " + std::to_string(event) + " of clip '" + def.name + "' is " +
                               number_text(ev.time) + " s '" + ev.name + "'" +
                               (ev.sound.empty() ? "" : " sound '" + ev.sound + "'"));
}

Result<void> ExpectCurve::run(ScriptContext& c) const {
    auto index = clip_index(c, clip);
    if (!index) return index.error();
    const anim::ClipDef& def = c.dojo.file().clips[*index];
    auto sampled = curve_value(c.dojo.file(), *index, node, *curve_channel_from_name(channel), time);
    if (!sampled) return sampled.error();
    return c.expect(close(*sampled, value, kCurveTolerance),
                    "clip '" + def.name + "' " + node + " " + channel + " at " + number_text(time) +
                        " s is " + number_text(*sampled) + ", expected " + number_text(value));
}

namespace {
// Clip `clip`'s definition and key `key` (from 1), or the failed expectation when it has no such key.
Result<const anim::ClipDef*> clip_with_key(ScriptContext& c, const std::string& clip, int key,
                                           std::size_t& index) {
    auto found = clip_index(c, clip);
    if (!found) return found.error();
    index = *found;
    const anim::ClipDef& def = c.dojo.file().clips[index];
    if (static_cast<std::size_t>(key - 1) >= def.phases.size()) {
        auto failed = c.expect(false, "clip '" + def.name + "' has no key " + std::to_string(key) +
                                          " (it has " + std::to_string(def.phases.size()) + ")");
        return failed.error();
    }
    return &def;
}
} // namespace

Result<void> ExpectKeyTime::run(ScriptContext& c) const {
    std::size_t index = 0;
    auto def = clip_with_key(c, clip, key, index);
    if (!def) return def.error();
    double end = 0;
    for (std::size_t p = 0; p < static_cast<std::size_t>(key); ++p) end += (*def)->phases[p].duration;
    return c.expect(close(end, seconds, kFileTolerance), "key " + std::to_string(key) + " of clip '" +
                                                             (*def)->name + "' is at " + number_text(end) +
                                                             " s, expected " + number_text(seconds));
}
Result<void> ExpectKeyValue::run(ScriptContext& c) const {
    std::size_t index = 0;
    auto def = clip_with_key(c, clip, key, index);
    if (!def) return def.error();
    auto curve = clip_curve(c.dojo.file(), index, node, *curve_channel_from_name(channel), 2);
    if (!curve) return curve.error();
    const CurveKey& k = curve->keys[static_cast<std::size_t>(key - 1)];
    if (!k.keyed)
        return c.expect(false, node + " has no " + channel + " key in key " + std::to_string(key) +
                                   " of clip '" + (*def)->name + "'");
    return c.expect(close(k.target_value, value, kFileTolerance),
                    node + " " + channel + " in key " + std::to_string(key) + " of clip '" + (*def)->name +
                        "' is " + number_text(k.target_value) + ", expected " + number_text(value));
}

} // namespace steps
} // namespace ks::editor
