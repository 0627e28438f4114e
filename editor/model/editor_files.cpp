// Editor: New, Open, Save, Save As, title and dirty state, external-change detection, autosave recovery,
// and the validation panel's hooks.
#include "model/editor.h"
#include "model/patrol_validation.h"
#include "model/reachability.h"

#include <chrono>

#include "core/files.h"
#include "core/log.h"
#include "level/level_io.h"
#include "model/autosave.h"
#include "model/recent_files.h"

namespace ks::editor {
namespace fs = std::filesystem;

void Editor::replace_level(level::Level level, fs::path path) {
    doc_ = Document{std::move(level), {}, {}, {}, doc_.grid, 0};
    refresh_view_sets(doc_);
    history_.clear();
    path_ = std::move(path);
    disk_ = path_.empty() ? DiskFingerprint{} : fingerprint_file(path_);
    recovery_.reset();
    ++reloads_;
}

void Editor::new_document() {
    replace_level(level::Level{}, {});
}

void Editor::remember_recent(const fs::path& path) {
    if (!recent_) return;
    recent_->add(path);
    if (auto r = recent_->save(); !r) log::warn("could not save the recent files list: ", r.error().str());
}

Result<void> Editor::open(const fs::path& path) {
    auto text = files::read_text(path);
    if (!text) return text.error();
    level::LoadReport report;
    auto loaded = level::load_level_string(*text, path.string(), &report);
    if (!loaded) return loaded.error();
    for (const auto& d : report.diagnostics)
        if (d.severity == level::Diagnostic::Severity::Warning) log::warn(d.error.str());
    replace_level(std::move(*loaded), path);
    disk_ = fingerprint_text(*text, disk_.mtime);
    recovery_ = find_recovery(path);
    remember_recent(path);
    // Prefabs edited since the level was saved: its instances follow them now (one undoable step).
    if (std::any_of(doc_.level.editor.groups.begin(), doc_.level.editor.groups.end(),
                    [](const level::Group& g) { return g.has_prefab; }))
        if (auto updated = update_prefab_instances(); !updated)
            log::warn(path.string(), ": prefab instances not updated: ", updated.error().str());
    return ok();
}

Result<SaveReport> Editor::write_to(const fs::path& path) {
    const std::string text = level::save_level_string(doc_.level);
    if (auto r = files::write_atomic(path, text); !r) return r.error();
    std::error_code ec;
    disk_ = fingerprint_text(text, fs::last_write_time(path, ec));
    path_ = path;
    history_.mark_saved();
    ++reloads_; // the title changes even when the level did not
    SaveReport report{path, false, 0, 0};
    for (const auto& issue : issues()) {
        if (issue.severity == IssueSeverity::Error)
            ++report.error_count;
        else
            ++report.warning_count;
    }
    report.draft = report.error_count > 0;
    if (report.draft)
        log::warn(path.string(), ": saved as a draft with ", report.error_count,
                  " design error(s); see the validation panel");
    remember_recent(path);
    return report;
}

Result<SaveReport> Editor::save(const SaveOptions& options) {
    if (path_.empty())
        return Error("this level has no file yet", Location{}, "use Save As to choose where to save it");
    if (!options.overwrite_external_changes && disk_.exists) {
        DiskFingerprint now = fingerprint_file(path_);
        if (now.exists && !now.same_content(disk_))
            return Error("the file changed on disk since it was opened; saving would overwrite those changes",
                         Location{path_.string()},
                         "Save As to keep both, re-open to take the other version, or save with overwrite to "
                         "replace it");
    }
    return write_to(path_);
}

Result<SaveReport> Editor::save_as(const fs::path& path, const SaveOptions& options) {
    if (path.empty())
        return Error("Save As needs a file name", Location{}, "for example levels/my_level.json");
    std::error_code ec;
    const bool same_file =
        !path_.empty() && fs::weakly_canonical(path, ec) == fs::weakly_canonical(path_, ec);
    if (same_file) return save(options);
    if (fs::exists(path, ec) && !options.overwrite_existing)
        return Error("a file with this name already exists", Location{path.string()},
                     "choose another name, or confirm overwriting it");
    if (path.has_parent_path() && !fs::is_directory(path.parent_path(), ec))
        return Error("the folder does not exist", Location{path.parent_path().string()},
                     "create it first or pick another");
    return write_to(path);
}

std::string Editor::title() {
    std::string t = path_.empty() ? std::string("Untitled") : path_.filename().string();
    if (has_unsaved_changes()) t += "*";
    if (count_errors(issues()) > 0) t += " [draft]";
    return t + " - Killswitch Editor";
}

DiskStatus Editor::disk_status() const {
    if (path_.empty() || !disk_.exists) return DiskStatus::NoFile;
    DiskFingerprint now = fingerprint_file(path_);
    if (!now.exists) return DiskStatus::Deleted;
    return now.same_content(disk_) ? DiskStatus::Unchanged : DiskStatus::Modified;
}

Result<void> Editor::accept_recovery() {
    if (!recovery_) return Error("there is no autosave to recover");
    const RecoveryOffer offer = *recovery_;
    auto text = files::read_text(offer.autosave);
    if (!text) return text.error();
    auto loaded = level::load_level_string(*text, offer.autosave.string());
    if (!loaded) return loaded.error();
    // One undoable step that swaps the whole level: undo returns to the file as it is on disk.
    auto change = std::make_unique<LevelChange>();
    change->set_name("Recover autosave " + offer.autosave.filename().string());
    for (size_t i = 0; i < doc_.level.entities.size(); ++i)
        change->removals.push_back({i, doc_.level.entities[i]});
    for (size_t i = 0; i < loaded->entities.size(); ++i)
        change->insertions.push_back({i, loaded->entities[i]});
    change->level_name = Change<std::string>{doc_.level.name, loaded->name};
    change->settings = Change<level::Settings>{doc_.level.settings, loaded->settings};
    change->player_start = Change<level::PlayerStart>{doc_.level.player_start, loaded->player_start};
    change->next_id = Change<int>{doc_.level.next_id, loaded->next_id};
    change->level_links = Change<std::vector<level::Link>>{doc_.level.links, loaded->links};
    change->objectives = Change<std::vector<level::Objective>>{doc_.level.objectives, loaded->objectives};
    execute(std::move(change), {});
    recovery_.reset();
    return ok();
}

void Editor::poll_walk_job(bool wait) {
    if (!walk_job_.valid()) return;
    if (!wait && walk_job_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return;
    PanelReachability done = walk_job_.get();
    walk_issues_ = std::move(done.issues);
    walk_mesh_ = std::move(done.mesh);
    walk_fingerprint_ = walk_job_fingerprint_;
    walk_known_ = true;
    ++walk_results_;
}

void Editor::wait_for_reachability() {
    poll_walk_job(true);
}

const std::vector<Issue>& Editor::issues() {
    // During a drag (an open transaction) the walk check (a navigation mesh build: docs/performance.md)
    // waits for the commit; every other rule stays live. In the window it runs in the background.
    poll_walk_job(false);
    const bool dragging = history_.in_transaction();
    const std::uint64_t key =
        ((history_.revision() + reloads_ + (walk_results_ << 32) + (prefabs_.revision() << 48)) << 1) |
        (dragging ? 1u : 0u);
    if (issues_revision_ != key) {
        ValidationOptions options = validation_options_;
        options.check_reachability = false;
        issues_ = validate_design(doc_.level, options);
        check_prefab_instances(doc_.level, prefabs_, issues_);
        if (validation_options_.check_reachability && !dragging) {
            const std::uint64_t fingerprint = walk_fingerprint(doc_.level, validation_options_);
            const bool stale = !walk_known_ || fingerprint != walk_fingerprint_;
            if (stale && validation_options_.background_reachability) {
                if (!walk_job_.valid()) { // one at a time; a newer level is checked when this one ends
                    walk_job_fingerprint_ = fingerprint;
                    walk_job_ =
                        std::async(std::launch::async, [level = doc_.level, o = validation_options_]() {
                            return check_panel_reachability(level, o);
                        });
                    ++walk_checks_run_;
                }
            } else if (stale) {
                PanelReachability done = check_panel_reachability(doc_.level, validation_options_);
                walk_issues_ = std::move(done.issues);
                walk_mesh_ = std::move(done.mesh);
                walk_fingerprint_ = fingerprint;
                walk_known_ = true;
                ++walk_checks_run_;
            }
            issues_.insert(issues_.end(), walk_issues_.begin(), walk_issues_.end());
            // Robots move without changing the mesh: asked again on every validation, no rebuild.
            if (walk_mesh_) {
                check_robot_reach(doc_.level, *walk_mesh_, validation_options_, issues_);
                check_patrol_on_mesh(doc_.level, *walk_mesh_, validation_options_, issues_);
                check_trigger_reach(doc_.level, *walk_mesh_, validation_options_, issues_);
            }
        }
        issues_revision_ = key;
    }
    return issues_;
}

Result<void> Editor::select_issue(const Issue& issue) {
    if (issue.entity_id == 0) return issue.rule == Rule::PlayerStart ? select({kPlayerStartId}) : ok();
    return select({issue.entity_id});
}

} // namespace ks::editor
