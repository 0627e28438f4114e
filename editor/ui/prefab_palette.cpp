// The left column's Prefabs tab: every prefab of the library (Editor::prefabs(): the shipped prefabs/ and
// the designer's own folder) with a rendered thumbnail, its title and entity count; a broken file shows
// its error in red. Clicking one arms placing it: the next viewport click places a linked instance
// (Shift keeps placing). The library is rescanned (file times only) every two seconds and when the window
// regains focus; thumbnails are rendered offscreen in the render pass, again only when the library's
// revision changes.
#include "ui/prefab_palette.h"
#include "model/edit_prefabs.h"

#include "model/bounds.h"
#include "render/level_scene.h"
#include "ui/panel_style.h"
#include "ui/thumbnail_camera.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace ks::editor::ui {

namespace {
constexpr int kThumbnailSize = 92; // two to a row in the narrowest left column (1280 wide)
constexpr double kRescanSeconds = 2.0;
} // namespace

void PrefabPalette::rescan(Editor& editor, EditorLog& log, bool focused) {
    const double now = glfwGetTime();
    const bool regained = focused && !was_focused_;
    was_focused_ = focused;
    if (!regained && now - last_rescan_ < kRescanSeconds) return;
    last_rescan_ = now;
    if (!editor.prefabs().rescan() || editor.history().in_transaction()) return;
    // A prefab file changed on disk (another editor applied an instance, an edit by hand): the instances in
    // this level follow it at once, as opening the level would, in one step that undo takes back.
    auto updated = update_prefab_instances(editor);
    if (!updated)
        log.line("prefab instances not updated: " + updated.error().str(), true);
    else if (*updated > 0)
        log.line("a prefab changed on disk: " + std::to_string(*updated) +
                 " entities of its instances follow it (" + editor.history().undo_name() +
                 "; undo keeps the old)");
}

void PrefabPalette::render_thumbnails(const PrefabLibrary& library, render::SceneRenderer& renderer,
                                      render::AssetLibrary& assets) {
    if (thumbnails_revision_ == library.revision()) return;
    thumbnails_revision_ = library.revision();
    std::vector<std::unique_ptr<PrefabThumbnail>> kept;
    render::LevelSceneOptions options = render::level_scene_options(renderer.settings());
    options.bake_light_map = false; // a thumbnail is lit per vertex: no bake for 96 pixels
    std::vector<render::MeshInstance> instances;
    std::vector<render::Light> lights;
    renderer.invalidate_shadows(); // the cached shadow map is the level's
    for (const PrefabEntry& entry : library.entries()) {
        if (!entry.prefab || entry.prefab->entities.empty()) continue;
        auto thumbnail = std::make_unique<PrefabThumbnail>();
        for (auto& old : thumbnails_)
            if (old && old->name == entry.name) thumbnail = std::move(old); // reuse its target
        thumbnail->name = entry.name;
        level::Level level;
        level.entities = entry.prefab->entities;
        const geometry::Aabb box = selection_bounds(level.entities);
        const Vec3 lo = box.min, hi = box.max;
        auto scene = render::LevelScene::build(level, assets, options);
        scene->emit(instances, lights);
        // A prefab without lights of its own is lit by a lamp over the camera's shoulder.
        if (!render_thumbnail(renderer, thumbnail->target, kThumbnailSize, lo, hi, scene->environment(),
                              instances, lights))
            continue;
        thumbnail->drawn = true;
        kept.push_back(std::move(thumbnail));
    }
    thumbnails_ = std::move(kept);
}

std::optional<std::string> PrefabPalette::draw(const PanelContext& ctx, const std::string& armed_name) {
    const PrefabLibrary& library = ctx.editor.prefabs();
    std::optional<std::string> picked;
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
    ImGui::TextWrapped("Click one, then click in the viewport (Shift: several)");
    ImGui::PopStyleColor();
    if (library.entries().empty()) {
        ImGui::TextWrapped("No prefabs yet. Select some entities and use Edit > Save selection as prefab...");
        return picked;
    }
    ImGui::BeginChild("prefab_cells");
    const float cell = static_cast<float>(kThumbnailSize) + 4.0f;
    const float width = ImGui::GetContentRegionAvail().x;
    const float spacing = ImGui::GetStyle().ItemSpacing.x;
    const int columns = std::max(1, static_cast<int>((width + spacing) / (cell + spacing)));
    int column = 0;
    // The prefabs that load first, in a grid; then each broken file, its name and error across the column.
    for (const PrefabEntry& entry : library.entries()) {
        if (!entry.prefab) continue;
        ImGui::PushID(entry.name.c_str());
        if (column > 0) ImGui::SameLine();
        ImGui::BeginGroup();
        const bool armed = armed_name == entry.name;
        const PrefabThumbnail* thumbnail = nullptr;
        for (const auto& t : thumbnails_)
            if (t->name == entry.name && t->drawn) thumbnail = t.get();
        if (armed) ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.25f, 0.55f, 0.3f, 1));
        const ImVec2 size(static_cast<float>(kThumbnailSize), static_cast<float>(kThumbnailSize));
        bool clicked = false;
        if (thumbnail)
            clicked = ImGui::ImageButton(
                reinterpret_cast<ImTextureID>(static_cast<intptr_t>(thumbnail->target.texture())), size,
                ImVec2(0, 1), ImVec2(1, 0), 2);
        else
            clicked = ImGui::Button("...", ImVec2(size.x + 4, size.y + 4));
        if (armed) ImGui::PopStyleColor();
        ctx.spots.here("prefab:" + entry.name);
        if (clicked) picked = entry.name;
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("%s\n%s  (%zu entities)\n%s\nClick, then click in the viewport to place a "
                              "linked instance; Shift+click places several.",
                              entry.prefab->title.empty() ? entry.name.c_str() : entry.prefab->title.c_str(),
                              entry.name.c_str(), entry.prefab->entities.size(), entry.path.string().c_str());
        thumbnail_label(entry.name, cell, armed);
        ImGui::EndGroup();
        column = (column + 1) % columns;
        ImGui::PopID();
    }
    for (const PrefabEntry& entry : library.entries()) {
        if (entry.prefab) continue;
        ImGui::Separator();
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 0.45f, 0.4f, 1));
        ImGui::TextWrapped("%s: %s", entry.path.filename().string().c_str(),
                           entry.prefab.error().str().c_str());
        ImGui::PopStyleColor();
        ctx.spots.here("prefab:" + entry.name);
    }
    ImGui::EndChild();
    return picked;
}

} // namespace ks::editor::ui
