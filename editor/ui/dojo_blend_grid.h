#pragma once
// The Blends page: the default blend time and a grid of every from -> to blend time, coloured by where it
// comes from (set for the pair, a * pair, the default); dragging or typing a cell sets the pair, right-click
// clears it, and selecting a cell plays that transition in the tester. Each change is one undo step through
// model/dojo_clips.h (a drag is one step).
#include "model/dojo_clips.h"
#include "ui/dojo_context.h"

#include <vector>

namespace ks::editor::ui {

class DojoBlendGrid {
  public:
    void draw(const DojoContext& dojo);
    // Selects a cell and plays its transition in the tester (--dojo-view blend=FROM>TO).
    void select(const DojoContext& dojo, int from, int to);
    int from() const { return from_; }
    int to() const { return to_; }
    // Status: each cell's centre as last drawn, row-major.
    const std::vector<Vec2>& centres() const { return centres_; }

  private:
    void cell(const DojoContext& dojo, std::size_t from, std::size_t to, const BlendCell& cell, float width);
    void details(const DojoContext& dojo, const BlendGrid& grid);

    int from_ = -1, to_ = -1; // the selected cell
    std::vector<Vec2> centres_;
};

} // namespace ks::editor::ui
