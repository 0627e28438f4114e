#pragma once
// The level checks' messages under the link, objective or kill name they are about: errors red, design
// warnings yellow, the fix as the tooltip.
#include "view/link_problems.h"

#include <imgui.h>

#include <vector>

namespace ks::editor::ui {

inline void problem_lines(const std::vector<const LogicProblem*>& problems) {
    for (const LogicProblem* p : problems) {
        ImGui::PushStyleColor(ImGuiCol_Text,
                              p->error ? ImVec4(1.0f, 0.4f, 0.35f, 1.0f) : ImVec4(1.0f, 0.8f, 0.3f, 1.0f));
        ImGui::TextWrapped("%s", p->message.c_str());
        ImGui::PopStyleColor();
        if (!p->hint.empty() && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", p->hint.c_str());
    }
}

} // namespace ks::editor::ui
