#pragma once
// Where the widgets a real-input test clicks were drawn this frame (window pixels), by name: "link_add",
// "link0.event", "combo:on_exit" (an open combo's entries), ... The --status-file reports them
// (status_report.cpp); without one nothing is recorded.
#include "core/math.h"

#include <imgui.h>

#include <map>
#include <string>

namespace ks::editor::ui {

class UiSpots {
  public:
    bool enabled = false;
    void clear() { spots_.clear(); }
    // The centre of the last item ImGui drew. Not while its window appears: a popup's first frame only
    // measures it (hidden, and not yet where it will be).
    void here(const std::string& name) {
        if (!enabled || ImGui::IsWindowAppearing()) return;
        const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
        spots_[name] = Vec2((lo.x + hi.x) * 0.5f, (lo.y + hi.y) * 0.5f);
    }
    // A point inside the last item (one number of a vector widget).
    void set(const std::string& name, Vec2 at) {
        if (enabled && !ImGui::IsWindowAppearing()) spots_[name] = at;
    }
    const std::map<std::string, Vec2>& all() const { return spots_; }

  private:
    std::map<std::string, Vec2> spots_;
};

} // namespace ks::editor::ui
