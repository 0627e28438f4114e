#pragma once
// The palette over the left column (place_palette.cpp): a button per entity type that arms placing it; the
// next viewport click places one. Where each button was drawn goes to the status file.
#include "core/math.h"
#include "level/level.h"

#include <nlohmann/json_fwd.hpp>

#include <array>
#include <optional>

namespace ks::editor::ui {

class PlacePalette {
  public:
    struct ScreenRect {
        Vec2 min{0.0f}, max{0.0f};
    };
    // The type clicked this frame, if any; `armed`: the type being placed (highlighted).
    std::optional<level::EntityType> draw(std::optional<level::EntityType> armed);
    const ScreenRect& rect(level::EntityType type) const { return rects_[static_cast<size_t>(type)]; }
    void status(nlohmann::json& status) const; // "palette": each drawn button's centre, by type name

  private:
    std::array<ScreenRect, static_cast<size_t>(level::EntityType::Count)> rects_{};
};

} // namespace ks::editor::ui
