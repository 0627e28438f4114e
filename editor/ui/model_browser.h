#pragma once
// The left column's Models tab (model_browser.cpp): every model file of the shipped and the designer's
// models folders (model/model_library.h) with a rendered thumbnail and a search box; a click arms placing it
// (the place tool puts a model entity on the surface under the next viewport click, one undo step), and a
// thumbnail dragged onto the viewport places it where it is let go (view/model_drop.h, one undo step). The
// folders are rescanned (file times only) every two seconds and when the window regains focus: a file added,
// removed or exported again shows, and the level viewport draws the new file (models_revision()).
#include "model/model_library.h"
#include "render/asset_library.h"
#include "render/scene_renderer.h"
#include "ui/panel_context.h"
#include "ui/render_target.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ks::editor::ui {

// A model's thumbnail: the model alone, rendered offscreen from a three-quarter view.
struct ModelThumbnail {
    std::string name;
    std::filesystem::file_time_type mtime{};
    RenderTarget target;
};

class ModelBrowser {
  public:
    ModelBrowser() : library_(ModelLibrary::with_default_folders()) {}

    void rescan(bool window_focused);
    // Render pass: the thumbnails missing or out of date, a few per frame (a model's first import is slow).
    void render_thumbnails(render::SceneRenderer& renderer, render::AssetLibrary& assets);
    // The tab; returns the model clicked this frame (to be placed). `armed`: the model being placed.
    std::optional<std::string> draw(const PanelContext& ctx, const std::string& armed);
    const ModelLibrary& library() const { return library_; }
    // Bumps when a model file changed on disk: the level viewport rebuilds its scene against it.
    std::uint64_t models_revision() const { return library_.revision(); }

  private:
    const ModelThumbnail* thumbnail(const std::string& name) const;
    void drag_source(const ModelEntry& entry, const ModelThumbnail* t) const;

    ModelLibrary library_;
    std::vector<std::unique_ptr<ModelThumbnail>> thumbnails_;
    char search_[128] = {};
    double last_rescan_ = -1e9;
    bool was_focused_ = true;
};

} // namespace ks::editor::ui
