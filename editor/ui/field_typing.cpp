#include "ui/field_typing.h"

#include <imgui_internal.h>

#include <cmath>
#include <limits>

namespace ks::editor::ui {

bool TypedEdit::typing_now() {
    const ImGuiContext& g = *ImGui::GetCurrentContext();
    return g.ActiveId != 0 && g.TempInputId == g.ActiveId;
}

bool TypedEdit::filter(ImGuiID widget, const std::vector<int>& target, bool changed, FieldValue& value) {
    const ImGuiContext& g = *ImGui::GetCurrentContext();
    const int frame = ImGui::GetFrameCount();
    auto found = typed_.find(widget);
    if (found != typed_.end() && found->second.frame < frame - 1) { // not drawn for a while: forgotten
        typed_.erase(found);
        found = typed_.end();
    }
    if (ImGui::IsItemActive() && typing_now()) {
        Typed& typed = typed_[widget];
        // Tab from one of a vector's numbers to the next: the first one's text is finished.
        const bool moved_on = typed.has_value && typed.component != g.ActiveId && typed.target == target;
        const FieldValue finished = typed.value;
        if (typed.component != g.ActiveId) typed.has_value = false;
        typed.component = g.ActiveId;
        typed.target = target;
        typed.frame = frame;
        if (changed) typed.value = value, typed.has_value = true;
        if (moved_on) value = finished;
        return moved_on;
    }
    if (found == typed_.end()) return changed; // a drag, or a click on a check box
    const Typed typed = std::move(found->second);
    typed_.erase(found);
    const bool commit = typed.has_value && typed.target == target &&
                        !ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false);
    if (commit) value = typed.value;
    return commit;
}

float float_at_least(double min) {
    const auto f = static_cast<float>(min);
    return static_cast<double>(f) < min ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

float float_at_most(double max) {
    const auto f = static_cast<float>(max);
    return static_cast<double>(f) > max ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}

void typing_hint(const FieldDescriptor& field) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
    if (field.min > -1e6 || field.max < 1e6)
        ImGui::TextWrapped("Enter or Tab sets it, Esc cancels (%g .. %g %s)", field.min, field.max,
                           field.unit.c_str());
    else
        ImGui::TextWrapped("Enter or Tab sets it, Esc cancels");
    ImGui::PopStyleColor();
}

} // namespace ks::editor::ui
