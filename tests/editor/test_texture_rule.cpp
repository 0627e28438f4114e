// Texture names in the editor, without a window: the texture field's kind, the validation's texture rule
// (an error naming the entity, with the did-you-mean as its quick fix, one undo step), the script's
// `fix texture`, and the texture browser's search.
#include "editor_test_util.h"
#include "level/texture_names.h"
#include "model/edit_entities.h"
#include "model/edit_selection.h"
#include "model/quick_fix.h"
#include "model/script.h"
#include "view/texture_search.h"

#include <algorithm>

using namespace ks;
using namespace ks::editor;

namespace {
std::vector<Issue> texture_issues(Editor& editor) {
    std::vector<Issue> out;
    for (const Issue& issue : editor.issues())
        if (issue.rule == Rule::Texture) out.push_back(issue);
    return out;
}

Editor two_walls() {
    Editor editor;
    editor.validation_options().check_reachability = false;
    REQUIRE(place(editor, level::EntityType::Wall, Vec3(0.0f), 0.0f, "North").ok());
    REQUIRE(place(editor, level::EntityType::Stair, Vec3(10, 0, 0)).ok());
    return editor;
}
} // namespace

TEST_CASE("texture fields are their own kind; an empty name is refused, an unknown one is the rule's") {
    level::Entity wall;
    wall.props = level::default_props(level::EntityType::Wall);
    const auto fields = describe_entity_fields(wall);
    const auto texture =
        std::find_if(fields.begin(), fields.end(), [](const auto& f) { return f.name == "texture"; });
    REQUIRE(texture != fields.end());
    CHECK(texture->kind == FieldKind::Texture);
    CHECK(set_entity_field(wall, "texture", FieldValue(std::string("wood"))).ok());
    CHECK_FALSE(set_entity_field(wall, "texture", FieldValue(std::string())).ok());
    CHECK(set_entity_field(wall, "texture", FieldValue(std::string("woood"))).ok()); // a draft may name it
    CHECK(parse_field_value(*texture, "tiles").ok());
}

TEST_CASE("an unknown texture is a validation error with the closest material as its quick fix") {
    Editor editor = two_walls();
    CHECK(texture_issues(editor).empty());
    REQUIRE(select(editor, {1}).ok());
    REQUIRE(set_field(editor, "texture", FieldValue(std::string("concret"))).ok());
    REQUIRE(select(editor, {2}).ok());
    REQUIRE(set_field(editor, "texture", FieldValue(std::string("granite_blocks"))).ok());
    auto issues = texture_issues(editor);
    REQUIRE(issues.size() == 2);
    const Issue& typo = issues[0];
    CHECK(typo.severity == IssueSeverity::Error);
    CHECK(typo.entity_id == 1);
    CHECK(typo.message.find("entities[0].props.texture") != std::string::npos);
    CHECK(typo.message.find("wall 1 (\"North\"): texture \"concret\"") != std::string::npos);
    CHECK(typo.message.find("did you mean \"concrete\"?") != std::string::npos);
    REQUIRE(typo.fix.is<fixes::SetField>());
    CHECK(typo.fix.label == "Use concrete");
    CHECK(!issues[1].fix.available()); // nothing close: no guess
    CHECK(issues[1].message.find("surface materials") != std::string::npos);
    // No duplicate under the format rule.
    for (const Issue& issue : editor.issues())
        if (issue.message.find("granite") != std::string::npos) CHECK(issue.rule == Rule::Texture);

    const size_t steps = editor.history().undo_count();
    REQUIRE(apply_quick_fix(editor, typo).ok());
    CHECK(editor.level().find(1)->as<level::WallProps>().texture == "concrete");
    CHECK(editor.history().undo_count() == steps + 1);
    CHECK(texture_issues(editor).size() == 1);
    editor.undo();
    CHECK(editor.level().find(1)->as<level::WallProps>().texture == "concret");
    CHECK(texture_issues(editor).size() == 2);
}

TEST_CASE("scripts check and fix texture names") {
    Editor editor;
    editor.validation_options().check_reachability = false;
    const char* script = R"(place floor at 0,0,0
set texture tyles
expect issue texture 1
fix texture
expect no_issue texture
expect field 1 texture tiles
set texture wood
expect no_issue texture
)";
    auto report = run_script_text(script, "textures.kss", {}, editor);
    REQUIRE_MESSAGE(report.ok(), report.error().str());
}

TEST_CASE("the texture browser's search: substrings, any case, else the closest name") {
    const std::vector<std::string> names = level::shipped_texture_names();
    REQUIRE(names.size() >= 6);
    CHECK(texture_matches(names, "") == names);
    CHECK(texture_matches(names, "  ") == names);
    CHECK(texture_matches(names, "TIL") == std::vector<std::string>{"tiles"});
    CHECK(texture_matches(names, "floor") == std::vector<std::string>{"dojo_floor"});
    const auto e = texture_matches(names, "e");
    CHECK(std::find(e.begin(), e.end(), "ceiling") != e.end());
    CHECK(std::find(e.begin(), e.end(), "wood") == e.end());
    CHECK(texture_matches(names, "concret") == std::vector<std::string>{"concrete"});
    CHECK(texture_matches(names, "woood") == std::vector<std::string>{"wood"});
    CHECK(texture_matches(names, "zzzzzzzz").empty());
}
