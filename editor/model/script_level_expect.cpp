// The script language's level expectations (script_level.h): `expect count|valid|issue|...`; each one's
// parser, its step's `run`, and the table entry that registers it (script_command.h).
#include "model/script_level_words.h"

#include "level/campaign.h"

namespace ks::editor {
namespace {
using namespace script_tokens;
using namespace level_words;

constexpr const char* kCountUsage = "expect count TYPE N";
constexpr const char* kIssueUsage = "expect issue RULE [ID]";
constexpr const char* kNoIssueUsage = "expect no_issue RULE";
constexpr const char* kSelectedUsage = "expect selected N";
constexpr const char* kFieldUsage = "expect field ID FIELD VALUE";
constexpr const char* kPatrolUsage = "expect patrol ID POINTS";
constexpr const char* kPlayerStartUsage = "expect player_start X,Y,Z [yaw D]";
constexpr const char* kCampaignUsage = "expect campaign FILE N";

Result<ScriptStep> parse_count(const LineWords& w) {
    steps::ExpectCount step;
    if (auto r = w.need(4, 4, kCountUsage); !r) return r.error();
    if (auto r = entity_type(w, 2, step.type); !r) return r.error();
    if (!to_int(w.text(3), step.count) || step.count < 0) return w.fail(3, "expected a count", kCountUsage);
    return level_step(step);
}

Result<ScriptStep> parse_selected(const LineWords& w) {
    steps::ExpectSelected step;
    if (auto r = w.need(3, 3, kSelectedUsage); !r) return r.error();
    if (!to_int(w.text(2), step.count) || step.count < 0)
        return w.fail(2, "expected a count", kSelectedUsage);
    return level_step(step);
}

Result<ScriptStep> parse_issue(const LineWords& w, bool wanted) {
    const char* usage = wanted ? kIssueUsage : kNoIssueUsage;
    steps::ExpectIssue step;
    step.wanted = wanted;
    if (auto r = w.need(3, wanted ? 4 : 3, usage); !r) return r.error();
    if (auto r = rule(w, 2, step.rule); !r) return r.error();
    if (w.size() == 4 && (!to_int(w.text(3), step.entity_id) || step.entity_id < 1))
        return w.fail(3, "expected an entity id", usage);
    return level_step(step);
}

Result<ScriptStep> parse_player_start(const LineWords& w) {
    steps::ExpectPlayerStart step;
    if (w.size() != 3 && w.size() != 5) return w.fail(w.size(), "wrong number of words", kPlayerStartUsage);
    if (auto r = w.vec(2, step.position); !r) return r.error();
    if (w.size() == 5) {
        float yaw = 0.0f;
        if (w.text(3) != "yaw") return w.fail(3, "expected 'yaw'", kPlayerStartUsage);
        if (!to_float(w.text(4), yaw)) return w.fail(4, "expected degrees", "yaw 90");
        step.yaw = yaw;
    }
    return level_step(step);
}

Result<ScriptStep> parse_patrol(const LineWords& w) {
    steps::ExpectPatrol step;
    if (auto r = w.need(4, 4, kPatrolUsage); !r) return r.error();
    if (!to_int(w.text(2), step.robot) || step.robot < 1)
        return w.fail(2, "expected an entity id", kPatrolUsage);
    if (!to_int(w.text(3), step.points) || step.points < 0)
        return w.fail(3, "expected a count of points", kPatrolUsage);
    return level_step(step);
}

Result<ScriptStep> parse_campaign(const LineWords& w) {
    steps::ExpectCampaign step;
    if (auto r = w.need(4, 4, kCampaignUsage); !r) return r.error();
    step.campaign = w.word(2);
    if (!to_int(w.text(3), step.levels) || step.levels < 0)
        return w.fail(3, "expected a count of levels", kCampaignUsage);
    return level_step(step);
}

Result<ScriptStep> parse_field(const LineWords& w) {
    steps::ExpectField step;
    if (w.size() < 5) return w.fail(w.size(), "missing words", kFieldUsage);
    if (!to_int(w.text(2), step.entity_id) || step.entity_id < 1)
        return w.fail(2, "expected an entity id", kFieldUsage);
    step.field = w.word(3);
    step.value = w.rest(4);
    return level_step(step);
}

constexpr CommandSpec kCommands[] = {
    {"count", true, kCountUsage, "the number of entities of a type", parse_count},
    {"valid", true, "expect valid", "no design errors",
     [](const LineWords& w) { return nothing_after(w, 2, steps::ExpectValid{}); }},
    {"issue", true, kIssueUsage, "an issue of a rule (about entity ID)",
     [](const LineWords& w) { return parse_issue(w, true); }},
    {"no_issue", true, kNoIssueUsage, "no issue of a rule",
     [](const LineWords& w) { return parse_issue(w, false); }},
    {"selected", true, kSelectedUsage, "the number of selected entities", parse_selected},
    {"field", true, kFieldUsage, "a property's value (compared as the field's type)", parse_field},
    {"patrol", true, kPatrolUsage, "the number of a robot's patrol points", parse_patrol},
    {"player_start", true, kPlayerStartUsage, "where the player starts (within 0.0001)", parse_player_start},
    {"dirty", true, "expect dirty", "unsaved changes",
     [](const LineWords& w) { return nothing_after(w, 2, steps::ExpectDirty{true}); }},
    {"clean", true, "expect clean", "no unsaved changes",
     [](const LineWords& w) { return nothing_after(w, 2, steps::ExpectDirty{false}); }},
    {"campaign", true, kCampaignUsage, "a campaign file that loads and lists N levels", parse_campaign},
};

std::string issue_list(const std::vector<Issue>& issues) {
    std::string s;
    for (const auto& i : issues) s += std::string("\n  [") + rule_name(i.rule) + "] " + i.message;
    return s;
}

} // namespace

std::span<const CommandSpec> level_expect_commands() {
    return kCommands;
}

// ---- running ------------------------------------------------------------------------------------------

namespace steps {

Result<void> ExpectCount::run(ScriptContext& c) const {
    int n = 0;
    for (const auto& e : c.editor.level().entities) n += e.type() == type;
    return c.expect(n == count, std::string(level::type_name(type)) + " count is " + std::to_string(n) +
                                    ", expected " + std::to_string(count));
}

Result<void> ExpectValid::run(ScriptContext& c) const {
    const auto& issues = c.editor.issues();
    return c.expect(count_errors(issues) == 0, "the level has design errors:" + issue_list(issues));
}

Result<void> ExpectIssue::run(ScriptContext& c) const {
    std::vector<Issue> matching;
    for (const auto& i : c.editor.issues())
        if (i.rule == rule && (entity_id == 0 || i.entity_id == entity_id)) matching.push_back(i);
    if (wanted)
        return c.expect(!matching.empty(), std::string("no ") + rule_name(rule) + " issue" +
                                               (entity_id ? " for entity " + std::to_string(entity_id) : "") +
                                               "; issues:" + issue_list(c.editor.issues()));
    return c.expect(matching.empty(),
                    std::string("unexpected ") + rule_name(rule) + " issue:" + issue_list(matching));
}

Result<void> ExpectSelected::run(ScriptContext& c) const {
    const size_t selected = c.editor.doc().selection.size();
    return c.expect(static_cast<int>(selected) == count,
                    std::to_string(selected) + " selected, expected " + std::to_string(count));
}

// Compared as values of the field's type, not as text, so a script need not spell a value the way the
// formatter does.
Result<void> ExpectField::run(ScriptContext& c) const {
    const level::Entity* e = c.editor.level().find(entity_id);
    if (!e) return Error("no entity with id " + std::to_string(entity_id));
    auto actual = get_entity_field(*e, field);
    if (!actual) return actual.error();
    for (const auto& f : describe_entity_fields(*e)) {
        if (f.name != field) continue;
        auto wanted = parse_field_value(f, value);
        if (!wanted) return wanted.error();
        return c.expect(*wanted == *actual, "entity " + std::to_string(entity_id) + " " + field + " is " +
                                                format_field_value(*actual) + ", expected " + value);
    }
    return Error("no field " + field);
}

Result<void> ExpectPatrol::run(ScriptContext& c) const {
    const level::Entity* e = c.editor.level().find(robot);
    if (!e) return Error("no entity with id " + std::to_string(robot));
    const auto* props = e->try_as<level::RobotProps>();
    if (!props) return Error("entity " + std::to_string(e->id) + " is not a robot");
    const size_t n = props->patrol.points.size();
    return c.expect(n == static_cast<size_t>(points), "robot " + std::to_string(e->id) + " has " +
                                                          std::to_string(n) + " patrol points, expected " +
                                                          std::to_string(points));
}

Result<void> ExpectDirty::run(ScriptContext& c) const {
    if (dirty) return c.expect(c.editor.has_unsaved_changes(), "the document is clean");
    return c.expect(!c.editor.has_unsaved_changes(), "the document has unsaved changes");
}

Result<void> ExpectCampaign::run(ScriptContext& c) const {
    auto loaded = level::load_campaign(c.resolve(campaign));
    if (!loaded) return loaded.error();
    const int n = static_cast<int>(loaded->levels.size());
    return c.expect(n == levels, campaign + " lists " + std::to_string(n) + " level(s), expected " +
                                     std::to_string(levels));
}

// Within a ten-thousandth: positions and angles that went through a turn carry float rounding.
Result<void> ExpectPlayerStart::run(ScriptContext& c) const {
    const level::PlayerStart& start = c.editor.level().player_start;
    const bool at = glm::all(glm::lessThanEqual(glm::abs(start.position - position), Vec3(1e-4f)));
    const bool facing = !yaw || std::abs(start.yaw - *yaw) <= 1e-4f;
    const auto text = [](const Vec3& p, float degrees) {
        return format_field_value(p) + " yaw " + format_field_value(static_cast<double>(degrees));
    };
    return c.expect(at && facing, "the player start is at " + text(start.position, start.yaw) +
                                      ", expected " + text(position, yaw.value_or(start.yaw)));
}

} // namespace steps
} // namespace ks::editor
