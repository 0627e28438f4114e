#pragma once
// The viewport's place tool (place_tool.cpp): armed by a click in the entity palette (place_palette.h) or the
// Prefabs tab (prefab_palette.h) or the Models tab (model_browser.h), it shows where a click would place
// (every view) and places there: one entity of the type, or the prefab's entities. Shift keeps it armed for
// several. A Models tab thumbnail dragged over a view shows its box the same way, armed or not
// (preview_drop; the viewport places it when it is let go, view/model_drop.h).
#include "ui/viewport_tool.h"

#include <optional>
#include <string>

namespace ks::editor::ui {

class PlaceTool final : public ViewportTool {
  public:
    void arm(level::EntityType type) { disarm(), type_ = type; }
    void arm_prefab(std::string name) { disarm(), prefab_ = std::move(name); }
    void arm_model(std::string file) { disarm(), model_ = std::move(file); } // the Models tab's
    const std::string& model() const { return model_; }
    const std::optional<level::EntityType>& type() const { return type_; } // the palette's armed button
    const std::string& prefab() const { return prefab_; }                  // the Prefabs tab's armed row

    bool armed() const override { return type_.has_value() || !prefab_.empty() || !model_.empty(); }
    void input(const ToolInput& in) override;
    void draw_lines(render::DebugDraw& debug, const ToolView& view) const override;
    std::string hint() const override;
    void disarm() override { type_.reset(), prefab_.clear(), model_.clear(); }
    void status(nlohmann::json& status) const override; // "placing", "placing_prefab"

    // A model file dragged from the Models tab over a view this frame, with the mouse's ray in that view:
    // draw_lines draws the box where it would land. The viewport ends it at the start of each frame.
    void preview_drop(std::string file, const geometry::Ray& ray) {
        drop_file_ = std::move(file), drop_ray_ = ray;
    }
    void end_drop_preview() { drop_file_.clear(), drop_ray_.reset(); }
    const std::string& dropping() const { return drop_file_; }

  private:
    std::string label() const; // the type's name or "prefab NAME"

    std::optional<level::EntityType> type_;
    std::string prefab_;    // a prefab's name
    std::string model_;     // a model file's name (level::ModelProps::file)
    std::string drop_file_; // a model being dragged over a view ("" when none)
    std::optional<geometry::Ray> drop_ray_;
};

} // namespace ks::editor::ui
