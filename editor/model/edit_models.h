#pragma once
// Placing a designer's model from the Models tab (ui/model_browser.h): a model entity naming the file, one
// undoable step. Tests: tests/editor/test_model_browser.cpp.
#include "model/editor.h"

#include <string>

namespace ks::editor {

// A model entity whose `file` is `file` (a name modelio::check_model_name accepts), at `position` snapped to
// the grid, turned by `yaw_degrees`, named after the file ("props/crate.glb": "crate"), with the default
// scale and collision; selects it and returns its id. An Error, and nothing placed, for a badly spelt name.
Result<int> place_model(Editor& editor, const std::string& file, Vec3 position, float yaw_degrees = 0.0f);

} // namespace ks::editor
