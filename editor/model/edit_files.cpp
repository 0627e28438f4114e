// The document's file: edit_files.h.
#include "model/edit_files.h"

#include "core/files.h"
#include "core/log.h"
#include "level/level_io.h"
#include "model/autosave.h"
#include "model/edit_prefabs.h"

namespace ks::editor {
namespace fs = std::filesystem;

void new_document(Editor& editor) {
    editor.replace_level(level::Level{}, {}, {});
}

Result<void> open(Editor& editor, const fs::path& path) {
    const Document& doc = editor.doc();
    auto text = files::read_text(path);
    if (!text) return text.error();
    level::LoadReport report;
    auto loaded = level::load_level_string(*text, path.string(), &report);
    if (!loaded) return loaded.error();
    for (const auto& d : report.diagnostics)
        if (d.severity == level::Diagnostic::Severity::Warning) log::warn(d.error.str());
    editor.replace_level(std::move(*loaded), path, fingerprint_text(*text, fingerprint_file(path).mtime));
    if (auto offer = find_recovery(path)) editor.offer_recovery(std::move(*offer));
    editor.remember_recent(path);
    // Prefabs edited since the level was saved: its instances follow them now (one undoable step).
    if (std::any_of(doc.level.editor.groups.begin(), doc.level.editor.groups.end(),
                    [](const level::Group& g) { return g.has_prefab; }))
        if (auto updated = update_prefab_instances(editor); !updated)
            log::warn(path.string(), ": prefab instances not updated: ", updated.error().str());
    return ok();
}

namespace {
Result<SaveReport> write_to(Editor& editor, const fs::path& path) {
    const Document& doc = editor.doc();
    const std::string text = level::save_level_string(doc.level);
    if (auto r = files::write_atomic(path, text); !r) return r.error();
    std::error_code ec;
    editor.mark_saved(path, fingerprint_text(text, fs::last_write_time(path, ec)));
    SaveReport report{path, false, 0, 0};
    for (const auto& issue : editor.issues()) {
        if (issue.severity == IssueSeverity::Error)
            ++report.error_count;
        else
            ++report.warning_count;
    }
    report.draft = report.error_count > 0;
    if (report.draft)
        log::warn(path.string(), ": saved as a draft with ", report.error_count,
                  " design error(s); see the validation panel");
    editor.remember_recent(path);
    return report;
}
} // namespace

Result<SaveReport> save(Editor& editor, const SaveOptions& options) {
    if (editor.file_path().empty())
        return Error("this level has no file yet", Location{}, "use Save As to choose where to save it");
    if (!options.overwrite_external_changes && editor.disk().exists) {
        DiskFingerprint now = fingerprint_file(editor.file_path());
        if (now.exists && !now.same_content(editor.disk()))
            return Error("the file changed on disk since it was opened; saving would overwrite those changes",
                         Location{editor.file_path().string()},
                         "Save As to keep both, re-open to take the other version, or save with overwrite to "
                         "replace it");
    }
    return write_to(editor, editor.file_path());
}

Result<SaveReport> save_as(Editor& editor, const fs::path& path, const SaveOptions& options) {
    if (path.empty())
        return Error("Save As needs a file name", Location{}, "for example levels/my_level.json");
    std::error_code ec;
    const bool same_file = !editor.file_path().empty() &&
                           fs::weakly_canonical(path, ec) == fs::weakly_canonical(editor.file_path(), ec);
    if (same_file) return save(editor, options);
    if (fs::exists(path, ec) && !options.overwrite_existing)
        return Error("a file with this name already exists", Location{path.string()},
                     "choose another name, or confirm overwriting it");
    if (path.has_parent_path() && !fs::is_directory(path.parent_path(), ec))
        return Error("the folder does not exist", Location{path.parent_path().string()},
                     "create it first or pick another");
    return write_to(editor, path);
}

std::string title(Editor& editor) {
    std::string t =
        editor.file_path().empty() ? std::string("Untitled") : editor.file_path().filename().string();
    if (editor.has_unsaved_changes()) t += "*";
    if (count_errors(editor.issues()) > 0) t += " [draft]";
    return t + " - Killswitch Editor";
}

DiskStatus disk_status(const Editor& editor) {
    if (editor.file_path().empty() || !editor.disk().exists) return DiskStatus::NoFile;
    DiskFingerprint now = fingerprint_file(editor.file_path());
    if (!now.exists) return DiskStatus::Deleted;
    return now.same_content(editor.disk()) ? DiskStatus::Unchanged : DiskStatus::Modified;
}

Result<void> accept_recovery(Editor& editor) {
    const Document& doc = editor.doc();
    if (!editor.recovery_offer()) return Error("there is no autosave to recover");
    const RecoveryOffer offer = *editor.recovery_offer();
    auto text = files::read_text(offer.autosave);
    if (!text) return text.error();
    auto loaded = level::load_level_string(*text, offer.autosave.string());
    if (!loaded) return loaded.error();
    // One undoable step that swaps the whole level: undo returns to the file as it is on disk.
    auto change = std::make_unique<LevelChange>();
    change->set_name("Recover autosave " + offer.autosave.filename().string());
    for (size_t i = 0; i < doc.level.entities.size(); ++i)
        change->removals.push_back({i, doc.level.entities[i]});
    for (size_t i = 0; i < loaded->entities.size(); ++i)
        change->insertions.push_back({i, loaded->entities[i]});
    change->level_name = Change<std::string>{doc.level.name, loaded->name};
    change->settings = Change<level::Settings>{doc.level.settings, loaded->settings};
    change->player_start = Change<level::PlayerStart>{doc.level.player_start, loaded->player_start};
    change->next_id = Change<int>{doc.level.next_id, loaded->next_id};
    change->level_links = Change<std::vector<level::Link>>{doc.level.links, loaded->links};
    change->objectives = Change<std::vector<level::Objective>>{doc.level.objectives, loaded->objectives};
    editor.execute(std::move(change), {});
    editor.decline_recovery();
    return ok();
}

} // namespace ks::editor
