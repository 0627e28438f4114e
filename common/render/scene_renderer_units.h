#pragma once
// Texture units and limits shared by the scene renderer's source files (scene_renderer*.cpp); not for
// callers of SceneRenderer.
#include "core/math.h"

namespace ks::render::scene_units {

enum TextureUnit { kBase = 0, kNormal, kOrm, kEmissive, kHeight, kShadow, kLightmap };
constexpr int kMaxLightsInView = 32;     // one bit each in a draw's light mask
constexpr float kLegacyLightScale = kPi; // three.js legacy light units (see pbr.frag)

} // namespace ks::render::scene_units
