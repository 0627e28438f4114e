// The script language's level-logic commands (script_logic.h): each command's parser and the table that
// registers it (script_command.h); their steps run in script_logic_runner.cpp. Event and action names are
// checked here against the whole vocabulary (with a did-you-mean); whether the source emits the event is
// the Editor's check when the line runs.
#include "model/script_command.h"

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
constexpr const char* kLinksUsage = "expect links SOURCE N";
constexpr const char* kLinkExpectUsage = "expect link SOURCE INDEX EVENT TARGET ACTION [delay S] [once]";
constexpr const char* kObjectivesUsage = "expect objectives N";
constexpr std::string_view kObjectivePrefix = "objective:";

template <class T>
Result<ScriptStep> logic_step(T step) {
    return step_of<LogicStep>(std::move(step));
}

// The logic lines' word readers: positions counted from 1, sources, event and action names, delays.
class LogicWords : public LineWords {
  public:
    explicit LogicWords(const LineWords& words) : LineWords(words) {}

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
    Result<void> source(size_t token, LinkOwner& owner, const char* usage) const {
        if (token >= tokens_.size()) return fail(token, "expected the links' source", usage);
        const std::string_view w = tokens_[token].text;
        int id = 0;
        if (w == "level")
            owner = LinkOwner::level();
        else if (w.starts_with(kObjectivePrefix) && w.size() > kObjectivePrefix.size())
            owner = LinkOwner::objective(std::string(w.substr(kObjectivePrefix.size())));
        else if (to_int(w, id) && id >= 1)
            owner = LinkOwner::entity(id);
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
    Result<void> link_words(size_t first, level::Link& link, const char* usage) const {
        if (tokens_.size() < first + 3) return fail(tokens_.size(), "missing words", usage);
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
};

// ---- commands -----------------------------------------------------------------------------------------

Result<ScriptStep> parse_name(const LineWords& w) {
    steps::Name step;
    if (w.size() < 3) return w.fail(w.size(), "missing words", kNameUsage);
    if (!to_int(w.text(1), step.entity_id) || step.entity_id < 1)
        return w.fail(1, "expected an entity id, got '" + w.word(1) + "'", kNameUsage);
    step.name = w.rest(2);
    return logic_step(std::move(step));
}

Result<ScriptStep> parse_link_set(const LogicWords& w, const LinkOwner& owner) {
    steps::LinkSet step{owner, 0, {}, {}, {}};
    if (w.size() < 6) return w.fail(w.size(), "missing words", kLinkUsage);
    if (auto r = w.position(3, step.index, "a link number", kLinkUsage); !r) return r.error();
    const std::string field = w.word(4);
    step.field = field;
    if (field == "target") {
        step.value = w.rest(5); // entity names may hold spaces
        return logic_step(std::move(step));
    }
    if (field != "event" && field != "action" && field != "delay" && field != "once") {
        const std::string near = jsonio::closest_match(field, {"event", "target", "action", "delay", "once"});
        return w.fail(4, "unknown link field '" + field + "'",
                      (near.empty() ? std::string() : "did you mean '" + near + "'? ") +
                          "fields: event, target, action, delay, once");
    }
    if (auto r = w.need(6, 6, kLinkUsage); !r) return r.error();
    if (field == "event") {
        if (auto r = w.event(5, step.value); !r) return r.error();
    } else if (field == "action") {
        if (auto r = w.action(5, step.value); !r) return r.error();
    } else if (field == "delay") {
        if (auto r = w.delay(5, step.link.delay, kLinkUsage); !r) return r.error();
    } else {
        if (w.text(5) != "true" && w.text(5) != "false")
            return w.fail(5, "expected true or false, got '" + w.word(5) + "'", "link 3 set 1 once true");
        step.link.once = w.text(5) == "true";
    }
    return logic_step(std::move(step));
}

Result<ScriptStep> parse_link(const LineWords& words) {
    const LogicWords w(words);
    LinkOwner owner;
    if (w.size() < 3) return w.fail(w.size(), "missing words", kLinkUsage);
    if (auto r = w.source(1, owner, kLinkUsage); !r) return r.error();
    const std::string_view verb = w.text(2);
    if (verb == "add") {
        steps::LinkAdd step{owner, {}};
        if (auto r = w.link_words(3, step.link, kLinkUsage); !r) return r.error();
        return logic_step(std::move(step));
    }
    if (verb == "remove") {
        steps::LinkRemove step{owner, 0};
        if (auto r = w.need(4, 4, kLinkUsage); !r) return r.error();
        if (auto r = w.position(3, step.index, "a link number", kLinkUsage); !r) return r.error();
        return logic_step(std::move(step));
    }
    if (verb == "set") return parse_link_set(w, owner);
    return w.fail(2, "unknown link command '" + std::string(verb) + "'", "link commands: add, set, remove");
}

Result<ScriptStep> parse_objective(const LineWords& words) {
    const LogicWords w(words);
    if (w.size() < 3) return w.fail(w.size(), "missing words", kObjectiveUsage);
    if (w.text(1) == "add") {
        if (w.size() < 4) return w.fail(w.size(), "expected the objective's text", kObjectiveUsage);
        return logic_step(steps::ObjectiveAdd{w.word(2), w.rest(3)});
    }
    const std::string id = w.word(1);
    const std::string_view verb = w.text(2);
    if (verb == "text") {
        if (w.size() < 4) return w.fail(w.size(), "expected the objective's text", kObjectiveUsage);
        return logic_step(steps::ObjectiveText{id, w.rest(3)});
    }
    if (verb == "kill") {
        steps::ObjectiveKill step{id, {}};
        for (size_t i = 3; i < w.size(); ++i) step.names.push_back(w.word(i));
        return logic_step(std::move(step));
    }
    if (verb == "remove") {
        if (auto r = w.need(3, 3, kObjectiveUsage); !r) return r.error();
        return logic_step(steps::ObjectiveRemove{id});
    }
    if (verb == "move") {
        steps::ObjectiveMove step{id, 0};
        if (auto r = w.need(4, 4, kObjectiveUsage); !r) return r.error();
        if (auto r = w.position(3, step.index, "a position", kObjectiveUsage); !r) return r.error();
        return logic_step(std::move(step));
    }
    return w.fail(2, "unknown objective command '" + std::string(verb) + "'",
                  "objective commands: add, text, kill, remove, move");
}

// ---- expectations -------------------------------------------------------------------------------------

Result<ScriptStep> parse_expect_objectives(const LineWords& words) {
    const LogicWords w(words);
    steps::ExpectObjectives step;
    if (auto r = w.need(3, 3, kObjectivesUsage); !r) return r.error();
    if (auto r = w.count(2, step.count, kObjectivesUsage); !r) return r.error();
    return logic_step(step);
}

Result<ScriptStep> parse_expect_links(const LineWords& words) {
    const LogicWords w(words);
    steps::ExpectLinks step;
    if (auto r = w.source(2, step.owner, kLinksUsage); !r) return r.error();
    if (auto r = w.need(4, 4, kLinksUsage); !r) return r.error();
    if (auto r = w.count(3, step.count, kLinksUsage); !r) return r.error();
    return logic_step(std::move(step));
}

Result<ScriptStep> parse_expect_link(const LineWords& words) {
    const LogicWords w(words);
    steps::ExpectLink step;
    if (auto r = w.source(2, step.owner, kLinkExpectUsage); !r) return r.error();
    if (auto r = w.position(3, step.index, "a link number", kLinkExpectUsage); !r) return r.error();
    if (auto r = w.link_words(4, step.link, kLinkExpectUsage); !r) return r.error();
    return logic_step(std::move(step));
}

constexpr CommandSpec kCommands[] = {
    {"name", false, kNameUsage, "name an entity (links and kill lists naming its old, unique name follow)",
     parse_name},
    {"link", false, kLinkUsage, "add, change or remove a link of an entity, an objective or the level",
     parse_link},
    {"objective", false, kObjectiveUsage, "add, edit, remove or move an objective", parse_objective},
    {"links", true, kLinksUsage, "the number of a source's links", parse_expect_links},
    {"link", true, kLinkExpectUsage, "one link exactly (delay 0 and not once unless given)",
     parse_expect_link},
    {"objectives", true, kObjectivesUsage, "the number of objectives", parse_expect_objectives},
};

} // namespace

std::span<const CommandSpec> logic_commands() {
    return kCommands;
}

} // namespace ks::editor
