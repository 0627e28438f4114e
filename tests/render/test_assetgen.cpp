// The asset generator (assets/generator, ks_assetgen): it must reproduce the committed assets (textures,
// models and sounds) byte for byte, write every asset the conventions and the audio plan name, write
// structurally valid glTF, and refuse bad command lines with a clear message. Needs no GL context.
#include "planned_sounds.h"
#include "test_support.h"

#include <doctest/doctest.h>
#include <stb_image.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

fs::path generator() {
    return ks::test::bin_dir() / "ks_assetgen";
}
fs::path committed() {
    return ks::test::source_dir() / "assets";
}

// The generated folders: models/*.gltf|*.bin, textures/**.png, sounds/*.wav and icons/**.png.
std::set<std::string> generated_files(const fs::path& root) {
    std::set<std::string> out;
    for (const char* folder : {"models", "textures", "sounds", "icons"}) {
        if (!fs::exists(root / folder)) continue;
        for (const auto& entry : fs::recursive_directory_iterator(root / folder)) {
            if (!entry.is_regular_file()) continue;
            const std::string ext = entry.path().extension().string();
            if (ext == ".gltf" || ext == ".bin" || ext == ".png" || ext == ".wav")
                out.insert(fs::relative(entry.path(), root).generic_string());
        }
    }
    return out;
}

const std::vector<std::string>& model_names() {
    static const std::vector<std::string> names = {
        "robot",         "rifle",        "door",          "floor_light", "top_light",
        "control_panel", "gas_cylinder", "pickup_health", "pickup_ammo", "pickup_shield"};
    return names;
}

// Every file the shared asset conventions promise.
std::vector<std::string> expected_files() {
    std::vector<std::string> files;
    for (const std::string& m : model_names()) {
        files.push_back("models/" + m + ".gltf");
        files.push_back("models/" + m + ".bin");
    }
    for (const char* s : {"concrete", "wood", "tiles", "ceiling", "metal", "dojo_floor"})
        for (const char* map : {"basecolor", "normal", "orm", "height"})
            files.push_back(std::string("textures/") + s + "_" + map + ".png");
    for (const char* p : {"fire", "smoke", "spark"})
        files.push_back(std::string("textures/particles/") + p + ".png");
    for (const auto* names : {&ks::test::planned_one_shots(), &ks::test::planned_loops()})
        for (const std::string& s : *names) files.push_back("sounds/" + s + ".wav");
    // The application icons at the icon theme's sizes (cmake/KsInstall.cmake installs them).
    for (int size : {16, 24, 32, 48, 64, 128, 256})
        for (const char* icon : {"killswitch", "killswitch-editor"})
            files.push_back("icons/hicolor/" + std::to_string(size) + "x" + std::to_string(size) + "/apps/" +
                            icon + ".png");
    return files;
}

std::string shell_quote(const fs::path& p) {
    return "'" + p.string() + "'";
}

struct Gltf {
    json doc;
    std::string bin;
};

Gltf load_model(const std::string& name) {
    Gltf g;
    const std::string text = ks::test::read_file(committed() / "models" / (name + ".gltf"));
    g.doc = json::parse(text, nullptr, false);
    g.bin = ks::test::read_file(committed() / "models" / (name + ".bin"));
    return g;
}

int components(const std::string& type) {
    static const std::map<std::string, int> n = {{"SCALAR", 1}, {"VEC2", 2}, {"VEC3", 3}, {"VEC4", 4}};
    auto it = n.find(type);
    return it == n.end() ? 0 : it->second;
}

int component_size(int component_type) {
    switch (component_type) {
    case 5126:
    case 5125:
        return 4;
    case 5123:
        return 2;
    default:
        return 0;
    }
}

// Reads accessor `index` as doubles (float, uint16 or uint32 components).
std::vector<double> read_accessor(const Gltf& g, int index) {
    const json& a = g.doc["accessors"][index];
    const json& v = g.doc["bufferViews"][a["bufferView"].get<int>()];
    const size_t offset = v["byteOffset"].get<size_t>() + a.value("byteOffset", size_t{0});
    const size_t count =
        a["count"].get<size_t>() * static_cast<size_t>(components(a["type"].get<std::string>()));
    const int ct = a["componentType"].get<int>();
    std::vector<double> out(count);
    for (size_t i = 0; i < count; ++i) {
        const char* p = g.bin.data() + offset + i * static_cast<size_t>(component_size(ct));
        if (ct == 5126) {
            float f;
            std::memcpy(&f, p, 4);
            out[i] = f;
        } else if (ct == 5125) {
            std::uint32_t u;
            std::memcpy(&u, p, 4);
            out[i] = u;
        } else {
            std::uint16_t u;
            std::memcpy(&u, p, 2);
            out[i] = u;
        }
    }
    return out;
}

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

TEST_CASE("ks_assetgen regenerates every committed asset byte for byte") {
    REQUIRE_MESSAGE(fs::exists(generator()), "build the ks_assetgen target first: " << generator());
    ks::test::ScratchDir scratch;
    const auto result =
        ks::test::run_command(shell_quote(generator()) + " --out " + shell_quote(scratch.path()));
    INFO(result.output);
    REQUIRE(result.exit_code == 0);

    const std::set<std::string> fresh = generated_files(scratch.path());
    const std::set<std::string> repo = generated_files(committed());
    std::set<std::string> designer_files;
    for (const std::string& name : ks::test::designer_sounds())
        designer_files.insert("sounds/" + name + ".wav");
    for (const std::string& file : expected_files()) {
        CHECK_MESSAGE(fresh.count(file) == 1, "the generator no longer writes " << file);
        CHECK_MESSAGE(repo.count(file) == 1,
                      "assets/" << file << " is not committed; run ks_assetgen --out assets");
    }
    for (const std::string& file : fresh) {
        CAPTURE(file);
        REQUIRE_MESSAGE(repo.count(file) == 1, "generated but not committed; run ks_assetgen --out assets");
        if (designer_files.count(file) > 0) continue; // a designer's replacement, not ours to compare
        // Compared as bytes: the generator must be deterministic, and the committed files current.
        const bool same =
            ks::test::read_file(scratch.path() / file) == ks::test::read_file(committed() / file);
        CHECK_MESSAGE(
            same, "assets/" << file << " differs from a fresh run; run ks_assetgen --out assets and commit");
    }
    for (const std::string& file : repo)
        CHECK_MESSAGE(fresh.count(file) == 1,
                      "assets/" << file << " is committed but no longer generated (stale)");
}

TEST_CASE("generated glTF files are structurally valid") {
    for (const std::string& name : model_names()) {
        CAPTURE(name);
        const Gltf g = load_model(name);
        const json& doc = g.doc;
        REQUIRE_FALSE(doc.is_discarded());
        CHECK(doc["asset"]["version"] == "2.0");
        REQUIRE(doc["buffers"].size() == 1);
        CHECK(doc["buffers"][0]["uri"] == name + ".bin");
        CHECK(doc["buffers"][0]["byteLength"].get<size_t>() == g.bin.size());
        for (const json& v : doc["bufferViews"]) {
            CHECK(v["buffer"] == 0);
            CHECK(v["byteOffset"].get<size_t>() % 4 == 0);
            CHECK(v["byteOffset"].get<size_t>() + v["byteLength"].get<size_t>() <= g.bin.size());
        }
        for (const json& a : doc["accessors"]) {
            const int n = components(a["type"].get<std::string>()),
                      size = component_size(a["componentType"].get<int>());
            REQUIRE(n > 0);
            REQUIRE(size > 0);
            CHECK(a["count"].get<size_t>() > 0);
            const json& v = doc["bufferViews"][a["bufferView"].get<int>()];
            CHECK(a["count"].get<size_t>() * static_cast<size_t>(n * size) <= v["byteLength"].get<size_t>());
        }
        // Images exist next to the model's folder, as their relative URIs say.
        for (const json& image : doc.value("images", json::array())) {
            const fs::path file = committed() / "models" / image["uri"].get<std::string>();
            CHECK_MESSAGE(fs::exists(file), "missing texture " << file);
        }
        for (const json& t : doc.value("textures", json::array()))
            CHECK(t["source"].get<size_t>() < doc["images"].size());
        // Material factors within the ranges glTF allows.
        auto in_unit = [](const json& v) { return v.get<double>() >= 0.0 && v.get<double>() <= 1.0; };
        for (const json& m : doc.value("materials", json::array())) {
            CAPTURE(m["name"].get<std::string>());
            const json& pbr = m["pbrMetallicRoughness"];
            for (const json& c : pbr["baseColorFactor"]) CHECK(in_unit(c));
            CHECK(in_unit(pbr["metallicFactor"]));
            CHECK(in_unit(pbr["roughnessFactor"]));
            for (const json& c : m.value("emissiveFactor", json::array())) CHECK(in_unit(c));
        }
        // Nodes form a forest: every child index valid and owned by exactly one parent; scene lists the
        // roots.
        std::vector<int> parents(doc["nodes"].size(), 0);
        for (const json& node : doc["nodes"])
            for (const json& c : node.value("children", json::array())) {
                REQUIRE(c.get<size_t>() < doc["nodes"].size());
                ++parents[c.get<size_t>()];
            }
        for (int p : parents) CHECK(p <= 1);
        for (const json& root : doc["scenes"][doc["scene"].get<int>()]["nodes"])
            CHECK(parents[root.get<size_t>()] == 0);

        for (const json& mesh : doc.value("meshes", json::array()))
            for (const json& prim : mesh["primitives"]) {
                CHECK(prim["material"].get<size_t>() < doc["materials"].size());
                const json& attr = prim["attributes"];
                for (const char* key : {"POSITION", "NORMAL", "TANGENT", "TEXCOORD_0"})
                    REQUIRE(attr.contains(key));
                const int pos = attr["POSITION"].get<int>();
                const size_t vertices = doc["accessors"][pos]["count"].get<size_t>();
                for (const char* key : {"NORMAL", "TANGENT", "TEXCOORD_0"})
                    CHECK(doc["accessors"][attr[key].get<int>()]["count"].get<size_t>() == vertices);
                // POSITION min/max must match the data exactly (glTF requires them).
                const std::vector<double> p = read_accessor(g, pos);
                glm::dvec3 lo(1e300), hi(-1e300);
                for (size_t i = 0; i < p.size(); i += 3) {
                    lo = glm::min(lo, glm::dvec3(p[i], p[i + 1], p[i + 2]));
                    hi = glm::max(hi, glm::dvec3(p[i], p[i + 1], p[i + 2]));
                }
                for (int k = 0; k < 3; ++k) {
                    CHECK(doc["accessors"][pos]["min"][k].get<double>() == lo[k]);
                    CHECK(doc["accessors"][pos]["max"][k].get<double>() == hi[k]);
                }
                const std::vector<double> normals = read_accessor(g, attr["NORMAL"].get<int>());
                const std::vector<double> tangents = read_accessor(g, attr["TANGENT"].get<int>());
                size_t bad_normals = 0, bad_tangents = 0;
                for (size_t i = 0; i < vertices; ++i) {
                    const glm::dvec3 n(normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]);
                    const glm::dvec3 t(tangents[4 * i], tangents[4 * i + 1], tangents[4 * i + 2]);
                    if (!(std::abs(glm::length(n) - 1.0) < 1e-3)) ++bad_normals;
                    if (!(std::abs(glm::length(t) - 1.0) < 1e-3) || std::abs(glm::dot(n, t)) > 1e-2 ||
                        std::abs(std::abs(tangents[4 * i + 3]) - 1.0) > 0.0)
                        ++bad_tangents;
                }
                CHECK(bad_normals == 0);
                CHECK(bad_tangents == 0);
                const std::vector<double> idx = read_accessor(g, prim["indices"].get<int>());
                CHECK(idx.size() % 3 == 0);
                CHECK(*std::max_element(idx.begin(), idx.end()) < static_cast<double>(vertices));
                // Front faces are counter-clockwise: each triangle's winding normal agrees with its vertex
                // normals. Tangents follow +u and the bitangent (cross(N, T) * w) points toward -v (image
                // up).
                const std::vector<double> uv = read_accessor(g, attr["TEXCOORD_0"].get<int>());
                size_t inverted = 0, wrong_tangent = 0, wrong_handedness = 0, measured = 0;
                for (size_t t = 0; t + 2 < idx.size(); t += 3) {
                    const size_t i[3] = {static_cast<size_t>(idx[t]), static_cast<size_t>(idx[t + 1]),
                                         static_cast<size_t>(idx[t + 2])};
                    auto P = [&](size_t k) { return glm::dvec3(p[3 * k], p[3 * k + 1], p[3 * k + 2]); };
                    auto N = [&](size_t k) {
                        return glm::dvec3(normals[3 * k], normals[3 * k + 1], normals[3 * k + 2]);
                    };
                    auto UV = [&](size_t k) { return glm::dvec2(uv[2 * k], uv[2 * k + 1]); };
                    const glm::dvec3 e1 = P(i[1]) - P(i[0]), e2 = P(i[2]) - P(i[0]);
                    const glm::dvec3 face = glm::cross(e1, e2);
                    if (glm::length(face) < 1e-10) continue; // degenerate
                    if (glm::dot(face, N(i[0]) + N(i[1]) + N(i[2])) <= 0.0) ++inverted;
                    const glm::dvec2 d1 = UV(i[1]) - UV(i[0]), d2 = UV(i[2]) - UV(i[0]);
                    const double det = d1.x * d2.y - d2.x * d1.y;
                    if (std::abs(det) < 1e-12) continue;
                    const glm::dvec3 dpdu = (e1 * d2.y - e2 * d1.y) / det,
                                     dpdv = (e2 * d1.x - e1 * d2.x) / det;
                    ++measured;
                    const size_t k = i[0];
                    const glm::dvec3 tan(tangents[4 * k], tangents[4 * k + 1], tangents[4 * k + 2]);
                    if (glm::dot(tan, dpdu) <= 0.0) ++wrong_tangent;
                    if (glm::dot(glm::cross(N(k), tan) * tangents[4 * k + 3], -dpdv) <= 0.0)
                        ++wrong_handedness;
                }
                CHECK(measured > 0);
                CHECK(inverted == 0);
                // Smoothed tangents can disagree with a sliver's own uv gradient; demand 99% agreement.
                CHECK(wrong_tangent <= measured / 100);
                CHECK(wrong_handedness <= measured / 100);
            }
    }
}

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

TEST_CASE("ks_assetgen rejects bad command lines with a clear message") {
    REQUIRE_MESSAGE(fs::exists(generator()), "build the ks_assetgen target first: " << generator());
    ks::test::ScratchDir scratch;
    const std::string exe = shell_quote(generator());

    const auto no_out = ks::test::run_command(exe);
    CHECK(no_out.exit_code != 0);
    CHECK(no_out.output.find("--out is required") != std::string::npos);

    const auto unknown =
        ks::test::run_command(exe + " --out " + shell_quote(scratch.path()) + " --only unicorn");
    CHECK(unknown.exit_code != 0);
    CHECK(unknown.output.find("no asset named 'unicorn'") != std::string::npos);
    CHECK(unknown.output.find("--list") != std::string::npos);

    const auto typo = ks::test::run_command(exe + " --out " + shell_quote(scratch.path()) + " --onyl robot");
    CHECK(typo.exit_code != 0);
    CHECK(typo.output.find("unknown option --onyl") != std::string::npos);

    // An output path that is a file, not a folder: a clear error naming it, not a crash.
    ks::test::run_command("touch " + shell_quote(scratch / "blocker"));
    const auto blocked =
        ks::test::run_command(exe + " --out " + shell_quote(scratch / "blocker") + " --only particles");
    CHECK(blocked.exit_code == 1);
    CHECK(blocked.output.find("blocker") != std::string::npos);

    // The label font missing or corrupt: a clear error naming the file and the fix.
    const fs::path data = scratch / "data";
    fs::create_directories(data / "assets" / "fonts");
    fs::create_directories(data / "levels");
    const std::string with_data =
        "KS_DATA_DIR=" + shell_quote(data) + " " + exe + " --out " + shell_quote(scratch / "x");
    const auto no_font = ks::test::run_command(with_data + " --only pickups");
    CHECK(no_font.exit_code == 1);
    CHECK(no_font.output.find("DejaVuSans-Bold.ttf") != std::string::npos);
    CHECK(no_font.output.find("restore it from git") != std::string::npos);
    ks::test::run_command("printf 'not a font' > " +
                          shell_quote(data / "assets" / "fonts" / "DejaVuSans-Bold.ttf"));
    const auto bad_font = ks::test::run_command(with_data + " --only pickups");
    CHECK(bad_font.exit_code == 1);
    CHECK(bad_font.output.find("not a TrueType font") != std::string::npos);

    // --only writes just that asset.
    const auto one =
        ks::test::run_command(exe + " --out " + shell_quote(scratch / "one") + " --only gas_cylinder");
    CHECK(one.exit_code == 0);
    CHECK(fs::exists(scratch / "one" / "models" / "gas_cylinder.gltf"));
    CHECK_FALSE(fs::exists(scratch / "one" / "models" / "robot.gltf"));
}

TEST_CASE("ks_assetgen debug views: contact sheet and model previews") {
    REQUIRE_MESSAGE(fs::exists(generator()), "build the ks_assetgen target first: " << generator());
    ks::test::ScratchDir scratch;
    const auto run =
        ks::test::run_command(shell_quote(generator()) + " --out " + shell_quote(scratch / "out") +
                              " --only pickups --contact-sheet " + shell_quote(scratch / "sheet.png") +
                              " --preview " + shell_quote(scratch / "previews") + " --preview-size 100");
    INFO(run.output);
    REQUIRE(run.exit_code == 0);
    // PNG width and height from the IHDR chunk (big-endian at bytes 16..23).
    auto png_size = [](const fs::path& file) {
        const std::string bytes = ks::test::read_file(file);
        REQUIRE(bytes.size() > 24);
        CHECK(bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0);
        auto be32 = [&](size_t at) {
            return (static_cast<unsigned>(static_cast<unsigned char>(bytes[at])) << 24) |
                   (static_cast<unsigned>(static_cast<unsigned char>(bytes[at + 1])) << 16) |
                   (static_cast<unsigned>(static_cast<unsigned char>(bytes[at + 2])) << 8) |
                   static_cast<unsigned>(static_cast<unsigned char>(bytes[at + 3]));
        };
        return std::pair<unsigned, unsigned>(be32(16), be32(20));
    };
    // 12 pickup textures: 8 columns of 160 px, 2 rows of 178 px.
    CHECK(png_size(scratch / "sheet.png") == std::pair<unsigned, unsigned>(1280, 356));
    for (const char* model : {"pickup_health", "pickup_ammo", "pickup_shield"})
        CHECK(png_size(scratch / "previews" / (std::string(model) + ".png")) ==
              std::pair<unsigned, unsigned>(400, 100));

    const auto bad =
        ks::test::run_command(shell_quote(generator()) + " --out " + shell_quote(scratch / "out2") +
                              " --preview " + shell_quote(scratch / "p") + " --preview-size 9");
    CHECK(bad.exit_code == 1);
    CHECK(bad.output.find("--preview-size must be a whole number from 64 to 2048") != std::string::npos);
    CHECK_FALSE(fs::exists(scratch / "out2")); // refused before generating anything
}
