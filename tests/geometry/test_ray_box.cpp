// The robust slab test against axis-aligned boxes: entry distances, starting inside, max distance, rays
// along a box's face (half-open: of two stacked boxes exactly one is hit), rays through the shared edge of
// two boxes (never lost), and axis-parallel rays (no inf·0).
#include "geometry/ray.h"

#include <doctest/doctest.h>

using namespace ks;
using namespace ks::geometry;

namespace {
bool hits(const Ray& ray, const Aabb& box, float& t) {
    return ray_aabb(ray, box, t);
}
} // namespace

TEST_CASE("ray vs aabb: entry distance, inside, behind, beyond the max distance") {
    const Aabb box{Vec3(4, -1, -1), Vec3(6, 1, 1)};
    float t = -1.0f;
    REQUIRE(hits({Vec3(0), Vec3(1, 0, 0)}, box, t));
    CHECK(t == doctest::Approx(4.0f));
    REQUIRE(hits({Vec3(5, 0, 0), Vec3(0, 1, 0)}, box, t)); // inside
    CHECK(t == 0.0f);
    CHECK_FALSE(hits({Vec3(0), Vec3(-1, 0, 0)}, box, t));      // pointing away
    CHECK_FALSE(hits({Vec3(0), Vec3(1, 0, 0), 3.9f}, box, t)); // short of it
    CHECK(hits({Vec3(0), Vec3(1, 0, 0), 4.0f}, box, t));       // reaching it exactly
    CHECK_FALSE(hits({Vec3(0, 2, 0), Vec3(1, 0, 0)}, box, t)); // passing above
    const Vec3 d = glm::normalize(Vec3(5, 0.9f, 0));
    REQUIRE(hits({Vec3(0), d}, box, t)); // slanted, entering through the x = 4 face
    CHECK(t == doctest::Approx(4.0f / d.x));
}

TEST_CASE("ray vs aabb: a ray along the face shared by two stacked boxes hits exactly one") {
    const Aabb lower{Vec3(-1, -2, -1), Vec3(1, 0, 1)}, upper{Vec3(-1, 0, -1), Vec3(1, 2, 1)};
    const Ray along{Vec3(-5, 0, 0), Vec3(1, 0, 0)}; // y = 0 exactly, direction.y == 0
    float t = 0.0f;
    const bool a = hits(along, lower, t), b = hits(along, upper, t);
    CHECK(a != b);
    CHECK(safe_inverse(along.direction).y > 0.0f); // the zero component became tiny, not inf
}

TEST_CASE("ray vs aabb: rays through the shared edge of two boxes are never lost") {
    const Aabb left{Vec3(-2, -1, -1), Vec3(0, 1, 1)}, right{Vec3(0, -1, -1), Vec3(2, 1, 1)};
    int lost = 0;
    for (int i = -50; i <= 50; ++i) {
        const float x = static_cast<float>(i) * 1e-7f; // straddling x = 0 within a few ulps
        const Ray down{Vec3(x, 5, 0.3f), glm::normalize(Vec3(1e-7f, -1, 0))};
        float t = 0.0f;
        if (!hits(down, left, t) && !hits(down, right, t)) ++lost;
    }
    CHECK(lost == 0);
}
