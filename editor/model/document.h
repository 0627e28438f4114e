#pragma once
// The document an editor session edits: the level itself (with its editor section: layers, groups, prefab
// instances, entities hidden and locked one by one, all saved in the file) plus view state around it
// (selection, the selected brush faces, the entered group, grid). Only commands change `level`; the selection
// and the entered group are not saved and not history steps.
#include "level/level.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <vector>

namespace ks::editor {

struct GridSettings {
    float step = 1.0f;           // origin snapping and nudge distance, units
    float rotation_step = 15.0f; // degrees
    bool snap = true;

    float snap_value(float v) const { return snap && step > 0 ? std::round(v / step) * step : v; }
    Vec3 snap_point(const Vec3& p) const { return {snap_value(p.x), snap_value(p.y), snap_value(p.z)}; }
    float snap_angle(float degrees) const {
        return snap && rotation_step > 0 ? std::round(degrees / rotation_step) * rotation_step : degrees;
    }
};

// A sorted set of entity ids (small: a handful to a few hundred).
class IdSet {
  public:
    bool contains(int id) const { return std::binary_search(ids_.begin(), ids_.end(), id); }
    void insert(int id) {
        auto it = std::lower_bound(ids_.begin(), ids_.end(), id);
        if (it == ids_.end() || *it != id) ids_.insert(it, id);
    }
    void erase(int id) {
        auto it = std::lower_bound(ids_.begin(), ids_.end(), id);
        if (it != ids_.end() && *it == id) ids_.erase(it);
    }
    void clear() { ids_.clear(); }
    bool empty() const { return ids_.empty(); }
    size_t size() const { return ids_.size(); }
    const std::vector<int>& ids() const { return ids_; }
    bool operator==(const IdSet&) const = default;

  private:
    std::vector<int> ids_;
};

// The player start in a selection: it is picked, moved and turned like an entity, under an id no entity has
// (entity ids start at 1). It has no level::Entity, so selected_entities() leaves it out.
inline constexpr int kPlayerStartId = -1;

// A selected face of a brush entity: its index in the brush's faces (in the entity's frame) and that face's
// plane there, by which it is found again when an edit or an undo reorders or replaces the faces
// (edit_faces.h follow_face_selection).
struct FaceRef {
    int entity = 0;
    int face = 0;
    brush::Plane plane;
    bool operator==(const FaceRef& other) const { return entity == other.entity && face == other.face; }
};

struct Document {
    level::Level level;
    // Selection in the order entities were picked (the first is the primary: gizmo pivot, inspector header);
    // it may hold kPlayerStartId.
    std::vector<int> selection;
    // What tools must not show or touch: the entities hidden or locked one by one or through their layer
    // (refresh_view_sets in groups.h derives both from level.editor after every change).
    IdSet hidden;
    IdSet locked;
    GridSettings grid;
    // The group entered by a double-click (0: none): clicks pick its members one by one (groups.h pick_unit).
    int open_group = 0;
    // The selected brush faces (edit_faces.h), in the order they were picked (the first is the primary: its
    // attributes are the ones shown and copied). Independent of `selection`; not saved, not history steps.
    std::vector<FaceRef> faces;

    bool is_selected(int id) const {
        return std::find(selection.begin(), selection.end(), id) != selection.end();
    }
    bool player_start_selected() const { return is_selected(kPlayerStartId); }
    // Tools may pick and edit it: it exists and is not locked.
    bool is_editable(int id) const { return level.find(id) != nullptr && !locked.contains(id); }
    int index_of(int id) const {
        for (size_t i = 0; i < level.entities.size(); ++i)
            if (level.entities[i].id == id) return static_cast<int>(i);
        return -1;
    }
};

} // namespace ks::editor
