// The texture browser window (texture_browser.h) and the inspector's texture field: a thumbnail button that
// opens the browser beside a text field for typing the name.
#include "ui/texture_browser.h"

#include "level/texture_names.h"
#include "ui/editor_app.h"
#include "view/texture_search.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

namespace ks::editor::ui {
namespace {
constexpr int kColumns = 3;
const ImVec4 kCurrentColour(1.0f, 0.62f, 0.1f, 1.0f);

bool known_texture(const std::string& name) {
    const auto& known = level::shipped_texture_names();
    return std::find(known.begin(), known.end(), name) != known.end();
}
} // namespace

void TextureBrowser::open(std::string query) {
    open_ = true;
    focus_search_ = true;
    std::snprintf(search_, sizeof search_, "%s", query.c_str());
}

ImTextureID TextureBrowser::thumbnail(render::AssetLibrary& assets, const std::string& name) {
    if (!known_texture(name)) return nullptr;
    const render::Texture& texture = assets.textures().get(
        assets.root() / "textures" / (name + "_basecolor.png"), render::ColorSpace::Srgb);
    return reinterpret_cast<ImTextureID>(static_cast<intptr_t>(texture.id));
}

namespace {
float cell_width() {
    const ImGuiStyle& style = ImGui::GetStyle();
    return kTextureThumbnail + style.FramePadding.x * 2 + style.ItemSpacing.x;
}
} // namespace

float TextureBrowser::width() {
    return cell_width() * kColumns + ImGui::GetStyle().WindowPadding.x * 2;
}

std::optional<std::string> TextureBrowser::draw(render::AssetLibrary& assets, const std::string& current,
                                                Vec2 position, UiSpots& spots) {
    if (!open_) return std::nullopt;
    const ImGuiStyle& style = ImGui::GetStyle();
    const float cell = cell_width();
    ImGui::SetNextWindowPos(ImVec2(position.x, position.y), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(width(), 0), ImGuiCond_Always); // 0: the height fits the rows
    bool keep_open = true;
    std::optional<std::string> picked;
    if (!ImGui::Begin("Textures###texture_browser", nullptr,
                      ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
                          ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove)) {
        ImGui::End();
        open_ = keep_open;
        return std::nullopt;
    }
    ImGui::SetNextItemWidth(-1);
    if (focus_search_) ImGui::SetKeyboardFocusHere(), focus_search_ = false;
    ImGui::InputTextWithHint("##texture_search", "Search textures...", search_, sizeof search_);
    spots.here("texture_search");
    query_ = search_;
    shown_ = texture_matches(level::shipped_texture_names(), query_);
    if (shown_.empty()) ImGui::TextDisabled("No surface material matches \"%s\"", search_);
    for (size_t i = 0; i < shown_.size(); ++i) {
        const std::string& name = shown_[i];
        ImGui::PushID(name.c_str());
        if (i % kColumns != 0) ImGui::SameLine();
        ImGui::BeginGroup();
        const bool is_current = name == current;
        ImGui::PushStyleColor(ImGuiCol_Button,
                              is_current ? ImVec4(0.55f, 0.35f, 0.08f, 1.0f) : style.Colors[ImGuiCol_Button]);
        if (ImGui::ImageButton(thumbnail(assets, name), ImVec2(kTextureThumbnail, kTextureThumbnail)))
            picked = name;
        ImGui::PopStyleColor();
        spots.here("texture:" + name);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s: click to use it", name.c_str());
        const float text_w = ImGui::CalcTextSize(name.c_str()).x;
        ImGui::SetCursorPosX(ImGui::GetCursorPosX() +
                             std::max(0.0f, (cell - style.ItemSpacing.x - text_w) * 0.5f));
        if (is_current)
            ImGui::TextColored(kCurrentColour, "%s", name.c_str());
        else
            ImGui::TextUnformatted(name.c_str());
        ImGui::EndGroup();
        ImGui::PopID();
    }
    ImGui::Separator();
    ImGui::AlignTextToFramePadding();
    ImGui::TextDisabled("%zu of %zu materials", shown_.size(), level::shipped_texture_names().size());
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("The surface materials in assets/textures");
    ImGui::SameLine(ImGui::GetWindowContentRegionMax().x - ImGui::CalcTextSize("Close").x -
                    style.FramePadding.x * 2);
    // Esc closes it too (editor_app.cpp, handle_shortcuts).
    if (ImGui::Button("Close")) keep_open = false;
    spots.here("texture_close");
    ImGui::End();
    open_ = keep_open;
    return picked;
}

} // namespace ks::editor::ui
