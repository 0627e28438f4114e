#include "level/campaign.h"

#include "core/files.h"
#include "core/log.h"
#include "jsonio/describe.h"
#include "jsonio/document.h"
#include "jsonio/json_path.h"
#include "jsonio/json_writer.h"
#include "jsonio/object_reader.h"
#include "jsonio/suggest.h"
#include "jsonio/text.h"
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

const char* const kExample =
    "a campaign file is {\"name\": \"Killswitch\", \"levels\": [{\"file\": \"main.json\", \"title\": \"The "
    "Simulation\"}]}";

// A level as read, with its index in the file's "levels" array (levels too broken to read are left out).
struct ListedLevel {
    CampaignLevel level;
    size_t index = 0;
};

bool is_blank(std::string_view text) {
    return std::all_of(text.begin(), text.end(),
                       [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; });
}

std::optional<ListedLevel> read_listed_level(const Json& value, size_t index, DiagnosticSink& sink) {
    jsonio::ObjectReader reader(value, element_path("levels", index), sink, "a level");
    if (!reader.is_object()) return std::nullopt;
    ListedLevel listed{{}, index};
    bool ok = reader.text("file", listed.level.file, jsonio::Need::Required, 0,
                          "the level file, relative to the campaign file's folder");
    ok &= reader.text("title", listed.level.title, jsonio::Need::Required, 0,
                      "the title the summary screen shows");
    reader.finish();
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
        if (std::any_of(file.begin(), file.end(),
                        [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; })) {
            sink.error(member_path(path, "file"),
                       "level file " + jsonio::quote_text(file) + " has a control character in its name",
                       "write the file's name as it is on disk; names with line breaks or tabs are refused");
            continue;
        }
        if (fs::path(file).is_absolute()) {
            sink.error(member_path(path, "file"),
                       "level file " + jsonio::quote_text(file) + " is an absolute path",
                       "write it relative to the campaign file's folder, so the campaign can move");
            continue;
        }
        const std::string key = fs::path(file).lexically_normal().generic_string();
        auto [first, inserted] = first_listing.emplace(key, listed.index);
        if (!inserted)
            sink.error(member_path(path, "file"),
                       "level " + jsonio::quote_text(file) + " is listed twice (also " +
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
    // The same file by two spellings ("lvl.json" and "../dir/lvl.json" from dir/): the lexical check in
    // check_content cannot see it, the file system can.
    std::map<std::string, size_t> first_file; // the file on disk -> its first position in `levels`
    for (size_t position = 0; position < levels.size(); ++position) {
        const ListedLevel& listed = levels[position];
        const fs::path relative(listed.level.file);
        if (is_blank(listed.level.file) || relative.is_absolute()) continue; // already reported
        const fs::path full = folder / relative;
        std::error_code ec;
        if (fs::is_regular_file(full, ec)) {
            const fs::path real = fs::canonical(full, ec);
            if (ec) continue;
            // A position in `levels`, not the array index: entries that could not be read are not in it.
            auto [first, inserted] = first_file.emplace(real.string(), position);
            const ListedLevel& first_listed = levels[first->second];
            const std::string& first_spelling = first_listed.level.file;
            if (!inserted && fs::path(first_spelling).lexically_normal() != relative.lexically_normal())
                sink.error(member_path(element_path("levels", listed.index), "file"),
                           "level " + jsonio::quote_text(listed.level.file) + " is the same file as " +
                               element_path("levels", first_listed.index) + " (" +
                               jsonio::quote_text(first_spelling) + ")",
                           "a campaign plays each level once: remove one of them");
            continue;
        }
        std::string hint = "level files are relative to the campaign file's folder";
        const std::vector<std::string> beside =
            level_files_in(full.parent_path().empty() ? fs::path(".") : full.parent_path());
        if (std::string near = jsonio::closest_match(relative.filename().string(), beside); !near.empty())
            hint = "did you mean " + jsonio::quote_text((relative.parent_path() / near).generic_string()) +
                   "? " + hint;
        const std::string what = fs::is_directory(full, ec) ? "is a folder, not a level file" : "not found";
        sink.error(member_path(element_path("levels", listed.index), "file"),
                   "level file " + jsonio::quote_text(listed.level.file) + " " + what + " (looked for " +
                       full.string() + ")",
                   hint);
    }
}

// Reads the campaign's fields; what cannot be read is reported and left out.
Campaign read_campaign(const Json& document, const fs::path& folder, DiagnosticSink& sink) {
    Campaign campaign;
    jsonio::ObjectReader reader(document, "", sink, "campaign");
    std::optional<std::string> name;
    if (std::string text;
        reader.text("name", text, jsonio::Need::Required, 0, "the campaign's name, e.g. \"Killswitch\""))
        name = campaign.name = text;
    std::vector<ListedLevel> listed;
    bool list_empty = false;
    const Json* levels = reader.get("levels", jsonio::Need::Required, kExample);
    reader.finish();
    if (levels && !levels->is_array()) {
        sink.error("levels",
                   "expected the levels as an array [...], found " + jsonio::describe_value(*levels),
                   kExample);
    } else if (levels) {
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

} // namespace

Result<Campaign> load_campaign_string(std::string_view text, const std::string& file_name,
                                      const fs::path& folder) {
    const jsonio::Document document = jsonio::Document::parse(text, file_name, {"campaign", kExample});
    DiagnosticSink sink(file_name, &document.positions());
    document.report_to(sink);
    Campaign campaign;
    if (document.root()) campaign = read_campaign(*document.root(), folder, sink);
    const bool failed = sink.has_errors();
    std::vector<Diagnostic> diagnostics = sink.take_sorted();
    // Warnings (an unknown field) do not stop a campaign; they go to the log.
    for (const Diagnostic& d : diagnostics)
        if (d.severity == Diagnostic::Severity::Warning) log::warn(d.error.str());
    if (failed) return errors_of(std::move(diagnostics), file_name);
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
    if (sink.has_errors()) return errors_of(sink.take_sorted(), file.string());
    return files::write_atomic(file, save_campaign_string(campaign));
}

fs::path campaign_level_path(const fs::path& campaign_file, const CampaignLevel& level) {
    return campaign_file.parent_path() / fs::path(level.file);
}

} // namespace ks::level
