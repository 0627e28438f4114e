// A designer's model's textures inside its file (a .glb's images, modelio::EmbeddedImage) become GL textures
// through the texture cache: the pixels as decoded, one texture per image however many materials use it, and
// a reference to an image the import does not hold drawn as the magenta checker, never a crash.
#include "gl_test_support.h"
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
