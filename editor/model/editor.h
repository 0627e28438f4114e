#pragma once
// The editor session's core: a document, its history, the clipboard, the file it belongs to and the cached
// validation. Its public edit API (execute, modify_selection, change_structure, execute_prefab_sync) is
// what every operation goes through; the operations themselves are free functions, one header per concern
// (edit_selection.h, edit_transforms.h, edit_entities.h, edit_patrols.h, edit_logic.h, edit_groups.h,
// edit_layers.h, edit_prefabs.h, edit_files.h, quick_fix.h), so the ImGui front end and the script
// language call the same functions. Operations report problems as Result errors and change nothing when
// they fail.
#include "core/result.h"
#include "model/disk_fingerprint.h"
#include "model/history.h"
#include "model/prefab_library.h"
#include "model/validation_cache.h"

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace ks::editor {

class RecentFiles;

// The face tools' session state (edit_faces.h): the attributes Copy took, and whether moving or turning a
// brush keeps its textures fixed on the world (off: they travel with the brush, as the file stores them).
struct FaceSession {
    std::optional<brush::FaceAttributes> copied;
    bool texture_lock = false;
};
class PrefabSync;

struct RecoveryOffer {
    std::filesystem::path level_file;
    std::filesystem::path autosave; // newer than level_file and different from it
};

class Editor {
  public:
    Editor();

    const Document& doc() const { return doc_; }
    const level::Level& level() const { return doc_.level; }
    const History& history() const { return history_; }
    // Bumps on every change to the level (edit, undo, redo, open, new); views cache against it.
    std::uint64_t revision() const { return history_.revision() + reloads_; }
    GridSettings& grid() { return doc_.grid; }

    // ---- view state (not history steps) ----
    void set_selection(std::vector<int> ids) { doc_.selection = std::move(ids); }
    void clear_selection() { doc_.selection.clear(); }
    // The group entered by a double-click (0: none).
    int open_group() const { return doc_.open_group; }
    void set_open_group(int group_id) { doc_.open_group = group_id; }
    void set_face_selection(std::vector<FaceRef> faces) { doc_.faces = std::move(faces); }
    FaceSession& face_session() { return face_session_; }
    const FaceSession& face_session() const { return face_session_; }

    // ---- the edit API the operations use (each call one undoable step) ----
    // Executes through History; entity renames in `change` take the links and kill lists naming them
    // along, and the editor section follows (follow_structure).
    void execute(std::unique_ptr<LevelChange> change, std::vector<int> selection_after);
    // Builds one LevelChange updating every selected entity with `edit` and, when the player start is
    // selected and `start_edit` is given, the player start; nothing changes if any edit fails.
    using EntityEdit = std::function<Result<void>(level::Entity&)>;
    using StartEdit = std::function<Result<void>(level::PlayerStart&)>;
    // `frame_edit` moves the frames of the groups the selection holds whole (a move or a turn).
    using FrameEdit = std::function<void(level::Group&)>;
    Result<void> modify_selection(std::string name, const EntityEdit& edit, std::string merge_key = {},
                                  const StartEdit& start_edit = {}, const FrameEdit& frame_edit = {});
    // One LevelChange replacing the editor section with `data` (no step when equal).
    void change_structure(std::string name, level::EditorData data, std::vector<int> selection_after);
    // One step from a PrefabSync and the editor section it leaves; members change because their prefab did,
    // so no overrides are recorded.
    void execute_prefab_sync(std::string name, const PrefabSync& sync, level::EditorData data,
                             std::vector<int> selection_after);

    bool undo();
    bool redo();
    // A drag or compound edit as one step.
    void begin_transaction(std::string name) { history_.begin_transaction(std::move(name)); }
    void commit_transaction() { history_.commit_transaction(); }
    void cancel_transaction();
    void end_merging() { history_.seal(); }

    // The selection as JSON text (edit_entities.h copy) and where paste reads it.
    const std::string& clipboard() const { return clipboard_; }
    void set_clipboard(std::string text) { clipboard_ = std::move(text); }

    PrefabLibrary& prefabs() { return prefabs_; }
    const PrefabLibrary& prefabs() const { return prefabs_; }

    // ---- validation (cached per revision; see validation_cache.h) ----
    const std::vector<Issue>& issues();
    ValidationOptions& validation_options() { return validation_.options(); }
    ValidationCache& validation() { return validation_; }
    const ValidationCache& validation() const { return validation_; }

    // ---- the file (opening and saving: edit_files.h) ----
    const std::filesystem::path& file_path() const { return path_; }
    // What the file looked like when it was last read or written.
    const DiskFingerprint& disk() const { return disk_; }
    bool has_unsaved_changes() const { return !history_.at_save_point(); }
    // A new document: `level` from `path` (empty: untitled) as `disk` holds it; no history, no offer.
    void replace_level(level::Level level, std::filesystem::path path, DiskFingerprint disk);
    // The level was written to `path`, which now holds `disk`: the save point.
    void mark_saved(std::filesystem::path path, DiskFingerprint disk);
    void set_recent_files(RecentFiles* recent) { recent_ = recent; }
    void remember_recent(const std::filesystem::path& path);
    // Offered after open when an autosave is newer than the file; accepting is one undoable step.
    const std::optional<RecoveryOffer>& recovery_offer() const { return recovery_; }
    // Start-up after a crash with an untitled level (see find_untitled_recovery).
    void offer_recovery(RecoveryOffer offer) { recovery_ = std::move(offer); }
    void decline_recovery() { recovery_.reset(); }

  private:
    // The editor section after `change` (edit_groups.cpp): removed entities leave layers, groups and
    // instances; new ones join the active layer; edited prefab members record their overrides.
    void follow_structure(LevelChange& change) const;

    Document doc_;
    History history_;
    std::string clipboard_;
    std::filesystem::path path_;
    DiskFingerprint disk_;
    RecentFiles* recent_ = nullptr;
    std::optional<RecoveryOffer> recovery_;
    ValidationCache validation_;
    std::uint64_t reloads_ = 0;
    PrefabLibrary prefabs_;
    FaceSession face_session_;
    bool syncing_prefabs_ = false; // while a prefab sync runs: follow_structure records no overrides
};

} // namespace ks::editor
