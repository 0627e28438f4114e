#pragma once
// Help > About: a modal box with the editor's version, what it is and its licence (view/about_text.h).
#include "ui/ui_spots.h"

#include <nlohmann/json_fwd.hpp>

namespace ks::editor::ui {

class AboutBox {
  public:
    // The menu bar's Help menu (call between BeginMainMenuBar and EndMainMenuBar). `spots` records where its
    // title ("menu.help"), its item ("menu.about") and the box's Close button ("about.close") were drawn.
    void menu(UiSpots& spots);
    // The box itself, once a frame after the menu bar.
    void draw(UiSpots& spots);
    // {"open": bool, "lines": [...]} for --status-file.
    nlohmann::json status() const;

  private:
    bool requested_ = false;
    bool open_ = false;
};

} // namespace ks::editor::ui
