#pragma once
// Draws what the HUD shows of the level's logic (game/level_logic.h) with ImGui: the objective list (the
// current objective highlighted, completed ones ticked), the message line (a message entity's text while it
// lasts) and a brief "Objective complete" banner when one completes. What to show and where is the model's
// (runtime/model/hud_presentation.h).
#include "game/game.h"
#include "runtime/model/hud_presentation.h"

struct ImDrawList;

namespace ks::shell {
struct Fonts;
}

namespace ks::runtime {

// The objective list (top right), the message line and the banner, over the world while playing.
void draw_logic_hud(ImDrawList* draw, const game::Game& game, const ObjectiveFlash& flash,
                    const shell::Fonts& fonts, float width, float height);

} // namespace ks::runtime
