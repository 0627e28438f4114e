#pragma once
// Shared by the asset generator's tests (tests/render/test_assetgen*.cpp): where the committed assets are,
// the models the generator writes, and reading a committed glTF model and its accessors.
#include "test_support.h"

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace ks::test::assetgen {

namespace fs = std::filesystem;
using nlohmann::json;

inline fs::path committed() {
    return ks::test::source_dir() / "assets";
}

inline const std::vector<std::string>& model_names() {
    static const std::vector<std::string> names = {
        "robot",         "rifle",        "door",          "floor_light", "top_light",
        "control_panel", "gas_cylinder", "pickup_health", "pickup_ammo", "pickup_shield"};
    return names;
}

struct Gltf {
    json doc;
    std::string bin;
};

inline Gltf load_model(const std::string& name) {
    Gltf g;
    const std::string text = ks::test::read_file(committed() / "models" / (name + ".gltf"));
    g.doc = json::parse(text, nullptr, false);
    g.bin = ks::test::read_file(committed() / "models" / (name + ".bin"));
    return g;
}

inline int components(const std::string& type) {
    static const std::map<std::string, int> n = {{"SCALAR", 1}, {"VEC2", 2}, {"VEC3", 3}, {"VEC4", 4}};
    auto it = n.find(type);
    return it == n.end() ? 0 : it->second;
}

inline int component_size(int component_type) {
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
inline std::vector<double> read_accessor(const Gltf& g, int index) {
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

} // namespace ks::test::assetgen
