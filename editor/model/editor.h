#pragma once
// The editor session: a document, its history, the clipboard and the file it belongs to. Every operation
// the UI offers (and the script language runs) is a method here that builds a command and executes it
// through History, so the ImGui front end only presents state and dispatches calls. Operations report
// problems as Result errors and change nothing when they fail.
#include "core/result.h"
#include "model/bounds.h"
#include "model/disk_fingerprint.h"
#include "model/field_access.h"
#include "model/groups.h"
#include "model/history.h"
#include "model/logic_edit.h"
#include "model/prefab_library.h"
#include "model/reachability.h"
#include "model/rotation.h"
#include "model/validation.h"

#include <filesystem>
#include <functional>
#include <future>
#include <optional>
#include <string>
#include <vector>

namespace ks::editor {

class RecentFiles;
class PrefabSync;

enum class SelectMode { Replace, Add, Toggle, Remove };

struct SaveOptions {
    bool overwrite_existing = false;         // Save As onto a file that exists (the UI asked first)
    bool overwrite_external_changes = false; // Save over a file someone changed since it was opened
};

struct SaveReport {
    std::filesystem::path path;
    bool draft = false; // saved with design errors: the level loads but should not ship
    int error_count = 0;
    int warning_count = 0;
};

struct RecoveryOffer {
    std::filesystem::path level_file;
    std::filesystem::path autosave; // newer than level_file and different from it
};

enum class DiskStatus { NoFile, Unchanged, Modified, Deleted };

class Editor {
  public:
    Editor();

    const Document& doc() const { return doc_; }
    const level::Level& level() const { return doc_.level; }
    const History& history() const { return history_; }
    // Bumps on every change to the level (edit, undo, redo, open, new); views cache against it.
    std::uint64_t revision() const { return history_.revision() + reloads_; }

    // ---- selection (view state: not history steps) ----
    // Unknown or locked ids are an error and leave the selection as it was.
    Result<void> select(const std::vector<int>& ids, SelectMode mode = SelectMode::Replace);
    // Tools: every visible, unlocked entity the predicate accepts (screen-space box select passes one).
    int select_where(const std::function<bool(const level::Entity&)>& accept,
                     SelectMode mode = SelectMode::Replace);
    int select_in_box(const geometry::Aabb& box, SelectMode mode = SelectMode::Replace);
    int select_all_of_type(level::EntityType type, SelectMode mode = SelectMode::Replace);
    int select_all();
    void clear_selection() { doc_.selection.clear(); }
    std::vector<const level::Entity*> selected_entities() const;

    // Hiding and locking one entity is saved in the level's editor section: one undoable step each. Locking
    // drops the entity from the selection. Unknown ids are an error.
    Result<void> set_hidden(int id, bool hidden);
    Result<void> set_locked(int id, bool locked);
    // What a click in the viewport selects (groups.h pick_unit): the entity's outermost group, or inside an
    // entered group its child group or the entity itself. A click outside the entered group leaves it.
    Result<void> select_picked(int entity_id, SelectMode mode = SelectMode::Replace);
    // Box select: every visible, unlocked entity the predicate accepts, each with what a click on it picks
    // (its whole group); returns how many entities were accepted.
    int select_picked_where(const std::function<bool(const level::Entity&)>& accept,
                            SelectMode mode = SelectMode::Replace);
    GridSettings& grid() { return doc_.grid; }

    // ---- edits (each one undoable step) ----
    // Snapped to the grid (origin) and rotation step; selects the new entity and returns its id.
    Result<int> place(level::EntityType type, Vec3 position, float yaw_degrees = 0.0f, std::string name = {});
    // With snap, the primary selected entity lands on the grid and the others keep their offsets to it.
    Result<void> move_selection(Vec3 delta, bool snap = false, std::string merge_key = {});
    // One grid step along axis 0/1/2 in direction +1/-1 (arrow keys).
    Result<void> nudge(int axis, int direction);
    // Yaw about the selection's pivot (the entity itself, or the centre of several); snapped to the rotation
    // step when the grid snaps. The same as rotate_selection_about(1, degrees, RotationSpace::World).
    Result<void> rotate_selection(float degrees, std::string merge_key = {});
    // A turn about axis 0 (x), 1 (y) or 2 (z) (editor_rotate.cpp, maths in rotation.h), snapped like
    // rotate_selection. World: the selection turns as one about its pivot (positions too); Local: each entity
    // turns in place about its own axis. About x or z only when every selected object keeps pitch and roll
    // (selection_turns_on_three_axes); the player start and the other types turn about y only.
    // `snap` false: the angle as given (a gizmo drag with Ctrl held), whatever the grid says.
    Result<void> rotate_selection_about(int axis, float degrees, RotationSpace space, bool snap = true,
                                        std::string merge_key = {});
    // Multiplies size fields along local x, y, z (types without size fields are left alone).
    Result<void> scale_selection(Vec3 factors, std::string merge_key = {});
    // On every selected entity that has the field (multi-selection edits common fields).
    Result<void> set_field(std::string_view name, const FieldValue& value, std::string merge_key = {});
    Result<void> set_field_text(std::string_view name, std::string_view text);
    Result<void> revert_field(std::string_view name);
    Result<void> rename(int id, std::string name);
    Result<void> duplicate(std::optional<Vec3> offset = std::nullopt); // default: one grid step in x and z
    Result<void> delete_selection();
    Result<void> delete_entities(const std::vector<int>& ids);
    std::string copy();                             // the selection as JSON text (also kept as the clipboard)
    Result<void> paste();                           // from the clipboard
    Result<void> paste_text(std::string_view text); // fresh ids; works with text from another level
    const std::string& clipboard() const { return clipboard_; }
    Result<void> set_setting(std::string_view name, const FieldValue& value, std::string merge_key = {});
    Result<void> set_setting_text(std::string_view name, std::string_view text);
    // Snapped to the grid; a drag of the inspector's fields passes a merge key (one step).
    Result<void> set_player_start(const level::PlayerStart& start, std::string merge_key = {});
    Result<void> rename_level(std::string name);

    // ---- robot patrols (editor_patrol.cpp; each one undoable step; the robot is named by id) ----
    // Adds after index `after` (at the end when none; -1 puts it first).
    Result<void> patrol_add(int id, Vec3 point, std::optional<int> after = std::nullopt);
    // A drag passes a merge key, so the whole drag is one step.
    Result<void> patrol_move(int id, int index, Vec3 point, std::string merge_key = {});
    // Removing the last point removes the patrol: the robot wanders again.
    Result<void> patrol_remove(int id, int index);
    Result<void> patrol_set_mode(int id, std::string_view mode);
    Result<void> patrol_set_wait(int id, float seconds, std::string merge_key = {});

    // ---- level logic (editor_logic.cpp; each one undoable step; see logic_edit.h) ----
    // Link and objective indices count from 0. A link's event must be one its owner emits, its action a
    // known one and its delay in 0 .. 3600 s; its target may name nothing yet (validation reports it).
    const std::vector<level::Link>* links_of(const LinkOwner& owner) const; // nullptr: no such owner
    Result<int> link_add(const LinkOwner& owner, level::Link link);         // returns the new index
    Result<void> link_set(const LinkOwner& owner, int index, level::Link link, std::string merge_key = {});
    Result<void> link_remove(const LinkOwner& owner, int index);
    Result<void> objective_add(level::Objective objective); // appended; id must be new & non-empty
    // Renaming the id re-targets the links that named it (complete links), in the same step.
    Result<void> objective_set(int index, level::Objective objective, std::string merge_key = {});
    Result<void> objective_remove(int index);
    Result<void> objective_move(int from, int to);
    // The objective every version-1 level had: "shutdown", completed by using any control panel (each panel
    // gets the on_use -> complete link); one undoable step. Fails when the level has no control panel.
    Result<void> add_shutdown_objective();
    // Name an entity so links can target it: a unique name from its type ("door_2") if it has none (or from
    // its name if another entity shares it); returns it. No step when it already has a unique name.
    Result<std::string> ensure_link_name(int entity_id);

    // ---- groups (editor_groups.cpp; each edit one undoable step) ----
    // Ctrl+G: the selection becomes one group (inside the entered group, if any). A group that is partly
    // selected joins whole. Returns the new group's id; its frame is the selection's centre at floor level.
    Result<int> group_selection(std::string name = {});
    // Ctrl+Shift+G: the groups the selection picks are dissolved (a prefab instance loses its link); their
    // members join the parent group.
    Result<void> ungroup_selection();
    // Double-click: the group's members become pickable one by one (view state, not a step).
    Result<void> enter_group(int group_id);
    void exit_group(); // one level up
    int open_group() const { return doc_.open_group; }
    Result<void> rename_group(int group_id, std::string name);
    // The groups the selection holds whole and that a click would pick (under the entered group).
    std::vector<int> selected_groups() const;

    // ---- layers (editor_layers.cpp; each edit one undoable step) ----
    // Layer 0 is "Default" and holds every entity no other layer lists; adding the first layer creates it.
    Result<int> layer_add(std::string name);
    Result<void> layer_rename(int index, std::string name);
    Result<void> layer_remove(int index); // not the Default layer; its entities go to Default
    Result<void> layer_set_visible(int index, bool visible);
    Result<void> layer_set_locked(int index, bool locked);
    Result<void> layer_set_active(int index); // where new entities go
    Result<void> move_selection_to_layer(int index);

    // ---- prefabs (editor_prefabs.cpp; see prefab.h) ----
    PrefabLibrary& prefabs() { return prefabs_; }
    const PrefabLibrary& prefabs() const { return prefabs_; }
    // The selection as prefabs/NAME.json (origin: the selection's centre at floor level, on the grid); the
    // selection becomes a linked instance of it (one step). Refuses a name in use unless `replace`.
    Result<std::filesystem::path> save_prefab(const std::string& name, std::string title = {},
                                              bool replace = false);
    // A linked instance with its origin at `position` (snapped) turned by `yaw`; selects it and returns
    // its group id. New names are made unique; links inside the prefab follow them.
    Result<int> place_prefab(const std::string& name, Vec3 position, float yaw_degrees = 0.0f);
    // The instance's members, as they are now, become the prefab (its file is rewritten); every instance
    // in the level follows (one step); the instance's overrides are cleared.
    Result<std::filesystem::path> apply_instance_to_prefab(int group_id);
    // Brings every instance in line with its prefab file (after a prefab changed on disk; open does it).
    // One step named after the prefabs when anything changed; returns how many entities changed.
    Result<int> update_prefab_instances();
    // Drops the instance's overrides (all, or one field of one member): they follow the prefab again.
    Result<void> revert_prefab_overrides(int group_id, int entity_id = 0, std::string field = {});
    // The instance becomes a plain group: it no longer follows its prefab.
    Result<void> unlink_prefab(int group_id);
    // The instance (group id) entity `entity_id` belongs to, or 0.
    int prefab_instance_of(int entity_id) const;

    bool undo();
    bool redo();
    // A drag or compound edit as one step.
    void begin_transaction(std::string name) { history_.begin_transaction(std::move(name)); }
    void commit_transaction() { history_.commit_transaction(); }
    void cancel_transaction() { history_.cancel_transaction(doc_); }
    void end_merging() { history_.seal(); }

    // ---- validation (cached per revision) ----
    const std::vector<Issue>& issues();
    ValidationOptions& validation_options() { return validation_options_; }
    size_t walk_checks_run() const { return walk_checks_run_; } // how often issues() ran the walk check
    // With background_reachability: whether a walk check is still running, and waiting for it (tests).
    bool reachability_pending() const { return walk_job_.valid(); }
    void wait_for_reachability();
    Result<void> apply_quick_fix(const Issue& issue);
    Result<void> select_issue(const Issue& issue);

    // ---- files ----
    void new_document();
    Result<void> open(const std::filesystem::path& path);
    Result<SaveReport> save(const SaveOptions& options = {});
    Result<SaveReport> save_as(const std::filesystem::path& path, const SaveOptions& options = {});
    const std::filesystem::path& file_path() const { return path_; }
    bool has_unsaved_changes() const { return !history_.at_save_point(); }
    // "main.json* [draft] - Killswitch Editor"
    std::string title();
    DiskStatus disk_status() const;
    void set_recent_files(RecentFiles* recent) { recent_ = recent; }

    // Offered after open when an autosave is newer than the file; accepting is one undoable step.
    const std::optional<RecoveryOffer>& recovery_offer() const { return recovery_; }
    // Start-up after a crash with an untitled level (see find_untitled_recovery).
    void offer_recovery(RecoveryOffer offer) { recovery_ = std::move(offer); }
    Result<void> accept_recovery();
    void decline_recovery() { recovery_.reset(); }

  private:
    // Builds one LevelChange updating every selected entity with `edit` and, when the player start is
    // selected and `start_edit` is given, the player start; nothing changes if any edit fails.
    using StartEdit = std::function<Result<void>(level::PlayerStart&)>;
    // `frame_edit` moves the frames of the groups the selection holds whole (a move or a turn).
    using FrameEdit = std::function<void(level::Group&)>;
    Result<void> modify_selection(std::string name, const std::function<Result<void>(level::Entity&)>& edit,
                                  std::string merge_key = {}, const StartEdit& start_edit = {},
                                  const FrameEdit& frame_edit = {});
    // The editor section after `change` (groups_edit.cpp): removed entities leave layers, groups and
    // instances; new ones join the active layer; edited prefab members record their overrides.
    void follow_structure(LevelChange& change) const;
    // Hiding/locking one entity (`list`: EditorData::hidden or ::locked) and a layer's visible/locked flag.
    Result<void> set_entity_flag(int id, std::vector<int> level::EditorData::*list, bool on,
                                 const char* what);
    Result<void> set_layer_flag(int index, bool level::Layer::*flag, bool value, const char* what);
    // One LevelChange replacing the editor section with `data` (no step when equal).
    void change_structure(std::string name, level::EditorData data, std::vector<int> selection_after);
    // One LevelChange updating robot `id`'s patrol with `edit`; nothing changes if it fails.
    Result<void> edit_patrol(int id, std::string name,
                             const std::function<Result<void>(level::Patrol&)>& edit,
                             std::string merge_key = {});
    // One LevelChange replacing `owner`'s links with `edit`'s result; nothing changes if it fails.
    Result<void> edit_links(const LinkOwner& owner, std::string name,
                            const std::function<Result<void>(std::vector<level::Link>&)>& edit,
                            std::string merge_key = {});
    // One LevelChange replacing the objectives with `edit`'s result (checked), links following `renames`.
    Result<void> edit_objectives(std::string name,
                                 const std::function<Result<void>(std::vector<level::Objective>&)>& edit,
                                 std::string merge_key = {}, const TargetRenames& renames = {});
    // Each kind of quick fix applied by its own specialization (quick_fix.cpp), one undo step named `name`.
    template <class Fix>
    Result<void> apply_fix(const Issue& issue, const std::string& name, const Fix& fix);
    // Executes through History; entity renames in `change` take the links and kill lists naming them along.
    void execute(std::unique_ptr<LevelChange> change, std::vector<int> selection_after);
    Result<SaveReport> write_to(const std::filesystem::path& path);
    void replace_level(level::Level level, std::filesystem::path path);
    void remember_recent(const std::filesystem::path& path);

    Document doc_;
    History history_;
    std::string clipboard_;
    std::filesystem::path path_;
    DiskFingerprint disk_;
    RecentFiles* recent_ = nullptr;
    std::optional<RecoveryOffer> recovery_;
    ValidationOptions validation_options_;
    std::vector<Issue> issues_;
    std::uint64_t issues_revision_ = ~0ull;
    // The walk check (most of a validation's time on a large level) is redone only when its inputs change.
    std::vector<Issue> walk_issues_;
    std::uint64_t walk_fingerprint_ = 0;
    bool walk_known_ = false;
    size_t walk_checks_run_ = 0;
    // The running background walk check and the fingerprint it answers for.
    std::future<PanelReachability> walk_job_;
    std::shared_ptr<nav::NavMesh> walk_mesh_; // the newest check's mesh: robots are asked of it every time
    std::uint64_t walk_job_fingerprint_ = 0;
    std::uint64_t walk_results_ = 0; // finished walk checks taken in: part of issues()' cache key
    void poll_walk_job(bool wait);
    std::uint64_t reloads_ = 0;
    PrefabLibrary prefabs_;
    // Prefab syncs (editor_prefabs.cpp): one step from a PrefabSync and the editor section it leaves; while
    // it runs, members change because their prefab did, so no overrides are recorded.
    struct SyncScope;
    friend struct SyncScope;
    bool syncing_prefabs_ = false;
    void execute_sync(std::string name, const PrefabSync& sync, level::EditorData data,
                      std::vector<int> selection_after);
};

} // namespace ks::editor
