// modelio: node animations written to glTF 2.0 (.glb and .gltf) through assimp and read back; the nodes are
// written as translation/rotation/scale (glTF forbids animating a matrix node); what the tracks cannot carry
// (scale channels, step and cubic-spline keys) is reported; bad files refused naming file and place.
#include "modelio/gltf_animation.h"
#include "test_support.h"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>

using namespace ks;
using namespace ks::modelio;

namespace {

AnimatedScene two_node_scene() {
    AnimatedScene s;
    s.nodes.push_back({"base", -1, {0, 0.5f, 0}, {1, 0, 0, 0}, {1, 1, 1}});
    s.nodes.push_back({"arm", 0, {0.3f, 0.2f, 0}, glm::angleAxis(0.4f, Vec3(0, 0, 1)), {1, 1, 1}});
    NodeTrack t;
    t.node = "arm";
    t.rotation_times = {0, 0.5, 1.25};
    t.rotations = {glm::angleAxis(0.4f, Vec3(0, 0, 1)), glm::angleAxis(1.2f, Vec3(0, 0, 1)),
                   glm::angleAxis(-0.3f, Vec3(1, 0, 0))};
    t.translation_times = {0, 1.25};
    t.translations = {{0.3f, 0.2f, 0}, {0.3f, 0.7f, 0.1f}};
    s.animations.push_back({"wave", {t}});
    return s;
}

nlohmann::json read_json(const std::filesystem::path& p) {
    std::ifstream in(p);
    return nlohmann::json::parse(in);
}

void write_json(const std::filesystem::path& p, const nlohmann::json& doc) {
    std::ofstream(p) << doc.dump(2);
}

void check_refused(const Result<AnimatedScene>& r, const std::filesystem::path& file,
                   const std::string& what) {
    REQUIRE_FALSE(r.ok());
    INFO(r.error().str());
    CHECK(r.error().where.file == file.string());
    CHECK(test::contains_text(r.error().str(), what));
}

} // namespace

TEST_CASE("modelio: node animations round-trip through .glb and .gltf; nodes are written as TRS") {
    test::ScratchDir dir;
    const AnimatedScene scene = two_node_scene();
    for (const char* name : {"clip.glb", "clip.gltf"}) {
        const auto file = dir / name;
        REQUIRE(write_gltf_animations(file, scene).ok());
        auto back = read_gltf_animations(file);
        REQUIRE(back.ok());
        CHECK(back->ignored.empty());
        REQUIRE(back->animations.size() == 1);
        CHECK(back->animations[0].name == "wave");
        REQUIRE(back->animations[0].tracks.size() == 1);
        const NodeTrack& t = back->animations[0].tracks[0];
        CHECK(t.node == "arm");
        REQUIRE(t.rotation_times.size() == 3);
        REQUIRE(t.translation_times.size() == 2);
        CHECK(t.rotation_times[2] == doctest::Approx(1.25).epsilon(1e-7));
        for (std::size_t k = 0; k < 3; ++k)
            CHECK(std::abs(glm::dot(t.rotations[k], scene.animations[0].tracks[0].rotations[k])) ==
                  doctest::Approx(1.0).epsilon(1e-6));
        CHECK(t.translations[1].y == doctest::Approx(0.7f));
        const auto arm =
            std::find_if(back->nodes.begin(), back->nodes.end(), [](auto& n) { return n.name == "arm"; });
        REQUIRE(arm != back->nodes.end());
        REQUIRE(arm->parent >= 0);
        CHECK(back->nodes[static_cast<std::size_t>(arm->parent)].name == "base");
        CHECK(arm->translation.x == doctest::Approx(0.3f));
    }
    // What Blender reads: times in seconds, and no node given as a matrix.
    const nlohmann::json doc = read_json(dir / "clip.gltf");
    for (const auto& node : doc["nodes"]) CHECK_FALSE(node.contains("matrix"));
    const auto& sampler = doc["animations"][0]["samplers"][0];
    const double last = doc["accessors"][sampler["input"].get<std::size_t>()]["max"][0].get<double>();
    CHECK(last == doctest::Approx(1.25).epsilon(1e-6));
}

TEST_CASE("modelio: scale channels, step and cubic-spline keys are reported") {
    test::ScratchDir dir;
    const auto file = dir / "clip.gltf";
    REQUIRE(write_gltf_animations(file, two_node_scene()).ok());
    nlohmann::json doc = read_json(file);
    auto& anim = doc["animations"][0];
    nlohmann::json scale = anim["channels"][0];
    for (const auto& c : anim["channels"])
        if (c["target"]["path"] == "translation") scale = c;
    scale["target"]["path"] = "scale";
    anim["channels"].push_back(scale);
    for (auto& c : anim["channels"])
        if (c["target"]["path"] == "rotation")
            anim["samplers"][c["sampler"].get<std::size_t>()]["interpolation"] = "STEP";
    write_json(file, doc);
    auto back = read_gltf_animations(file);
    REQUIRE(back.ok());
    REQUIRE(back->ignored.size() == 1);
    CHECK(test::contains_text(back->ignored[0], "scale"));
    CHECK(back->animations[0].tracks[0].rotation_interpolation == KeyInterpolation::Step);
    CHECK(back->animations[0].tracks[0].translation_interpolation == KeyInterpolation::Linear);
}

TEST_CASE("modelio: truncated, NaN-keyed and animation-free glTF files are refused naming file and place") {
    test::ScratchDir dir;
    const auto glb = dir / "clip.glb";
    REQUIRE(write_gltf_animations(glb, two_node_scene()).ok());
    std::string bytes;
    {
        std::ifstream in(glb, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), {});
    }
    const auto cut = dir / "cut.glb";
    test::write_file(cut, bytes.substr(0, bytes.size() / 2));
    check_refused(read_gltf_animations(cut), cut, "truncated");

    // A NaN written into the rotation keys' bytes.
    const auto gltf = dir / "nan.gltf";
    REQUIRE(write_gltf_animations(gltf, two_node_scene()).ok());
    const nlohmann::json doc = read_json(gltf);
    for (const auto& c : doc["animations"][0]["channels"]) {
        if (c["target"]["path"] != "rotation") continue;
        const auto& acc =
            doc["accessors"][doc["animations"][0]["samplers"][c["sampler"].get<std::size_t>()]["output"]
                                 .get<std::size_t>()];
        const auto& view = doc["bufferViews"][acc["bufferView"].get<std::size_t>()];
        const auto bin = dir / doc["buffers"][0]["uri"].get<std::string>();
        std::fstream f(bin, std::ios::in | std::ios::out | std::ios::binary);
        f.seekp(static_cast<std::streamoff>(view.value("byteOffset", 0) + acc.value("byteOffset", 0) + 16));
        const float nan = std::numeric_limits<float>::quiet_NaN();
        f.write(reinterpret_cast<const char*>(&nan), 4);
    }
    auto r = read_gltf_animations(gltf);
    check_refused(r, gltf, "not a finite number");
    CHECK(test::contains_text(r.error().str(), "node 'arm', rotation key 1"));

    AnimatedScene still = two_node_scene();
    still.animations.clear();
    const auto none = dir / "still.glb";
    REQUIRE(write_gltf_animations(none, still).ok());
    check_refused(read_gltf_animations(none), none, "no animations");

    AnimatedScene bad = two_node_scene();
    bad.animations[0].tracks[0].translations[0].x = std::numeric_limits<float>::infinity();
    const auto refused = write_gltf_animations(dir / "bad.glb", bad);
    REQUIRE_FALSE(refused.ok());
    CHECK(test::contains_text(refused.error().str(), "translation key 0"));
}
