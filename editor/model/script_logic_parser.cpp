// The script language's level-logic lines (script_logic.h): each to a LogicStep, or an error at the
// offending word. Event and action names are checked here against the whole vocabulary (with a did-you-mean);
// whether the source emits the event is the Editor's check when the line runs.
#include "model/script_logic.h"

#include "jsonio/suggest.h"
#include "level/logic_names.h"

#include <algorithm>

namespace ks::editor {
namespace {
using namespace script_tokens;

constexpr const char* kNameUsage = "name ID TEXT...";
constexpr const char* kLinkUsage =
    "link SOURCE add EVENT TARGET ACTION [delay S] [once] | link SOURCE set INDEX "
    "event|target|action|delay|once "
    "VALUE | link SOURCE remove INDEX   (SOURCE: an entity id, level or objective:ID; INDEX from 1)";
constexpr const char* kObjectiveUsage = "objective add ID TEXT... | objective ID text TEXT... | objective ID "
                                        "kill NAME... | objective ID remove | "
                                        "objective ID move INDEX   (INDEX from 1)";
constexpr const char* kExpectUsage =
    "expect links SOURCE N | expect link SOURCE INDEX EVENT TARGET ACTION [delay S] [once] | "
    "expect objectives N";
constexpr std::string_view kObjectivePrefix = "objective:";

class LogicLineParser : LineWords {
  public:
    LogicLineParser(std::string_view line, const std::vector<Token>& tokens, int line_no,
                    const std::string& file)
        : LineWords(line, tokens, line_no, file) {
        step_.op = ScriptOp::Logic;
        step_.line = line_no;
    }

    Result<ScriptStep> parse() {
        const std::string_view word = tokens_[0].text;
        if (word == "expect") return expect();
        if (word == "name") return name();
        if (word == "link") return link();
        return objective();
    }

  private:
    // ---- helpers --------------------------------------------------------------------------------------

    LogicStep& logic() { return step_.logic; }

    // A position counted from 1, as the inspector shows them; kept counted from 0.
    Result<void> position(size_t token, int& out, const char* what, const char* usage) const {
        if (token >= tokens_.size()) return fail(token, std::string("expected ") + what, usage);
        if (!to_int(tokens_[token].text, out) || out < 1)
            return fail(token,
                        std::string("expected ") + what + " (counted from 1), got '" + word(token) + "'",
                        usage);
        --out;
        return ok();
    }
    Result<void> count(size_t token, int& out, const char* usage) const {
        if (!to_int(tokens_[token].text, out) || out < 0)
            return fail(token, "expected a count (0 or more), got '" + word(token) + "'", usage);
        return ok();
    }
    // SOURCE: an entity id, `level` or `objective:ID`.
    Result<void> source(size_t token, const char* usage) {
        if (token >= tokens_.size()) return fail(token, "expected the links' source", usage);
        const std::string_view w = tokens_[token].text;
        int id = 0;
        if (w == "level")
            logic().owner = LinkOwner::level();
        else if (w.starts_with(kObjectivePrefix) && w.size() > kObjectivePrefix.size())
            logic().owner = LinkOwner::objective(std::string(w.substr(kObjectivePrefix.size())));
        else if (to_int(w, id) && id >= 1)
            logic().owner = LinkOwner::entity(id);
        else
            return fail(token, "expected an entity id, level or objective:ID, got '" + std::string(w) + "'",
                        usage);
        return ok();
    }
    // A name from `known`, or an error naming the closest one.
    Result<void> vocabulary(size_t token, const std::vector<std::string>& known, const char* what,
                            std::string& out) const {
        out = word(token);
        if (std::find(known.begin(), known.end(), out) != known.end()) return ok();
        const std::string near = jsonio::closest_match(out, known);
        return fail(token, std::string("unknown ") + what + " '" + out + "'",
                    (near.empty() ? std::string() : "did you mean '" + near + "'? ") + what +
                        "s: " + jsonio::join(known));
    }
    Result<void> event(size_t token, std::string& out) const {
        return vocabulary(token, level::event_names(level::all_events()), "event", out);
    }
    Result<void> action(size_t token, std::string& out) const {
        return vocabulary(token, level::action_names(level::all_actions()), "action", out);
    }
    Result<void> delay(size_t token, float& out, const char* usage) const {
        if (token >= tokens_.size()) return fail(token, "expected seconds after 'delay'", usage);
        if (!to_float(tokens_[token].text, out) || out < 0.0f ||
            out > static_cast<float>(level::kMaxLinkDelay))
            return fail(token, "expected seconds from 0 to 3600, got '" + word(token) + "'", usage);
        return ok();
    }
    // EVENT TARGET ACTION [delay S] [once], from token `first` to the end of the line.
    Result<void> link_words(size_t first, const char* usage) {
        if (tokens_.size() < first + 3) return fail(tokens_.size(), "missing words", usage);
        level::Link& link = logic().link;
        if (auto r = event(first, link.event); !r) return r;
        link.target = word(first + 1);
        if (auto r = action(first + 2, link.action); !r) return r;
        for (size_t i = first + 3; i < tokens_.size(); ++i) {
            if (tokens_[i].text == "once" && !link.once) {
                link.once = true;
            } else if (tokens_[i].text == "delay") {
                if (auto r = delay(i + 1, link.delay, usage); !r) return r;
                ++i;
            } else {
                return fail(i, "unexpected '" + word(i) + "'", "after the action: [delay S] [once]");
            }
        }
        return ok();
    }

    // ---- commands -------------------------------------------------------------------------------------

    Result<ScriptStep> name() {
        logic().op = LogicOp::Name;
        if (tokens_.size() < 3) return fail(tokens_.size(), "missing words", kNameUsage);
        if (!to_int(tokens_[1].text, logic().entity_id) || logic().entity_id < 1)
            return fail(1, "expected an entity id, got '" + word(1) + "'", kNameUsage);
        logic().text = rest(2);
        return step_;
    }

    Result<ScriptStep> link() {
        if (tokens_.size() < 3) return fail(tokens_.size(), "missing words", kLinkUsage);
        if (auto r = source(1, kLinkUsage); !r) return r.error();
        const std::string_view verb = tokens_[2].text;
        if (verb == "add") {
            logic().op = LogicOp::LinkAdd;
            if (auto r = link_words(3, kLinkUsage); !r) return r.error();
            return step_;
        }
        if (verb == "remove") {
            logic().op = LogicOp::LinkRemove;
            if (auto r = need(4, 4, kLinkUsage); !r) return r.error();
            if (auto r = position(3, logic().index, "a link number", kLinkUsage); !r) return r.error();
            return step_;
        }
        if (verb == "set") return link_set();
        return fail(2, "unknown link command '" + std::string(verb) + "'", "link commands: add, set, remove");
    }

    Result<ScriptStep> link_set() {
        logic().op = LogicOp::LinkSet;
        if (tokens_.size() < 6) return fail(tokens_.size(), "missing words", kLinkUsage);
        if (auto r = position(3, logic().index, "a link number", kLinkUsage); !r) return r.error();
        const std::string field = word(4);
        logic().text = field;
        if (field == "event") {
            if (auto r = need(6, 6, kLinkUsage); !r) return r.error();
            if (auto r = event(5, logic().value); !r) return r.error();
        } else if (field == "action") {
            if (auto r = need(6, 6, kLinkUsage); !r) return r.error();
            if (auto r = action(5, logic().value); !r) return r.error();
        } else if (field == "target") {
            logic().value = rest(5); // entity names may hold spaces
        } else if (field == "delay") {
            if (auto r = need(6, 6, kLinkUsage); !r) return r.error();
            if (auto r = delay(5, logic().link.delay, kLinkUsage); !r) return r.error();
        } else if (field == "once") {
            if (auto r = need(6, 6, kLinkUsage); !r) return r.error();
            if (tokens_[5].text != "true" && tokens_[5].text != "false")
                return fail(5, "expected true or false, got '" + word(5) + "'", "link 3 set 1 once true");
            logic().link.once = tokens_[5].text == "true";
        } else {
            const std::string near =
                jsonio::closest_match(field, {"event", "target", "action", "delay", "once"});
            return fail(4, "unknown link field '" + field + "'",
                        (near.empty() ? std::string() : "did you mean '" + near + "'? ") +
                            "fields: event, target, action, delay, once");
        }
        return step_;
    }

    Result<ScriptStep> objective() {
        if (tokens_.size() < 3) return fail(tokens_.size(), "missing words", kObjectiveUsage);
        if (tokens_[1].text == "add") {
            logic().op = LogicOp::ObjectiveAdd;
            if (tokens_.size() < 4)
                return fail(tokens_.size(), "expected the objective's text", kObjectiveUsage);
            logic().text = word(2);
            logic().value = rest(3);
            return step_;
        }
        logic().text = word(1);
        const std::string_view verb = tokens_[2].text;
        if (verb == "text") {
            logic().op = LogicOp::ObjectiveText;
            if (tokens_.size() < 4)
                return fail(tokens_.size(), "expected the objective's text", kObjectiveUsage);
            logic().value = rest(3);
            return step_;
        }
        if (verb == "kill") {
            logic().op = LogicOp::ObjectiveKill;
            for (size_t i = 3; i < tokens_.size(); ++i) logic().words.push_back(word(i));
            return step_;
        }
        if (verb == "remove") {
            logic().op = LogicOp::ObjectiveRemove;
            if (auto r = need(3, 3, kObjectiveUsage); !r) return r.error();
            return step_;
        }
        if (verb == "move") {
            logic().op = LogicOp::ObjectiveMove;
            if (auto r = need(4, 4, kObjectiveUsage); !r) return r.error();
            if (auto r = position(3, logic().index, "a position", kObjectiveUsage); !r) return r.error();
            return step_;
        }
        return fail(2, "unknown objective command '" + std::string(verb) + "'",
                    "objective commands: add, text, kill, remove, move");
    }

    Result<ScriptStep> expect() {
        const std::string_view what = tokens_[1].text;
        if (what == "objectives") {
            logic().op = LogicOp::ExpectObjectives;
            if (auto r = need(3, 3, kExpectUsage); !r) return r.error();
            if (auto r = count(2, logic().count, kExpectUsage); !r) return r.error();
            return step_;
        }
        if (auto r = source(2, kExpectUsage); !r) return r.error();
        if (what == "links") {
            logic().op = LogicOp::ExpectLinks;
            if (auto r = need(4, 4, kExpectUsage); !r) return r.error();
            if (auto r = count(3, logic().count, kExpectUsage); !r) return r.error();
            return step_;
        }
        logic().op = LogicOp::ExpectLink;
        if (auto r = position(3, logic().index, "a link number", kExpectUsage); !r) return r.error();
        if (auto r = link_words(4, kExpectUsage); !r) return r.error();
        return step_;
    }

    ScriptStep step_;
};

} // namespace

bool is_logic_command(std::string_view word) {
    return word == "name" || word == "link" || word == "objective";
}

bool is_logic_expectation(std::string_view word) {
    return word == "links" || word == "link" || word == "objectives";
}

Result<ScriptStep> parse_logic_line(std::string_view line, const std::vector<Token>& tokens, int line_no,
                                    const std::string& file) {
    return LogicLineParser(line, tokens, line_no, file).parse();
}

} // namespace ks::editor
