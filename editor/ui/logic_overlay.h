#pragma once
// The level logic in the viewport (logic_overlay.cpp): markers for the logic entities the game does not draw
// (render pass) and, over the picture, trigger fills and the link arrows between entities (ImGui pass). Its
// state is the arrows and their labels, kept until the level, the selection or what is shown changes.
#include "level/level.h"
#include "model/editor.h"
#include "render/debug_draw.h"
#include "view/link_arrows.h"
#include "view/logic_markers.h"
#include "view/view_camera.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

struct ImDrawList;

namespace ks::editor::ui {

class LogicOverlay {
  public:
    using Shown = std::function<bool(const level::Entity&)>; // not hidden (and ceilings only when shown)

    // Render pass: a trigger's box, a spawner's ring and post, a message's bubble; other types draw nothing.
    void draw_marker(render::DebugDraw& debug, const ViewCamera& view, const level::Entity& e, bool selected);
    // ImGui pass over the view whose picture starts at `origin`; `ceilings` is part of what is shown.
    void draw(ImDrawList* draw, Vec2 origin, const ViewCamera& view, const Editor& editor, bool links,
              bool ceilings, const Shown& shown);
    std::size_t arrow_count() const { return link_arrows_.size(); }

  private:
    void update_link_arrows(const Editor& editor, bool ceilings, const Shown& shown);

    std::vector<MarkerLine> marker_lines_;  // a marker's or an arrow's lines, reused every frame
    std::vector<LinkArrow> link_arrows_;    // cached until the level, the selection or what is shown changes
    std::vector<std::string> arrow_labels_; // each arrow's labels, one per line
    std::uint64_t arrows_key_ = ~0ull;
    std::vector<int> arrows_selection_;
};

} // namespace ks::editor::ui
