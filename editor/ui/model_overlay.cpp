#include "ui/model_overlay.h"

namespace ks::editor::ui {

namespace {
// Cyan: apart from the selection box (orange) and the trigger/brush colours.
const Vec4 kCollisionColour(0.3f, 0.95f, 1.0f, 0.9f);
constexpr std::size_t kMaxOverlaidModels = 16; // a box selection of a whole level draws no overlay storm
} // namespace

void ModelCollisionOverlay::draw(render::DebugDraw& debug, const Editor& editor) {
    if (editor.revision() != revision_ || editor.doc().selection != selection_) {
        revision_ = editor.revision();
        selection_ = editor.doc().selection;
        wires_.clear();
        for (int id : selection_) {
            const level::Entity* e = editor.level().find(id);
            if (!e || e->type() != level::EntityType::Model) continue;
            if (wires_.size() == kMaxOverlaidModels) break;
            if (Result<CollisionWire> wire = model_collision_wire(*e)) wires_.push_back(std::move(*wire));
        }
    }
    for (const CollisionWire& wire : wires_)
        for (const auto& segment : wire.segments) debug.line(segment[0], segment[1], kCollisionColour);
}

} // namespace ks::editor::ui
