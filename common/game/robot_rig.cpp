#include "game/robot_rig.h"

#include "core/files.h"
#include "core/log.h"
#include "core/paths.h"

#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include <cmath>

namespace ks::game {

Result<anim::Rig> rig_with_model_offsets(const anim::Rig& rig, const std::filesystem::path& gltf) {
    auto text = files::read_text(gltf);
    if (!text) return text.error();
    const auto doc = nlohmann::json::parse(*text, nullptr, false);
    if (doc.is_discarded() || !doc.is_object() || !doc.contains("nodes") || !doc["nodes"].is_array())
        return Error("not a glTF JSON file with a \"nodes\" array", Location(gltf.string()),
                     "regenerate the robot model (see docs/assets.md)");
    std::vector<anim::RigNode> nodes(rig.nodes().begin(), rig.nodes().end());
    const auto& gnodes = doc["nodes"];
    for (std::size_t i = 0; i < gnodes.size(); ++i) {
        const auto& n = gnodes[i];
        if (!n.is_object() || !n.contains("name") || !n["name"].is_string()) continue;
        const int index = rig.find(n["name"].get<std::string>());
        if (index < 0) continue;
        auto& node = nodes[static_cast<std::size_t>(index)];
        const std::string where = "nodes[" + std::to_string(i) + "]";
        auto read = [&](const char* key, std::size_t count, float* out) -> Result<void> {
            if (!n.contains(key)) return ok();
            const auto& a = n[key];
            if (!a.is_array() || a.size() != count)
                return Error(std::string(key) + " must be an array of " + std::to_string(count) + " numbers",
                             Location(gltf.string(), 0, 0, where + "." + key), "fix or regenerate the model");
            for (std::size_t k = 0; k < count; ++k) {
                if (!a[k].is_number() || !std::isfinite(a[k].get<double>()))
                    return Error(std::string(key) + " holds a non-finite or non-number value",
                                 Location(gltf.string(), 0, 0, where + "." + key),
                                 "fix or regenerate the model");
                out[k] = a[k].get<float>();
            }
            return ok();
        };
        float t[3] = {node.rest_position.x, node.rest_position.y, node.rest_position.z};
        float q[4] = {0, 0, 0, 1};
        float s[3] = {node.rest_scale.x, node.rest_scale.y, node.rest_scale.z};
        if (auto r = read("translation", 3, t); !r) return r.error();
        if (auto r = read("rotation", 4, q); !r) return r.error();
        if (auto r = read("scale", 3, s); !r) return r.error();
        node.rest_position = Vec3(t[0], t[1], t[2]);
        node.rest_scale = Vec3(s[0], s[1], s[2]);
        if (n.contains("rotation")) node.rest_euler = glm::eulerAngles(Quat(q[3], q[0], q[1], q[2]));
    }
    return anim::Rig::create(std::move(nodes));
}

Result<std::shared_ptr<const anim::AnimationLibrary>> load_robot_animations() {
    auto lib = anim::load_animation_library(paths::asset("animations/robot.json"));
    if (!lib) return lib.error();
    const auto model = paths::asset("models/robot.gltf");
    auto rig = rig_with_model_offsets(lib->rig, model);
    if (!rig) {
        log::warn("robot shots use the clip file's joint offsets: " + rig.error().str());
    } else if (auto clips = anim::compile(lib->file, *rig); !clips) {
        log::warn("robot clips do not fit the model's rig, using the clip file's: " + clips.error().str());
    } else {
        lib->rig = std::move(*rig);
        lib->clips = std::move(*clips);
    }
    return std::make_shared<const anim::AnimationLibrary>(std::move(*lib));
}

} // namespace ks::game
