// modelio: textures stored inside a .glb (aiScene::mTextures, named "*N"): a PNG decoded from the file's
// binary chunk, assimp's raw texels, and every kind of bad embedded image refused with an Error naming the
// file and the texture (the level then draws the model as a marker), never a crash.
#include "modelio/embedded_textures.h"
#include "modelio/model_import.h"
#include "modelio/model_writers.h"
#include "test_support.h"

#include <assimp/scene.h>
#include <assimp/texture.h>
#include <doctest/doctest.h>

#include <cstring>

using namespace ks;
using namespace ks::modelio;

namespace {

// 2x2: red, green (top row); blue, half-transparent white (bottom row).
const std::vector<unsigned char> kPixels{255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 128};

void check_embedded_refused(const Result<ImportedModel>& r, const std::filesystem::path& file,
                            const std::string& what) {
    REQUIRE_FALSE(r.ok());
    const std::string text = r.error().str();
    INFO(text);
    CHECK(r.error().where.file == file.string());
    CHECK(test::contains_text(text, what));
    CHECK_FALSE(r.error().hint.empty());
}

} // namespace

TEST_CASE("modelio: a .glb's embedded PNG is decoded, top row first, and its material names it \"*0\"") {
    test::ScratchDir dir;
    const auto file = test::write_glb_cube(dir.path(), "painted", {.image = test::png_bytes(2, 2, kPixels)});
    Result<ImportedModel> m = import_model(file);
    REQUIRE_MESSAGE(m.ok(), m.error().str());
    CHECK(m->triangle_count == 12);
    REQUIRE(m->materials.size() >= 1);
    const ImportedMaterial& mat = m->materials[static_cast<size_t>(m->meshes.at(0).material)];
    CHECK(mat.textures.base_color == "*0");
    REQUIRE(m->images.size() == 1);
    const EmbeddedImage& image = m->images[0];
    CHECK(image.width == 2);
    CHECK(image.height == 2);
    CHECK(image.rgba == kPixels);
    CHECK(image.hash != 0);
    // Other pixels, another hash: the renderer's texture cache key changes when the file is exported again.
    std::vector<unsigned char> other = kPixels;
    other[0] = 10;
    const auto again = test::write_glb_cube(dir.path(), "repainted", {.image = test::png_bytes(2, 2, other)});
    Result<ImportedModel> m2 = import_model(again);
    REQUIRE_MESSAGE(m2.ok(), m2.error().str());
    REQUIRE(m2->images.size() == 1);
    CHECK(m2->images[0].hash != image.hash);
}

TEST_CASE("modelio: a bad embedded texture is refused naming the file and the texture") {
    test::ScratchDir dir;
    const std::string png = test::png_bytes(2, 2, kPixels);
    SUBCASE("not an image") {
        const auto file = test::write_glb_cube(dir.path(), "junk", {.image = "definitely not a picture"});
        check_embedded_refused(import_model(file), file, "is not an image the game reads");
    }
    SUBCASE("a PNG cut short") {
        const auto file = test::write_glb_cube(dir.path(), "cut", {.image = png.substr(0, png.size() - 20)});
        check_embedded_refused(import_model(file), file, "embedded texture \"*0\"");
    }
    SUBCASE("larger than the limit") {
        const auto file = test::write_glb_cube(dir.path(), "big", {.image = png});
        ImportLimits limits;
        limits.max_texture_pixels = 3;
        check_embedded_refused(import_model(file, limits), file, "more than the 3 pixels");
    }
    SUBCASE("a texture naming an image the file does not hold") {
        const auto file = test::write_glb_cube(dir.path(), "dangling", {.image = png, .texture_source = 1});
        Result<ImportedModel> r = import_model(file);
        REQUIRE_FALSE(r.ok()); // assimp's glTF reader or ours: either way refused, naming the file
        CHECK(r.error().where.file == file.string());
    }
}

TEST_CASE("modelio: assimp's uncompressed texels become RGBA; a \"*N\" past the file's textures is refused") {
    aiTexel texels[2];
    texels[0].b = 1;
    texels[0].g = 2;
    texels[0].r = 3;
    texels[0].a = 4;
    texels[1].b = 5;
    texels[1].g = 6;
    texels[1].r = 7;
    texels[1].a = 8;
    aiTexture texture;
    texture.mWidth = 2;
    texture.mHeight = 1;
    texture.pcData = texels;
    Result<EmbeddedImage> image = decode_embedded_texture(texture, "*0", "raw.fbx", 16);
    texture.pcData = nullptr; // not aiTexture's to free
    REQUIRE_MESSAGE(image.ok(), image.error().str());
    CHECK(image->width == 2);
    CHECK(image->height == 1);
    CHECK(image->rgba == std::vector<std::uint8_t>{3, 2, 1, 4, 7, 6, 5, 8});

    aiScene scene; // holds no embedded textures
    ImportedModel model;
    model.path = "props/statue.glb";
    model.materials.emplace_back();
    model.materials[0].name = "stone";
    model.materials[0].textures.normal = "*2";
    Result<void> r = load_embedded_textures(scene, model, {});
    REQUIRE_FALSE(r.ok());
    CHECK(r.error().where.file == "props/statue.glb");
    CHECK(test::contains_text(r.error().str(), "\"stone\" names the embedded texture \"*2\""));
}
