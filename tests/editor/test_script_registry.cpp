// The script language's command registry (model/script_command.h): one entry per command, and the hints,
// --help-script listing and docs/editor.md's command tables agree with it.
#include "editor_test_util.h"

#include "model/script_command.h"

#include <algorithm>
#include <set>
#include <sstream>

using namespace ks;
using namespace ks::editor;

namespace {

using CommandKey = std::pair<std::string, bool>; // the word, and whether it follows `expect`

std::string key_text(const CommandKey& key) {
    return key.second ? "expect " + key.first : key.first;
}

std::set<CommandKey> registry_commands() {
    std::set<CommandKey> out;
    for (const CommandTable& table : script_command_tables())
        for (const CommandSpec& command : table.commands)
            out.insert({std::string(command.word), command.expectation});
    return out;
}

// The commands the first column of docs/editor.md's tables in "## Script language" names: each `code span`
// there is a command's form, so its first word (after `expect`, its second) is the command.
std::set<CommandKey> documented_commands() {
    const std::string doc = test::read_file(test::source_dir() / "docs" / "editor.md");
    const size_t begin = doc.find("\n## Script language");
    REQUIRE(begin != std::string::npos);
    const size_t end = doc.find("\n## ", begin + 1);
    std::istringstream section(doc.substr(begin, end - begin));
    std::set<CommandKey> out;
    for (std::string line; std::getline(section, line);) {
        if (line.rfind("| `", 0) != 0) continue;
        // The first column ends at the first '|' that is not escaped (`\|` stands inside forms).
        size_t column_end = 1;
        while ((column_end = line.find('|', column_end)) != std::string::npos && line[column_end - 1] == '\\')
            ++column_end;
        const std::string column = line.substr(1, column_end - 1);
        for (size_t open = column.find('`'); open != std::string::npos; open = column.find('`', open)) {
            const size_t close = column.find('`', open + 1);
            REQUIRE(close != std::string::npos);
            std::istringstream words(column.substr(open + 1, close - open - 1));
            std::string first, second;
            words >> first >> second;
            out.insert(first == "expect" ? CommandKey{second, true} : CommandKey{first, false});
            open = close + 1;
        }
    }
    return out;
}

} // namespace

TEST_CASE("script registry: docs/editor.md's command tables list exactly the registry's commands") {
    const auto registered = registry_commands();
    const auto documented = documented_commands();
    for (const CommandKey& key : registered)
        CHECK_MESSAGE(documented.contains(key), ("undocumented: " + key_text(key)));
    for (const CommandKey& key : documented)
        CHECK_MESSAGE(registered.contains(key), ("not a command: " + key_text(key)));
}

TEST_CASE("script registry: each command is registered once, and its usage spells its own word") {
    std::set<CommandKey> seen;
    for (const CommandTable& table : script_command_tables()) {
        for (const CommandSpec& command : table.commands) {
            const CommandKey key{std::string(command.word), command.expectation};
            INFO(key_text(key));
            CHECK(seen.insert(key).second);
            CHECK(find_script_command(command.word, command.expectation) == &command);
            CHECK(std::string_view(command.summary).size() > 0);
            // Every form of the usage starts with the command.
            std::string_view usage = command.usage;
            for (size_t at = 0; at != std::string_view::npos;) {
                const size_t bar = usage.find(" | ", at);
                const std::string_view form =
                    usage.substr(at, bar == std::string_view::npos ? bar : bar - at);
                CHECK(form.rfind(key_text(key), 0) == 0);
                at = bar == std::string_view::npos ? bar : bar + 3;
            }
        }
    }
    CHECK(find_script_command("plaec", false) == nullptr);
    CHECK(find_script_command("place", true) == nullptr); // `expect place` is no expectation
}

TEST_CASE("script registry: unknown words get a did-you-mean and the registry's words") {
    const auto unknown = parse_script("plaec robot at 0,0,0\n", "a.kss");
    REQUIRE_FALSE(unknown.ok());
    const std::string command = unknown.error().str();
    CHECK(command.find("a.kss:1:1: unknown command 'plaec'") != std::string::npos);
    CHECK(command.find("did you mean 'place'?") != std::string::npos);
    for (const CommandKey& key : registry_commands())
        if (!key.second) CHECK_MESSAGE(command.find(" " + key.first) != std::string::npos, key.first);

    const auto expectation = parse_script("place robot at 0,0,0\nexpect slected 1\n", "a.kss");
    REQUIRE_FALSE(expectation.ok());
    const std::string text = expectation.error().str();
    CHECK(text.find("a.kss:2:8: unknown expectation 'slected'") != std::string::npos);
    CHECK(text.find("did you mean 'selected'?") != std::string::npos);
    for (const CommandKey& key : registry_commands())
        if (key.second) CHECK_MESSAGE(text.find(" " + key.first) != std::string::npos, key.first);

    CHECK(parse_script("expect\n", "a.kss").error().str().find("a.kss:1:7: missing words") !=
          std::string::npos);
}

TEST_CASE("script registry: --help-script lists every form of every command") {
    const std::string listing = script_usage_listing();
    for (const CommandTable& table : script_command_tables()) {
        CHECK(listing.find(std::string(table.label) + ":\n") != std::string::npos);
        for (const CommandSpec& command : table.commands) {
            std::string_view usage = command.usage;
            const size_t bar = usage.find(" | ");
            CHECK_MESSAGE(listing.find("  " + std::string(usage.substr(0, bar)) + "\n") != std::string::npos,
                          command.usage);
            CHECK(listing.find(command.summary) != std::string::npos);
        }
    }
}

TEST_CASE("script registry: a parsed line is the typed step of its command") {
    auto script =
        parse_script("place robot at 1,0,2 yaw 90 name Guard\nexpect no_issue support\n"
                     "layer Walls hide\nlink 3 add on_enter Door open once\nclip loop wave next idle\n",
                     "a.kss");
    REQUIRE_MESSAGE(script.ok(), (script.ok() ? std::string() : script.error().str()));
    REQUIRE(script->steps.size() == 5);
    const auto& place = std::get<steps::Place>(std::get<LevelStep>(script->steps[0].action).step);
    CHECK(place.type == level::EntityType::Robot);
    CHECK(place.position == Vec3(1, 0, 2));
    CHECK(place.yaw == 90.0f);
    CHECK(place.name == "Guard");
    const auto& no_issue = std::get<steps::ExpectIssue>(std::get<LevelStep>(script->steps[1].action).step);
    CHECK_FALSE(no_issue.wanted);
    CHECK(no_issue.rule == Rule::Support);
    const auto& hide = std::get<steps::LayerVisible>(std::get<StructureStep>(script->steps[2].action).step);
    CHECK(hide.layer == "Walls");
    CHECK_FALSE(hide.visible);
    const auto& link = std::get<steps::LinkAdd>(std::get<LogicStep>(script->steps[3].action).step);
    CHECK(link.owner == LinkOwner::entity(3));
    CHECK(link.link.target == "Door");
    CHECK(link.link.once);
    const auto& loop = std::get<steps::ClipLoop>(std::get<DojoStep>(script->steps[4].action).step);
    CHECK(loop.clip == "wave");
    CHECK(loop.mode == "next");
    CHECK(loop.next == "idle");
    CHECK(script->steps[4].line == 5);
}
