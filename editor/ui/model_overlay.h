#pragma once
// The level viewport's collision overlay for a selected model entity (docs/models.md): the edges of the box,
// hull or triangle mesh the game collides with (model/model_collision_wire.h) in a colour of their own. The
// wire is made again only when the level or the selection changed (a hull costs Qhull milliseconds).
#include "model/editor.h"
#include "model/model_collision_wire.h"
#include "render/debug_draw.h"

#include <cstdint>
#include <vector>

namespace ks::editor::ui {

class ModelCollisionOverlay {
  public:
    void draw(render::DebugDraw& debug, const Editor& editor);

  private:
    std::uint64_t revision_ = ~0ull;
    std::vector<int> selection_;
    std::vector<CollisionWire> wires_;
};

} // namespace ks::editor::ui
