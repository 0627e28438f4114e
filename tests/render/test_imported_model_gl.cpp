// A designer's model's textures inside its file (a .glb's images, modelio::EmbeddedImage) become GL textures
// through the texture cache: the pixels as decoded, one texture per image however many materials use it, and
// a reference to an image the import does not hold drawn as the magenta checker, never a crash. Texture files
// beside the model give the fast path's one-lookup map (metalness in alpha) when the base colour is opaque.
#include "gl_test_support.h"
#include "modelio/model_writers.h"
#include "test_support.h"

#include "render/imported_model.h"
#include "render/texture_cache.h"

#include <epoxy/gl.h>
#include <doctest/doctest.h>

using namespace ks;
using namespace ks::render;

#ifndef KS_REQUIRE_GL
#endif

namespace {

// One triangle using material 0; materials 0 and 1 both name the embedded image "*0" (2x1: red, blue with
// alpha 128); material 2 names "*7", which the import does not hold.
modelio::ImportedModel embedded_texture_model() {
    modelio::ImportedModel m;
    m.path = "props/painted.glb";
    modelio::ImportedMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    mesh.uvs = {{0, 0}, {1, 0}, {0, 1}};
    mesh.indices = {0, 1, 2};
    m.meshes.push_back(mesh);
    for (const char* ref : {"*0", "*0", "*7"}) {
        modelio::ImportedMaterial mat;
        mat.textures.base_color = ref;
        m.materials.push_back(mat);
    }
    modelio::EmbeddedImage image;
    image.name = "*0";
    image.width = 2;
    image.height = 1;
    image.rgba = {255, 0, 0, 255, 0, 0, 255, 128};
    image.hash = 42;
    m.images.push_back(image);
    m.bounds = {{0, 0, 0}, {1, 1, 0}};
    m.triangle_count = 1;
    return m;
}

} // namespace

TEST_CASE("imported model: a texture inside the file is uploaded from its decoded pixels") {
    KS_REQUIRE_GL();
    TextureCache textures;
    int next_id = 1;
    const modelio::ImportedModel imported = embedded_texture_model();
    ModelLevels levels = model_levels_from_import(imported, textures, next_id);
    REQUIRE(levels.levels.size() == 1);
    const std::vector<Material>& mats = levels.full().materials;
    REQUIRE(mats.size() == 3);
    CHECK_FALSE(mats[0].placeholder);
    CHECK(mats[0].base_map != 0);
    CHECK(mats[0].base_map != textures.placeholder().id);
    CHECK(mats[1].base_map == mats[0].base_map); // one texture for the image
    CHECK(mats[2].placeholder);
    CHECK(mats[2].base_map == textures.placeholder().id);
    CHECK(textures.placeholder_count() == 1);

    glBindTexture(GL_TEXTURE_2D, mats[0].base_map);
    GLint w = 0, h = 0;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &w);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &h);
    CHECK(w == 2);
    CHECK(h == 1);
    std::vector<unsigned char> back(8, 7);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back.data());
    // 0 and 255 read back the same through sRGB; alpha is linear either way.
    CHECK(back == imported.images[0].rgba);

    // The same file exported again with other pixels: another hash, another texture.
    modelio::ImportedModel changed = embedded_texture_model();
    changed.images[0].rgba[0] = 10;
    changed.images[0].hash = 43;
    ModelLevels again = model_levels_from_import(changed, textures, next_id);
    CHECK(again.full().materials[0].base_map != mats[0].base_map);
}

TEST_CASE("imported model: base and metal-roughness files give the fast path's one-lookup map, an opaque "
          "base's alpha the metalness") {
    KS_REQUIRE_GL();
    test::ScratchDir dir;
    // 2x1 texels: ORM (occlusion, roughness, metalness) = (255, 128, 0) and (64, 128, 200).
    test::write_file(dir / "orm.png", test::png_bytes(2, 1, {255, 128, 0, 255, 64, 128, 200, 255}));
    test::write_file(dir / "opaque.png", test::png_bytes(2, 1, {200, 100, 50, 255, 100, 200, 50, 255}));
    test::write_file(dir / "clear.png", test::png_bytes(2, 1, {200, 100, 50, 255, 100, 200, 50, 90}));
    modelio::ImportedModel m = embedded_texture_model();
    m.path = dir / "prop.gltf";
    m.images.clear();
    m.materials.clear();
    for (const char* base : {"opaque.png", "clear.png"}) {
        modelio::ImportedMaterial mat;
        mat.textures.base_color = base;
        mat.textures.metal_rough = "orm.png";
        m.materials.push_back(mat);
    }
    TextureCache textures(disk_cache::Store({}));
    int next_id = 1;
    ModelLevels levels = model_levels_from_import(m, textures, next_id);
    const std::vector<Material>& mats = levels.full().materials;
    REQUIRE(mats.size() == 2);
    REQUIRE(mats[0].fast_base_map != 0);
    CHECK(mats[0].fast_metal_in_alpha);
    CHECK(mats[0].fast_metallic == doctest::Approx(100.0 / 255.0).epsilon(1e-4));
    std::vector<unsigned char> back(8, 7);
    glBindTexture(GL_TEXTURE_2D, mats[0].fast_base_map);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back.data());
    CHECK(back[3] == 0);   // the first texel's metalness
    CHECK(back[7] == 200); // the second's
    CHECK(back[4] == 50);  // 100 x sqrt(64 / 255): occlusion in the colour (gamma 2)
    // A base colour with an alpha of its own keeps it: the model reads its ORM map as before.
    CHECK_FALSE(mats[1].fast_metal_in_alpha);
}
