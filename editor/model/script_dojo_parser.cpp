// The script language's dojo commands (script_dojo.h): each command's parser and the table that registers
// it (script_command.h); their steps run in script_dojo_runner.cpp.
#include "model/dojo_curves.h"
#include "model/script_command.h"

namespace ks::editor {
namespace {
using namespace script_tokens;

constexpr const char* kDojoUsage = "dojo open [FILE] | dojo save [FILE] | dojo export FILE.glb [CLIP] | dojo "
                                   "import FILE.glb | dojo undo|redo [N|all]";
constexpr const char* kClipUsage =
    "clip new NAME [from CLIP [SECONDS]] | clip duplicate|delete NAME | clip rename "
    "OLD NEW | clip loop NAME once|loop|ping_pong|next [NEXT]";
constexpr const char* kBlendUsage = "blend default S | blend FROM TO S | blend clear FROM TO";
constexpr const char* kEventUsage =
    "event add CLIP TIME NAME [SOUND] | event move CLIP N TIME | event rename "
    "CLIP N NAME | event sound CLIP N SOUND|none | event remove CLIP N";
constexpr const char* kKeyUsage =
    "key time CLIP N S | key value CLIP N NODE rot.x..pos.z V | key add|remove CLIP "
    "N NODE";
constexpr const char* kExpectClipUsage =
    "expect clip NAME exists|missing | expect clip NAME loop MODE [NEXT] | expect clip NAME duration S";
constexpr const char* kExpectBlendUsage = "expect blend FROM TO S";
constexpr const char* kExpectEventsUsage = "expect events CLIP N";
constexpr const char* kExpectEventUsage = "expect event CLIP N TIME [NAME [SOUND]]";
constexpr const char* kExpectKeyUsage = "expect key CLIP N time S | expect key CLIP N NODE CHANNEL V";
constexpr const char* kExpectCurveUsage = "expect curve CLIP NODE CHANNEL TIME V";
constexpr const char* kExpectDojoUsage = "expect dojo valid|dirty|clean | expect dojo issue TEXT";

template <class T>
Result<ScriptStep> dojo_step(T step) {
    return step_of<DojoStep>(std::move(step));
}

// The dojo lines' word readers: seconds and values, key and event numbers, channels.
class DojoWords : public LineWords {
  public:
    explicit DojoWords(const LineWords& words) : LineWords(words) {}

    Result<void> number(size_t token, double& out, const char* what, const std::string& usage) const {
        if (!to_double(tokens_[token].text, out))
            return fail(token, "expected " + std::string(what) + ", got '" + word(token) + "'", usage);
        return ok();
    }
    // A key or event number, counted from 1.
    Result<void> ordinal(size_t token, int& out, const char* what, const std::string& usage) const {
        if (!to_int(tokens_[token].text, out) || out < 1)
            return fail(token, "expected " + std::string(what) + " number (1 is the first)", usage);
        return ok();
    }
    Result<void> channel(size_t token, std::string& out) const {
        if (!curve_channel_from_name(tokens_[token].text))
            return fail(token, "unknown channel '" + word(token) + "'",
                        "rot.x, rot.y, rot.z, pos.x, pos.y or pos.z");
        out = word(token);
        return ok();
    }
    // CLIP MODE [NEXT] from word `first`: NEXT only (and always) with mode next.
    Result<void> loop(size_t first, std::string& mode, std::string& next, const std::string& usage) const {
        if (auto r = need(first + 2, first + 3, usage); !r) return r;
        mode = word(first + 1);
        if (mode != "once" && mode != "loop" && mode != "ping_pong" && mode != "next")
            return fail(first + 1, "unknown loop mode '" + mode + "'", "once, loop, ping_pong or next");
        if ((mode == "next") != (tokens_.size() == first + 3))
            return fail(first + 2,
                        mode == "next" ? "loop mode next needs the clip to play next"
                                       : "only loop mode next names another clip",
                        usage);
        if (tokens_.size() == first + 3) next = word(first + 2);
        return ok();
    }
};

// ---- dojo open|save|undo|redo -------------------------------------------------------------------------

Result<ScriptStep> parse_dojo(const LineWords& words) {
    const DojoWords w(words);
    if (w.size() < 2) return w.fail(1, "missing words", kDojoUsage);
    const std::string_view action = w.text(1);
    if (action == "open") return dojo_step(steps::DojoOpen{w.size() > 2 ? w.rest(2) : std::string()});
    if (action == "save") return dojo_step(steps::DojoSave{w.size() > 2 ? w.rest(2) : std::string()});
    if (action == "export") {
        if (auto r = w.need(3, 4, kDojoUsage); !r) return r.error();
        return dojo_step(steps::DojoExport{w.word(2), w.size() == 4 ? w.word(3) : std::string()});
    }
    if (action == "import") {
        if (auto r = w.need(3, 3, kDojoUsage); !r) return r.error();
        return dojo_step(steps::DojoImport{w.word(2)});
    }
    if (action == "undo" || action == "redo") {
        if (auto r = w.need(2, 3, kDojoUsage); !r) return r.error();
        int count = 1;
        if (w.size() == 3 && w.text(2) == "all")
            count = -1;
        else if (w.size() == 3 && (!to_int(w.text(2), count) || count < 1))
            return w.fail(2, "expected a count of steps", "dojo " + std::string(action) + " 3, or all");
        if (action == "undo") return dojo_step(steps::DojoUndo{count});
        return dojo_step(steps::DojoRedo{count});
    }
    return w.fail(1, "unknown dojo action '" + std::string(action) + "'", kDojoUsage);
}

// ---- clips --------------------------------------------------------------------------------------------

Result<ScriptStep> parse_clip_new(const DojoWords& w) {
    steps::ClipNew step;
    if (w.size() != 3 && w.size() != 5 && w.size() != 6)
        return w.fail(w.size() < 3 ? w.size() : 3, "wrong number of words",
                      "clip new NAME, or clip new NAME from CLIP [SECONDS] (its pose then, default its end)");
    step.name = w.word(2);
    if (w.size() > 3) {
        if (w.text(3) != "from") return w.fail(3, "expected 'from'", "clip new NAME from CLIP [SECONDS]");
        step.from = w.word(4);
        if (w.size() == 6) {
            double seconds = 0;
            if (auto r = w.number(5, seconds, "seconds", kClipUsage); !r) return r.error();
            step.seconds = seconds;
        }
    }
    return dojo_step(std::move(step));
}

Result<ScriptStep> parse_clip(const LineWords& words) {
    const DojoWords w(words);
    if (w.size() < 2) return w.fail(1, "missing words", kClipUsage);
    const std::string_view action = w.text(1);
    if (action == "new") return parse_clip_new(w);
    if (action == "duplicate" || action == "delete") {
        if (auto r = w.need(3, 3, kClipUsage); !r) return r.error();
        if (action == "duplicate") return dojo_step(steps::ClipDuplicate{w.word(2)});
        return dojo_step(steps::ClipDelete{w.word(2)});
    }
    if (action == "rename") {
        if (auto r = w.need(4, 4, kClipUsage); !r) return r.error();
        return dojo_step(steps::ClipRename{w.word(2), w.word(3)});
    }
    if (action == "loop") {
        steps::ClipLoop step;
        if (auto r = w.loop(2, step.mode, step.next, kClipUsage); !r) return r.error();
        step.clip = w.word(2);
        return dojo_step(std::move(step));
    }
    return w.fail(1, "unknown clip action '" + std::string(action) + "'", kClipUsage);
}

// ---- the blend table ----------------------------------------------------------------------------------

Result<ScriptStep> parse_blend(const LineWords& words) {
    const DojoWords w(words);
    if (w.size() < 2) return w.fail(1, "missing words", kBlendUsage);
    const std::string_view action = w.text(1);
    if (action == "default") {
        steps::BlendDefault step;
        if (auto r = w.need(3, 3, kBlendUsage); !r) return r.error();
        if (auto r = w.number(2, step.seconds, "seconds", kBlendUsage); !r) return r.error();
        return dojo_step(step);
    }
    if (action == "clear") {
        if (auto r = w.need(4, 4, kBlendUsage); !r) return r.error();
        return dojo_step(steps::BlendClear{w.word(2), w.word(3)});
    }
    steps::BlendSet step{w.word(1), {}, 0};
    if (auto r = w.need(4, 4, kBlendUsage); !r) return r.error();
    if (auto r = w.number(3, step.seconds, "seconds", kBlendUsage); !r) return r.error();
    step.to = w.word(2);
    return dojo_step(std::move(step));
}

// ---- events -------------------------------------------------------------------------------------------

Result<ScriptStep> parse_event(const LineWords& words) {
    const DojoWords w(words);
    if (w.size() < 2) return w.fail(1, "missing words", kEventUsage);
    const std::string_view action = w.text(1);
    if (action == "add") {
        steps::EventAdd step;
        if (auto r = w.need(5, 6, kEventUsage); !r) return r.error();
        if (auto r = w.number(3, step.time, "seconds", kEventUsage); !r) return r.error();
        step.clip = w.word(2);
        step.name = w.word(4);
        if (w.size() > 5) step.sound = w.word(5);
        return dojo_step(std::move(step));
    }
    if (action != "move" && action != "rename" && action != "sound" && action != "remove")
        return w.fail(1, "unknown event action '" + std::string(action) + "'", kEventUsage);
    const size_t count = action == "remove" ? 4 : 5;
    if (auto r = w.need(count, count, kEventUsage); !r) return r.error();
    const std::string clip = w.word(2);
    int event = 1;
    if (auto r = w.ordinal(3, event, "an event", kEventUsage); !r) return r.error();
    if (action == "move") {
        steps::EventMove step{clip, event, 0};
        if (auto r = w.number(4, step.time, "seconds", kEventUsage); !r) return r.error();
        return dojo_step(std::move(step));
    }
    if (action == "rename") return dojo_step(steps::EventRename{clip, event, w.word(4)});
    if (action == "sound") return dojo_step(steps::EventSound{clip, event, w.word(4)});
    return dojo_step(steps::EventRemove{clip, event});
}

// ---- keys ---------------------------------------------------------------------------------------------

Result<ScriptStep> parse_key(const LineWords& words) {
    const DojoWords w(words);
    if (w.size() < 2) return w.fail(1, "missing words", kKeyUsage);
    const std::string_view action = w.text(1);
    if (action != "time" && action != "value" && action != "add" && action != "remove")
        return w.fail(1, "unknown key action '" + std::string(action) + "'", kKeyUsage);
    const size_t count = action == "value" ? 7 : 5;
    if (auto r = w.need(count, count, kKeyUsage); !r) return r.error();
    const std::string clip = w.word(2);
    int key = 1;
    if (auto r = w.ordinal(3, key, "a key", kKeyUsage); !r) return r.error();
    if (action == "time") {
        steps::KeyTime step{clip, key, 0};
        if (auto r = w.number(4, step.seconds, "seconds", kKeyUsage); !r) return r.error();
        return dojo_step(std::move(step));
    }
    if (action == "add") return dojo_step(steps::KeyAdd{clip, key, w.word(4)});
    if (action == "remove") return dojo_step(steps::KeyRemove{clip, key, w.word(4)});
    steps::KeyValue step{clip, key, w.word(4), {}, 0};
    if (auto r = w.channel(5, step.channel); !r) return r.error();
    if (auto r = w.number(6, step.value, "a value", kKeyUsage); !r) return r.error();
    return dojo_step(std::move(step));
}

// ---- expectations -------------------------------------------------------------------------------------

Result<ScriptStep> parse_expect_dojo(const LineWords& words) {
    const DojoWords w(words);
    if (w.size() < 3) return w.fail(2, "missing words", kExpectDojoUsage);
    const std::string_view what = w.text(2);
    if (what == "issue") {
        if (w.size() < 4)
            return w.fail(3, "expected words of the issue's message", "expect dojo issue missing");
        return dojo_step(steps::ExpectDojoIssue{w.rest(3)});
    }
    if (auto r = w.need(3, 3, kExpectDojoUsage); !r) return r.error();
    if (what == "valid") return dojo_step(steps::ExpectDojoValid{});
    if (what == "dirty" || what == "clean") return dojo_step(steps::ExpectDojoDirty{what == "dirty"});
    return w.fail(2, "unknown dojo expectation '" + std::string(what) + "'",
                  "valid, dirty, clean or issue TEXT");
}

Result<ScriptStep> parse_expect_clip(const LineWords& words) {
    const DojoWords w(words);
    if (w.size() < 4) return w.fail(w.size(), "missing words", kExpectClipUsage);
    const std::string clip = w.word(2);
    const std::string_view what = w.text(3);
    if (what == "exists" || what == "missing") {
        if (auto r = w.need(4, 4, kExpectClipUsage); !r) return r.error();
        return dojo_step(steps::ExpectClipExists{clip, what == "exists"});
    }
    if (what == "duration") {
        steps::ExpectClipDuration step{clip, 0};
        if (auto r = w.need(5, 5, kExpectClipUsage); !r) return r.error();
        if (auto r = w.number(4, step.seconds, "seconds", kExpectClipUsage); !r) return r.error();
        return dojo_step(std::move(step));
    }
    if (what == "loop") {
        // NAME loop MODE [NEXT]: checked like `clip loop NAME MODE [NEXT]`.
        steps::ExpectClipLoop step{clip, {}, {}};
        if (auto r = w.loop(3, step.mode, step.next, kExpectClipUsage); !r) return r.error();
        return dojo_step(std::move(step));
    }
    return w.fail(3, "unknown clip expectation '" + std::string(what) + "'",
                  "exists, missing, loop MODE [NEXT] or duration S");
}

Result<ScriptStep> parse_expect_blend(const LineWords& words) {
    const DojoWords w(words);
    steps::ExpectBlend step;
    if (auto r = w.need(5, 5, kExpectBlendUsage); !r) return r.error();
    if (auto r = w.number(4, step.seconds, "seconds", kExpectBlendUsage); !r) return r.error();
    step.from = w.word(2);
    step.to = w.word(3);
    return dojo_step(std::move(step));
}

Result<ScriptStep> parse_expect_events(const LineWords& words) {
    const DojoWords w(words);
    steps::ExpectEvents step;
    if (auto r = w.need(4, 4, kExpectEventsUsage); !r) return r.error();
    step.clip = w.word(2);
    if (!to_int(w.text(3), step.count) || step.count < 0)
        return w.fail(3, "expected a count of events", kExpectEventsUsage);
    return dojo_step(std::move(step));
}

Result<ScriptStep> parse_expect_event(const LineWords& words) {
    const DojoWords w(words);
    steps::ExpectEvent step;
    if (auto r = w.need(5, 7, kExpectEventUsage); !r) return r.error();
    step.clip = w.word(2);
    if (auto r = w.ordinal(3, step.event, "an event", kExpectEventUsage); !r) return r.error();
    if (auto r = w.number(4, step.time, "seconds", kExpectEventUsage); !r) return r.error();
    if (w.size() > 5) step.name = w.word(5);
    if (w.size() > 6) step.sound = w.word(6);
    return dojo_step(std::move(step));
}

Result<ScriptStep> parse_expect_key(const LineWords& words) {
    const DojoWords w(words);
    if (auto r = w.need(6, 7, kExpectKeyUsage); !r) return r.error();
    const std::string clip = w.word(2);
    int key = 1;
    if (auto r = w.ordinal(3, key, "a key", kExpectKeyUsage); !r) return r.error();
    if (w.text(4) == "time") {
        steps::ExpectKeyTime step{clip, key, 0};
        if (auto r = w.need(6, 6, kExpectKeyUsage); !r) return r.error();
        if (auto r = w.number(5, step.seconds, "seconds", kExpectKeyUsage); !r) return r.error();
        return dojo_step(std::move(step));
    }
    steps::ExpectKeyValue step{clip, key, w.word(4), {}, 0};
    if (auto r = w.need(7, 7, kExpectKeyUsage); !r) return r.error();
    if (auto r = w.channel(5, step.channel); !r) return r.error();
    if (auto r = w.number(6, step.value, "a value", kExpectKeyUsage); !r) return r.error();
    return dojo_step(std::move(step));
}

Result<ScriptStep> parse_expect_curve(const LineWords& words) {
    const DojoWords w(words);
    steps::ExpectCurve step;
    if (auto r = w.need(7, 7, kExpectCurveUsage); !r) return r.error();
    step.clip = w.word(2);
    step.node = w.word(3);
    if (auto r = w.channel(4, step.channel); !r) return r.error();
    if (auto r = w.number(5, step.time, "seconds", kExpectCurveUsage); !r) return r.error();
    if (auto r = w.number(6, step.value, "a value", kExpectCurveUsage); !r) return r.error();
    return dojo_step(std::move(step));
}

constexpr CommandSpec kCommands[] = {
    {"dojo", false, kDojoUsage, "open or save a clip file; its own undo history", parse_dojo},
    {"clip", false, kClipUsage, "add, copy, rename, delete a clip; its loop mode", parse_clip},
    {"blend", false, kBlendUsage, "the default blend; set or clear a cell of the blend table", parse_blend},
    {"event", false, kEventUsage, "add, move, rename, re-sound or remove a clip event", parse_event},
    {"key", false, kKeyUsage, "move a key in time; set, add or remove a node's key", parse_key},
    {"clip", true, kExpectClipUsage, "a clip exists or not; its loop mode; its duration", parse_expect_clip},
    {"blend", true, kExpectBlendUsage, "the effective blend time", parse_expect_blend},
    {"events", true, kExpectEventsUsage, "a clip's number of events", parse_expect_events},
    {"event", true, kExpectEventUsage, "an event's time (name, sound: none for no sound)",
     parse_expect_event},
    {"key", true, kExpectKeyUsage, "a key's time; the stored target value", parse_expect_key},
    {"curve", true, kExpectCurveUsage, "the sampled value at TIME, within 0.001", parse_expect_curve},
    {"dojo", true, kExpectDojoUsage, "the file's checks; unsaved edits; an issue containing TEXT",
     parse_expect_dojo},
};

} // namespace

std::span<const CommandSpec> dojo_commands() {
    return kCommands;
}

} // namespace ks::editor
