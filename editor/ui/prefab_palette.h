#pragma once
// The left column's Prefabs tab (prefab_palette.cpp): every prefab of the library with a rendered
// thumbnail, its title and entity count (a broken file shows its error); a click arms placing it. It also
// keeps the library fresh: rescanned (file times only) every two seconds and when the window regains focus.
#include "model/editor.h"
#include "render/asset_library.h"
#include "render/scene_renderer.h"
#include "ui/panel_context.h"
#include "ui/render_target.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ks::editor::ui {

// A prefab's thumbnail: its entities rendered offscreen from a three-quarter view.
struct PrefabThumbnail {
    std::string name;
    RenderTarget target;
    bool drawn = false;
};

class PrefabPalette {
  public:
    // Rescans the library when due; instances in the level follow a prefab file changed on disk.
    void rescan(Editor& editor, EditorLog& log, bool window_focused);
    // Render pass: one small target per prefab, drawn again only when the library changed.
    void render_thumbnails(const PrefabLibrary& library, render::SceneRenderer& renderer,
                           render::AssetLibrary& assets);
    // The tab; returns the prefab clicked this frame (to be placed). `armed`: the prefab being placed.
    std::optional<std::string> draw(const PanelContext& ctx, const std::string& armed);
    size_t thumbnail_count() const { return thumbnails_.size(); }

  private:
    std::vector<std::unique_ptr<PrefabThumbnail>> thumbnails_;
    std::uint64_t thumbnails_revision_ = ~0ull;
    double last_rescan_ = -1e9;
    bool was_focused_ = true;
};

} // namespace ks::editor::ui
