#pragma once
// The level checks' messages under the link, objective or kill name they are about: errors red, design
// warnings yellow, the fix as the tooltip.
#include "ui/panel_style.h"
#include "view/link_problems.h"

#include <imgui.h>

#include <vector>

namespace ks::editor::ui {

inline void problem_lines(const std::vector<const LogicProblem*>& problems) {
    for (const LogicProblem* p : problems) {
        ImGui::PushStyleColor(ImGuiCol_Text, p->error ? kErrorColour : kWarningColour);
        ImGui::TextWrapped("%s", p->message.c_str());
        ImGui::PopStyleColor();
        if (!p->hint.empty() && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", p->hint.c_str());
    }
}

} // namespace ks::editor::ui
