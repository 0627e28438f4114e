// Back-face culling of single-sided materials (Material::double_sided false: glTF's default, every generated
// model) hides nothing: each shipped model drawn alone from 26 directions around it, near and far, on both
// paths, and once mirrored (a negative determinant winds its front faces clockwise), matches the same
// picture drawn with every face (a coarser level of detail from as near as it is drawn); and it does cull
// (fewer triangles reach the rasteriser's fragments).
#include "gl_test_support.h"
#include "render/asset_library.h"
#include "render/model.h"
#include "render/png_writer.h"
#include "render/scene_renderer.h"
#include "test_support.h"

#include <epoxy/gl.h>
#include <doctest/doctest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>

using namespace ks;
using namespace ks::render;

namespace {

RendererSettings settings_for(RenderQuality quality, bool cull) {
    RendererSettings s;
    s.quality = quality;
    s.render_scale = 1.0f;
    s.cull_single_sided = cull;
    return s;
}

constexpr int kTiedPixels = 3; // of 57 600

// Pixels whose largest channel difference is over 24/255: a hole where a back face was the visible one.
int differing_pixels(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b) {
    int n = 0;
    for (size_t i = 0; i + 2 < a.size() && i + 2 < b.size(); i += 3) {
        int d = 0;
        for (size_t c = 0; c < 3; ++c) d = std::max(d, std::abs(int(a[i + c]) - int(b[i + c])));
        n += d > 24 ? 1 : 0;
    }
    return n;
}

std::vector<std::string> shipped_models() {
    std::vector<std::string> names;
    for (const auto& entry :
         std::filesystem::directory_iterator(ks::test::source_dir() / "assets" / "models"))
        if (entry.path().extension() == ".gltf") names.push_back(entry.path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

// The 26 directions of a cube's faces, edges and corners.
std::vector<Vec3> directions() {
    std::vector<Vec3> out;
    for (int x = -1; x <= 1; ++x)
        for (int y = -1; y <= 1; ++y)
            for (int z = -1; z <= 1; ++z)
                if (x || y || z) out.push_back(glm::normalize(Vec3(x, y, z)));
    return out;
}

geometry::Camera orbit_camera(const geometry::Aabb& box, const Vec3& direction, float distance_in_radii) {
    const Vec3 centre = box.center();
    const float radius = std::max(glm::length(box.extent()), 0.05f);
    geometry::Camera camera;
    camera.aspect = static_cast<float>(ks::test::kGlWidth) / ks::test::kGlHeight;
    camera.fov_y = radians(50.0f);
    camera.near_plane = radius * 0.02f;
    camera.far_plane = radius * (distance_in_radii + 10.0f);
    camera.position = centre + direction * (radius * distance_in_radii);
    const Vec3 to = centre - camera.position;
    camera.yaw = std::atan2(-to.x, -to.z);
    camera.pitch = std::asin(std::clamp(to.y / glm::length(to), -0.999f, 0.999f));
    return camera;
}

// How near the model is drawn, in radii of its bounds from their centre, for orbit_camera's view: 1.3 for a
// model in full; a coarser level of detail (robot_lod2) only from where its error covers under a pixel
// (render::pick_model_level), where parts that touch no longer tie along their sharpened edges.
float nearest_drawn(AssetLibrary& assets, const std::string& name) {
    const auto at = name.rfind("_lod");
    if (at == std::string::npos) return 1.3f;
    const ModelLevels& levels = assets.model_levels(name.substr(0, at));
    const int level = std::stoi(name.substr(at + 4));
    REQUIRE(level < static_cast<int>(levels.relative_errors.size()));
    // The bounds' diagonal covers 180 / (2 tan 25 deg) / distance pixels; a level is taken when its error,
    // relative error times those pixels, is under 0.8 of a pixel.
    const float pixels_per_radius =
        static_cast<float>(ks::test::kGlHeight) / (2.0f * std::tan(radians(25.0f)));
    return std::max(1.3f, pixels_per_radius * levels.relative_errors[static_cast<std::size_t>(level)] / 0.8f);
}

} // namespace

TEST_CASE("single-sided materials: culling their back faces hides nothing on any shipped model, from 26 "
          "directions near and far, on both paths, mirrored too") {
    KS_REQUIRE_GL();
    AssetLibrary assets(ks::test::source_dir() / "assets");
    Environment env;
    const std::vector<Light> lights;
    int pictures = 0, worst = 0, single_sided = 0;
    for (RenderQuality quality : {RenderQuality::Fast, RenderQuality::Full}) {
        auto culled = SceneRenderer::create(assets.textures(), settings_for(quality, true));
        auto every_face = SceneRenderer::create(assets.textures(), settings_for(quality, false));
        REQUIRE(culled);
        REQUIRE(every_face);
        for (const std::string& name : shipped_models()) {
            CAPTURE(name);
            const Model& model = assets.model(name);
            const float nearest = nearest_drawn(assets, name);
            REQUIRE_FALSE(model.placeholder);
            if (quality == RenderQuality::Fast)
                for (const Material& m : model.materials) single_sided += m.double_sided ? 0 : 1;
            for (bool mirrored : {false, true}) {
                CAPTURE(mirrored);
                std::vector<MeshInstance> instances;
                std::vector<Mat4> scratch;
                const Mat4 root = mirrored ? glm::scale(Mat4(1.0f), Vec3(-1.0f, 1.0f, 1.0f)) : Mat4(1.0f);
                model.emit(root, scratch, instances);
                geometry::Aabb box = geometry::transform_aabb(model.bounds, root);
                for (const Vec3& direction : directions())
                    for (float distance : {nearest, 2.3f * nearest}) {
                        CAPTURE(direction);
                        CAPTURE(distance);
                        const geometry::Camera camera = orbit_camera(box, direction, distance);
                        const auto a = ks::test::render_offscreen(**culled, camera, env, instances, lights);
                        const auto b =
                            ks::test::render_offscreen(**every_face, camera, env, instances, lights);
                        const int differ = differing_pixels(a, b);
                        if (const char* dir = std::getenv("KS_TEST_SHOTS"); dir && differ > 0) {
                            const std::string stem =
                                std::string(dir) + "/cull_" + name + "_" + std::to_string(pictures);
                            (void)write_png_rgb(stem + "_culled.png", ks::test::kGlWidth, ks::test::kGlHeight,
                                                a.data(), ks::test::kGlWidth * 3);
                            (void)write_png_rgb(stem + "_every_face.png", ks::test::kGlWidth,
                                                ks::test::kGlHeight, b.data(), ks::test::kGlWidth * 3);
                        }
                        // A few pixels may differ where a back face tied in depth with a front face drawn
                        // after it (parts that touch): culled, the front face shows, as it should.
                        // A coarser level's sharp edges meet along lines (a door's frame pieces): a few
                        // more ties, never a hole's hundreds of pixels.
                        CHECK(differ <=
                              (name.find("_lod") != std::string::npos ? 3 * kTiedPixels : kTiedPixels));
                        worst = std::max(worst, differ);
                        ++pictures;
                    }
            }
        }
    }
    MESSAGE(pictures << " pictures, the most differing pixels in one: " << worst << "; " << single_sided
                     << " single-sided materials");
    CHECK(single_sided > 20); // the generated models' materials are single-sided (glTF's default)
}

TEST_CASE("single-sided materials: culling sends fewer fragments to the shaders, mirrored or not") {
    KS_REQUIRE_GL();
    AssetLibrary assets(ks::test::source_dir() / "assets");
    Environment env;
    const std::vector<Light> lights;
    auto culled = SceneRenderer::create(assets.textures(), settings_for(RenderQuality::Fast, true));
    auto every_face = SceneRenderer::create(assets.textures(), settings_for(RenderQuality::Fast, false));
    REQUIRE(culled);
    REQUIRE(every_face);
    const Model& robot = assets.model("robot");
    for (bool mirrored : {false, true}) {
        CAPTURE(mirrored);
        std::vector<MeshInstance> instances;
        std::vector<Mat4> scratch;
        robot.emit(mirrored ? glm::scale(Mat4(1.0f), Vec3(-1.0f, 1.0f, 1.0f)) : Mat4(1.0f), scratch,
                   instances);
        // Seen from behind the robot's far side first: without culling the back faces nearest the eye in
        // draw order are shaded and then covered.
        const geometry::Camera camera = orbit_camera(robot.bounds, glm::normalize(Vec3(1, 0.4f, 0.3f)), 2.0f);
        auto fragments = [&](SceneRenderer& renderer) {
            GLuint query = 0;
            glGenQueries(1, &query);
            glBeginQuery(GL_SAMPLES_PASSED, query);
            const auto rgb = ks::test::render_offscreen(renderer, camera, env, instances, lights);
            glEndQuery(GL_SAMPLES_PASSED);
            GLuint64 samples = 0;
            glGetQueryObjectui64v(query, GL_QUERY_RESULT, &samples);
            glDeleteQueries(1, &query);
            return std::make_pair(samples, rgb);
        };
        const auto [with_culling, a] = fragments(**culled);
        const auto [without, b] = fragments(**every_face);
        INFO("fragments passing the depth test: " << with_culling << " culled, " << without << " every face");
        CHECK(differing_pixels(a, b) <= kTiedPixels);
        CHECK(with_culling < without);
        CHECK(with_culling > 0);
    }
}
