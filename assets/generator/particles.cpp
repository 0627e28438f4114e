// Particle sprites: RGBA with colour already multiplied by alpha, so both additive and premultiplied
// blending work and the background is black and transparent.
#include "catalog.h"
#include "noise.h"
#include "surface_ops.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace ks::assetgen {
namespace {
constexpr int kParticleSize = 128;

Image sprite(const std::function<Color(float r, float angle, int x, int y)>& shade) {
    Image image(kParticleSize, kParticleSize, Color(0.0f));
    for (int y = 0; y < kParticleSize; ++y)
        for (int x = 0; x < kParticleSize; ++x) {
            const float dx = (static_cast<float>(x) + 0.5f) / kParticleSize * 2.0f - 1.0f;
            const float dy = (static_cast<float>(y) + 0.5f) / kParticleSize * 2.0f - 1.0f;
            const float r = std::sqrt(dx * dx + dy * dy);
            Color c = shade(r, std::atan2(dy, dx), x, y);
            c.a = std::clamp(c.a, 0.0f, 1.0f);
            image.at(x, y) = Color(glm::vec3(c) * c.a, c.a); // premultiply
        }
    return image;
}
} // namespace

Result<void> make_particles(Output& out) {
    const Field fire_noise = fractal_noise(kParticleSize, kParticleSize, NoiseKind::Perlin, 4, 5, 71);
    const Image fire = sprite([&](float r, float, int x, int y) {
        const float n = fire_noise.at(x, y);
        const float body = std::clamp(1.0f - (r + (n - 0.5f) * 0.6f) * 1.15f, 0.0f, 1.0f);
        const float heat = std::clamp(body * 1.6f, 0.0f, 1.0f);
        const glm::vec3 colour =
            glm::mix(glm::vec3(0.9f, 0.18f, 0.02f), glm::vec3(1.0f, 0.85f, 0.45f), heat * heat);
        return Color(colour, std::pow(body, 0.8f));
    });
    const Field smoke_noise = fractal_noise(kParticleSize, kParticleSize, NoiseKind::Perlin, 3, 6, 72);
    const Image smoke = sprite([&](float r, float, int x, int y) {
        const float n = smoke_noise.at(x, y);
        const float puff = std::clamp(1.0f - r * 1.05f, 0.0f, 1.0f);
        const float density = std::clamp(puff * (0.45f + n * 0.9f), 0.0f, 1.0f);
        const float shade = 0.35f + 0.4f * n;
        return Color(glm::vec3(shade), density * density * 1.4f);
    });
    const Image spark = sprite([&](float r, float angle, int, int) {
        // A hot core with a soft glow and four thin rays.
        const float core = std::exp(-r * r * 60.0f);
        const float glow = std::exp(-r * 5.0f) * 0.5f;
        const float rays =
            std::pow(std::abs(std::cos(angle * 2.0f)), 40.0f) * std::clamp(1.0f - r, 0.0f, 1.0f) * 0.8f;
        const float a = std::clamp(core + glow + rays, 0.0f, 1.0f);
        const glm::vec3 colour = glm::mix(glm::vec3(1.0f, 0.6f, 0.15f), glm::vec3(1.0f, 0.97f, 0.85f),
                                          std::clamp(core * 2.0f, 0.0f, 1.0f));
        return Color(colour, a);
    });
    KS_ASSETGEN_TRY(out.texture("particles/fire", fire, PngChannels::Rgba));
    KS_ASSETGEN_TRY(out.texture("particles/smoke", smoke, PngChannels::Rgba));
    return out.texture("particles/spark", spark, PngChannels::Rgba);
}

} // namespace ks::assetgen
