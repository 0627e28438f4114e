#pragma once
// Label text rasterised from a TrueType font (DejaVu Sans Bold from assets/fonts) with stb_truetype, as
// anti-aliased coverage painted into a Field.
#include "core/result.h"
#include "paint.h"

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

namespace ks::assetgen {

class Font {
  public:
    static Result<Font> load(const std::filesystem::path& path);

    // Width in pixels of `text` at a cap-to-descender size of `pixel_height`.
    float measure(std::string_view text, float pixel_height) const;
    // Draws with the baseline's left end at `origin`.
    void draw(Field& field, std::string_view text, Vec2f origin, float pixel_height,
              const Stroke& stroke = {}) const;
    // Draws centred horizontally on `centre.x`, with capitals centred vertically on `centre.y`.
    void draw_centred(Field& field, std::string_view text, Vec2f centre, float pixel_height,
                      const Stroke& stroke = {}) const;

  private:
    struct State;
    std::shared_ptr<const State> state_;
};

} // namespace ks::assetgen
