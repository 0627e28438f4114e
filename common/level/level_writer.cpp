#include "level/level_writer.h"

#include "level/editor_data_io.h"

#include "level/brush_faces.h"

#include "jsonio/number_text.h"

#include <algorithm>
#include <cmath>

namespace ks::level {
namespace {

using Json = nlohmann::ordered_json;

Json number(float v) {
    return jsonio::float_to_double(v);
}

template <int N>
Json vec_json(const glm::vec<N, float>& v) {
    Json array = Json::array();
    for (int i = 0; i < N; ++i) array.push_back(number(v[i]));
    return array;
}

Json patrol_json(const Patrol& patrol) {
    Json json = Json::object();
    Json points = Json::array();
    for (const Vec3& p : patrol.points) points.push_back(vec_json(p));
    json["points"] = std::move(points);
    json["mode"] = patrol.mode.value;
    json["wait"] = number(patrol.wait);
    return json;
}

Json links_json(const std::vector<Link>& links);

class FieldWriter {
  public:
    explicit FieldWriter(Json& object) : object_(object) {}
    void field(float& v, const FieldInfo& info) { object_[info.name] = number(v); }
    void field(int& v, const FieldInfo& info) { object_[info.name] = v; }
    void field(bool& v, const FieldInfo& info) { object_[info.name] = v; }
    void field(std::string& v, const FieldInfo& info) { object_[info.name] = v; }
    void field(Vec2& v, const FieldInfo& info) { object_[info.name] = vec_json(v); }
    void field(Vec3& v, const FieldInfo& info) { object_[info.name] = vec_json(v); }
    void field(Color& v, const FieldInfo& info) { object_[info.name] = color_to_hex(v); }
    void field(Choice& v, const FieldInfo& info) { object_[info.name] = v.value; }
    void field(SoundName& v, const FieldInfo& info) { object_[info.name] = v.value; }
    // No patrol is no key at all (random wander), so robots without one save as they always did.
    void field(Patrol& v, const FieldInfo& info) {
        if (v.active()) object_[info.name] = patrol_json(v);
    }
    void field(brush::Brush& v, const FieldInfo& info) { object_[info.name] = brush_faces_json(v); }
    // Lists are left out while empty, so entities and objectives without them save as they always did.
    void field(std::vector<Link>& v, const FieldInfo& info) {
        if (!v.empty()) object_[info.name] = links_json(v);
    }
    void field(std::vector<std::string>& v, const FieldInfo& info) {
        if (!v.empty()) object_[info.name] = v;
    }

  private:
    Json& object_;
};

// Collects the names of the fields that are left out of a file while they hold their default.
struct OmittableFields {
    std::vector<std::string> names;
    template <class T>
    void field(T&, const FieldInfo& info) {
        if (info.omitted_at_default) names.emplace_back(info.name);
    }
};

// visit() is a non-const member (the same list serves readers); writing only reads the values.
template <class T>
Json fields_json(const T& object) {
    Json json = Json::object();
    FieldWriter writer(json);
    const_cast<T&>(object).visit(writer);
    OmittableFields omittable;
    T defaults{};
    defaults.visit(omittable);
    if (!omittable.names.empty()) {
        Json default_json = Json::object();
        FieldWriter default_writer(default_json);
        defaults.visit(default_writer);
        for (const std::string& name : omittable.names)
            if (json.contains(name) && default_json.contains(name) && json[name] == default_json[name])
                json.erase(name);
    }
    return json;
}

Json links_json(const std::vector<Link>& links) {
    Json array = Json::array();
    for (const Link& link : links) array.push_back(fields_json(link));
    return array;
}

} // namespace

Vec3 normalized_direction(Vec3 direction) {
    const float length = glm::length(direction);
    if (std::isfinite(length) && length > 1e-6f && std::fabs(length - 1.0f) > 1e-4f) direction /= length;
    return direction;
}

std::string color_to_hex(const Color& color) {
    static const char kDigits[] = "0123456789abcdef";
    std::string out = "#";
    for (float c : {color.r, color.g, color.b}) {
        const float clamped = std::isfinite(c) ? std::clamp(c, 0.0f, 1.0f) : 0.0f;
        const int byte = static_cast<int>(std::lround(clamped * 255.0f));
        out += kDigits[byte >> 4];
        out += kDigits[byte & 15];
    }
    return out;
}

Json write_entity(const Entity& entity) {
    Json json = Json::object();
    json["id"] = entity.id;
    json["type"] = std::string(type_name(entity.type()));
    json["name"] = entity.name;
    json["position"] = vec_json(entity.position);
    json["rotation"] = vec_json(entity.rotation);
    json["props"] = std::visit([](const auto& props) { return fields_json(props); }, entity.props);
    if (!entity.links.empty()) json["links"] = links_json(entity.links);
    return json;
}

Json write_level(const Level& level) {
    Json json = Json::object();
    json["format"] = std::string(kFormatName);
    json["version"] = kFormatVersion;
    json["name"] = level.name;
    Settings settings = level.settings;
    settings.sun_direction = normalized_direction(settings.sun_direction);
    json["settings"] = fields_json(settings);
    json["player_start"] = Json::object();
    json["player_start"]["position"] = vec_json(level.player_start.position);
    json["player_start"]["yaw"] = number(level.player_start.yaw);
    json["next_id"] = level.next_id;
    if (!level.objectives.empty()) {
        Json objectives = Json::array();
        for (const Objective& objective : level.objectives) objectives.push_back(fields_json(objective));
        json["objectives"] = std::move(objectives);
    }
    if (!level.links.empty()) json["links"] = links_json(level.links);
    Json entities = Json::array();
    for (const Entity& entity : level.entities) entities.push_back(write_entity(entity));
    json["entities"] = std::move(entities);
    if (!level.editor.empty()) json["editor"] = write_editor_data(level.editor);
    return json;
}

} // namespace ks::level
