#include "version_label.h"

#include "core/version.h"
#include "menu_style.h"

#include <imgui.h>

#include <string>

namespace ks::runtime {

void version_label(const shell::Fonts& fonts, float w, float h) {
    const std::string text = "Killswitch " + std::string(version::number());
    ImFont* font = fonts.body ? fonts.body : ImGui::GetFont();
    const float size = font->FontSize;
    const ImVec2 extent = font->CalcTextSizeA(size, w, 0.0f, text.c_str());
    const float margin = 14.0f * ui::ui_scale(w, h);
    ImGui::GetBackgroundDrawList()->AddText(font, size, ImVec2(w - extent.x - margin, h - extent.y - margin),
                                            IM_COL32(200, 210, 222, 210), text.c_str());
}

} // namespace ks::runtime
