#pragma once
// The texture browser: a window of thumbnails (each surface material's base colour) with a search box, for
// the selection's texture field. A click on a thumbnail picks that material (the caller makes the edit); the
// window stays open so several can be tried, and closes with its button, Esc, or when the selection has no
// texture field any more. The names are level::shipped_texture_names(), the one list the checks use.
#include "render/asset_library.h"
#include "ui/ui_spots.h"

#include <optional>
#include <string>
#include <vector>

namespace ks::editor::ui {

inline constexpr float kTextureThumbnail = 96.0f; // pixels

class TextureBrowser {
  public:
    void open(std::string query = {});
    void close() { open_ = false; }
    bool is_open() const { return open_; }
    // Draws the window at `position` (screen pixels) while open; `current` is the selection's texture
    // (outlined). Returns the name clicked this frame, if any. Spots: "texture_search", "texture:NAME",
    // "texture_close".
    std::optional<std::string> draw(render::AssetLibrary& assets, const std::string& current, Vec2 position,
                                    UiSpots& spots);
    const std::string& query() const { return query_; }
    const std::vector<std::string>& shown() const { return shown_; } // what the search shows

    // The base-colour map of material `name` as an ImGui texture, or nullptr when it is not a known
    // material (never the magenta placeholder: an unknown name shows as a "?" instead).
    static ImTextureID thumbnail(render::AssetLibrary& assets, const std::string& name);
    // The window's width: three thumbnails to a row.
    static float width();

  private:
    bool open_ = false;
    bool focus_search_ = false;
    char search_[64] = {};
    std::string query_;
    std::vector<std::string> shown_;
};

} // namespace ks::editor::ui
