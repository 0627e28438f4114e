#include "editor_test_util.h"
#include "model/reachability.h"
#include "model/validation.h"

using namespace ks;
using namespace ks::editor;
using level::EntityType;

namespace {
std::string dump(const std::vector<Issue>& issues) {
    std::string s;
    for (const auto& i : issues)
        s += std::string(rule_name(i.rule)) + " #" + std::to_string(i.entity_id) + ": " + i.message + "\n";
    return s;
}
[[maybe_unused]] int count_rule(const std::vector<Issue>& issues, Rule rule, int id = -1) {
    int n = 0;
    for (const auto& i : issues) n += i.rule == rule && (id < 0 || i.entity_id == id);
    return n;
}
} // namespace

TEST_CASE("validation: the shipped main level passes every design rule") {
    const auto level = editor_test::load_shipped("main.json");
    auto issues = validate_design(level);
    INFO(dump(issues));
    CHECK(count_errors(issues) == 0);
    CHECK(issues.empty());
    auto walk = walk_to_control_panel(level, {});
    CHECK(walk.decided);
    CHECK(walk.reachable);
}
