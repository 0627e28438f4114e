// A designer's prop, not an entity type of the game: the archive shelf, a wooden shelving unit full of books
// (4 wide, 4.5 tall, 1.2 deep; open side +Z, origin at the bottom centre). The Archive places it as a
// `model` entity (levels/source/archive.kss), so the shipped game reads a generated file through the
// designers' model path (docs/models.md): a .gltf with its .bin and the wood surface's textures.
#include "catalog.h"
#include "model_kit.h"

#include "core/random.h"

#include <array>
#include <cmath>

namespace ks::assetgen {
namespace {
constexpr float kWidth = 4.0f, kHeight = 4.5f, kDepth = 1.2f;
constexpr float kBoard = 0.08f; // the thickness of the sides, shelves and top
constexpr int kShelves = 4;     // spaces for books, bottom to top

// Books standing along one shelf from x0 to x1 on the board top at `y`, at most `room` tall: random widths
// and heights, now and then a gap or a book leaning on its neighbour.
void fill_shelf(Node& node, const std::array<int, 6>& covers, int pages, Rng& rng, float x0, float x1,
                float y, float room) {
    float x = x0 + rng.uniform(0.0f, 0.15f);
    while (true) {
        const float width = rng.uniform(0.1f, 0.22f);
        const float height = room * rng.uniform(0.62f, 0.9f);
        const float depth = rng.uniform(0.62f, 0.78f);
        if (x + width > x1) break;
        if (rng.chance(0.07f)) { // a gap where a book is out
            x += rng.uniform(0.2f, 0.45f);
            continue;
        }
        const int cover = covers[rng.below(static_cast<std::uint32_t>(covers.size()))];
        const float z = kDepth * 0.5f - 0.06f - depth * 0.5f;
        mat4 place = at(vec3(x + width * 0.5f, y + height * 0.5f, z));
        if (rng.chance(0.06f) && x + width + height * 0.4f < x1) { // leaning to the right on its foot
            const float lean = rng.uniform(0.2f, 0.35f);
            place = at(vec3(x + width * 0.5f + height * 0.5f * std::sin(lean),
                            y + height * 0.5f * std::cos(lean) + width * 0.5f * std::sin(lean), z)) *
                    glm::rotate(mat4(1.0f), -lean, vec3(0, 0, 1));
            x += height * std::sin(lean);
        }
        node.part(cover).append(rounded_box(vec3(width, height, depth)), place);
        // The page block showing at the front, set in from the cover.
        node.part(pages).append(rounded_box(vec3(width - 0.03f, height - 0.05f, 0.02f)),
                                place * at(vec3(0.0f, 0.0f, depth * 0.5f - 0.005f)));
        x += width + rng.uniform(0.0f, 0.02f);
    }
}
} // namespace

Result<void> make_archive_shelf(Output& out) {
    Model model("archive_shelf");
    const int wood =
        model.add_material(textured("shelf_wood", "wood", vec4(0.72f, 0.6f, 0.5f, 1.0f), 0.0f, 1.0f));
    const std::array<int, 6> covers = {
        model.add_material(plain("book_red", vec3(0.5f, 0.12f, 0.1f), 0.0f, 0.7f)),
        model.add_material(plain("book_green", vec3(0.14f, 0.32f, 0.2f), 0.0f, 0.7f)),
        model.add_material(plain("book_blue", vec3(0.14f, 0.2f, 0.42f), 0.0f, 0.65f)),
        model.add_material(plain("book_ochre", vec3(0.62f, 0.46f, 0.18f), 0.0f, 0.75f)),
        model.add_material(plain("book_brown", vec3(0.36f, 0.22f, 0.14f), 0.0f, 0.8f)),
        model.add_material(plain("book_grey", vec3(0.4f, 0.4f, 0.38f), 0.0f, 0.75f)),
    };
    const int pages = model.add_material(plain("book_pages", vec3(0.86f, 0.82f, 0.7f), 0.0f, 0.9f));
    const int root = model.add_node("archive_shelf", -1);
    Node& n = model.node(root);
    const float half_w = kWidth * 0.5f, half_d = kDepth * 0.5f;
    // The sides, the back, the plinth and the top.
    for (float x : {-half_w + kBoard * 0.5f, half_w - kBoard * 0.5f})
        n.part(wood).append(rounded_box(vec3(kBoard, kHeight, kDepth), 0.01f, 1, 0.5f),
                            at(vec3(x, kHeight * 0.5f, 0.0f)));
    n.part(wood).append(rounded_box(vec3(kWidth - 2 * kBoard, kHeight - kBoard, 0.04f), 0.0f, 1, 0.5f),
                        at(vec3(0.0f, (kHeight - kBoard) * 0.5f, -half_d + 0.02f)));
    n.part(wood).append(rounded_box(vec3(kWidth - 2 * kBoard, 0.2f, kDepth - 0.1f), 0.0f, 1, 0.5f),
                        at(vec3(0.0f, 0.1f, -0.05f)));
    n.part(wood).append(rounded_box(vec3(kWidth + 0.08f, kBoard, kDepth + 0.06f), 0.015f, 1, 0.5f),
                        at(vec3(0.0f, kHeight - kBoard * 0.5f, 0.0f)));
    // The shelves, each holding a row of books.
    Rng rng(0xA4C1u);
    const float bottom = 0.2f, space = (kHeight - kBoard - bottom) / kShelves;
    for (int s = 0; s < kShelves; ++s) {
        const float y = bottom + static_cast<float>(s) * space;
        n.part(wood).append(rounded_box(vec3(kWidth - 2 * kBoard, kBoard, kDepth - 0.06f), 0.01f, 1, 0.5f),
                            at(vec3(0.0f, y + kBoard * 0.5f, 0.0f)));
        fill_shelf(n, covers, pages, rng, -half_w + kBoard, half_w - kBoard, y + kBoard, space - kBoard);
    }
    return out.model(model);
}

} // namespace ks::assetgen
