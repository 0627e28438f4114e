// The left column's Models tab (model_browser.h).
#include "ui/model_browser.h"

#include "render/level_scene.h"
#include "ui/thumbnail_camera.h"
#include "view/model_drop.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>

namespace ks::editor::ui {

namespace {
constexpr int kModelThumbnailSize = 92; // as the Prefabs tab's: two to a row at 1280 wide
constexpr double kModelRescanSeconds = 2.0;
constexpr int kThumbnailsPerFrame = 4;
} // namespace

void ModelBrowser::rescan(bool focused) {
    const double now = glfwGetTime();
    const bool regained = focused && !was_focused_;
    was_focused_ = focused;
    if (!regained && now - last_rescan_ < kModelRescanSeconds) return;
    last_rescan_ = now;
    library_.rescan();
}

const ModelThumbnail* ModelBrowser::thumbnail(const std::string& name) const {
    for (const auto& t : thumbnails_)
        if (t->name == name) return t.get();
    return nullptr;
}

void ModelBrowser::render_thumbnails(render::SceneRenderer& renderer, render::AssetLibrary& assets) {
    std::erase_if(thumbnails_, [&](const auto& t) {
        const ModelEntry* entry = library_.find(t->name);
        return !entry || entry->mtime != t->mtime;
    });
    int drawn = 0;
    render::LevelSceneOptions options = render::level_scene_options(renderer.settings());
    options.bake_light_map = false; // lit per vertex: no bake for 92 pixels
    std::vector<render::MeshInstance> instances;
    std::vector<render::Light> lights;
    for (const ModelEntry& entry : library_.entries()) {
        if (entry.shadowed || thumbnail(entry.name) || drawn == kThumbnailsPerFrame) continue;
        ++drawn;
        auto made = std::make_unique<ModelThumbnail>();
        made->name = entry.name;
        made->mtime = entry.mtime;
        level::Level level;
        level.add(level::EntityType::Model, Vec3(0.0f), entry.name).as<level::ModelProps>().file = entry.name;
        auto scene = render::LevelScene::build(level, assets, options);
        scene->emit(instances, lights);
        if (!render_thumbnail(renderer, made->target, kModelThumbnailSize, scene->bounds().min,
                              scene->bounds().max, scene->environment(), instances, lights))
            continue;
        thumbnails_.push_back(std::move(made));
    }
}

// The thumbnail just drawn as a drag-and-drop source: dragged onto the viewport, the model is placed where it
// is let go (LevelViewport::model_drop); the small picture and the name follow the mouse.
void ModelBrowser::drag_source(const ModelEntry& entry, const ModelThumbnail* t) const {
    if (!ImGui::BeginDragDropSource()) return;
    ImGui::SetDragDropPayload(kModelDragPayload, entry.name.c_str(), entry.name.size() + 1);
    if (t)
        ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(t->target.texture())),
                     ImVec2(48.0f, 48.0f), ImVec2(0, 1), ImVec2(1, 0));
    ImGui::TextUnformatted(entry.name.c_str());
    ImGui::EndDragDropSource();
}

std::optional<std::string> ModelBrowser::draw(const PanelContext& ctx, const std::string& armed_name) {
    std::optional<std::string> picked;
    ImGui::SetNextItemWidth(-1.0f);
    ImGui::InputTextWithHint("##model_search", "Search models...", search_, sizeof(search_));
    ctx.spots.here("models.search");
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
    ImGui::TextWrapped("Drag one onto the viewport, or click it, then click there (Shift: several)");
    ImGui::PopStyleColor();
    const std::vector<const ModelEntry*> shown = library_.search(search_);
    if (library_.entries().empty()) {
        ImGui::TextWrapped("No models. Export a .glb into your models folder (docs/models.md).");
        return picked;
    }
    if (shown.empty()) ImGui::TextWrapped("No model matches \"%s\".", search_);
    ImGui::BeginChild("model_cells");
    const float cell = static_cast<float>(kModelThumbnailSize) + 4.0f;
    const float spacing = ImGui::GetStyle().ItemSpacing.x;
    const int columns =
        std::max(1, static_cast<int>((ImGui::GetContentRegionAvail().x + spacing) / (cell + spacing)));
    int column = 0;
    for (const ModelEntry* entry : shown) {
        if (entry->shadowed) continue;
        ImGui::PushID(entry->name.c_str());
        if (column > 0) ImGui::SameLine();
        ImGui::BeginGroup();
        const bool armed = armed_name == entry->name;
        if (armed) ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.25f, 0.55f, 0.3f, 1));
        const ImVec2 size(static_cast<float>(kModelThumbnailSize), static_cast<float>(kModelThumbnailSize));
        bool clicked = false;
        const ModelThumbnail* t = thumbnail(entry->name);
        if (t)
            clicked =
                ImGui::ImageButton(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(t->target.texture())),
                                   size, ImVec2(0, 1), ImVec2(1, 0), 2);
        else
            clicked = ImGui::Button("...", ImVec2(size.x + 4, size.y + 4));
        drag_source(*entry, t);
        if (armed) ImGui::PopStyleColor();
        ctx.spots.here("model:" + entry->name);
        if (clicked) picked = entry->name;
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip(
                "%s\n%s (%s)\nDrag it onto the viewport, or click it, then click in the viewport to "
                "place it; Shift+click places several.",
                entry->name.c_str(), entry->path.string().c_str(),
                entry->shipped ? "shipped" : "your models folder");
        thumbnail_label(entry->name.substr(entry->name.rfind('/') + 1), cell, armed);
        ImGui::EndGroup();
        column = (column + 1) % columns;
        ImGui::PopID();
    }
    ImGui::EndChild();
    return picked;
}

} // namespace ks::editor::ui
