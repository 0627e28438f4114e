#include "model/campaign_add.h"

#include "core/paths.h"
#include "level/campaign.h"
#include "model/validation.h"

#include <system_error>

namespace ks::editor {

namespace fs = std::filesystem;

namespace {

// The same file however it is spelled ("levels/../levels/x.json", a link): compared canonically where it
// exists, lexically where it does not.
fs::path canonical_or_normal(const fs::path& path) {
    std::error_code ec;
    fs::path canonical = fs::weakly_canonical(fs::absolute(path, ec), ec);
    return ec ? fs::absolute(path).lexically_normal() : canonical;
}

Error refuse(const fs::path& about, std::string message, std::string fix) {
    return Error(std::move(message), Location(about.string()), std::move(fix));
}

} // namespace

fs::path default_campaign_file() {
    return paths::level("campaign.json");
}

Result<CampaignAddReport> add_to_campaign(Editor& editor, const fs::path& campaign_file, std::string title) {
    if (editor.file_path().empty())
        return refuse({}, "the level is untitled: a campaign lists level files",
                      "save it first (File > Save As...), then add it to the campaign");
    if (editor.has_unsaved_changes())
        return refuse(
            editor.file_path(),
            "the level has unsaved changes: the campaign would play the file on disk, not what you see",
            "save it first (File > Save, Ctrl+S), then add it to the campaign");
    if (campaign_file.empty())
        return refuse({}, "no campaign file given", "name one, like " + default_campaign_file().string());
    if (editor.validation().reachability_pending()) editor.validation().wait_for_reachability();
    if (const int errors = count_errors(editor.issues()); errors > 0)
        return refuse(editor.file_path(),
                      "the level has " + std::to_string(errors) + " design error(s) and should not ship",
                      "fix them in the Validation panel, save, then add it to the campaign");
    if (title.empty()) title = editor.level().name;
    if (title.empty()) title = editor.file_path().stem().string();

    CampaignAddReport report;
    report.campaign_file = campaign_file;
    level::Campaign campaign;
    std::error_code ec;
    if (fs::exists(campaign_file, ec)) {
        auto loaded = level::load_campaign(campaign_file);
        if (!loaded) return loaded.error();
        campaign = std::move(*loaded);
    } else {
        campaign.name = campaign_file.stem().string();
        report.created = true;
    }

    const fs::path level_path = canonical_or_normal(editor.file_path());
    for (size_t i = 0; i < campaign.levels.size(); ++i) {
        const level::CampaignLevel& listed = campaign.levels[i];
        if (canonical_or_normal(level::campaign_level_path(campaign_file, listed)) == level_path)
            return refuse(campaign_file,
                          "\"" + editor.file_path().filename().string() + "\" is already in " +
                              campaign_file.string() + ", as level " + std::to_string(i + 1) + " (\"" +
                              listed.title + "\")",
                          "a campaign plays each level once; edit the campaign file to reorder it");
    }

    const fs::path folder = canonical_or_normal(campaign_file).parent_path();
    report.file = level_path.lexically_relative(folder).generic_string();
    if (report.file.empty())
        return refuse(campaign_file, "the level's path cannot be written relative to " + folder.string(),
                      "keep the level and the campaign file on the same drive");
    report.title = std::move(title);
    campaign.levels.push_back({report.file, report.title});
    if (auto saved = level::save_campaign(campaign, campaign_file); !saved) return saved.error();
    report.position = static_cast<int>(campaign.levels.size());
    return report;
}

} // namespace ks::editor
