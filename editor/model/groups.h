#pragma once
// Questions about the level's groups and layers (level/editor_data.h), window-free: which group holds an
// entity, every entity of a group and its children, what a click picks while a group is entered, which
// layer an entity is in, and the entities a document hides and locks (one by one, or through a layer).
// The edits that change groups and layers are free functions in edit_groups.h and edit_layers.h.
#include "core/math.h"
#include "level/editor_data.h"

#include <nlohmann/json.hpp>

#include <unordered_map>
#include <vector>

namespace ks::editor {

struct Document;

// The group that lists entity `entity_id` among its own members (0: none).
int parent_group_of_entity(const level::EditorData& data, int entity_id);
// The group that lists group `group_id` among its children (0: a top-level group).
int parent_group_of_group(const level::EditorData& data, int group_id);
// `group_id` and its ancestors, innermost first.
std::vector<int> group_ancestry(const level::EditorData& data, int group_id);
// Whether `group_id` is `ancestor` or lies inside it.
bool group_within(const level::EditorData& data, int group_id, int ancestor);
// The entities of a group and of every group inside it, sorted.
std::vector<int> group_entities_deep(const level::EditorData& data, int group_id);

// What a click on entity `entity_id` picks while group `open_group` is entered (0: none): the outermost
// group holding the entity that lies inside `open_group` (a group id), or 0 when the entity is a direct
// member of `open_group` (or of no group), so the entity itself is picked. A click outside the entered
// group picks as if no group were entered.
int pick_unit(const level::EditorData& data, int open_group, int entity_id);
// The entities a click on `entity_id` selects: its picked group's entities, or the entity alone.
std::vector<int> pick_unit_entities(const level::EditorData& data, int open_group, int entity_id);

// The groups every one of whose entities (and whose children's) is in `ids` (sorted), outermost first;
// only groups with at least one entity count. Moving or turning `ids` moves or turns these groups' frames.
std::vector<int> groups_wholly_in(const level::EditorData& data, const std::vector<int>& sorted_ids);

// After entities were copied (`copies`: old id -> new id) and moved by `offset`: the groups the originals
// filled wholly are copied too (new ids, prefab links kept), beside their originals; a copy of a member of
// a group that was not copied whole joins that group (unless it is a prefab instance); every copy joins
// its original's layer.
void copy_structure(level::EditorData& data, const std::unordered_map<int, int>& copies, Vec3 offset);

// Copy and paste (the clipboard's "editor" key): the groups the selection holds whole, as the level file
// writes its editor section (null when there are none); and those groups pasted into `data` with fresh
// ids, their entities renumbered by `pasted` (clipboard id -> new id), inside `open_group` when it is a
// plain group. Prefab instances stay linked to their prefab.
nlohmann::json copied_structure(const Document& doc);
void paste_structure(level::EditorData& data, const nlohmann::json& copied,
                     const std::unordered_map<int, int>& pasted, int open_group);

// A sorted id list with `id` in it (once).
void insert_sorted(std::vector<int>& ids, int id);
// Groups left with no entities and no child groups go (each also leaves its parent's list), until none is
// left empty; a prefab instance all of whose members were deleted is such a group.
void prune_empty_groups(level::EditorData& data);

// The index of the layer entity `entity_id` is in (0: the Default layer, also when there are no layers).
int layer_of(const level::EditorData& data, int entity_id);
// Entity id -> layer index for every entity some layer > 0 lists (the rest are in layer 0).
std::unordered_map<int, int> layer_table(const level::EditorData& data);

// Recomputes the document's hidden and locked sets from its level's editor section: the entities hidden or
// locked one by one plus every entity of an invisible or locked layer. Called after every change (commands,
// undo, redo, open), so the tools read one set and never ask about layers.
void refresh_view_sets(Document& doc);

} // namespace ks::editor
