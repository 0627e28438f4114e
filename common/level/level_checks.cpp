#include "level/level_checks.h"

#include "jsonio/number_text.h"
#include "jsonio/suggest.h"
#include "jsonio/text.h"
#include "level/brush_faces.h"
#include "level/entity_shapes.h"
#include "level/logic_checks.h"
#include "level/model_entity.h"
#include "level/patrol_checks.h"
#include "level/sound_name.h"
#include "level/texture_names.h"
#include "modelio/model_files.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace ks::level {
namespace {

using jsonio::element_path;
using jsonio::join;
using jsonio::member_path;

void report_not_finite(const std::string& shown, const std::string& path, const FieldInfo& info,
                       DiagnosticSink& sink) {
    sink.error(path, "value is " + shown + " (not a finite number)", "valid: " + range_text(info));
}

void report_out_of_range(const std::string& shown, const std::string& path, const FieldInfo& info,
                         DiagnosticSink& sink) {
    std::string hint = "valid: " + range_text(info);
    if (info.tooltip && *info.tooltip) hint += "; " + std::string(info.tooltip);
    sink.error(path, shown + " is out of range", hint);
}

// Whether a float field's value passes (finite, in range compared in float precision, as check_float):
// the common case, checked before any message or path is built.
bool float_passes(float v, const FieldInfo& info) {
    return std::isfinite(v) && v >= static_cast<float>(info.min) && v <= static_cast<float>(info.max);
}

void check_int(int v, const std::string& path, const FieldInfo& info, DiagnosticSink& sink) {
    if (v < info.min || v > info.max) report_out_of_range(std::to_string(v), path, info, sink);
}

// Float fields are compared in float precision: 0.01 in a file becomes 0.00999999978f, which must still
// pass a documented minimum of 0.01. (Not by rounding the bounds through float into a copied FieldInfo:
// GCC 12.2 at -O2 drops that double->float->double round trip when it merges the struct copy.)
void check_float(float v, const std::string& shown, const std::string& path, const FieldInfo& info,
                 DiagnosticSink& sink) {
    const float lo = static_cast<float>(info.min);
    const float hi = static_cast<float>(info.max);
    if (!std::isfinite(v))
        report_not_finite(shown, path, info, sink);
    else if (v < lo || v > hi)
        report_out_of_range(shown, path, info, sink);
}

// The read-only twin of FieldReader: walks the same visit() list and checks each value.
class FieldChecker {
  public:
    FieldChecker(std::string path, DiagnosticSink& sink, std::string subject = {})
        : path_(std::move(path)), sink_(sink), subject_(std::move(subject)) {}

    void field(float& v, const FieldInfo& info) {
        if (!float_passes(v, info)) check_float(v, jsonio::readable_float(v), path_of(info), info, sink_);
    }
    void field(int& v, const FieldInfo& info) {
        if (v < info.min || v > info.max) check_int(v, path_of(info), info, sink_);
    }
    void field(bool&, const FieldInfo&) {}
    // A text field with a non-negative minimum bounds its length (a message's text).
    void field(std::string& v, const FieldInfo& info) {
        if (is_texture_field(info.name) && v.empty())
            sink_.error(path_of(info), "texture name is empty",
                        "name a material from assets/textures, e.g. \"concrete\"");
        const auto length = static_cast<double>(jsonio::character_count(v));
        if (info.min >= 0 && (length < info.min || length > info.max))
            sink_.error(path_of(info),
                        v.empty() ? std::string(info.name) + " is empty"
                                  : std::string(info.name) + " of " + jsonio::format_readable(length) +
                                        " characters is too long",
                        "valid: " + jsonio::format_readable(info.min) + " .. " +
                            jsonio::format_readable(info.max) + " characters; " + info.tooltip);
    }
    template <int N>
    void field(glm::vec<N, float>& v, const FieldInfo& info) {
        for (int i = 0; i < N; ++i)
            if (!float_passes(v[i], info))
                check_float(v[i], jsonio::readable_float(v[i]), element_path(path_of(info), i), info, sink_);
    }
    void field(Color& c, const FieldInfo& info) {
        const FieldInfo unit_range{info.name, info.tooltip, 0, 1, ""};
        const float components[3] = {c.r, c.g, c.b};
        static const char* const kNames[3] = {"red", "green", "blue"};
        for (int i = 0; i < 3; ++i) {
            if (!std::isfinite(components[i]) || components[i] < 0 || components[i] > 1)
                check_float(components[i],
                            std::string(kNames[i]) + " " + jsonio::readable_float(components[i]),
                            path_of(info), unit_range, sink_);
        }
    }
    void field(Choice& v, const FieldInfo& info) {
        if (std::find(v.options.begin(), v.options.end(), v.value) == v.options.end())
            sink_.error(path_of(info),
                        "unknown " + std::string(info.name) + " " + jsonio::quote_text(v.value),
                        "valid: " + join(v.options));
    }
    // min and max of a sound name's FieldInfo bound its length (level.h).
    void field(SoundName& v, const FieldInfo& info) {
        const auto problem =
            sound_name_problem(v.value, static_cast<int>(info.min), static_cast<int>(info.max));
        if (!problem.message.empty()) sink_.error(path_of(info), problem.message, problem.hint);
    }
    // A patrol's problems lie deep inside one robot, so their messages name it.
    void field(Patrol& v, const FieldInfo& info) {
        SubjectScope scope(sink_, subject_);
        check_patrol(v, path_of(info), sink_);
    }

    // The planes are valid by construction (brush::Brush refuses others); an empty material is not.
    void field(brush::Brush& v, const FieldInfo& info) {
        SubjectScope scope(sink_, subject_);
        check_brush_materials(v, path_of(info), sink_);
    }

  private:
    std::string path_of(const FieldInfo& info) const { return member_path(path_, info.name); }
    std::string path_;
    DiagnosticSink& sink_;
    std::string subject_;
};

// visit() is a non-const member (the same list serves readers that write); the checker only reads.
template <class T>
void check_fields(const T& object, const std::string& path, DiagnosticSink& sink, std::string subject = {}) {
    FieldChecker checker(path, sink, std::move(subject));
    const_cast<T&>(object).visit(checker);
}

void check_placement(const Vec3& position, const Vec3& rotation, const std::string& path,
                     DiagnosticSink& sink) {
    FieldChecker checker(path, sink);
    Vec3 p = position, r = rotation;
    checker.field(p, {"position", "Bottom centre of the entity", -kPositionLimit, kPositionLimit, "units"});
    checker.field(r, {"rotation", "Yaw, pitch, roll", -kAngleLimit, kAngleLimit, "deg"});
}

// The placed model's largest side against what a level can hold and what a player can see: a scale typed
// for another unit (100 for centimetres on a file already in metres) is a warning, the fix the scale.
void check_model_size(const modelio::ImportedModel& model, float scale, const std::string& subject,
                      const std::string& scale_path, DiagnosticSink& sink) {
    const Vec3 sides = model.bounds.max - model.bounds.min;
    const float file_size = std::max({sides.x, sides.y, sides.z}), placed = file_size * scale;
    const std::string file_says =
        "; the file alone is " + jsonio::readable_float(file_size) + " units across";
    if (placed > kMaxPlacedModelSize)
        sink.warning(scale_path,
                     subject + "scaled by " + jsonio::readable_float(scale) + " it is " +
                         jsonio::readable_float(placed) + " units across, larger than a level (" +
                         jsonio::readable_float(kMaxPlacedModelSize) + ")",
                     "reset the scale to 1" + file_says);
    else if (placed < kMinPlacedModelSize)
        sink.warning(scale_path,
                     subject + "scaled by " + jsonio::readable_float(scale) + " it is " +
                         jsonio::readable_float(placed) + " units across, too small to see (under " +
                         jsonio::readable_float(kMinPlacedModelSize) + ")",
                     "reset the scale to 1" + file_says);
}

// A badly spelt name is an error; a file that is missing or cannot be read, or a collision that cannot be
// built, is a warning: the level still opens and the game draws a marker in its place (docs/models.md).
void check_model(const Entity& entity, const ModelProps& model, const std::string& props_path,
                 DiagnosticSink& sink) {
    if (model.file.empty()) return; // the field check reports the empty name
    const std::string subject = entity_subject(entity) + ": ";
    if (Result<void> name = modelio::check_model_name(model.file); !name) {
        sink.error(member_path(props_path, "file"), subject + name.error().message, name.error().hint);
        return;
    }
    Result<std::shared_ptr<const modelio::ImportedModel>> file = entity_model(entity);
    if (!file) {
        sink.warning(member_path(props_path, "file"), subject + file.error().str());
        return;
    }
    check_model_size(**file, model.scale, subject, member_path(props_path, "scale"), sink);
    if (Result<std::vector<brush::Brush>> collision = model_collision(entity); !collision)
        sink.warning(member_path(props_path, "collision"), collision.error().message, collision.error().hint);
    if (Result<std::optional<CollisionMesh>> mesh = model_mesh_collision(entity); !mesh)
        sink.warning(member_path(props_path, "collision"), mesh.error().message, mesh.error().hint);
}

} // namespace

void check_entity(const Entity& entity, const std::string& path, DiagnosticSink& sink) {
    if (entity.id < 1)
        sink.error(member_path(path, "id"), "id " + std::to_string(entity.id) + " is not positive",
                   "ids are whole numbers >= 1");
    check_placement(entity.position, entity.rotation, path, sink);
    const std::string props_path = member_path(path, "props");
    const std::string subject = entity_subject(entity);
    std::visit([&](const auto& props) { check_fields(props, props_path, sink, subject); }, entity.props);

    const auto* spawner = entity.try_as<SpawnerProps>();
    const RobotProps* robot = spawner ? &spawner->robot : entity.try_as<RobotProps>();
    if (robot && robot->eye_radius_min > robot->eye_radius_max)
        sink.error(member_path(props_path, "eye_radius_min"),
                   "eye_radius_min " + jsonio::readable_float(robot->eye_radius_min) +
                       " is larger than eye_radius_max " + jsonio::readable_float(robot->eye_radius_max),
                   "the robot starts following inside eye_radius_min and keeps following inside "
                   "eye_radius_max, so min <= max");
    if (entity.type() == EntityType::Brush) {
        if (Result<brush::Brush> placed = world_brush(entity); !placed)
            sink.error(member_path(path, "position"), entity_subject(entity) + ": " + placed.error().message,
                       placed.error().hint);
    }
    if (const auto* model = entity.try_as<ModelProps>()) check_model(entity, *model, props_path, sink);
    if (spawner && spawner->robot.dummy)
        sink.error(member_path(props_path, "dummy"),
                   entity_subject(entity) + ": a spawner cannot make animation dummies",
                   "set \"dummy\": false; dummies belong in the dojo");
    SubjectScope scope(sink, subject);
    check_links(entity.links, entity_events(entity.type()), with_article(type_name(entity.type())),
                member_path(path, "links"), sink);
}

void check_level(const Level& level, DiagnosticSink& sink, const std::vector<size_t>& source_index) {
    check_fields(level.settings, "settings", sink);
    const Vec3 sun = level.settings.sun_direction;
    if (is_finite(sun) && glm::dot(sun, sun) < 1e-12f)
        sink.error("settings.sun_direction", "sun_direction is zero",
                   "give the direction sunlight travels, e.g. [-0.3, -1, -0.2]");

    {
        FieldChecker checker("player_start", sink);
        Vec3 position = level.player_start.position;
        float yaw = level.player_start.yaw;
        checker.field(position, {"position", "Feet of the player", -kPositionLimit, kPositionLimit, "units"});
        checker.field(yaw, {"yaw", "Facing; 0 faces -z", -kAngleLimit, kAngleLimit, "deg"});
    }

    std::unordered_map<int, size_t> first_use; // id -> index of the entity that has it first
    int largest_id = 0;
    for (size_t i = 0; i < level.entities.size(); ++i) {
        const Entity& entity = level.entities[i];
        const size_t shown = i < source_index.size() ? source_index[i] : i;
        const std::string path = element_path("entities", shown);
        check_entity(entity, path, sink);
        largest_id = std::max(largest_id, entity.id);
        auto [it, inserted] = first_use.emplace(entity.id, i);
        if (!inserted) {
            const Entity& first = level.entities[it->second];
            const size_t first_shown =
                it->second < source_index.size() ? source_index[it->second] : it->second;
            sink.error(member_path(path, "id"),
                       "duplicate id " + std::to_string(entity.id) + " (also used by entities[" +
                           std::to_string(first_shown) + "] " + jsonio::quote_text(first.name) + ")",
                       "ids must be unique; give this entity an unused id such as " +
                           std::to_string(std::max(level.next_id, largest_id + 1)));
        }
    }
    check_patrol_reach(level, sink, source_index);
    check_logic(level, sink, source_index);
    check_texture_names(level, shipped_texture_names(), sink, source_index);
    if (level.next_id <= largest_id)
        sink.error("next_id",
                   "next_id " + std::to_string(level.next_id) + " is not above the largest id " +
                       std::to_string(largest_id) + ", so a new entity would reuse an id",
                   "set next_id to " + std::to_string(largest_id + 1) + " or more");
}

} // namespace ks::level
