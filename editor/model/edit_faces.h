#pragma once
// Brush faces one by one: the face selection (entity id + face index, found again by its plane after edits
// and undo), and the texturing edits on the selected faces, each one undoable step: material, offset,
// scale, rotation (set or adjusted), fit (the texture once across the face), align to an edge (u along a
// face edge, starting at its first corner), copy/paste of attributes, and replacing a texture across the
// level. Texture lock: with it on, moving or turning a brush entity keeps its textures fixed on the world
// (Editor::modify_selection calls keep_textures_on_world); off, they travel with the brush.
//
// Numbers are the face's stored attributes, in the entity's frame (brush/texture_mapping.h says how they
// map): offset in texture units, scale in world units per texture unit (one texture unit is the image
// once), rotation in degrees, kept in (-180, 180]. Refusals name the entity and the face and change
// nothing. Tests: tests/editor/test_edit_faces.cpp.
#include "model/edit_selection.h"
#include "model/editor.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace ks::editor {

// A scale smaller than this (world units per texture repeat) is refused: the texture would repeat more
// than a thousand times a unit, which only a typing slip asks for; fit refuses faces narrower than it.
inline constexpr double kMinTextureScale = 1e-3;
inline constexpr double kMaxTextureScale = 1e5;
// An edge shorter than this has no reliable direction to align to.
inline constexpr double kMinAlignEdge = 1e-6;

// ---- the face selection ----
// Selects face `face` of brush entity `entity` (Replace, Add, Toggle or Remove). Refused for a missing,
// locked or non-brush entity and a face index out of range, naming how many faces the brush has.
Result<void> select_face(Editor& editor, int entity, int face, SelectMode mode = SelectMode::Replace);
// Every face of the selected brush entities (TrenchBroom's "select faces of the selected brushes").
Result<void> select_faces_of_selection(Editor& editor);
void clear_face_selection(Editor& editor);
// The face of a brush entity whose world normal points most along `direction` (scripts: `face select 12
// +y` is the top); refused for a non-brush or a zero direction.
Result<int> face_facing(const level::Entity& entity, const DVec3& direction);
// After every change (execute, undo, redo): each selected face is found again by its plane (its index
// may have moved); faces whose entity or plane is gone leave the selection.
void follow_face_selection(Document& doc);

// A selected face as it is now: its entity, its index and its face (plane and attributes, entity frame).
struct SelectedFace {
    const level::Entity* entity = nullptr;
    int index = 0;
    brush::Face face;
};
std::vector<SelectedFace> selected_faces(const Document& doc);

// ---- attribute edits on every selected face ----
// What every edit below does: each selected face's attributes changed by `edit` (given its entity, its
// brush in the entity's frame and its index) as one step named `name`, refused whole when an edit refuses
// one face; no step when nothing changes. Only attributes change, so the brushes are not derived again.
// A drag passes `merge_key` so the whole drag is one step (the texture drag: face_drag.h).
using FaceAttributeEdit =
    std::function<Result<void>(const level::Entity&, const brush::Brush&, int, brush::FaceAttributes&)>;
Result<void> edit_selected_faces(Editor& editor, const std::string& name, const FaceAttributeEdit& edit,
                                 std::string merge_key = {});

Result<void> set_face_material(Editor& editor, const std::string& material);
Result<void> set_face_offset(Editor& editor, glm::dvec2 offset, std::string merge_key = {});
Result<void> shift_face_offset(Editor& editor, glm::dvec2 delta, std::string merge_key = {});
Result<void> set_face_scale(Editor& editor, glm::dvec2 scale, std::string merge_key = {});
Result<void> set_face_rotation(Editor& editor, double degrees, std::string merge_key = {});
Result<void> turn_face_texture(Editor& editor, double delta_degrees, std::string merge_key = {});
// The texture `repeats` times across each face along u and v (1, 1: once), starting at the face's corner
// lowest in u and v; rotation kept, a flipped (negative) scale stays flipped.
Result<void> fit_face_texture(Editor& editor, glm::dvec2 repeats = glm::dvec2(1.0));
// Each face's texture u axis along its edge `edge` (from corner `edge` to the next, counter-clockwise seen
// from outside), the texture origin on that corner.
Result<void> align_face_texture_to_edge(Editor& editor, int edge);
// Copy: the primary selected face's attributes (Editor::face_session().copied). Paste: onto every selected
// face, material and mapping.
Result<void> copy_face_attributes(Editor& editor);
Result<void> paste_face_attributes(Editor& editor);

// Every brush face of material `from` and every texture field (walls, floors, stairs) naming it takes `to`,
// in unlocked entities, as one step; returns how many faces and fields changed. Refused when nothing uses
// `from`, or `to` is empty or the same.
Result<int> replace_texture(Editor& editor, const std::string& from, const std::string& to);

// ---- texture lock ----
void set_texture_lock(Editor& editor, bool on);
// When `after` is a brush entity whose position or rotation differs from `before`'s, its faces' attributes
// change so that each face's texture stays where it was on the world (a turned face projects the same
// world mapping onto its new plane); anything else is left as it is.
Result<void> keep_textures_on_world(const level::Entity& before, level::Entity& after);

} // namespace ks::editor
