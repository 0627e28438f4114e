#include "modelio/gltf_animation.h"

#include <assimp/Exporter.hpp>
#include <assimp/Importer.hpp>
#include <assimp/scene.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <memory>
#include <sstream>
#include <system_error>

namespace ks::modelio {

namespace gltf_io {

// Named, not anonymous: the module is built as one unity source with model_import.cpp.
// assimp keeps key times in ticks; its glTF reader and writer use milliseconds.
constexpr double kTicksPerSecond = 1000.0;

Error file_error(const std::filesystem::path& path, std::string what, std::string place = {},
                 std::string fix = {}) {
    return Error(std::move(what), Location(path.string(), 0, 0, std::move(place)), std::move(fix));
}

std::string lower_extension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

bool finite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
bool finite(const Quat& q) {
    return std::isfinite(q.w) && std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z);
}

std::string key_place(const std::string& animation, const std::string& node, const char* channel,
                      std::size_t key) {
    return "animation '" + animation + "', node '" + node + "', " + channel + " key " + std::to_string(key);
}

// ---- the file's JSON (a .gltf file, or a .glb's first chunk) ------------------------------------------

std::uint32_t read_u32(const std::string& bytes, std::size_t at) {
    std::uint32_t v = 0;
    std::memcpy(&v, bytes.data() + at, 4);
    return v;
}
// The JSON chunk of a .glb file.
Result<std::string> glb_json(const std::filesystem::path& path, const std::string& bytes) {
    if (bytes.size() < 20 || bytes.compare(0, 4, "glTF") != 0)
        return file_error(path, "not a binary glTF (.glb) file: no glTF header", "file header",
                          "export the file again as glTF 2.0 binary");
    const std::uint32_t json_length = read_u32(bytes, 12);
    if (read_u32(bytes, 16) != 0x4E4F534Au || 20 + std::size_t{json_length} > bytes.size())
        return file_error(path, "the .glb file is truncated or corrupt (its JSON chunk is cut off)",
                          "JSON chunk", "export the file again");
    return bytes.substr(20, json_length);
}

Result<std::string> read_bytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return file_error(path, "cannot open the file", {}, "check the path");
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

Result<nlohmann::json> parse_json(const std::filesystem::path& path, const std::string& text) {
    nlohmann::json doc = nlohmann::json::parse(text, nullptr, false);
    if (doc.is_discarded() || !doc.is_object())
        return file_error(path, "the glTF JSON is not valid (truncated or corrupt)", "JSON",
                          "export the file again");
    return doc;
}

// ---- writing --------------------------------------------------------------------------------------------

Result<void> check_scene(const std::filesystem::path& path, const AnimatedScene& scene) {
    for (std::size_t i = 0; i < scene.nodes.size(); ++i) {
        const AnimNode& n = scene.nodes[i];
        if (n.parent >= static_cast<int>(i) || n.parent < -1)
            return Error("node '" + n.name + "' names a parent that is not an earlier node",
                         Location(path.string()));
        if (!finite(n.translation) || !finite(n.rotation) || !finite(n.scale))
            return Error("node '" + n.name + "' has a rest transform that is not finite",
                         Location(path.string()));
    }
    for (const NodeAnimation& a : scene.animations)
        for (const NodeTrack& t : a.tracks) {
            if (std::none_of(scene.nodes.begin(), scene.nodes.end(),
                             [&](const AnimNode& n) { return n.name == t.node; }))
                return Error("animation '" + a.name + "' animates node '" + t.node +
                                 "', which is not in the scene",
                             Location(path.string()));
            if (t.translation_times.size() != t.translations.size() ||
                t.rotation_times.size() != t.rotations.size())
                return Error("animation '" + a.name + "', node '" + t.node +
                                 "': times and values differ in number",
                             Location(path.string()));
            for (std::size_t k = 0; k < t.translations.size(); ++k)
                if (!finite(t.translations[k]) || !std::isfinite(t.translation_times[k]))
                    return Error("a key is not finite",
                                 Location(path.string(), 0, 0, key_place(a.name, t.node, "translation", k)));
            for (std::size_t k = 0; k < t.rotations.size(); ++k)
                if (!finite(t.rotations[k]) || !std::isfinite(t.rotation_times[k]))
                    return Error("a key is not finite",
                                 Location(path.string(), 0, 0, key_place(a.name, t.node, "rotation", k)));
        }
    return ok();
}

aiNode* build_nodes(const AnimatedScene& scene) {
    std::vector<aiNode*> made;
    for (const AnimNode& n : scene.nodes) {
        auto* node = new aiNode(n.name);
        node->mTransformation =
            aiMatrix4x4(aiVector3D(n.scale.x, n.scale.y, n.scale.z),
                        aiQuaternion(n.rotation.w, n.rotation.x, n.rotation.y, n.rotation.z),
                        aiVector3D(n.translation.x, n.translation.y, n.translation.z));
        made.push_back(node);
    }
    // One root holds the scene's roots (assimp needs a single root; it is written as a node too).
    auto* root = new aiNode("killswitch_rig");
    std::vector<std::vector<aiNode*>> children(made.size() + 1);
    for (std::size_t i = 0; i < made.size(); ++i) {
        const int parent = scene.nodes[i].parent;
        children[parent < 0 ? made.size() : static_cast<std::size_t>(parent)].push_back(made[i]);
    }
    for (std::size_t i = 0; i <= made.size(); ++i) {
        aiNode* owner = i == made.size() ? root : made[i];
        if (children[i].empty()) continue;
        owner->addChildren(static_cast<unsigned>(children[i].size()), children[i].data());
    }
    return root;
}

aiAnimation* build_animation(const NodeAnimation& animation) {
    auto* out = new aiAnimation;
    out->mName = aiString(animation.name);
    out->mTicksPerSecond = kTicksPerSecond;
    double end = 0;
    out->mNumChannels = static_cast<unsigned>(animation.tracks.size());
    out->mChannels = new aiNodeAnim*[out->mNumChannels];
    for (std::size_t c = 0; c < animation.tracks.size(); ++c) {
        const NodeTrack& t = animation.tracks[c];
        auto* channel = new aiNodeAnim;
        channel->mNodeName = aiString(t.node);
        channel->mNumPositionKeys = static_cast<unsigned>(t.translations.size());
        channel->mPositionKeys = t.translations.empty() ? nullptr : new aiVectorKey[t.translations.size()];
        for (std::size_t k = 0; k < t.translations.size(); ++k) {
            const Vec3& v = t.translations[k];
            channel->mPositionKeys[k] =
                aiVectorKey(t.translation_times[k] * kTicksPerSecond, aiVector3D(v.x, v.y, v.z));
            end = std::max(end, t.translation_times[k]);
        }
        channel->mNumRotationKeys = static_cast<unsigned>(t.rotations.size());
        channel->mRotationKeys = t.rotations.empty() ? nullptr : new aiQuatKey[t.rotations.size()];
        for (std::size_t k = 0; k < t.rotations.size(); ++k) {
            const Quat& q = t.rotations[k];
            channel->mRotationKeys[k] =
                aiQuatKey(t.rotation_times[k] * kTicksPerSecond, aiQuaternion(q.w, q.x, q.y, q.z));
            end = std::max(end, t.rotation_times[k]);
        }
        out->mChannels[c] = channel;
    }
    out->mDuration = end * kTicksPerSecond;
    return out;
}

} // namespace gltf_io

Result<void> write_gltf_animations(const std::filesystem::path& path, const AnimatedScene& scene) {
    using namespace gltf_io;
    const std::string ext = lower_extension(path);
    if (ext != ".gltf" && ext != ".glb")
        return file_error(path, "\"" + ext + "\" is not a glTF file name", {}, "name the file .glb or .gltf");
    if (auto checked = check_scene(path, scene); !checked) return checked.error();
    aiScene out;
    out.mRootNode = build_nodes(scene);
    out.mNumAnimations = static_cast<unsigned>(scene.animations.size());
    out.mAnimations = out.mNumAnimations == 0 ? nullptr : new aiAnimation*[out.mNumAnimations];
    for (std::size_t a = 0; a < scene.animations.size(); ++a)
        out.mAnimations[a] = build_animation(scene.animations[a]);
    Assimp::Exporter exporter;
    if (exporter.Export(&out, ext == ".glb" ? "glb2" : "gltf2", path.string()) != AI_SUCCESS)
        return file_error(path, std::string("cannot write the glTF file: ") + exporter.GetErrorString(), {},
                          "check that the folder exists and is writable");
    return ok();
}

namespace gltf_io {

// ---- reading --------------------------------------------------------------------------------------------

// What the file's JSON says about each animation channel, which assimp does not keep: the property animated
// and the sampler's interpolation. Keyed by animation index, node name and path.
struct ChannelInfo {
    std::size_t animation = 0;
    std::string node, path, interpolation;
};

std::vector<ChannelInfo> scan_channels(const nlohmann::json& doc) {
    std::vector<ChannelInfo> out;
    const auto nodes = doc.find("nodes");
    const auto animations = doc.find("animations");
    if (animations == doc.end() || !animations->is_array()) return out;
    for (std::size_t a = 0; a < animations->size(); ++a) {
        const nlohmann::json& anim = (*animations)[a];
        if (!anim.is_object() || !anim.contains("channels") || !anim["channels"].is_array()) continue;
        const nlohmann::json samplers = anim.value("samplers", nlohmann::json::array());
        for (const nlohmann::json& channel : anim["channels"]) {
            if (!channel.is_object() || !channel.contains("target") || !channel["target"].is_object())
                continue;
            ChannelInfo info;
            info.animation = a;
            const nlohmann::json& target = channel["target"];
            info.path = target.value("path", std::string());
            const auto node = target.find("node");
            if (node != target.end() && node->is_number_unsigned() && nodes != doc.end() &&
                nodes->is_array() && node->get<std::size_t>() < nodes->size()) {
                const nlohmann::json& n = (*nodes)[node->get<std::size_t>()];
                info.node = n.is_object() ? n.value("name", std::string()) : std::string();
            }
            const auto sampler = channel.find("sampler");
            info.interpolation = "LINEAR";
            if (sampler != channel.end() && sampler->is_number_unsigned() && samplers.is_array() &&
                sampler->get<std::size_t>() < samplers.size() &&
                samplers[sampler->get<std::size_t>()].is_object())
                info.interpolation =
                    samplers[sampler->get<std::size_t>()].value("interpolation", std::string("LINEAR"));
            out.push_back(std::move(info));
        }
    }
    return out;
}

const ChannelInfo* find_channel(const std::vector<ChannelInfo>& channels, std::size_t animation,
                                const std::string& node, const char* path) {
    for (const ChannelInfo& c : channels)
        if (c.animation == animation && c.node == node && c.path == path) return &c;
    return nullptr;
}

KeyInterpolation interpolation_of(const ChannelInfo& info) {
    if (info.interpolation == "STEP") return KeyInterpolation::Step;
    if (info.interpolation == "CUBICSPLINE") return KeyInterpolation::CubicSpline;
    return KeyInterpolation::Linear;
}

Result<nlohmann::json> read_document(const std::filesystem::path& path, bool binary) {
    auto bytes = read_bytes(path);
    if (!bytes) return bytes.error();
    if (bytes->empty()) return file_error(path, "the file is empty", {}, "export the animation again");
    if (!binary) return parse_json(path, *bytes);
    auto json = glb_json(path, *bytes);
    if (!json) return json.error();
    return parse_json(path, *json);
}

void collect_nodes(const aiNode* node, int parent, std::vector<AnimNode>& out) {
    std::vector<std::pair<const aiNode*, int>> stack{{node, parent}};
    while (!stack.empty()) {
        auto [n, p] = stack.back();
        stack.pop_back();
        aiVector3D s, t;
        aiQuaternion r;
        n->mTransformation.Decompose(s, r, t);
        out.push_back(AnimNode{n->mName.C_Str(), p, Vec3(t.x, t.y, t.z), Quat(r.w, r.x, r.y, r.z),
                               Vec3(s.x, s.y, s.z)});
        const int index = static_cast<int>(out.size()) - 1;
        for (unsigned c = n->mNumChildren; c-- > 0;) stack.emplace_back(n->mChildren[c], index);
    }
}

template <class Key, class Value, class Convert>
Result<void> read_keys(const std::filesystem::path& path, const Key* keys, unsigned count, double ticks,
                       const std::string& place, std::vector<double>& times, std::vector<Value>& values,
                       Convert convert) {
    for (unsigned k = 0; k < count; ++k) {
        const double time = keys[k].mTime / ticks;
        const Value value = convert(keys[k].mValue);
        if (!std::isfinite(time) || !finite(value))
            return file_error(path, "a key is not a finite number (NaN or infinity)",
                              place + " key " + std::to_string(k),
                              "fix the key in the animation program and export again");
        if (!times.empty() && time <= times.back())
            return file_error(path, "key times do not increase", place + " key " + std::to_string(k),
                              "export the animation again");
        times.push_back(time);
        values.push_back(value);
    }
    return ok();
}

Result<NodeAnimation> read_animation(const std::filesystem::path& path, const aiAnimation& anim,
                                     std::size_t index, const std::vector<ChannelInfo>& channels,
                                     std::vector<std::string>& ignored) {
    NodeAnimation out;
    out.name = anim.mName.length > 0 ? anim.mName.C_Str() : "animation_" + std::to_string(index);
    const double ticks = anim.mTicksPerSecond > 0 ? anim.mTicksPerSecond : kTicksPerSecond;
    for (unsigned c = 0; c < anim.mNumChannels; ++c) {
        const aiNodeAnim& channel = *anim.mChannels[c];
        NodeTrack track;
        track.node = channel.mNodeName.C_Str();
        const std::string place = "animation '" + out.name + "', node '" + track.node + "', ";
        // assimp fills a property the file does not animate with one rest key: only animated ones are read.
        if (const ChannelInfo* info = find_channel(channels, index, track.node, "translation")) {
            track.translation_interpolation = interpolation_of(*info);
            auto r = read_keys(path, channel.mPositionKeys, channel.mNumPositionKeys, ticks,
                               place + "translation", track.translation_times, track.translations,
                               [](const aiVector3D& v) { return Vec3(v.x, v.y, v.z); });
            if (!r) return r.error();
        }
        if (const ChannelInfo* info = find_channel(channels, index, track.node, "rotation")) {
            track.rotation_interpolation = interpolation_of(*info);
            auto r = read_keys(path, channel.mRotationKeys, channel.mNumRotationKeys, ticks,
                               place + "rotation", track.rotation_times, track.rotations,
                               [](const aiQuaternion& q) { return Quat(q.w, q.x, q.y, q.z); });
            if (!r) return r.error();
        }
        if (track.translation_interpolation == KeyInterpolation::CubicSpline ||
            track.rotation_interpolation == KeyInterpolation::CubicSpline)
            ignored.push_back(place + "cubic-spline tangents (the keys are joined linearly)");
        if (!track.translations.empty() || !track.rotations.empty()) out.tracks.push_back(std::move(track));
    }
    for (const ChannelInfo& info : channels)
        if (info.animation == index && (info.path == "scale" || info.path == "weights"))
            ignored.push_back("animation '" + out.name + "', node '" + info.node + "', " + info.path +
                              " channel (clips animate rotation and translation only)");
    return out;
}

} // namespace gltf_io

Result<AnimatedScene> read_gltf_animations(const std::filesystem::path& path) {
    using namespace gltf_io;
    const std::string ext = lower_extension(path);
    if (ext != ".gltf" && ext != ".glb")
        return file_error(path, "\"" + ext + "\" is not a glTF file", {},
                          "export the animation as .glb or .gltf");
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        return file_error(path, "no such file", {}, "check the path");
    auto doc = read_document(path, ext == ".glb");
    if (!doc) return doc.error();
    const std::vector<ChannelInfo> channels = scan_channels(*doc);
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(path.string(), 0);
    if (scene == nullptr || scene->mRootNode == nullptr)
        return file_error(path, std::string("cannot read the glTF file: ") + importer.GetErrorString(), {},
                          "the file is truncated or corrupt: export it again");
    AnimatedScene out;
    collect_nodes(scene->mRootNode, -1, out.nodes);
    for (unsigned a = 0; a < scene->mNumAnimations; ++a) {
        auto animation = read_animation(path, *scene->mAnimations[a], a, channels, out.ignored);
        if (!animation) return animation.error();
        out.animations.push_back(std::move(*animation));
    }
    if (out.animations.empty())
        return file_error(path, "the file has no animations", "animations",
                          "export with animations on (Blender: glTF export > Animation)");
    return out;
}

} // namespace ks::modelio
