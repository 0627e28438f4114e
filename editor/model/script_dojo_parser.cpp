// The script language's dojo lines (script_dojo.h): each to a DojoStep, or an error at the offending word.
#include "model/dojo_curves.h"
#include "model/script_dojo.h"

#include <algorithm>

namespace ks::editor {
namespace {
using namespace script_tokens;

constexpr const char* kDojoUsage =
    "dojo open [FILE] | dojo save [FILE] | dojo undo|redo [N|all] | clip new NAME [from CLIP [SECONDS]] | "
    "clip duplicate|delete NAME | clip rename OLD NEW | clip loop NAME once|loop|ping_pong|next [NEXT] | "
    "blend default S | blend FROM TO S | blend clear FROM TO | event add CLIP TIME NAME [SOUND] | "
    "event move CLIP N TIME | event rename CLIP N NAME | event sound CLIP N SOUND|none | "
    "event remove CLIP N | key time CLIP N S | key value CLIP N NODE rot.x..pos.z V | "
    "key add|remove CLIP N NODE";
constexpr const char* kExpectUsage =
    "expect clip NAME exists|missing | expect clip NAME loop MODE [NEXT] | expect clip NAME duration S | "
    "expect blend FROM TO S | expect events CLIP N | expect event CLIP N TIME [NAME [SOUND]] | "
    "expect key CLIP N time S | expect key CLIP N NODE CHANNEL V | expect curve CLIP NODE CHANNEL TIME V | "
    "expect dojo valid|dirty|clean | expect dojo issue TEXT";

class DojoLineParser : LineWords {
  public:
    DojoLineParser(std::string_view line, const std::vector<Token>& tokens, int line_no,
                   const std::string& file)
        : LineWords(line, tokens, line_no, file) {
        step_.op = ScriptOp::Dojo;
        step_.line = line_no;
    }

    Result<ScriptStep> parse() {
        const std::string_view word = tokens_[0].text;
        if (word == "expect") return expect();
        if (tokens_.size() < 2) return fail(1, "missing words", usage_of(word));
        const std::string_view action = tokens_[1].text;
        if (word == "dojo") return dojo(action);
        if (word == "clip") return clip(action);
        if (word == "blend") return blend(action);
        if (word == "event") return event(action);
        return key(action);
    }

  private:
    // ---- helpers --------------------------------------------------------------------------------------

    static std::string usage_of(std::string_view command) {
        // The part of the usage about this command, e.g. every "clip ..." form.
        std::string out;
        const std::string all = kDojoUsage, prefix = std::string(command) + " ";
        for (size_t at = 0; at < all.size();) {
            const size_t end = std::min(all.find(" | ", at), all.size());
            const std::string form = all.substr(at, end - at);
            if (form.rfind(prefix, 0) == 0) out += (out.empty() ? "" : " | ") + form;
            at = end + 3;
        }
        return out;
    }
    Result<ScriptStep> words(size_t min, size_t max, const std::string& usage) const {
        if (tokens_.size() < min) return fail(tokens_.size(), "missing words", usage);
        if (tokens_.size() > max)
            return fail(max, "unexpected '" + std::string(tokens_[max].text) + "'", usage);
        return step_;
    }
    // Copies words [first, last) into the step's names.
    void keep(size_t first, size_t last) {
        for (size_t i = first; i < last && i < tokens_.size(); ++i)
            step_.dojo.words.emplace_back(tokens_[i].text);
    }
    Result<void> number(size_t token, double& out, const char* what, const std::string& usage) const {
        if (!to_double(tokens_[token].text, out))
            return fail(token,
                        "expected " + std::string(what) + ", got '" + std::string(tokens_[token].text) + "'",
                        usage);
        return ok();
    }
    Result<void> ordinal(size_t token, const char* what, const std::string& usage) {
        if (!to_int(tokens_[token].text, step_.dojo.index) || step_.dojo.index < 1)
            return fail(token, "expected " + std::string(what) + " number (1 is the first)", usage);
        return ok();
    }
    Result<void> channel(size_t token) const {
        if (!curve_channel_from_name(tokens_[token].text))
            return fail(token, "unknown channel '" + std::string(tokens_[token].text) + "'",
                        "rot.x, rot.y, rot.z, pos.x, pos.y or pos.z");
        return ok();
    }
    Result<ScriptStep> as(DojoOp op) {
        step_.dojo.op = op;
        return step_;
    }

    // ---- dojo FILE, save, undo, redo ----------------------------------------------------------------

    Result<ScriptStep> dojo(std::string_view action) {
        const std::string usage = usage_of("dojo");
        if (action == "open" || action == "save") {
            step_.dojo.op = action == "open" ? DojoOp::Open : DojoOp::Save;
            if (tokens_.size() > 2) step_.dojo.words.emplace_back(line_.substr(tokens_[2].column - 1));
            return step_;
        }
        if (action == "undo" || action == "redo") {
            if (auto r = words(2, 3, usage); !r) return r;
            step_.dojo.index = 1;
            if (tokens_.size() == 3 && tokens_[2].text == "all")
                step_.dojo.index = -1;
            else if (tokens_.size() == 3 &&
                     (!to_int(tokens_[2].text, step_.dojo.index) || step_.dojo.index < 1))
                return fail(2, "expected a count of steps", "dojo " + std::string(action) + " 3, or all");
            return as(action == "undo" ? DojoOp::Undo : DojoOp::Redo);
        }
        return fail(1, "unknown dojo action '" + std::string(action) + "'", usage);
    }

    // ---- clips ----------------------------------------------------------------------------------------

    Result<ScriptStep> clip(std::string_view action) {
        const std::string usage = usage_of("clip");
        if (action == "new") {
            if (tokens_.size() != 3 && tokens_.size() != 5 && tokens_.size() != 6)
                return fail(
                    tokens_.size() < 3 ? tokens_.size() : 3, "wrong number of words",
                    "clip new NAME, or clip new NAME from CLIP [SECONDS] (its pose then, default its end)");
            keep(2, 3);
            if (tokens_.size() > 3) {
                if (tokens_[3].text != "from")
                    return fail(3, "expected 'from'", "clip new NAME from CLIP [SECONDS]");
                keep(4, 5);
                if (tokens_.size() == 6) {
                    if (auto r = number(5, step_.dojo.number, "seconds", usage); !r) return r.error();
                    step_.dojo.has_number = true;
                }
            }
            return as(DojoOp::ClipNew);
        }
        if (action == "duplicate" || action == "delete") {
            if (auto r = words(3, 3, usage); !r) return r;
            keep(2, 3);
            return as(action == "duplicate" ? DojoOp::ClipDuplicate : DojoOp::ClipDelete);
        }
        if (action == "rename") {
            if (auto r = words(4, 4, usage); !r) return r;
            keep(2, 4);
            return as(DojoOp::ClipRename);
        }
        if (action == "loop") return loop(DojoOp::ClipLoop, 2, usage);
        return fail(1, "unknown clip action '" + std::string(action) + "'", usage);
    }
    // NAME MODE [NEXT] from word `first`: NEXT only (and always) with mode next.
    Result<ScriptStep> loop(DojoOp op, size_t first, const std::string& usage) {
        if (auto r = words(first + 2, first + 3, usage); !r) return r;
        const std::string_view mode = tokens_[first + 1].text;
        if (mode != "once" && mode != "loop" && mode != "ping_pong" && mode != "next")
            return fail(first + 1, "unknown loop mode '" + std::string(mode) + "'",
                        "once, loop, ping_pong or next");
        if ((mode == "next") != (tokens_.size() == first + 3))
            return fail(first + 2,
                        mode == "next" ? "loop mode next needs the clip to play next"
                                       : "only loop mode next names another clip",
                        usage);
        keep(first, first + 3);
        return as(op);
    }

    // ---- blend table ----------------------------------------------------------------------------------

    Result<ScriptStep> blend(std::string_view action) {
        const std::string usage = usage_of("blend");
        if (action == "default") {
            if (auto r = words(3, 3, usage); !r) return r;
            if (auto r = number(2, step_.dojo.number, "seconds", usage); !r) return r.error();
            return as(DojoOp::BlendDefault);
        }
        if (action == "clear") {
            if (auto r = words(4, 4, usage); !r) return r;
            keep(2, 4);
            return as(DojoOp::BlendClear);
        }
        if (auto r = words(4, 4, usage); !r) return r;
        if (auto r = number(3, step_.dojo.number, "seconds", usage); !r) return r.error();
        keep(1, 3);
        return as(DojoOp::BlendSet);
    }

    // ---- events ---------------------------------------------------------------------------------------

    Result<ScriptStep> event(std::string_view action) {
        const std::string usage = usage_of("event");
        if (action == "add") {
            if (auto r = words(5, 6, usage); !r) return r;
            if (auto r = number(3, step_.dojo.number, "seconds", usage); !r) return r.error();
            keep(2, 3);
            keep(4, 6);
            return as(DojoOp::EventAdd);
        }
        struct Form {
            std::string_view action;
            DojoOp op;
            size_t count; // words on the line
        };
        static constexpr Form kForms[] = {{"move", DojoOp::EventMove, 5},
                                          {"rename", DojoOp::EventRename, 5},
                                          {"sound", DojoOp::EventSound, 5},
                                          {"remove", DojoOp::EventRemove, 4}};
        for (const Form& form : kForms) {
            if (action != form.action) continue;
            if (auto r = words(form.count, form.count, usage); !r) return r;
            keep(2, 3);
            if (auto r = ordinal(3, "an event", usage); !r) return r.error();
            if (form.op == DojoOp::EventMove) {
                if (auto r = number(4, step_.dojo.number, "seconds", usage); !r) return r.error();
            } else {
                keep(4, 5);
            }
            return as(form.op);
        }
        return fail(1, "unknown event action '" + std::string(action) + "'", usage);
    }

    // ---- keys -----------------------------------------------------------------------------------------

    Result<ScriptStep> key(std::string_view action) {
        const std::string usage = usage_of("key");
        if (action != "time" && action != "value" && action != "add" && action != "remove")
            return fail(1, "unknown key action '" + std::string(action) + "'", usage);
        const size_t count = action == "time" ? 5 : action == "value" ? 7 : 5;
        if (auto r = words(count, count, usage); !r) return r;
        keep(2, 3);
        if (auto r = ordinal(3, "a key", usage); !r) return r.error();
        if (action == "time") {
            if (auto r = number(4, step_.dojo.number, "seconds", usage); !r) return r.error();
            return as(DojoOp::KeyTime);
        }
        keep(4, 5);
        if (action != "value") return as(action == "add" ? DojoOp::KeyAdd : DojoOp::KeyRemove);
        if (auto r = channel(5); !r) return r.error();
        keep(5, 6);
        if (auto r = number(6, step_.dojo.number, "a value", usage); !r) return r.error();
        return as(DojoOp::KeyValue);
    }

    // ---- expectations ---------------------------------------------------------------------------------

    Result<ScriptStep> expect() {
        const std::string_view what = tokens_[1].text;
        if (what == "dojo") return expect_dojo();
        if (what == "clip") return expect_clip();
        if (what == "blend") {
            if (auto r = words(5, 5, kExpectUsage); !r) return r;
            if (auto r = number(4, step_.dojo.number, "seconds", kExpectUsage); !r) return r.error();
            keep(2, 4);
            return as(DojoOp::ExpectBlend);
        }
        if (what == "events") {
            if (auto r = words(4, 4, kExpectUsage); !r) return r;
            keep(2, 3);
            if (!to_int(tokens_[3].text, step_.dojo.index) || step_.dojo.index < 0)
                return fail(3, "expected a count of events", kExpectUsage);
            return as(DojoOp::ExpectEvents);
        }
        if (what == "event") {
            if (auto r = words(5, 7, kExpectUsage); !r) return r;
            keep(2, 3);
            if (auto r = ordinal(3, "an event", kExpectUsage); !r) return r.error();
            if (auto r = number(4, step_.dojo.number, "seconds", kExpectUsage); !r) return r.error();
            keep(5, 7);
            return as(DojoOp::ExpectEvent);
        }
        if (what == "key") return expect_key();
        // curve CLIP NODE CHANNEL TIME V
        if (auto r = words(7, 7, kExpectUsage); !r) return r;
        keep(2, 4);
        if (auto r = channel(4); !r) return r.error();
        keep(4, 5);
        if (auto r = number(5, step_.dojo.number, "seconds", kExpectUsage); !r) return r.error();
        if (auto r = number(6, step_.dojo.number2, "a value", kExpectUsage); !r) return r.error();
        return as(DojoOp::ExpectCurve);
    }
    Result<ScriptStep> expect_dojo() {
        if (tokens_.size() < 3) return fail(2, "missing words", kExpectUsage);
        const std::string_view what = tokens_[2].text;
        if (what == "issue") {
            if (tokens_.size() < 4)
                return fail(3, "expected words of the issue's message", "expect dojo issue missing");
            step_.dojo.words.emplace_back(line_.substr(tokens_[3].column - 1));
            return as(DojoOp::ExpectIssue);
        }
        if (auto r = words(3, 3, kExpectUsage); !r) return r;
        if (what == "valid") return as(DojoOp::ExpectValid);
        if (what == "dirty") return as(DojoOp::ExpectDirty);
        if (what == "clean") return as(DojoOp::ExpectClean);
        return fail(2, "unknown dojo expectation '" + std::string(what) + "'",
                    "valid, dirty, clean or issue TEXT");
    }
    Result<ScriptStep> expect_clip() {
        if (tokens_.size() < 4) return fail(tokens_.size(), "missing words", kExpectUsage);
        const std::string_view what = tokens_[3].text;
        if (what == "exists" || what == "missing") {
            if (auto r = words(4, 4, kExpectUsage); !r) return r;
            keep(2, 3);
            return as(what == "exists" ? DojoOp::ExpectClipExists : DojoOp::ExpectClipMissing);
        }
        if (what == "duration") {
            if (auto r = words(5, 5, kExpectUsage); !r) return r;
            keep(2, 3);
            if (auto r = number(4, step_.dojo.number, "seconds", kExpectUsage); !r) return r.error();
            return as(DojoOp::ExpectClipDuration);
        }
        if (what == "loop") {
            // NAME loop MODE [NEXT]: checked like `clip loop NAME MODE [NEXT]`, so the name moves first.
            if (auto r = loop(DojoOp::ExpectClipLoop, 3, kExpectUsage); !r) return r;
            step_.dojo.words[0] = std::string(tokens_[2].text);
            return step_;
        }
        return fail(3, "unknown clip expectation '" + std::string(what) + "'",
                    "exists, missing, loop MODE [NEXT] or duration S");
    }
    Result<ScriptStep> expect_key() {
        if (auto r = words(6, 7, kExpectUsage); !r) return r;
        keep(2, 3);
        if (auto r = ordinal(3, "a key", kExpectUsage); !r) return r.error();
        if (tokens_[4].text == "time") {
            if (auto r = words(6, 6, kExpectUsage); !r) return r;
            if (auto r = number(5, step_.dojo.number, "seconds", kExpectUsage); !r) return r.error();
            return as(DojoOp::ExpectKeyTime);
        }
        if (auto r = words(7, 7, kExpectUsage); !r) return r;
        keep(4, 5);
        if (auto r = channel(5); !r) return r.error();
        keep(5, 6);
        if (auto r = number(6, step_.dojo.number, "a value", kExpectUsage); !r) return r.error();
        return as(DojoOp::ExpectKeyValue);
    }

    ScriptStep step_;
};

} // namespace

bool is_dojo_command(std::string_view word) {
    return word == "dojo" || word == "clip" || word == "blend" || word == "event" || word == "key";
}

bool is_dojo_expectation(std::string_view word) {
    return word == "clip" || word == "blend" || word == "events" || word == "event" || word == "key" ||
           word == "curve" || word == "dojo";
}

const char* dojo_commands_usage() {
    return kDojoUsage;
}

Result<ScriptStep> parse_dojo_line(std::string_view line, const std::vector<Token>& tokens, int line_no,
                                   const std::string& file) {
    return DojoLineParser(line, tokens, line_no, file).parse();
}

} // namespace ks::editor
