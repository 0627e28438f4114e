#include "model/prefab.h"

#include "core/log.h"
#include "jsonio/describe.h"
#include "jsonio/document.h"
#include "jsonio/json_path.h"
#include "jsonio/object_reader.h"
#include "jsonio/text.h"
#include "level/diagnostics.h"
#include "level/entity_shapes.h"
#include "level/level_checks.h"
#include "level/level_io.h"
#include "level/level_reader.h"
#include "model/field_access.h"
#include "model/rotation.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

namespace ks::editor {
namespace {

constexpr const char* kFormat = "killswitch-prefab";
constexpr int kVersion = 1;
constexpr double kSameNumber = 1e-3;

Vec3 into_frame(const Vec3& p, const Frame& frame) {
    return Vec3(turned_offset(DVec3(p) - DVec3(frame.position), 1, -frame.yaw));
}
Vec3 out_of_frame(const Vec3& p, const Frame& frame) {
    return Vec3(DVec3(frame.position) + turned_offset(DVec3(p), 1, frame.yaw));
}

level::Entity turned_entity(const level::Entity& e, float yaw,
                            const std::function<Vec3(const Vec3&)>& place) {
    level::Entity out = e;
    out.position = place(e.position);
    out.rotation = level::keeps_pitch_and_roll(e.type())
                       ? turned_ypr(e.rotation, 1, yaw, RotationSpace::World)
                       : Vec3(wrap_degrees(e.rotation.x + yaw), e.rotation.y, e.rotation.z);
    if (auto* robot = out.try_as<level::RobotProps>())
        for (Vec3& point : robot->patrol.points) point = place(point);
    return out;
}

bool same_value(const FieldValue& a, const FieldValue& b) {
    if (a.index() != b.index()) return false;
    if (const auto* x = std::get_if<double>(&a)) return std::abs(*x - std::get<double>(b)) <= kSameNumber;
    if (const auto* x = std::get_if<Vec3>(&a))
        return glm::all(glm::lessThanEqual(glm::abs(*x - std::get<Vec3>(b)), Vec3(kSameNumber)));
    if (const auto* x = std::get_if<Vec2>(&a))
        return glm::all(glm::lessThanEqual(glm::abs(*x - std::get<Vec2>(b)), Vec2(kSameNumber)));
    return a == b;
}

bool same_angles(const Vec3& a, const Vec3& b) {
    for (int i = 0; i < 3; ++i)
        if (std::abs(wrap_degrees(a[i] - b[i])) > kSameNumber) return false;
    return true;
}

} // namespace

std::string prefab_name_problem(std::string_view name) {
    if (name.empty()) return "a prefab needs a name";
    if (jsonio::character_count(name) > kMaxPrefabNameLength)
        return "a prefab name has at most " + std::to_string(kMaxPrefabNameLength) + " characters";
    for (size_t i = 0; i < name.size(); ++i) {
        const char c = name[i];
        if ((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-') continue;
        size_t end = i + 1; // the whole character, not one byte of it
        while (end < name.size() && (static_cast<unsigned char>(name[end]) & 0xC0) == 0x80) ++end;
        return jsonio::quote_text(name) + " holds " + jsonio::quote_text(name.substr(i, end - i)) +
               ": a prefab name uses a-z, 0-9, _ and - (it names the file prefabs/NAME.json)";
    }
    return {};
}

namespace {

const char* const kPrefabExample = "a prefab file is {\"format\": \"killswitch-prefab\", \"version\": 1, "
                                   "\"name\": ..., \"entities\": [...]}; "
                                   "save it again from the editor";

// The prefab's fields, read as a level's are: every problem reported at its line:column, unknown fields (an
// "objectives" or "settings" copied from a level) warned about, each entity through the level's reader and
// checks.
void read_prefab(const jsonio::Json& root, level::DiagnosticSink& sink, Prefab& prefab) {
    jsonio::ObjectReader reader(root, "", sink, "prefab");
    std::string format;
    if (reader.text("format", format, jsonio::Need::Required, 0, kPrefabExample) && format != kFormat)
        sink.error("format", "not a prefab file: format is " + jsonio::quote_text(format), kPrefabExample);
    int version = kVersion;
    if (reader.whole("version", version, {0, 1e6}, jsonio::Need::Required) && version != kVersion)
        sink.error("version", "prefab version " + std::to_string(version) + " is not known",
                   "this editor reads version " + std::to_string(kVersion) +
                       "; save the prefab again from it");
    if (reader.text("name", prefab.name, jsonio::Need::Required, 0, kPrefabExample))
        if (std::string problem = prefab_name_problem(prefab.name); !problem.empty())
            sink.error("name", problem, "rename it in the file");
    prefab.title = prefab.name;
    reader.text("title", prefab.title);
    const jsonio::Json* list = reader.get("entities", jsonio::Need::Required, kPrefabExample);
    reader.finish();
    if (!list) return;
    if (!list->is_array() || list->empty() || list->size() > kMaxPrefabEntities) {
        sink.error("entities",
                   "a prefab needs a list of 1 to " + std::to_string(kMaxPrefabEntities) +
                       " entities, found " + jsonio::describe_value(*list) +
                       (list->is_array() ? " of " + std::to_string(list->size()) : ""),
                   kPrefabExample);
        return;
    }
    for (size_t i = 0; i < list->size(); ++i) {
        const std::string path = jsonio::element_path("entities", i);
        std::optional<level::Entity> entity = level::read_entity((*list)[i], path, sink);
        if (!entity) continue;
        level::check_entity(*entity, path, sink);
        entity->id = static_cast<int>(i) + 1;
        prefab.entities.push_back(std::move(*entity));
    }
}

} // namespace

Result<Prefab> prefab_from_text(std::string_view text, const std::string& file,
                                std::vector<Error>* warnings) {
    const jsonio::Document document = jsonio::Document::parse(text, file, {"prefab", kPrefabExample});
    level::DiagnosticSink sink(file, &document.positions());
    document.report_to(sink);
    Prefab prefab;
    if (const jsonio::Json* root = document.root()) read_prefab(*root, sink, prefab);
    const bool failed = sink.has_errors();
    std::vector<Error> errors;
    for (level::Diagnostic& d : sink.take_sorted()) {
        if (d.severity == level::Diagnostic::Severity::Error)
            errors.push_back(std::move(d.error));
        else if (warnings)
            warnings->push_back(std::move(d.error));
        else
            log::warn(d.error.str());
    }
    if (failed) return jsonio::combined_error(std::move(errors), file);
    return prefab;
}

std::string prefab_to_text(const Prefab& prefab) {
    nlohmann::ordered_json json;
    json["format"] = kFormat;
    json["version"] = kVersion;
    json["name"] = prefab.name;
    json["title"] = prefab.title;
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const level::Entity& e : prefab.entities)
        list.push_back(nlohmann::ordered_json(level::entity_to_json(e)));
    json["entities"] = std::move(list);
    return json.dump(2) + "\n";
}

level::Entity entity_into_frame(const level::Entity& world, const Frame& frame) {
    return turned_entity(world, -frame.yaw, [&](const Vec3& p) { return into_frame(p, frame); });
}

level::Entity entity_out_of_frame(const level::Entity& local, const Frame& frame) {
    return turned_entity(local, frame.yaw, [&](const Vec3& p) { return out_of_frame(p, frame); });
}

std::vector<std::string> differing_fields(const level::Entity& a, const level::Entity& b) {
    std::vector<std::string> out;
    for (const FieldDescriptor& field : describe_entity_fields(a)) {
        auto x = get_entity_field(a, field.name), y = get_entity_field(b, field.name);
        if (!x || !y) continue;
        const bool same = field.name == "rotation" ? same_angles(std::get<Vec3>(*x), std::get<Vec3>(*y))
                                                   : same_value(*x, *y);
        if (!same) out.push_back(field.name);
    }
    if (const auto* ra = a.try_as<level::RobotProps>()) {
        const auto& pa = ra->patrol.points;
        const auto& pb = b.as<level::RobotProps>().patrol.points;
        bool same = pa.size() == pb.size() && ra->patrol.mode == b.as<level::RobotProps>().patrol.mode &&
                    ra->patrol.wait == b.as<level::RobotProps>().patrol.wait;
        for (size_t i = 0; same && i < pa.size(); ++i)
            same = same_value(FieldValue(pa[i]), FieldValue(pb[i]));
        if (!same) out.emplace_back("patrol");
    }
    if (a.links != b.links) out.emplace_back("links");
    return out;
}

std::vector<level::Link> renamed_links(const std::vector<level::Link>& links,
                                       const std::unordered_map<std::string, std::string>& renames) {
    std::vector<level::Link> out = links;
    for (level::Link& link : out)
        if (auto it = renames.find(link.target); it != renames.end()) link.target = it->second;
    return out;
}

Result<level::Entity> refreshed_member(const level::Entity& local, const level::Entity& current,
                                       const Frame& frame, const std::vector<std::string>& overrides,
                                       const std::unordered_map<std::string, std::string>& renames) {
    level::Entity out = entity_out_of_frame(local, frame);
    out.id = current.id;
    out.name = current.name;
    out.links = renamed_links(local.links, renames);
    if (current.type() != out.type()) return out; // the prefab changed the type: nothing can be kept
    for (const std::string& field : overrides) {
        if (field == "name") continue;
        if (field == "links") {
            out.links = current.links;
        } else if (field == "patrol") {
            out.as<level::RobotProps>().patrol = current.as<level::RobotProps>().patrol;
        } else if (auto value = get_entity_field(current, field)) {
            if (auto r = set_entity_field(out, field, *value); !r) return r.error();
        }
    }
    return out;
}

} // namespace ks::editor
