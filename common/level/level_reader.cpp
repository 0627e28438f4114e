#include "level/level_reader.h"

#include "level/editor_data_io.h"

#include "level/brush_faces.h"

#include "jsonio/describe.h"
#include "jsonio/number_text.h"
#include "jsonio/object_reader.h"
#include "jsonio/suggest.h"
#include "jsonio/text.h"
#include "level/patrol_checks.h"

#include <algorithm>
#include <cfloat>
#include <climits>
#include <cmath>

namespace ks::level {
namespace {

using jsonio::closest_match;
using jsonio::describe_value;
using jsonio::element_path;
using jsonio::join;
using jsonio::member_path;

using Json = nlohmann::ordered_json;

// A JSON number as a double: the shared read (jsonio/object_reader.h) with the level's own range text.
bool read_double(const Json& value, const std::string& path, const std::string& valid, DiagnosticSink& sink,
                 double& out) {
    return jsonio::read_finite(value, path, sink, out, valid);
}

// The common case, a finite number in float range with nothing reported about the document's numbers,
// read without building the messages a problem would need (the reads are most of a level's load).
bool read_plain_float(const Json& value, const DiagnosticSink& sink, float& out) {
    if (!value.is_number() || sink.any_reported()) return false;
    const double d = value.get<double>();
    if (!std::isfinite(d) || std::fabs(d) > FLT_MAX) return false;
    out = static_cast<float>(d);
    return true;
}

bool read_float(const Json& value, const std::string& path, const FieldInfo& info, DiagnosticSink& sink,
                float& out) {
    if (read_plain_float(value, sink, out)) return true;
    double d = 0;
    if (!read_double(value, path, range_text(info), sink, d)) return false;
    if (std::fabs(d) > FLT_MAX) {
        sink.error(path, jsonio::format_number(d) + " is too large (beyond a 32-bit float)",
                   "valid: " + range_text(info));
        return false;
    }
    out = static_cast<float>(d);
    return true;
}

bool read_int(const Json& value, const std::string& path, const FieldInfo& info, DiagnosticSink& sink,
              int& out) {
    double d = 0;
    if (!read_double(value, path, "whole numbers " + range_text(info), sink, d)) return false;
    if (d != std::floor(d) || d < INT_MIN || d > INT_MAX) {
        sink.error(path, jsonio::format_number(d) + " is not a whole number",
                   "valid: whole numbers " + range_text(info));
        return false;
    }
    out = static_cast<int>(d);
    return true;
}

template <int N>
bool read_vec(const Json& value, const std::string& path, const FieldInfo& info, DiagnosticSink& sink,
              glm::vec<N, float>& out) {
    static const char* const kShapes[] = {"", "[x]", "[x, y]", "[x, y, z]"};
    if (!value.is_array() || value.size() != N) {
        sink.error(path,
                   "expected an array of " + std::to_string(N) + " numbers " + kShapes[N] + ", found " +
                       describe_value(value) +
                       (value.is_array() ? " of " + std::to_string(value.size()) : ""),
                   "valid components: " + range_text(info));
        return false;
    }
    glm::vec<N, float> result = out;
    bool ok = true;
    for (int i = 0; i < N; ++i)
        if (!read_plain_float(value[i], sink, result[i]))
            ok &= read_float(value[i], element_path(path, i), info, sink, result[i]);
    if (ok) out = result;
    return ok;
}

int hex_digit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

bool read_color(const Json& value, const std::string& path, DiagnosticSink& sink, Color& out) {
    const char* const kHint = "write a colour as \"#rrggbb\" in hex digits, e.g. \"#ffcc80\"";
    if (!value.is_string()) {
        sink.error(path, "expected a colour string, found " + describe_value(value), kHint);
        return false;
    }
    const std::string& s = value.get_ref<const std::string&>();
    int digits[6];
    bool ok = s.size() == 7 && s[0] == '#';
    for (int i = 0; ok && i < 6; ++i) ok = (digits[i] = hex_digit(s[static_cast<size_t>(i) + 1])) >= 0;
    if (!ok) {
        sink.error(path, "bad colour " + jsonio::quote(value), kHint);
        return false;
    }
    out.r = static_cast<float>(digits[0] * 16 + digits[1]) / 255.0f;
    out.g = static_cast<float>(digits[2] * 16 + digits[3]) / 255.0f;
    out.b = static_cast<float>(digits[4] * 16 + digits[5]) / 255.0f;
    return true;
}

bool read_string(const Json& value, const std::string& path, DiagnosticSink& sink, std::string& out) {
    return jsonio::read_text(value, path, sink, out);
}

bool read_bool(const Json& value, const std::string& path, DiagnosticSink& sink, bool& out) {
    return jsonio::read_flag(value, path, sink, out);
}

bool expect_object(const Json& value, const std::string& path, std::string_view what, DiagnosticSink& sink) {
    if (value.is_object()) return true;
    sink.error(path, "expected " + std::string(what) + " as an object {...}, found " + describe_value(value),
               "write it as {\"key\": value, ...}; docs/level-format.md lists every field");
    return false;
}

void read_patrol(const Json& value, const std::string& path, const FieldInfo& info, DiagnosticSink& sink,
                 Patrol& out);
void read_links(const Json& value, const std::string& path, DiagnosticSink& sink, std::vector<Link>& out);
void read_names(const Json& value, const std::string& path, DiagnosticSink& sink,
                std::vector<std::string>& out);

// Walks a props struct's visit() list: reads each field that is present, leaves the others at their
// defaults, then warns about members that no field claimed.
class FieldReader {
  public:
    FieldReader(const Json& object, std::string path, DiagnosticSink& sink)
        : object_(object), path_(std::move(path)), sink_(sink) {}

    void field(float& v, const FieldInfo& info) {
        if (const Json* j = member(info)) read_float(*j, path_of(info), info, sink_, v);
    }
    void field(int& v, const FieldInfo& info) {
        if (const Json* j = member(info)) read_int(*j, path_of(info), info, sink_, v);
    }
    void field(bool& v, const FieldInfo& info) {
        if (const Json* j = member(info)) read_bool(*j, path_of(info), sink_, v);
    }
    void field(std::string& v, const FieldInfo& info) {
        if (const Json* j = member(info)) read_string(*j, path_of(info), sink_, v);
    }
    void field(Vec2& v, const FieldInfo& info) {
        if (const Json* j = member(info)) read_vec<2>(*j, path_of(info), info, sink_, v);
    }
    void field(Vec3& v, const FieldInfo& info) {
        if (const Json* j = member(info)) read_vec<3>(*j, path_of(info), info, sink_, v);
    }
    void field(Color& v, const FieldInfo& info) {
        if (const Json* j = member(info)) read_color(*j, path_of(info), sink_, v);
    }
    void field(Choice& v, const FieldInfo& info) {
        if (const Json* j = member(info)) read_string(*j, path_of(info), sink_, v.value);
    }
    void field(SoundName& v, const FieldInfo& info) {
        if (const Json* j = member(info)) read_string(*j, path_of(info), sink_, v.value);
    }
    // A patrol's problems lie deep inside one robot, so their messages name it.
    void field(Patrol& v, const FieldInfo& info) {
        const Json* j = member(info);
        if (!j) return;
        SubjectScope scope(sink_, subject_);
        read_patrol(*j, path_of(info), info, sink_, v);
    }

    // A brush's problems name the entity too; the brush is read whole or not at all.
    void field(brush::Brush& v, const FieldInfo& info) {
        const Json* j = member(info);
        if (!j) return;
        SubjectScope scope(sink_, subject_);
        read_brush_faces(*j, path_of(info), sink_, v);
    }

    // Links and name lists hang off an entity or an objective, so their messages name it too.
    void field(std::vector<Link>& v, const FieldInfo& info) {
        const Json* j = member(info);
        if (!j) return;
        SubjectScope scope(sink_, subject_);
        read_links(*j, path_of(info), sink_, v);
    }
    void field(std::vector<std::string>& v, const FieldInfo& info) {
        const Json* j = member(info);
        if (!j) return;
        SubjectScope scope(sink_, subject_);
        read_names(*j, path_of(info), sink_, v);
    }

    void set_subject(std::string subject) { subject_ = std::move(subject); }

    // Names that are read elsewhere (an entity's id, type, ...), so they are not "unknown".
    void claim(std::string name) { known_.push_back(std::move(name)); }

    void warn_unknown(std::string_view what) {
        jsonio::report_unknown_members(object_, path_, known_, what, sink_);
    }

  private:
    const Json* member(const FieldInfo& info) {
        known_.emplace_back(info.name);
        auto it = object_.find(info.name);
        return it == object_.end() ? nullptr : &*it;
    }
    std::string path_of(const FieldInfo& info) const { return member_path(path_, info.name); }

    const Json& object_;
    std::string path_;
    DiagnosticSink& sink_;
    std::vector<std::string> known_;
    std::string subject_;
};

std::vector<std::string> type_names() {
    std::vector<std::string> names;
    for (EntityType t : all_types()) names.emplace_back(type_name(t));
    return names;
}

// Read whole or not at all: half a route would send a robot somewhere nobody meant.
void read_patrol(const Json& value, const std::string& path, const FieldInfo& info, DiagnosticSink& sink,
                 Patrol& out) {
    if (!expect_object(value, path, "patrol", sink)) return;
    Patrol patrol;
    bool complete = true;
    FieldReader reader(value, path, sink);
    reader.claim("points");
    const std::string points_path = member_path(path, "points");
    const auto points = value.find("points");
    if (points == value.end()) {
        sink.error(points_path, "missing required field \"points\"",
                   "write \"points\": [[x, y, z], ...], or remove \"patrol\" to let the robot wander");
        complete = false;
    } else if (!points->is_array()) {
        sink.error(points_path, "expected an array of [x, y, z] points, found " + describe_value(*points),
                   "write \"points\": [[x, y, z], ...]");
        complete = false;
    } else if (points->size() > static_cast<size_t>(kMaxPatrolPoints)) {
        sink.error(points_path,
                   "patrol has " + std::to_string(points->size()) + " points; at most " +
                       std::to_string(kMaxPatrolPoints),
                   "a patrol is a route of a few points; keep the corners and drop the rest");
        complete = false;
    } else {
        if (points->empty())
            sink.warning(points_path, "patrol has no points, so the robot wanders",
                         "add points, or remove \"patrol\"");
        for (size_t i = 0; i < points->size(); ++i) {
            Vec3 point(0.0f);
            complete &= read_vec<3>((*points)[i], element_path(points_path, i), info, sink, point);
            patrol.points.push_back(point);
        }
    }
    reader.field(patrol.mode, {"mode", "loop: last point back to the first; ping_pong: back and forth"});
    reader.field(patrol.wait, {"wait", "Seconds the robot stands at each point", 0, kMaxPatrolWait, "s"});
    reader.warn_unknown("patrol");
    if (complete)
        out = std::move(patrol);
    else
        check_patrol_mode_and_wait(patrol, path, sink); // the checks after loading see no patrol
}

// A list longer than `limit` is refused whole before any element is read: a file with a million links is a
// generator gone wrong, and reading it would bury the one message that matters.
bool check_list(const Json& value, const std::string& path, const char* what, const char* example,
                size_t limit, const char* hint, DiagnosticSink& sink) {
    if (!value.is_array()) {
        sink.error(path, std::string("expected an array of ") + what + ", found " + describe_value(value),
                   std::string("write it as ") + example);
        return false;
    }
    if (value.size() > limit) {
        sink.error(path, std::to_string(value.size()) + " " + what + "; at most " + std::to_string(limit),
                   hint);
        return false;
    }
    return true;
}

// A link is read whole or not at all: one without its event, target or action could never fire.
void read_links(const Json& value, const std::string& path, DiagnosticSink& sink, std::vector<Link>& out) {
    if (!check_list(value, path, "links", "[{\"event\": ..., \"target\": ..., \"action\": ...}, ...]",
                    kMaxLinks,
                    "split the work over more entities (a trigger can start a chain), or remove links", sink))
        return;
    out.clear();
    for (size_t i = 0; i < value.size(); ++i) {
        const std::string link_path = element_path(path, i);
        if (!expect_object(value[i], link_path, "a link", sink)) continue;
        Link link;
        FieldReader reader(value[i], link_path, sink);
        link.visit(reader);
        reader.warn_unknown("link");
        bool complete = true;
        for (const char* key : {"event", "target", "action"}) {
            if (value[i].contains(key)) continue;
            sink.error(member_path(link_path, key), std::string("missing required field \"") + key + "\"",
                       "a link is {\"event\": \"on_enter\", \"target\": \"door_2\", \"action\": \"open\"}"
                       " with an optional \"delay\" and \"once\"");
            complete = false;
        }
        if (complete) out.push_back(std::move(link));
    }
}

void read_names(const Json& value, const std::string& path, DiagnosticSink& sink,
                std::vector<std::string>& out) {
    if (!check_list(value, path, "names", "[\"guard_1\", \"hall_spawner\"]", kMaxKillNames,
                    "list the robots and spawners by name; a spawner stands for all the robots it makes",
                    sink))
        return;
    out.clear();
    for (size_t i = 0; i < value.size(); ++i) {
        std::string name;
        if (read_string(value[i], element_path(path, i), sink, name)) out.push_back(std::move(name));
    }
}

std::vector<Objective> read_objectives(const Json& value, const std::string& path, DiagnosticSink& sink) {
    std::vector<Objective> objectives;
    if (!check_list(value, path, "objectives",
                    "[{\"id\": \"clear_hall\", \"text\": \"Clear the hall\"}, ...]", kMaxObjectives,
                    "a level is a few objectives; merge some", sink))
        return objectives;
    for (size_t i = 0; i < value.size(); ++i) {
        const std::string objective_path = element_path(path, i);
        if (!expect_object(value[i], objective_path, "an objective", sink)) continue;
        Objective objective;
        FieldReader reader(value[i], objective_path, sink);
        if (auto id = value[i].find("id"); id != value[i].end() && id->is_string())
            reader.set_subject("objective " + jsonio::quote_text(id->get<std::string>()));
        objective.visit(reader);
        reader.warn_unknown("objective");
        objectives.push_back(std::move(objective));
    }
    return objectives;
}

Settings read_settings(const Json& json, const std::string& path, DiagnosticSink& sink) {
    Settings settings;
    if (!expect_object(json, path, "settings", sink)) return settings;
    FieldReader reader(json, path, sink);
    settings.visit(reader);
    reader.warn_unknown("settings");
    return settings;
}

PlayerStart read_player_start(const Json& json, const std::string& path, DiagnosticSink& sink) {
    PlayerStart start;
    if (!expect_object(json, path, "player_start", sink)) return start;
    FieldReader reader(json, path, sink);
    reader.field(start.position, {"position", "Feet of the player", -1e5, 1e5, "units"});
    reader.field(start.yaw, {"yaw", "Facing; 0 faces -z", -3600, 3600, "deg"});
    reader.warn_unknown("player_start");
    return start;
}

} // namespace

std::optional<Entity> read_entity(const Json& json, const std::string& path, DiagnosticSink& sink) {
    if (!expect_object(json, path, "an entity", sink)) return std::nullopt;
    Entity entity;
    bool complete = true;
    FieldReader reader(json, path, sink);

    auto required = [&](const char* name, std::string_view hint) -> const Json* {
        auto it = json.find(name);
        if (it != json.end()) return &*it;
        sink.error(member_path(path, name), std::string("missing required field \"") + name + "\"",
                   std::string(hint));
        complete = false;
        return nullptr;
    };

    reader.claim("id");
    if (const Json* id = required("id", "every entity needs a unique whole-number id >= 1")) {
        complete &= read_int(*id, member_path(path, "id"), {"id", "", 1, INT_MAX}, sink, entity.id);
    }

    reader.claim("type");
    const std::vector<std::string> known_types = type_names();
    bool typed = false;
    if (const Json* type = required("type", "valid types: " + join(known_types))) {
        EntityType t{};
        if (!type->is_string()) {
            sink.error(member_path(path, "type"),
                       "expected the type name as a string, found " + describe_value(*type),
                       "valid types: " + join(known_types));
        } else if (!type_from_name(type->get<std::string>(), t)) {
            std::string hint = "valid types: " + join(known_types);
            if (std::string near = closest_match(type->get<std::string>(), known_types); !near.empty())
                hint = "did you mean \"" + near + "\"? " + hint;
            sink.error(member_path(path, "type"), "unknown entity type " + jsonio::quote(*type), hint);
        } else {
            entity.props = default_props(t);
            typed = true;
        }
    }
    complete &= typed;

    reader.field(entity.name, {"name", "Shown in the editor's outliner"});
    reader.claim("position");
    if (const Json* position = required("position", "write the bottom centre as [x, y, z]")) {
        complete &= read_vec<3>(*position, member_path(path, "position"),
                                {"position", "", -1e5, 1e5, "units"}, sink, entity.position);
    }
    reader.field(entity.rotation, {"rotation", "Yaw, pitch, roll", -3600, 3600, "deg"});

    reader.claim("props");
    if (auto props = json.find("props"); props != json.end() && typed) {
        const std::string props_path = member_path(path, "props");
        if (expect_object(*props, props_path, "props", sink)) {
            FieldReader props_reader(*props, props_path, sink);
            props_reader.set_subject(entity_subject(entity));
            std::visit([&](auto& p) { p.visit(props_reader); }, entity.props);
            props_reader.warn_unknown(std::string(type_name(entity.type())));
        }
    }
    reader.set_subject(typed ? entity_subject(entity) : "entity " + std::to_string(entity.id));
    reader.field(entity.links, {"links", "What this entity's events set off"});
    reader.warn_unknown("entity");
    if (!complete) return std::nullopt;
    return entity;
}

ReadLevel read_level(const Json& document, DiagnosticSink& sink) {
    ReadLevel out;
    Level& level = out.level;
    FieldReader reader(document, "", sink);
    reader.claim("format");
    reader.claim("version");
    reader.field(level.name, {"name", "Level name"});
    if (auto it = document.find("settings"); it != document.end())
        level.settings = read_settings(*it, "settings", sink);
    reader.claim("settings");
    if (auto it = document.find("player_start"); it != document.end())
        level.player_start = read_player_start(*it, "player_start", sink);
    reader.claim("player_start");

    bool has_next_id = document.contains("next_id");
    reader.field(level.next_id, {"next_id", "The id the next new entity gets", 1, INT_MAX});
    reader.claim("objectives");
    if (auto it = document.find("objectives"); it != document.end())
        level.objectives = read_objectives(*it, "objectives", sink);
    reader.set_subject("the level");
    reader.field(level.links, {"links", "The level's on_start links"});
    reader.set_subject({});

    reader.claim("entities");
    auto entities = document.find("entities");
    if (entities == document.end()) {
        sink.error("entities", "missing required field \"entities\"",
                   "add \"entities\": [], which may be empty");
    } else if (!entities->is_array()) {
        sink.error("entities",
                   "expected \"entities\" to be an array [...], found " + describe_value(*entities),
                   "write \"entities\": [ {...}, {...} ]");
    } else {
        level.entities.reserve(entities->size());
        for (size_t i = 0; i < entities->size(); ++i) {
            if (auto entity = read_entity((*entities)[i], element_path("entities", i), sink)) {
                level.entities.push_back(std::move(*entity));
                out.source_index.push_back(i);
            }
        }
    }
    if (!has_next_id) {
        // Optional: hand-written files may leave it out; it then follows the largest id.
        level.next_id = 1;
        for (const Entity& e : level.entities) level.next_id = std::max(level.next_id, e.id + 1);
    }
    reader.claim("editor");
    if (auto it = document.find("editor"); it != document.end()) {
        level.editor = read_editor_data(*it, "editor", sink);
        reconcile_editor_data(level.editor, level, "editor", sink);
    }
    reader.warn_unknown("level");
    return out;
}

} // namespace ks::level
