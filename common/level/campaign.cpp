#include "level/campaign.h"

#include "core/files.h"
#include "jsonio/describe.h"
#include "jsonio/json_path.h"
#include "jsonio/json_writer.h"
#include "jsonio/parse_failure.h"
#include "jsonio/position_map.h"
#include "jsonio/suggest.h"
#include "level/diagnostics.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <map>

namespace ks::level {
namespace fs = std::filesystem;

namespace {

using Json = nlohmann::ordered_json;
using jsonio::element_path;
using jsonio::member_path;

constexpr size_t kMaxErrorsInMessage = 50;
const char* const kExample =
    "a campaign file is {\"name\": \"Killswitch\", \"levels\": [{\"file\": \"main.json\", \"title\": \"The "
    "Simulation\"}]}";
const std::vector<std::string> kCampaignFields = {"name", "levels"};
const std::vector<std::string> kLevelFields = {"file", "title"};

// A level as read, with its index in the file's "levels" array (levels too broken to read are left out).
struct ListedLevel {
    CampaignLevel level;
    size_t index = 0;
};

bool is_blank(std::string_view text) {
    return std::all_of(text.begin(), text.end(),
                       [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; });
}

void reject_unknown_fields(const Json& object, const std::string& path, const std::vector<std::string>& known,
                           DiagnosticSink& sink) {
    for (auto it = object.begin(); it != object.end(); ++it) {
        if (std::find(known.begin(), known.end(), it.key()) != known.end()) continue;
        std::string hint = "known fields: " + jsonio::join(known);
        if (std::string near = jsonio::closest_match(it.key(), known); !near.empty())
            hint = "did you mean \"" + near + "\"? " + hint;
        sink.error(member_path(path, it.key()), "unknown field \"" + it.key() + "\"", hint);
    }
}

bool read_string_field(const Json& object, const std::string& path, const char* key, const std::string& hint,
                       DiagnosticSink& sink, std::string& out) {
    auto it = object.find(key);
    if (it == object.end()) {
        sink.error(member_path(path, key), "missing required field \"" + std::string(key) + "\"", hint);
        return false;
    }
    if (!it->is_string()) {
        sink.error(member_path(path, key), "expected a string, found " + jsonio::describe_value(*it), hint);
        return false;
    }
    out = it->get<std::string>();
    return true;
}

std::optional<ListedLevel> read_listed_level(const Json& value, size_t index, DiagnosticSink& sink) {
    const std::string path = element_path("levels", index);
    if (!value.is_object()) {
        sink.error(path, "expected a level as an object {...}, found " + jsonio::describe_value(value),
                   "write it as {\"file\": \"main.json\", \"title\": \"The Simulation\"}");
        return std::nullopt;
    }
    reject_unknown_fields(value, path, kLevelFields, sink);
    ListedLevel listed{{}, index};
    bool ok = read_string_field(value, path, "file", "the level file, relative to the campaign file's folder",
                                sink, listed.level.file);
    ok &= read_string_field(value, path, "title", "the title the summary screen shows", sink,
                            listed.level.title);
    if (!ok) return std::nullopt;
    return listed;
}

// The checks on content that load and save share: names present, no level twice, relative paths.
void check_content(const std::optional<std::string>& name, const std::vector<ListedLevel>& levels,
                   bool list_empty, DiagnosticSink& sink) {
    if (name && is_blank(*name))
        sink.error("name", "the campaign has no name", "give it one, e.g. \"name\": \"Killswitch\"");
    if (list_empty)
        sink.error("levels", "the campaign lists no levels",
                   "add at least one, e.g. {\"file\": \"main.json\", \"title\": \"The Simulation\"}");
    std::map<std::string, size_t> first_listing;
    for (const ListedLevel& listed : levels) {
        const std::string path = element_path("levels", listed.index);
        const std::string& file = listed.level.file;
        if (is_blank(listed.level.title))
            sink.error(member_path(path, "title"), "the level has no title",
                       "write the title the summary screen shows, e.g. \"The Simulation\"");
        if (is_blank(file)) {
            sink.error(member_path(path, "file"), "the level file is empty",
                       "write the level file's name, relative to the campaign file's folder");
            continue;
        }
        if (fs::path(file).is_absolute()) {
            sink.error(member_path(path, "file"), "level file \"" + file + "\" is an absolute path",
                       "write it relative to the campaign file's folder, so the campaign can move");
            continue;
        }
        const std::string key = fs::path(file).lexically_normal().generic_string();
        auto [first, inserted] = first_listing.emplace(key, listed.index);
        if (!inserted)
            sink.error(member_path(path, "file"),
                       "level \"" + file + "\" is listed twice (also " +
                           element_path("levels", first->second) + ")",
                       "a campaign plays each level once: remove one of them");
    }
}

// The .json files beside a missing one, for "did you mean".
std::vector<std::string> level_files_in(const fs::path& folder) {
    std::vector<std::string> names;
    for (const fs::path& file : files::list(folder, ".json").value_or(std::vector<fs::path>{}))
        names.push_back(file.filename().string());
    return names;
}

void check_level_files_exist(const std::vector<ListedLevel>& levels, const fs::path& folder,
                             DiagnosticSink& sink) {
    for (const ListedLevel& listed : levels) {
        const fs::path relative(listed.level.file);
        if (is_blank(listed.level.file) || relative.is_absolute()) continue; // already reported
        const fs::path full = folder / relative;
        std::error_code ec;
        if (fs::is_regular_file(full, ec)) continue;
        std::string hint = "level files are relative to the campaign file's folder";
        const std::vector<std::string> beside =
            level_files_in(full.parent_path().empty() ? fs::path(".") : full.parent_path());
        if (std::string near = jsonio::closest_match(relative.filename().string(), beside); !near.empty())
            hint = "did you mean \"" + (relative.parent_path() / near).generic_string() + "\"? " + hint;
        const std::string what = fs::is_directory(full, ec) ? "is a folder, not a level file" : "not found";
        sink.error(member_path(element_path("levels", listed.index), "file"),
                   "level file \"" + listed.level.file + "\" " + what + " (looked for " + full.string() + ")",
                   hint);
    }
}

std::optional<Json> parse_document(std::string_view text, jsonio::PositionMap& positions,
                                   DiagnosticSink& sink) {
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    if (is_blank(text)) {
        sink.error_at({}, "", "file is empty", kExample);
        return std::nullopt;
    }
    positions = jsonio::PositionMap::scan(text);
    try {
        Json document = Json::parse(text);
        for (const jsonio::DuplicateKey& d : positions.duplicate_keys())
            sink.error_at(d.second, d.path,
                          "duplicate key (also at line " + std::to_string(d.first.line) + ":" +
                              std::to_string(d.first.column) + "); only one would be kept",
                          "remove one of them");
        return document;
    } catch (const nlohmann::json::parse_error& e) {
        const jsonio::ParseFailure failure = jsonio::describe_parse_error(text, e);
        sink.error_at(failure.position, "",
                      (failure.at_end ? "file ends early (truncated?): " : "") + failure.message,
                      failure.at_end ? "complete the file" : "fix the JSON syntax at this place");
    } catch (const nlohmann::json::exception& e) {
        sink.error_at({}, "", std::string("JSON could not be read: ") + e.what(), "fix the JSON syntax");
    }
    return std::nullopt;
}

// Reads the campaign's fields; what cannot be read is reported and left out.
Campaign read_campaign(const Json& document, const fs::path& folder, DiagnosticSink& sink) {
    Campaign campaign;
    reject_unknown_fields(document, "", kCampaignFields, sink);
    std::optional<std::string> name;
    if (std::string text;
        read_string_field(document, "", "name", "the campaign's name, e.g. \"Killswitch\"", sink, text))
        name = campaign.name = text;
    std::vector<ListedLevel> listed;
    bool list_empty = false;
    auto levels = document.find("levels");
    if (levels == document.end()) {
        sink.error("levels", "missing required field \"levels\"", kExample);
    } else if (!levels->is_array()) {
        sink.error("levels",
                   "expected the levels as an array [...], found " + jsonio::describe_value(*levels),
                   kExample);
    } else {
        list_empty = levels->empty();
        for (size_t i = 0; i < levels->size(); ++i)
            if (std::optional<ListedLevel> level = read_listed_level((*levels)[i], i, sink)) {
                campaign.levels.push_back(level->level);
                listed.push_back(std::move(*level));
            }
    }
    check_content(name, listed, list_empty, sink);
    check_level_files_exist(listed, folder, sink);
    return campaign;
}

Error combined_error(std::vector<Diagnostic> diagnostics, const std::string& file) {
    std::vector<Error> errors;
    for (Diagnostic& d : diagnostics)
        if (errors.size() < kMaxErrorsInMessage) errors.push_back(std::move(d.error));
    if (diagnostics.size() > kMaxErrorsInMessage)
        errors.emplace_back("... and " + std::to_string(diagnostics.size() - kMaxErrorsInMessage) +
                                " more errors",
                            Location(file));
    Error combined = combine_errors(errors);
    if (combined.where.file.empty()) combined.where.file = file;
    return combined;
}

} // namespace

Result<Campaign> load_campaign_string(std::string_view text, const std::string& file_name,
                                      const fs::path& folder) {
    jsonio::PositionMap positions;
    DiagnosticSink sink(file_name, &positions);
    std::optional<Json> document = parse_document(text, positions, sink);
    Campaign campaign;
    if (document && !document->is_object())
        sink.error_at(positions.find(""), "",
                      "expected the campaign as a JSON object {...}, found " +
                          jsonio::describe_value(*document),
                      kExample);
    else if (document)
        campaign = read_campaign(*document, folder, sink);
    if (sink.has_errors()) return combined_error(sink.take_sorted(), file_name);
    return campaign;
}

Result<Campaign> load_campaign(const fs::path& file) {
    Result<std::string> text = files::read_text(file);
    if (!text) return text.error();
    return load_campaign_string(*text, file.string(), file.parent_path());
}

std::string save_campaign_string(const Campaign& campaign) {
    Json document = Json::object();
    document["name"] = campaign.name;
    Json levels = Json::array();
    for (const CampaignLevel& level : campaign.levels)
        levels.push_back(Json{{"file", level.file}, {"title", level.title}});
    document["levels"] = std::move(levels);
    return jsonio::write_document(document);
}

Result<void> save_campaign(const Campaign& campaign, const fs::path& file) {
    DiagnosticSink sink(file.string());
    std::vector<ListedLevel> listed;
    for (size_t i = 0; i < campaign.levels.size(); ++i) listed.push_back({campaign.levels[i], i});
    check_content(campaign.name, listed, campaign.levels.empty(), sink);
    if (sink.has_errors()) return combined_error(sink.take_sorted(), file.string());
    return files::write_atomic(file, save_campaign_string(campaign));
}

fs::path campaign_level_path(const fs::path& campaign_file, const CampaignLevel& level) {
    return campaign_file.parent_path() / fs::path(level.file);
}

} // namespace ks::level
