#include "screen_ui.h"

#include "noise.h"
#include "surface_ops.h"

#include <algorithm>
#include <cmath>

namespace ks::assetgen {
namespace {
// Layers are painted as coverage fields and composited with their colours, in order.
struct Layer {
    Field mask;
    Color color;
};

Display compose(int w, int h, Color background, const std::vector<Layer>& layers, float glass_glow) {
    Image emissive(w, h, background);
    for (const Layer& l : layers) blend(emissive, l.mask, l.color);
    Display d{Image(w, h), emissive};
    for (size_t i = 0; i < emissive.pixels.size(); ++i) {
        // Scanlines: every other pair of rows slightly darker, as on a real display.
        const int row = static_cast<int>(i / static_cast<size_t>(w));
        const float scan = (row / 2) % 2 == 0 ? 1.0f : 0.86f;
        d.emissive.pixels[i] = Color(glm::vec3(emissive.pixels[i]) * scan, 1.0f);
        d.basecolor.pixels[i] =
            Color(glm::vec3(0.03f, 0.035f, 0.04f) + glm::vec3(emissive.pixels[i]) * glass_glow, 1.0f);
    }
    return d;
}
} // namespace

Display simulation_control_screen(const Font& font) {
    constexpr int w = 1024, h = 512;
    const Color cyan(0.35f, 0.9f, 1.0f, 1.0f), dim(0.1f, 0.3f, 0.4f, 1.0f), red(1.0f, 0.12f, 0.08f, 1.0f),
        amber(1.0f, 0.7f, 0.15f, 1.0f), white(0.92f, 0.97f, 1.0f, 1.0f), green(0.3f, 1.0f, 0.45f, 1.0f);
    Field grid(w, h), frames(w, h), text(w, h), bars(w, h), bars_warn(w, h), graph(w, h), button(w, h),
        ring(w, h), button_text(w, h), warning(w, h), ok_text(w, h);
    for (int x = 0; x < w; x += 32) draw_line(grid, Vec2f(x, 0), Vec2f(x, h), 1.0f, Stroke{0.5f});
    for (int y = 0; y < h; y += 32) draw_line(grid, Vec2f(0, y), Vec2f(w, y), 1.0f, Stroke{0.5f});
    // Title bar.
    fill_rounded_rect(frames, Vec2f(16, 14), Vec2f(w - 16, 96), 10.0f);
    fill_rounded_rect(frames, Vec2f(20, 18), Vec2f(w - 20, 92), 8.0f, Stroke{0.0f, Paint::Set});
    font.draw_centred(text, "SIMULATION CONTROL", Vec2f(w * 0.5f, 55.0f), 64.0f);
    // Left: subsystem status with level bars.
    fill_rounded_rect(frames, Vec2f(16, 112), Vec2f(400, 440), 8.0f);
    fill_rounded_rect(frames, Vec2f(19, 115), Vec2f(397, 437), 6.0f, Stroke{0.0f, Paint::Set});
    const char* names[] = {"CORE", "ROBOTS", "DOORS", "LIGHTS", "SHIELD"};
    const float levels[] = {0.92f, 0.78f, 0.35f, 0.6f, 0.18f};
    for (int k = 0; k < 5; ++k) {
        const float y = 150.0f + static_cast<float>(k) * 60.0f;
        font.draw(text, names[k], Vec2f(36, y + 10), 30.0f);
        fill_rounded_rect(frames, Vec2f(170, y - 12), Vec2f(380, y + 14), 4.0f, Stroke{0.6f});
        fill_rounded_rect(frames, Vec2f(172, y - 10), Vec2f(378, y + 12), 3.0f, Stroke{0.0f, Paint::Set});
        Field& bar = levels[k] < 0.4f ? bars_warn : bars;
        for (int s = 0; s < static_cast<int>(levels[k] * 20.0f); ++s)
            fill_rounded_rect(bar, Vec2f(175.0f + static_cast<float>(s) * 10.2f, y - 7),
                              Vec2f(182.0f + static_cast<float>(s) * 10.2f, y + 9), 1.5f);
    }
    // Middle: a live waveform.
    fill_rounded_rect(frames, Vec2f(416, 112), Vec2f(700, 300), 8.0f);
    fill_rounded_rect(frames, Vec2f(419, 115), Vec2f(697, 297), 6.0f, Stroke{0.0f, Paint::Set});
    Vec2f prev(424, 206);
    for (int x = 424; x <= 692; x += 4) {
        const float t = static_cast<float>(x - 424) / 268.0f;
        const Vec2f p(static_cast<float>(x), 206.0f - 60.0f * std::sin(t * 18.0f) * std::exp(-t * 1.5f) -
                                                 12.0f * std::sin(t * 53.0f));
        draw_line(graph, prev, p, 3.0f);
        prev = p;
    }
    font.draw(text, "FIELD SIGNAL", Vec2f(428, 140), 22.0f);
    // Middle bottom: warning.
    fill_rounded_rect(frames, Vec2f(416, 316), Vec2f(700, 440), 8.0f);
    fill_rounded_rect(frames, Vec2f(419, 319), Vec2f(697, 437), 6.0f, Stroke{0.0f, Paint::Set});
    fill_polygon(warning, {{470, 345}, {500, 405}, {440, 405}});
    fill_polygon(warning, {{470, 358}, {490, 398}, {450, 398}}, Stroke{0.0f, Paint::Set});
    draw_line(warning, Vec2f(470, 368), Vec2f(470, 386), 5.0f);
    fill_circle(warning, Vec2f(470, 393), 3.0f);
    font.draw(warning, "ROGUE UNITS", Vec2f(515, 370), 26.0f);
    font.draw(warning, "DETECTED", Vec2f(515, 402), 26.0f);
    // Right: the big red shutdown button.
    fill_rounded_rect(frames, Vec2f(716, 112), Vec2f(w - 16, 440), 8.0f);
    fill_rounded_rect(frames, Vec2f(719, 115), Vec2f(w - 19, 437), 6.0f, Stroke{0.0f, Paint::Set});
    const Vec2f centre(862, 250);
    // A hazard ring: diagonal stripes clipped to an annulus.
    Field annulus(w, h), stripes(w, h);
    fill_ring(annulus, centre, 114.0f, 96.0f);
    hazard_stripes(stripes, centre - Vec2f(120), centre + Vec2f(120), 28.0f);
    for (size_t i = 0; i < ring.values.size(); ++i)
        ring.values[i] = annulus.values[i] * (1.0f - stripes.values[i] * 0.85f);
    fill_circle(button, centre, 88.0f, Stroke{1.0f, Paint::Max, 10.0f});
    font.draw_centred(button_text, "SHUTDOWN", centre, 34.0f);
    font.draw_centred(button_text, "PRESS E", Vec2f(862, 398), 30.0f, Stroke{0.8f});
    // Footer.
    font.draw(ok_text, "SECTOR 3  //  ALL SYSTEMS NOMINAL  //  SIM 0.4.7", Vec2f(24, 486), 26.0f);
    return compose(w, h, Color(0.02f, 0.05f, 0.08f, 1.0f),
                   {{grid, Color(0.05f, 0.14f, 0.2f, 1.0f)},
                    {frames, dim},
                    {text, cyan},
                    {bars, green},
                    {bars_warn, amber},
                    {graph, cyan},
                    {warning, amber},
                    {ring, amber},
                    {button, red},
                    {button_text, white},
                    {ok_text, Color(0.3f, 0.75f, 0.85f, 1.0f)}},
                   0.35f);
}

Display button_desk(const Font& font) {
    constexpr int w = 512, h = 256;
    Field plate(w, h), labels(w, h), green(w, h), amber(w, h), blue(w, h), red(w, h), slots(w, h);
    Field* colours[] = {&green, &amber, &blue, &green, &red, &blue, &amber, &green};
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 8; ++i) {
            const Vec2f lo(24.0f + static_cast<float>(i) * 38.0f, 40.0f + static_cast<float>(j) * 52.0f);
            fill_rounded_rect(plate, lo - Vec2f(4), lo + Vec2f(34, 30), 5.0f);
            const bool lit = hash01(i, j, 401) > 0.3f;
            fill_rounded_rect(*colours[(i + j * 3) % 8], lo, lo + Vec2f(26, 22), 4.0f,
                              Stroke{lit ? 1.0f : 0.25f, Paint::Max, 3.0f});
        }
    for (int k = 0; k < 4; ++k) {
        const float x = 350.0f + static_cast<float>(k) * 36.0f;
        fill_rounded_rect(slots, Vec2f(x, 36), Vec2f(x + 8, 196), 4.0f);
        const float knob = 60.0f + hash01(k, 0, 402) * 110.0f;
        fill_rounded_rect(amber, Vec2f(x - 8, knob), Vec2f(x + 16, knob + 14), 3.0f, Stroke{0.9f});
    }
    font.draw(labels, "AUX   PWR   NAV   COMMS", Vec2f(24, 26), 18.0f);
    font.draw(labels, "GAIN", Vec2f(372, 222), 18.0f);
    font.draw(labels, "DOOR CTRL  /  LIGHT GRID", Vec2f(24, 222), 18.0f);
    return compose(w, h, Color(0.03f, 0.035f, 0.04f, 1.0f),
                   {{plate, Color(0.08f, 0.09f, 0.1f, 1.0f)},
                    {slots, Color(0.0f, 0.0f, 0.0f, 1.0f)},
                    {labels, Color(0.6f, 0.7f, 0.75f, 1.0f)},
                    {green, Color(0.25f, 1.0f, 0.4f, 1.0f)},
                    {amber, Color(1.0f, 0.65f, 0.1f, 1.0f)},
                    {blue, Color(0.25f, 0.6f, 1.0f, 1.0f)},
                    {red, Color(1.0f, 0.15f, 0.1f, 1.0f)}},
                   0.5f);
}

} // namespace ks::assetgen
