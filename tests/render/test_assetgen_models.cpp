// The generated models (assets/models, written by ks_assetgen) carry the node names, hierarchy,
// dimensions, facing and materials the shared asset conventions promise (docs/assets.md): the robot, the
// rifle and its painted parts, the door, the lights, the control panel's upright screen, the gas cylinder,
// the pickups and a designer's prop. Needs no GL context.
#include "assetgen_test_support.h"

#include <doctest/doctest.h>
#include <stb_image.h>

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace ks::test::assetgen {
namespace {

int find_node(const json& doc, const std::string& name) {
    for (size_t i = 0; i < doc["nodes"].size(); ++i)
        if (doc["nodes"][i].value("name", "") == name) return static_cast<int>(i);
    return -1;
}

int parent_of(const json& doc, int node) {
    for (size_t i = 0; i < doc["nodes"].size(); ++i)
        for (const json& c : doc["nodes"][i].value("children", json::array()))
            if (c.get<int>() == node) return static_cast<int>(i);
    return -1;
}

glm::mat4 local_matrix(const json& node) {
    glm::vec3 t(0.0f), s(1.0f);
    glm::quat r(1.0f, 0.0f, 0.0f, 0.0f);
    if (node.contains("translation"))
        t = {node["translation"][0], node["translation"][1], node["translation"][2]};
    if (node.contains("rotation"))
        r = glm::quat(node["rotation"][3].get<float>(), node["rotation"][0].get<float>(),
                      node["rotation"][1].get<float>(), node["rotation"][2].get<float>());
    if (node.contains("scale")) s = {node["scale"][0], node["scale"][1], node["scale"][2]};
    return glm::translate(glm::mat4(1.0f), t) * glm::mat4_cast(r) * glm::scale(glm::mat4(1.0f), s);
}

glm::mat4 world_matrix(const json& doc, int node) {
    glm::mat4 m(1.0f);
    for (int n = node; n >= 0; n = parent_of(doc, n)) m = local_matrix(doc["nodes"][n]) * m;
    return m;
}

// World-space bounds of every mesh in the model (from the accessors' min/max, transformed corner by corner).
std::pair<glm::vec3, glm::vec3> model_bounds(const json& doc) {
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (size_t i = 0; i < doc["nodes"].size(); ++i) {
        const json& node = doc["nodes"][i];
        if (!node.contains("mesh")) continue;
        const glm::mat4 w = world_matrix(doc, static_cast<int>(i));
        for (const json& prim : doc["meshes"][node["mesh"].get<int>()]["primitives"]) {
            const json& a = doc["accessors"][prim["attributes"]["POSITION"].get<int>()];
            for (int c = 0; c < 8; ++c) {
                const glm::vec3 p((c & 1 ? a["max"] : a["min"])[0].get<float>(),
                                  (c & 2 ? a["max"] : a["min"])[1].get<float>(),
                                  (c & 4 ? a["max"] : a["min"])[2].get<float>());
                const glm::vec3 q = glm::vec3(w * glm::vec4(p, 1.0f));
                lo = glm::min(lo, q);
                hi = glm::max(hi, q);
            }
        }
    }
    return {lo, hi};
}

bool has_material(const json& doc, const std::string& name) {
    for (const json& m : doc.value("materials", json::array()))
        if (m.value("name", "") == name) return true;
    return false;
}

} // namespace

TEST_CASE("generated models carry the node names and dimensions the conventions promise") {
    const std::map<std::string, std::vector<std::string>> nodes = {
        {"robot",
         {"robot", "wheel_base", "wheels", "chest", "arm_r", "forearm_r", "hand_r", "hand_r_tip", "arm_l",
          "forearm_l", "hand_l", "head"}},
        {"rifle", {"rifle", "muzzle"}},
        {"door", {"door", "frame", "door_l", "door_r"}},
        {"floor_light", {"floor_light", "lamp_head", "light_origin"}},
        {"top_light", {"top_light", "light_origin"}},
        {"control_panel", {"control_panel"}},
        {"gas_cylinder", {"gas_cylinder"}},
        {"pickup_health", {"pickup"}},
        {"pickup_ammo", {"pickup"}},
        {"pickup_shield", {"pickup"}},
        {"archive_shelf", {"archive_shelf"}},
    };
    for (const auto& [model, names] : nodes) {
        CAPTURE(model);
        const json doc = load_model(model).doc;
        for (const std::string& n : names) CHECK_MESSAGE(find_node(doc, n) >= 0, "missing node " << n);
        CHECK(parent_of(doc, find_node(doc, names.front())) == -1); // the root is named after the model
    }

    SUBCASE("robot hierarchy, size and facing") {
        const json doc = load_model("robot").doc;
        auto parent = [&](const char* n) {
            const int p = parent_of(doc, find_node(doc, n));
            return p < 0 ? std::string() : doc["nodes"][p]["name"].get<std::string>();
        };
        CHECK(parent("wheel_base") == "robot");
        CHECK(parent("wheels") == "wheel_base");
        CHECK(parent("chest") == "wheel_base");
        CHECK(parent("arm_r") == "chest");
        CHECK(parent("forearm_r") == "arm_r");
        CHECK(parent("hand_r") == "forearm_r");
        CHECK(parent("hand_r_tip") == "hand_r");
        CHECK(parent("arm_l") == "chest");
        CHECK(parent("forearm_l") == "arm_l");
        CHECK(parent("hand_l") == "forearm_l");
        CHECK(parent("head") == "chest");
        const auto [lo, hi] = model_bounds(doc);
        CHECK(lo.y == doctest::Approx(0.0).epsilon(0.01));
        CHECK(hi.y == doctest::Approx(3.0).epsilon(0.01));
        CHECK(hi.z - lo.z == doctest::Approx(1.6).epsilon(0.1));
        // Right arm on +Z, left on -Z; arms hang down from the shoulder pivots at rest.
        const glm::vec3 arm_r = world_matrix(doc, find_node(doc, "arm_r"))[3];
        const glm::vec3 arm_l = world_matrix(doc, find_node(doc, "arm_l"))[3];
        const glm::vec3 tip = world_matrix(doc, find_node(doc, "hand_r_tip"))[3];
        CHECK(arm_r.z > 0.3f);
        CHECK(arm_l.z < -0.3f);
        CHECK(tip.y < arm_r.y - 1.0f);
        CHECK(std::abs(tip.x - arm_r.x) < 0.05f);
        // The glowing visor is on the head's +X side: the robot faces +X.
        const json& head = doc["nodes"][find_node(doc, "head")];
        bool visor_forward = false;
        for (const json& prim : doc["meshes"][head["mesh"].get<int>()]["primitives"])
            if (doc["materials"][prim["material"].get<int>()]["name"] == "robot_visor")
                visor_forward =
                    visor_forward ||
                    doc["accessors"][prim["attributes"]["POSITION"].get<int>()]["max"][0].get<double>() >
                        0.25;
        CHECK(visor_forward);
        size_t triangles = 0;
        for (const json& m : doc["meshes"])
            for (const json& p : m["primitives"])
                triangles += doc["accessors"][p["indices"].get<int>()]["count"].get<size_t>() / 3;
        CHECK(triangles >= 3000);
        CHECK(triangles <= 6500);
    }
    SUBCASE("rifle points along -Z with the muzzle at the barrel tip") {
        const json doc = load_model("rifle").doc;
        const auto [lo, hi] = model_bounds(doc);
        CHECK(hi.z - lo.z == doctest::Approx(1.0).epsilon(0.1));
        const glm::vec3 muzzle = world_matrix(doc, find_node(doc, "muzzle"))[3];
        CHECK(muzzle.z == doctest::Approx(lo.z).epsilon(0.02));
        // Issue 28: the reference's orange and grey painted rifle, not a dark silhouette. Each material's
        // geometry where its parts are: polymer grip and magazine below, orange from handguard to stock,
        // steel at the muzzle, markings and a luminous sight post.
        std::map<std::string, std::pair<glm::vec3, glm::vec3>> parts;
        size_t triangles = 0;
        for (const json& prim : doc["meshes"][0]["primitives"]) {
            const json& a = doc["accessors"][prim["attributes"]["POSITION"].get<int>()];
            parts[doc["materials"][prim["material"].get<int>()]["name"].get<std::string>()] = {
                glm::vec3(a["min"][0], a["min"][1], a["min"][2]),
                glm::vec3(a["max"][0], a["max"][1], a["max"][2])};
            triangles += doc["accessors"][prim["indices"].get<int>()]["count"].get<size_t>() / 3;
        }
        for (const char* m : {"rifle_orange", "rifle_grey", "rifle_polymer", "rifle_steel", "rifle_decal",
                              "rifle_lens", "rifle_sight"})
            CHECK_MESSAGE(parts.count(m) == 1, "missing material " << m);
        CHECK(triangles >= 4000);
        CHECK(parts["rifle_polymer"].first.y < lo.y + 0.01f);
        CHECK(parts["rifle_orange"].second.z - parts["rifle_orange"].first.z > 0.6f);
        CHECK(parts["rifle_steel"].first.z < lo.z + 0.01f);
        // The maps: orange paint is orange, grey paint a light neutral grey, polymer darker than both but not
        // black, and the markings atlas has the contrast of legible print.
        struct Stats {
            glm::dvec3 mean_rgb{0.0};
            double mean_luma = 0, luma_stddev = 0;
        };
        auto stats = [](const std::string& texture) {
            int w = 0, h = 0, c = 0;
            const std::string path = (committed() / "textures" / (texture + ".png")).string();
            unsigned char* p = stbi_load(path.c_str(), &w, &h, &c, 3);
            REQUIRE_MESSAGE(p != nullptr, "cannot read " << path);
            Stats s;
            double sum2 = 0;
            const size_t n = static_cast<size_t>(w) * h;
            for (size_t i = 0; i < n; ++i) {
                const glm::dvec3 rgb(p[3 * i], p[3 * i + 1], p[3 * i + 2]);
                const double luma = glm::dot(rgb, glm::dvec3(0.2126, 0.7152, 0.0722));
                s.mean_rgb += rgb / static_cast<double>(n);
                s.mean_luma += luma / static_cast<double>(n);
                sum2 += luma * luma / static_cast<double>(n);
            }
            stbi_image_free(p);
            s.luma_stddev = std::sqrt(std::max(0.0, sum2 - s.mean_luma * s.mean_luma));
            return s;
        };
        const auto orange = stats("rifle_orange_basecolor"), grey = stats("rifle_grey_basecolor");
        const auto polymer = stats("rifle_polymer_basecolor"), decals = stats("rifle_decals_basecolor");
        CHECK(orange.mean_rgb.x > orange.mean_rgb.z + 120.0);
        CHECK(grey.mean_luma > 90.0);
        CHECK(std::abs(grey.mean_rgb.x - grey.mean_rgb.z) < 20.0);
        CHECK(polymer.mean_luma > 45.0);
        CHECK(polymer.mean_luma < grey.mean_luma - 30.0);
        CHECK(decals.luma_stddev > 40.0);
    }
    SUBCASE("door leaves and doorway") {
        const json doc = load_model("door").doc;
        const glm::vec3 l = world_matrix(doc, find_node(doc, "door_l"))[3];
        const glm::vec3 r = world_matrix(doc, find_node(doc, "door_r"))[3];
        CHECK(l.x > 0.0f);
        CHECK(r.x < 0.0f);
        const json& leaf = doc["nodes"][find_node(doc, "door_l")];
        const json& a =
            doc["accessors"]
               [doc["meshes"][leaf["mesh"].get<int>()]["primitives"][0]["attributes"]["POSITION"].get<int>()];
        CHECK(a["max"][1].get<double>() - a["min"][1].get<double>() == doctest::Approx(5.36).epsilon(0.01));
        CHECK(a["max"][2].get<double>() - a["min"][2].get<double>() == doctest::Approx(0.14).epsilon(0.01));
    }
    SUBCASE("lights: emissive lens material and light origins") {
        const json floor = load_model("floor_light").doc;
        CHECK(has_material(floor, "light_emissive"));
        const glm::mat4 origin = world_matrix(floor, find_node(floor, "light_origin"));
        CHECK(origin[3].y == doctest::Approx(3.8).epsilon(0.05));
        const glm::vec3 aim = -glm::vec3(origin[2]); // local -Z in the model frame
        CHECK(aim.z < -0.8f);
        CHECK(aim.y == doctest::Approx(-0.5).epsilon(0.05)); // tilted 30 degrees down
        const auto [flo, fhi] = model_bounds(floor);
        CHECK(fhi.y == doctest::Approx(4.0).epsilon(0.05));

        const json top = load_model("top_light").doc;
        CHECK(has_material(top, "light_emissive"));
        const auto [tlo, thi] = model_bounds(top);
        CHECK(thi.y == doctest::Approx(0.0).epsilon(0.01));
        CHECK(tlo.y == doctest::Approx(-2.0).epsilon(0.05));
    }
    SUBCASE("control panel footprint and screen") {
        const json doc = load_model("control_panel").doc;
        CHECK(has_material(doc, "screen_emissive"));
        const auto [lo, hi] = model_bounds(doc);
        CHECK(hi.x - lo.x == doctest::Approx(2.94).epsilon(0.01));
        CHECK(hi.z - lo.z == doctest::Approx(5.34).epsilon(0.01));
        CHECK(hi.y == doctest::Approx(4.0).epsilon(0.01));
        // The screen faces -X; a player there has +Z on the right and +Y up, so u grows with z and v
        // (0 at the image's top) falls with y, or the "SIMULATION CONTROL" title ends up at the bottom,
        // upside down (it was, issue 28). The screen's centre is 2.65 up.
        const Gltf g = load_model("control_panel");
        int front_vertices = 0;
        for (const json& m : doc["meshes"])
            for (const json& prim : m["primitives"]) {
                if (doc["materials"][prim["material"].get<int>()]["name"] != "screen_emissive") continue;
                const std::vector<double> pos = read_accessor(g, prim["attributes"]["POSITION"].get<int>());
                const std::vector<double> nrm = read_accessor(g, prim["attributes"]["NORMAL"].get<int>());
                const std::vector<double> uv = read_accessor(g, prim["attributes"]["TEXCOORD_0"].get<int>());
                for (size_t i = 0; i < pos.size() / 3; ++i) {
                    if (nrm[3 * i] > -0.5) continue;
                    ++front_vertices;
                    CHECK(uv[2 * i] == doctest::Approx(pos[3 * i + 2] / 4.4 + 0.5).epsilon(0.01));
                    CHECK(uv[2 * i + 1] ==
                          doctest::Approx(0.5 - (pos[3 * i + 1] - 2.65) / 2.1).epsilon(0.01));
                }
            }
        CHECK(front_vertices >= 4);
    }
    SUBCASE("gas cylinder and pickups") {
        const auto [lo, hi] = model_bounds(load_model("gas_cylinder").doc);
        CHECK(hi.x == doctest::Approx(0.5).epsilon(0.01));
        CHECK(hi.y == doctest::Approx(2.0).epsilon(0.01));
        for (const char* p : {"pickup_health", "pickup_ammo", "pickup_shield"}) {
            const json doc = load_model(p).doc;
            const auto [plo, phi] = model_bounds(doc);
            CHECK(phi.x - plo.x == doctest::Approx(0.8).epsilon(0.01));
            CHECK(plo.y == doctest::Approx(-0.4).epsilon(0.01));
            CHECK(doc["materials"][0].contains("emissiveTexture"));
        }
    }
    SUBCASE("the archive shelf: a designer's prop standing on its origin, open to +Z") {
        const json doc = load_model("archive_shelf").doc;
        const auto [lo, hi] = model_bounds(doc);
        CHECK(lo.y == doctest::Approx(0.0).epsilon(0.001));
        CHECK(hi.y == doctest::Approx(4.5).epsilon(0.01));
        CHECK(hi.x - lo.x == doctest::Approx(4.08).epsilon(0.01));
        CHECK(hi.x == doctest::Approx(-lo.x).epsilon(0.001)); // centred on x and z
        CHECK(hi.z == doctest::Approx(-lo.z).epsilon(0.001));
    }
}

} // namespace ks::test::assetgen
