// The player start as a viewport object: its figure (view/player_start_marker.h) drawn over the level. Its
// row at the top of the outliner is in outliner_tree.cpp, its inspector section in inspector_sections.cpp.
// It is selected, moved and turned like an entity (kPlayerStartId in the selection); every change is an
// Editor edit.
#include "level/entity_shapes.h"
#include "ui/editor_app.h"

namespace ks::editor::ui {
namespace {
const Vec4 kStartColour(0.3f, 1.0f, 0.4f, 1.0f);
const Vec4 kStartSelected(1.0f, 0.62f, 0.1f, 1.0f); // the selection's orange
} // namespace

void EditorApp::draw_player_start() {
    if (!overlays_.player_start) return;
    marker_lines_.clear();
    player_start_figure(editor_.level().player_start, marker_lines_);
    const Vec4 colour = editor_.doc().player_start_selected() ? kStartSelected : kStartColour;
    for (const MarkerLine& line : marker_lines_) debug_.line(line.a, line.b, colour);
}

} // namespace ks::editor::ui
