#pragma once
// The panels along the bottom and under the inspector, each drawn in the rectangle the window gives it:
// the history (click a step to jump there), the log, and the validation list (click a finding to select
// what it is about; quick fixes). The play-test report panel is analysis_panel.cpp.
#include "ui/layout.h"
#include "ui/panel_context.h"

#include <cstdint>

namespace ks::editor::ui {

class DojoPanel;

// The level's history, or in the Dojo tab the clip file's (its own undo steps: dojo_panel.h).
class HistoryPanel {
  public:
    void draw(Editor& editor, const Rect& rect);
    void draw(DojoPanel& dojo, const Rect& rect);
};

class LogPanel {
  public:
    void draw(EditorLog& log, const Rect& rect);

  private:
    std::uint64_t shown_revision_ = 0; // the log's revision last scrolled to: new lines scroll to the end
};

class ValidationPanel {
  public:
    void draw(const PanelContext& ctx, const Rect& rect);
};

} // namespace ks::editor::ui
