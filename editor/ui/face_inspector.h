#pragma once
// The selected brush faces in the editor window: the inspector's Faces section (material from the texture
// browser, offset, scale and rotation numbers, Fit, Align to edge, Copy/Paste, the texture lock, Replace
// texture across the level), the Brush menu (CSG on the selected brushes: subtract, hollow with its
// thickness, merge, intersect, each greyed with the reason when it does not apply), and the status file's
// view of the face selection. The edits are edit_faces.h and edit_brushes.h; faces are picked with
// Ctrl+Shift+click in the viewport (view/face_picking.h).
#include "render/debug_draw.h"
#include "ui/inspector.h"

#include <nlohmann/json.hpp>

#include <memory>
#include <optional>

namespace ks::editor::ui {

// The Faces section of the inspector's Properties tab (one line in make_inspector_sections()).
std::unique_ptr<InspectorSection> make_face_section();

// The Brush menu of the menu bar; its hollow thickness is kept between frames, the grid step until the
// designer sets one (TrenchBroom's hollow takes the grid size: walls that stay on the grid).
class BrushMenu {
  public:
    void draw(const PanelContext& ctx);

  private:
    std::optional<float> thickness_;
};

// The selected faces outlined in the viewport (just off their planes), each with its texture's u axis as a
// line from the face's centre, so a turn or an alignment shows.
void draw_selected_faces(render::DebugDraw& draw, const Document& doc);

// The face selection for --status-file: each face's entity, index, material, offset, scale and rotation,
// and the texture lock.
nlohmann::json face_status(const Editor& editor);

} // namespace ks::editor::ui
