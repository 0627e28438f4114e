#pragma once
// Placing a model file from the Models tab where the mouse is in a view, window-free: by a click after
// arming it (ui/place_tool.h) or by dragging its thumbnail onto the view and letting go (ImGui drag and drop;
// ui/model_browser.cpp is the source, the viewport's picture the target). Both place through place_model
// (model/edit_models.h): one entity, one undo step. Tests: tests/editor/test_model_browser.cpp.
#include "model/editor.h"
#include "view/picking.h"

#include <optional>
#include <string>

namespace ks::editor {

// The ImGui drag-and-drop payload type of a model file dragged from the Models tab (at most 32 characters,
// ImGui's limit); the payload is the file's name (level::ModelProps::file) with its terminating zero.
inline constexpr const char* kModelDragPayload = "ks_model_file";

// The file name a model payload carries: the bytes up to the terminating zero, which must be the last of
// `size` bytes. nullopt for anything else (no data, no zero, a zero inside, over 4096 bytes).
std::optional<std::string> model_payload_file(const void* data, int size);

// Where the model lands: the surface `ray` meets first (place_point: floors, stairs, walls, else the ground
// plane, else the plane through `fallback`), as a model entity stands on it (placement_for).
Vec3 model_drop_point(const Document& doc, const geometry::Ray& ray, const ShownFn& shown,
                      const Vec3& fallback);

// place_model at model_drop_point: the model entity, selected, one undo step; an Error and nothing placed
// for a badly spelt name.
Result<int> place_model_at(Editor& editor, const std::string& file, const geometry::Ray& ray,
                           const ShownFn& shown, const Vec3& fallback);

} // namespace ks::editor
