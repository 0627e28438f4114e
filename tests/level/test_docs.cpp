// docs/level-format.md documents every field: its tables are generated from the same visit() lists that
// the loader uses, and this test fails when they drift apart. KS_WRITE_DOCS=1 rewrites the generated part.
#include "core/files.h"
#include "jsonio/json_writer.h"
#include "jsonio/number_text.h"
#include "jsonio/suggest.h"
#include "level/diagnostics.h"
#include "level/level_io.h"
#include "level/level_writer.h"
#include "level/logic_names.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <cstdlib>

using namespace ks::level;

namespace {

const char* const kBegin =
    "<!-- BEGIN GENERATED FIELD TABLES (tests/level/test_docs.cpp; KS_WRITE_DOCS=1 to update) -->";
const char* const kEnd = "<!-- END GENERATED FIELD TABLES -->";

std::string code(const std::string& s) {
    return "`" + s + "`";
}

// One table row per field: name, value kind, default (as the file writes it), range, unit, meaning.
class DocLister {
  public:
    explicit DocLister(const nlohmann::ordered_json& defaults) : defaults_(defaults) {}
    void field(float& v, const FieldInfo& info) {
        row(info, "number", range_text_of(info), ks::jsonio::format_number(ks::jsonio::float_to_double(v)));
    }
    void field(int& v, const FieldInfo& info) {
        row(info, "whole number", range_text_of(info), std::to_string(v));
    }
    void field(bool& v, const FieldInfo& info) { row(info, "true / false", "", v ? "true" : "false"); }
    // A text whose FieldInfo has a non-negative minimum bounds its length.
    void field(std::string&, const FieldInfo& info) {
        row(info, "string",
            info.min >= 0 ? ks::jsonio::format_readable(info.min) + " .. " +
                                ks::jsonio::format_readable(info.max) + " characters"
                          : "");
    }
    void field(ks::Vec2&, const FieldInfo& info) { row(info, "[x, z]", range_text_of(info) + " each"); }
    void field(ks::Vec3&, const FieldInfo& info) { row(info, "[x, y, z]", range_text_of(info) + " each"); }
    void field(Color&, const FieldInfo& info) { row(info, "colour \"#rrggbb\"", ""); }
    void field(Choice& choice, const FieldInfo& info) {
        row(info, "one of " + ks::jsonio::join(choice.options, ", "), "");
    }
    void field(SoundName& v, const FieldInfo& info) {
        row(info, "sound name (a-z, 0-9, _)",
            ks::jsonio::format_readable(info.min) + " .. " + ks::jsonio::format_readable(info.max) +
                " characters",
            "\"" + v.value + "\"");
    }
    void field(Patrol&, const FieldInfo& info) {
        row(info, "{points, mode, wait} (see Patrols)", "", "none: wanders");
    }
    void field(std::vector<Link>&, const FieldInfo& info) {
        row(info, "array of links (see Level logic)", "at most " + std::to_string(kMaxLinks), "[]");
    }
    void field(std::vector<std::string>&, const FieldInfo& info) {
        row(info, "array of names", "at most " + std::to_string(kMaxKillNames), "[]");
    }
    void field(ks::brush::Brush&, const FieldInfo& info) {
        // Its default written out would be six faces of JSON: the table names it instead.
        rows_ += "| " + code(info.name) +
                 " | array of faces (see Brushes) | a 4 × 4 × 4 box of `concrete` | 4 .. " +
                 std::to_string(ks::brush::kMaxFaces) + " faces | " + info.unit + " | " + info.tooltip +
                 " |\n";
    }
    std::string table() const {
        return "| field | value | default | range | unit | meaning |\n|---|---|---|---|---|---|\n" + rows_;
    }

  private:
    static std::string range_text_of(const FieldInfo& info) {
        return ks::jsonio::format_readable(info.min) + " .. " + ks::jsonio::format_readable(info.max);
    }
    // `unwritten`: what the default column shows for a field the file leaves out at its default.
    void row(const FieldInfo& info, const std::string& kind, const std::string& range,
             const std::string& unwritten = "") {
        std::string fallback =
            defaults_.contains(info.name) ? ks::jsonio::write_document(defaults_[info.name]) : unwritten;
        if (!fallback.empty() && fallback.back() == '\n') fallback.pop_back();
        rows_ += "| " + code(info.name) + " | " + kind + " | " + code(fallback) + " | " + range + " | " +
                 info.unit + " | " + info.tooltip +
                 (info.omitted_at_default ? " (left out of the file while it is the default)" : "") + " |\n";
    }
    const nlohmann::ordered_json& defaults_;
    std::string rows_;
};

template <class T>
std::string table_for(T object, const nlohmann::ordered_json& defaults) {
    DocLister lister(defaults);
    object.visit(lister);
    return lister.table();
}

std::string generated_tables() {
    std::string out = std::string(kBegin) + "\n\n";
    const auto level_json = write_level(Level{});
    out += "### `settings`\n\n" + table_for(Settings{}, level_json["settings"]) + "\n";
    for (EntityType type : all_types()) {
        Entity entity;
        entity.props = default_props(type);
        const auto props = write_entity(entity)["props"];
        out += "### `" + std::string(type_name(type)) + "`\n\n";
        out += std::visit([&](auto p) { return table_for(p, props); }, entity.props) + "\n";
    }
    // The level logic's own objects: a link (under an entity's, an objective's or the level's "links") and
    // an objective (under the level's "objectives").
    Level with_logic;
    with_logic.objectives.push_back({});
    with_logic.links.push_back({});
    const auto logic_json = write_level(with_logic);
    out += "### link\n\n" + table_for(Link{}, logic_json["links"][0]) + "\n";
    out += "### objective\n\n" + table_for(Objective{}, logic_json["objectives"][0]) + "\n";
    out += kEnd;
    return out;
}

std::filesystem::path doc_path() {
    return ks::test::source_dir() / "docs" / "level-format.md";
}

} // namespace

TEST_CASE("docs/level-format.md holds the field tables generated from the schema") {
    std::string doc = ks::test::read_file(doc_path());
    const size_t begin = doc.find(kBegin);
    const size_t end = doc.find(kEnd);
    REQUIRE_MESSAGE(begin != std::string::npos, "the doc lost its generated-table markers");
    REQUIRE(end != std::string::npos);
    const std::string expected = generated_tables();
    const std::string actual = doc.substr(begin, end + std::string(kEnd).size() - begin);
    if (const char* flag = std::getenv("KS_WRITE_DOCS");
        flag && std::string(flag) == "1" && actual != expected) {
        doc.replace(begin, actual.size(), expected);
        REQUIRE(ks::files::write_atomic(doc_path(), doc).ok());
        return;
    }
    CHECK_MESSAGE(actual == expected, "field tables are stale: run ks_tests_level with KS_WRITE_DOCS=1");
}

TEST_CASE("every field name and type name appears in the doc, and its example level loads") {
    const std::string doc = ks::test::read_file(doc_path());
    for (EntityType type : all_types())
        CHECK(doc.find("`" + std::string(type_name(type)) + "`") != std::string::npos);
    for (const char* key :
         {"format", "version",  "name",     "settings", "player_start", "next_id", "entities",   "id",
          "type",   "position", "rotation", "props",    "yaw",          "links",   "objectives", "event",
          "target", "action",   "delay",    "once",     "kill",         "text"})
        CHECK_MESSAGE(doc.find("`" + std::string(key) + "`") != std::string::npos, key);
    for (LinkEvent event : all_events())
        CHECK_MESSAGE(doc.find("`" + std::string(event_name(event)) + "`") != std::string::npos,
                      event_name(event));
    for (LinkAction action : all_actions())
        CHECK_MESSAGE(doc.find("`" + std::string(action_name(action)) + "`") != std::string::npos,
                      action_name(action));

    // The example between ```json fences after "## Example" must load without a single diagnostic.
    const size_t example = doc.find("## Example");
    REQUIRE(example != std::string::npos);
    const size_t open = doc.find("```json\n", example);
    const size_t close = doc.find("\n```", open + 8);
    REQUIRE(open != std::string::npos);
    REQUIRE(close != std::string::npos);
    LoadReport report;
    auto level =
        load_level_string(doc.substr(open + 8, close - open - 8), "level-format.md example", &report);
    CHECK_MESSAGE(level.ok(), report.str());
    CHECK_MESSAGE(report.diagnostics.empty(), report.str());
}
