// The fast path's one-lookup model map (TextureCache::get_occluded_base): base x occlusion in rgb and the ORM
// map's metalness in alpha, read by the fast_model "orm in base" programs instead of a second (ORM) lookup.
// The map holds exactly the ORM map's metalness; every shipped model drawn with it looks like the same model
// drawn with its ORM map looked up (RendererSettings::fast_occluded_base off), within the 8-bit rounding.
#include "gl_test_support.h"
#include "render/asset_library.h"
#include "render/model.h"
#include "render/scene_renderer.h"
#include "test_support.h"

#include <epoxy/gl.h>
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>

using namespace ks;
using namespace ks::render;

namespace {

std::vector<unsigned char> texels(unsigned texture, int& width, int& height) {
    glBindTexture(GL_TEXTURE_2D, texture);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &width);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &height);
    std::vector<unsigned char> rgba(static_cast<size_t>(width) * static_cast<size_t>(height) * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    glBindTexture(GL_TEXTURE_2D, 0);
    return rgba;
}

} // namespace

TEST_CASE("fast model maps: the rifle's one-lookup map holds its ORM map's metalness in alpha, exactly") {
    KS_REQUIRE_GL();
    AssetLibrary assets(ks::test::source_dir() / "assets");
    const Model& rifle = assets.model("rifle");
    int packed_materials = 0;
    for (const Material& m : rifle.materials) {
        CAPTURE(m.name);
        if (!m.orm_map) continue;
        REQUIRE(m.fast_base_map != 0);
        CHECK(m.fast_metal_in_alpha);
        ++packed_materials;
        int w = 0, h = 0, ow = 0, oh = 0;
        const auto packed = texels(m.fast_base_map, w, h);
        const auto orm = texels(m.orm_map, ow, oh);
        REQUIRE(w == ow);
        REQUIRE(h == oh);
        size_t worst = 0;
        double mean_metal = 0.0;
        for (size_t i = 0; i < packed.size(); i += 4) {
            worst = std::max<size_t>(worst, static_cast<size_t>(std::abs(packed[i + 3] - orm[i + 2])));
            mean_metal += orm[i + 2] / 255.0;
        }
        CHECK(worst == 0);
        CHECK(m.fast_metallic ==
              doctest::Approx(mean_metal / (static_cast<double>(packed.size()) / 4)).epsilon(1e-4));
    }
    CHECK(packed_materials == 3); // its orange, grey and polymer finishes
}

TEST_CASE("fast model maps: every shipped model drawn with its one-lookup map looks like it drawn with its "
          "ORM map") {
    KS_REQUIRE_GL();
    AssetLibrary assets(ks::test::source_dir() / "assets");
    RendererSettings one_lookup, orm_lookup;
    one_lookup.quality = orm_lookup.quality = RenderQuality::Fast;
    one_lookup.render_scale = orm_lookup.render_scale = 1.0f;
    orm_lookup.fast_occluded_base = false;
    auto a = SceneRenderer::create(assets.textures(), one_lookup);
    auto b = SceneRenderer::create(assets.textures(), orm_lookup);
    REQUIRE(a);
    REQUIRE(b);
    Environment env;
    const std::vector<Light> lights;
    double worst = 0.0;
    for (const auto& entry :
         std::filesystem::directory_iterator(ks::test::source_dir() / "assets" / "models")) {
        if (entry.path().extension() != ".gltf") continue;
        const std::string name = entry.path().stem().string();
        CAPTURE(name);
        const Model& model = assets.model(name);
        std::vector<MeshInstance> instances;
        std::vector<Mat4> scratch;
        model.emit(Mat4(1.0f), scratch, instances);
        const Vec3 centre = model.bounds.center();
        const float radius = std::max(glm::length(model.bounds.extent()), 0.05f);
        for (float yaw : {0.4f, 2.2f, 4.0f}) {
            geometry::Camera camera;
            camera.aspect = static_cast<float>(ks::test::kGlWidth) / ks::test::kGlHeight;
            camera.near_plane = radius * 0.02f;
            camera.far_plane = radius * 10.0f;
            camera.yaw = yaw;
            camera.pitch = -0.3f;
            camera.position = centre - camera.forward() * (radius * 1.6f);
            const auto one = ks::test::render_offscreen(**a, camera, env, instances, lights);
            const auto two = ks::test::render_offscreen(**b, camera, env, instances, lights);
            const double diff = ks::test::mean_abs_diff(one, two);
            CHECK(diff < 0.5);
            worst = std::max(worst, diff);
        }
    }
    MESSAGE("one-lookup map against the ORM lookup: worst mean abs diff " << worst << "/255");
}
