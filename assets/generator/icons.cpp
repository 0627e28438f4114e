// Application icons: a red power ("kill") switch on a dark steel disc for the game; the same switch over a
// blue level grid with a pencil for the editor. Shapes are signed distance functions in unit coordinates
// (-1..1, y down), composited front to back with 4x4 supersampling at every size, so the small sizes stay
// crisp instead of being downscaled from the large one.
#include "catalog.h"
#include "paint.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace ks::assetgen {
namespace {

constexpr int kIconSizes[] = {16, 24, 32, 48, 64, 128, 256};

struct Layer {
    std::function<float(Vec2f)> sdf;   // unit coordinates, negative inside
    std::function<Color(Vec2f)> paint; // straight-alpha colour at the point
};

Color hex(unsigned rgb, float alpha = 1.0f) {
    return Color(static_cast<float>((rgb >> 16) & 0xff) / 255.0f,
                 static_cast<float>((rgb >> 8) & 0xff) / 255.0f, static_cast<float>(rgb & 0xff) / 255.0f,
                 alpha);
}

// The layers painted over each other ("over" with premultiplied sums), then stored with straight alpha.
Image render_icon(int size, const std::vector<Layer>& layers) {
    constexpr int kSub = 4;
    const float pixel = 2.0f / static_cast<float>(size); // one pixel in unit coordinates
    Image image(size, size, Color(0.0f));
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            glm::vec4 sum(0.0f); // premultiplied
            for (int sy = 0; sy < kSub; ++sy)
                for (int sx = 0; sx < kSub; ++sx) {
                    const Vec2f p(
                        (static_cast<float>(x) + (static_cast<float>(sx) + 0.5f) / kSub) * pixel - 1.0f,
                        (static_cast<float>(y) + (static_cast<float>(sy) + 0.5f) / kSub) * pixel - 1.0f);
                    glm::vec4 c(0.0f);
                    for (const Layer& layer : layers) {
                        const float d = layer.sdf(p);
                        if (d > pixel) continue;
                        const float cover = std::clamp(0.5f - d / pixel, 0.0f, 1.0f);
                        const Color paint = layer.paint(p);
                        const float a = paint.a * cover;
                        c = glm::vec4(glm::vec3(paint) * a, a) + c * (1.0f - a);
                    }
                    sum += c;
                }
            sum /= static_cast<float>(kSub * kSub);
            image.at(x, y) = sum.a > 0.0f ? Color(glm::vec3(sum) / sum.a, sum.a) : Color(0.0f);
        }
    return image;
}

// Inigo Quilez's arc: a ring of radius `ra` and half thickness `rb`, symmetric about +y (down here), spanning
// `aperture` radians either side, with round caps.
float sdf_arc(Vec2f p, float aperture, float ra, float rb) {
    const Vec2f sc(std::sin(aperture), std::cos(aperture));
    p.x = std::abs(p.x);
    const float d = sc.y * p.x > sc.x * p.y ? glm::length(p - sc * ra) : std::abs(glm::length(p) - ra);
    return d - rb;
}

// The power symbol: an arc open at the top and a bar through the gap, `scale` about `centre`.
float sdf_power(Vec2f p, Vec2f centre, float scale) {
    const Vec2f q = (p - centre) / scale;
    const float arc = sdf_arc(q, glm::radians(142.0f), 0.44f, 0.085f);
    const float bar = sdf_segment(q, Vec2f(0.0f, -0.62f), Vec2f(0.0f, -0.1f), 0.085f);
    return std::min(arc, bar) * scale;
}

void disc_layers(std::vector<Layer>& layers) {
    // Steel rim, lit from above, then the dark body.
    layers.push_back({[](Vec2f p) { return sdf_circle(p, Vec2f(0.0f), 0.97f); },
                      [](Vec2f p) { return mix(hex(0x8a95a5), hex(0x262b33), (p.y + 1.0f) * 0.5f); }});
    layers.push_back({[](Vec2f p) { return sdf_circle(p, Vec2f(0.0f), 0.86f); },
                      [](Vec2f p) { return mix(hex(0x2c3444), hex(0x0a0d13), (p.y + 1.0f) * 0.5f); }});
}

void power_layers(std::vector<Layer>& layers, Vec2f centre, float scale) {
    // A red glow behind the switch, a dark outline for contrast, then the switch itself.
    layers.push_back({[=](Vec2f p) { return sdf_circle(p, centre, 0.78f * scale); },
                      [=](Vec2f p) {
                          const float t =
                              std::clamp(1.0f - glm::length(p - centre) / (0.78f * scale), 0.0f, 1.0f);
                          return hex(0xff2a1f, 0.45f * t * t);
                      }});
    layers.push_back({[=](Vec2f p) { return sdf_power(p, centre, scale) - 0.045f * scale; },
                      [](Vec2f) { return hex(0x07080b, 0.9f); }});
    layers.push_back({[=](Vec2f p) { return sdf_power(p, centre, scale); },
                      [=](Vec2f p) {
                          const float t = (p.y - centre.y + 0.7f * scale) / (1.3f * scale);
                          return mix(hex(0xff6a55), hex(0xc4101a), std::clamp(t, 0.0f, 1.0f));
                      }});
}

// The editor's level grid: thin blue lines inside the body disc.
void grid_layer(std::vector<Layer>& layers) {
    layers.push_back({[](Vec2f p) {
                          constexpr float kStep = 0.22f;
                          auto line = [](float v) {
                              return std::abs(v / kStep - std::round(v / kStep)) * kStep;
                          };
                          const float d = std::min(line(p.x), line(p.y)) - 0.012f;
                          return std::max(d, sdf_circle(p, Vec2f(0.0f), 0.8f));
                      },
                      [](Vec2f) { return hex(0x29abe2, 0.55f); }});
}

// A pencil lying across the lower right, its point down-left.
void pencil_layers(std::vector<Layer>& layers) {
    const Vec2f tip(0.02f, 0.86f), axis = glm::normalize(Vec2f(1.0f, -1.0f)), side(axis.y * -1.0f, axis.x);
    const float half = 0.11f;
    auto local = [=](Vec2f p) { return Vec2f(glm::dot(p - tip, axis), glm::dot(p - tip, side)); };
    // In local coordinates u runs from the point (0) to the eraser's end; |v| < half is the pencil's width.
    auto body = [=](Vec2f p, float from, float to) {
        const Vec2f q = local(p);
        return std::max(std::max(from - q.x, q.x - to), std::abs(q.y) - half);
    };
    auto cone = [=](Vec2f p, float length) { // the sharpened end, 0..length
        const Vec2f q = local(p);
        const float slope = half / length;
        const float edge = (std::abs(q.y) - q.x * slope) / std::sqrt(1.0f + slope * slope);
        return std::max(edge, q.x - length);
    };
    const float cone_len = 0.26f, body_end = 0.92f, band_end = 1.0f, eraser_end = 1.1f;
    auto whole = [=](Vec2f p) { return std::min(cone(p, cone_len), body(p, cone_len, eraser_end)); };
    layers.push_back({[=](Vec2f p) { return whole(p) - 0.045f; }, [](Vec2f) { return hex(0x07080b, 0.9f); }});
    layers.push_back({[=](Vec2f p) { return cone(p, cone_len); }, [](Vec2f) { return hex(0xe9c48f); }});
    layers.push_back({[=](Vec2f p) { return cone(p, 0.09f); }, [](Vec2f) { return hex(0x30333a); }});
    layers.push_back({[=](Vec2f p) { return body(p, cone_len, body_end); },
                      [=](Vec2f p) { return local(p).y < 0.0f ? hex(0xffc928) : hex(0xe0a300); }});
    layers.push_back(
        {[=](Vec2f p) { return body(p, body_end, band_end); }, [](Vec2f) { return hex(0xb8c0ca); }});
    layers.push_back(
        {[=](Vec2f p) { return body(p, band_end, eraser_end); }, [](Vec2f) { return hex(0xe57b8c); }});
}

} // namespace

Result<void> make_icons(Output& out) {
    std::vector<Layer> game;
    disc_layers(game);
    power_layers(game, Vec2f(0.0f, 0.04f), 1.0f);
    std::vector<Layer> editor;
    disc_layers(editor);
    grid_layer(editor);
    power_layers(editor, Vec2f(-0.14f, -0.08f), 0.8f);
    pencil_layers(editor);
    for (int size : kIconSizes) {
        KS_ASSETGEN_TRY(out.icon("killswitch", render_icon(size, game)));
        KS_ASSETGEN_TRY(out.icon("killswitch-editor", render_icon(size, editor)));
    }
    return ok();
}

} // namespace ks::assetgen
