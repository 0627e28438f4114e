#pragma once
// The GL side of a LightBake: one RGB16F texture (bilinear, no mipmaps: texel centres sit on face
// edges, so a mip level would mix neighbouring faces), re-uploaded when the bake re-combines.
#include "render/light_bake.h"

#include <vector>

namespace ks::render {

// What a LightmapTexture's texels mean: 0 = linear RGB16F (RendererSettings::lightmap_float), else
// sqrt(irradiance / range) in RGBA8.
float lightmap_encoding_range(bool lightmap_float);

// The mean linear colour of a mipmapped sRGB colour texture (its 1x1 mip level): the albedo the light
// bake's bounce uses for a surface. `fallback` when the texture is 0 or has no such level.
Vec3 texture_mean_color(unsigned texture, const Vec3& fallback);

class LightmapTexture {
  public:
    explicit LightmapTexture(bool lightmap_float = false) : float_(lightmap_float) {}
    ~LightmapTexture();
    LightmapTexture(const LightmapTexture&) = delete;
    LightmapTexture& operator=(const LightmapTexture&) = delete;

    void upload(const LightBake& bake);
    unsigned id() const { return id_; }
    // 0: RGB16F (exact); > 0: RGBA8 holding sqrt(irradiance / range) (the shader squares it), which
    // llvmpipe samples about twice as fast as a float texture.
    float range() const { return range_; }

  private:
    unsigned id_ = 0;
    int width_ = 0, height_ = 0;
    float range_ = 0.0f;
    bool float_ = false;
    std::vector<unsigned char> encoded_;
};

} // namespace ks::render
