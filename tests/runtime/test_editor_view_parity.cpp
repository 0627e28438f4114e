// The editor's inline copy of the camera maths (editor/view/camera_math.h, so the editor's view code links
// without the render module) must agree exactly with render::Camera, which draws the picture.
#include "editor/view/camera_math.h"
#include "render/camera.h"

#include <doctest/doctest.h>

using namespace ks;

TEST_CASE("editor camera maths equals render::Camera for perspective, orthographic, straight down and roll") {
    struct Case {
        Vec3 position;
        float yaw, pitch, roll, ortho_height;
    };
    const Case cases[] = {{{0, 3, 0}, 0.0f, 0.0f, 0.0f, 0.0f},
                          {{12, 30, 40}, 0.35f, -0.7f, 0.0f, 0.0f},
                          {{5, 200, -7}, 0.0f, -1.5707964f, 0.0f, 110.0f}, // the top view
                          {{-300, 8, 0}, 1.5707964f, 0.0f, 0.0f, 40.0f},   // the side view
                          {{1, 2, 3}, -2.0f, 0.4f, 0.3f, 0.0f}};
    for (const Case& c : cases) {
        render::Camera cam;
        cam.position = c.position;
        cam.yaw = c.yaw;
        cam.pitch = c.pitch;
        cam.roll = c.roll;
        cam.ortho_height = c.ortho_height;
        cam.aspect = 960.0f / 540.0f;
        CHECK(editor::camera_view(cam) == cam.view());
        CHECK(editor::camera_projection(cam) == cam.projection());
        const Vec3 f = editor::camera_forward(cam), g = cam.forward();
        CHECK(glm::length(f - g) < 1e-6f);
        CHECK(glm::length(editor::camera_basis(cam)[0] - cam.right()) < 1e-6f);
        CHECK(glm::length(editor::camera_basis(cam)[1] - cam.up()) < 1e-6f);
    }
}
