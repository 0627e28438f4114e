// The generated glTF models (assets/models, written by ks_assetgen) are structurally valid: buffers, views
// and accessors in range, their textures present, material factors glTF allows, a node forest, POSITION
// bounds exact, unit normals and tangents, indices in range, counter-clockwise front faces and tangents that
// follow the texture coordinates. Needs no GL context.
#include "assetgen_test_support.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace ks::test::assetgen {

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

} // namespace ks::test::assetgen
