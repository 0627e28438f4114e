#include "level/editor_data_io.h"

#include "jsonio/describe.h"
#include "jsonio/json_path.h"
#include "jsonio/number_text.h"
#include "jsonio/object_reader.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <map>
#include <set>

namespace ks::level {

using Json = nlohmann::ordered_json;
using jsonio::element_path;
using jsonio::member_path;

namespace {

Json sorted_ids(std::vector<int> ids) {
    std::sort(ids.begin(), ids.end());
    return Json(ids);
}

Json group_json(const Group& group) {
    Json json = Json::object();
    json["id"] = group.id;
    json["name"] = group.name;
    json["position"] =
        Json::array({jsonio::float_to_double(group.position.x), jsonio::float_to_double(group.position.y),
                     jsonio::float_to_double(group.position.z)});
    json["yaw"] = jsonio::float_to_double(group.yaw);
    json["entities"] = sorted_ids(group.entities);
    if (!group.groups.empty()) json["groups"] = sorted_ids(group.groups);
    if (group.has_prefab) {
        Json prefab = Json::object();
        prefab["name"] = group.prefab.prefab;
        prefab["members"] = group.prefab.members; // in the prefab's entity order, not sorted
        prefab["overrides"] = group.prefab.overrides;
        json["prefab"] = std::move(prefab);
    }
    return json;
}

// The editor section is advisory (the game never reads it, and a designer's layers are worth keeping when
// one entry is broken): the shared reader's problems in it all arrive as warnings, and that part keeps its
// default or is left out.
class AdvisorySink : public jsonio::ProblemSink {
  public:
    explicit AdvisorySink(DiagnosticSink& sink) : sink_(sink) {}
    void report(jsonio::Severity, const std::string& path, std::string message, std::string hint) override {
        sink_.warning(path, std::move(message), with_consequence(std::move(hint)));
    }
    void report_at(jsonio::Severity, jsonio::TextPosition pos, const std::string& path, std::string message,
                   std::string hint) override {
        sink_.report_at(jsonio::Severity::Warning, pos, path, std::move(message),
                        with_consequence(std::move(hint)));
    }
    void mark_reported(const std::string& path) override { sink_.mark_reported(path); }
    bool already_reported(const std::string& path) const override { return sink_.already_reported(path); }
    bool any_reported() const override { return sink_.any_reported(); }

  private:
    static std::string with_consequence(std::string hint) {
        return hint.empty() ? "the default is used" : hint + "; the default is used";
    }
    DiagnosticSink& sink_;
};

// One object of the editor section, read with jsonio::ObjectReader through an AdvisorySink.
class SectionReader {
  public:
    SectionReader(const Json& json, std::string path, DiagnosticSink& sink, std::string what)
        : json_(json), advisory_(sink), reader_(json, std::move(path), advisory_, std::move(what)) {}

    bool is_object() const { return reader_.is_object(); }
    const Json* get(const char* key) { return reader_.get(key); }
    void text(const char* key, std::string& out, size_t max_characters = 256) {
        reader_.text(key, out, jsonio::Need::Optional, max_characters);
    }
    void flag(const char* key, bool& out) { reader_.flag(key, out); }
    void integer(const char* key, int& out, int min, int max) {
        reader_.whole(key, out, {double(min), double(max)});
    }
    void number(const char* key, float& out) { reader_.number(key, out, {-1e6, 1e6}); }
    void vec3(const char* key, Vec3& out) {
        double v[3] = {};
        if (reader_.numbers(key, v, 3, {-1e6, 1e6}))
            out = Vec3(static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]));
    }
    // Whole numbers; `allow_zero` keeps 0 (a prefab member the designer deleted).
    void ids(const char* key, std::vector<int>& out, bool allow_zero = false) {
        const Json* v = get(key);
        if (!v) return;
        if (!v->is_array()) return warn(key, "expected a list of ids [1, 2, ...]");
        for (size_t i = 0; i < v->size(); ++i) {
            const Json& id = (*v)[i];
            if (id.is_number_integer() && id.get<long long>() >= (allow_zero ? 0 : 1) &&
                id.get<long long>() <= INT_MAX)
                out.push_back(id.get<int>());
            else
                advisory_.report(jsonio::Severity::Warning, element_path(reader_.path_of(key), i),
                                 "expected an id (a whole number of at least 1), found " +
                                     jsonio::describe_value(id),
                                 "this entry is left out");
        }
    }
    void finish() { reader_.finish(); }
    void warn(const char* key, const std::string& expected) {
        advisory_.report(jsonio::Severity::Warning, reader_.path_of(key),
                         expected + ", found " + jsonio::describe_value(json_[key]), {});
    }
    const std::string& path() const { return reader_.path(); }

  private:
    const Json& json_;
    AdvisorySink advisory_;
    jsonio::ObjectReader reader_;
};

std::optional<Layer> read_layer(const Json& json, const std::string& path, DiagnosticSink& sink) {
    SectionReader reader(json, path, sink, "a layer");
    if (!reader.is_object()) return std::nullopt;
    Layer layer;
    reader.text("name", layer.name, kMaxLayerNameLength);
    reader.flag("visible", layer.visible);
    reader.flag("locked", layer.locked);
    reader.ids("entities", layer.entities);
    reader.finish();
    if (layer.name.empty()) {
        sink.warning(member_path(path, "name"), "a layer needs a name", "the layer is left out");
        return std::nullopt;
    }
    return layer;
}

void read_prefab(const Json& json, const std::string& path, DiagnosticSink& sink, Group& group) {
    SectionReader reader(json, path, sink, "a prefab link");
    if (!reader.is_object()) return;
    PrefabLink link;
    reader.text("name", link.prefab, 128);
    reader.ids("members", link.members, true);
    if (const Json* overrides = reader.get("overrides")) {
        bool ok = overrides->is_array() && overrides->size() == link.members.size();
        for (size_t i = 0; ok && i < overrides->size(); ++i) {
            ok = (*overrides)[i].is_array();
            std::vector<std::string> fields;
            for (size_t k = 0; ok && k < (*overrides)[i].size(); ++k) {
                ok = (*overrides)[i][k].is_string();
                if (ok) fields.push_back((*overrides)[i][k].get<std::string>());
            }
            std::sort(fields.begin(), fields.end());
            link.overrides.push_back(std::move(fields));
        }
        if (!ok) {
            reader.warn("overrides", "expected one list of field names per member");
            link.overrides.clear();
        }
    }
    link.overrides.resize(link.members.size());
    reader.finish();
    if (link.prefab.empty()) {
        sink.warning(member_path(path, "name"), "a prefab instance needs its prefab's name",
                     "the group is kept as a plain group");
        return;
    }
    group.has_prefab = true;
    group.prefab = std::move(link);
}

std::optional<Group> read_group(const Json& json, const std::string& path, DiagnosticSink& sink) {
    SectionReader reader(json, path, sink, "a group");
    if (!reader.is_object()) return std::nullopt;
    Group group;
    reader.integer("id", group.id, 1, INT_MAX);
    reader.text("name", group.name);
    reader.vec3("position", group.position);
    reader.number("yaw", group.yaw);
    reader.ids("entities", group.entities);
    reader.ids("groups", group.groups);
    if (const Json* prefab = reader.get("prefab"))
        read_prefab(*prefab, member_path(path, "prefab"), sink, group);
    reader.finish();
    if (group.id == 0) {
        sink.warning(member_path(path, "id"), "a group needs an id of at least 1", "the group is left out");
        return std::nullopt;
    }
    return group;
}

template <class T, class ReadOne>
void read_list(SectionReader& reader, const char* key, std::vector<T>& out, DiagnosticSink& sink,
               ReadOne read_one) {
    const Json* list = reader.get(key);
    if (!list) return;
    if (!list->is_array()) return reader.warn(key, "expected a list [...]");
    for (size_t i = 0; i < list->size(); ++i)
        if (auto item = read_one((*list)[i], element_path(member_path(reader.path(), key), i), sink))
            out.push_back(std::move(*item));
}

// Removes the ids `drop` says so of, warning about each (remove_if leaves the removed tail unspecified, so
// the warning is given while the id is still at hand).
template <class Drop>
void drop_ids(std::vector<int>& ids, Drop drop, DiagnosticSink& sink, const std::string& where,
              const std::string& why, const std::string& what_happens) {
    std::vector<int> kept;
    kept.reserve(ids.size());
    for (int id : ids) {
        if (drop(id))
            sink.warning(where, "entity " + std::to_string(id) + " " + why, what_happens);
        else
            kept.push_back(id);
    }
    ids = std::move(kept);
}

void sort_unique(std::vector<int>& ids) {
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
}

} // namespace

Json write_editor_data(const EditorData& data) {
    Json json = Json::object();
    if (!data.layers.empty()) {
        Json layers = Json::array();
        for (const Layer& layer : data.layers)
            layers.push_back(Json{{"name", layer.name},
                                  {"visible", layer.visible},
                                  {"locked", layer.locked},
                                  {"entities", sorted_ids(layer.entities)}});
        json["layers"] = std::move(layers);
        json["active_layer"] = data.active_layer;
    }
    if (!data.groups.empty()) {
        Json groups = Json::array();
        for (const Group& group : data.groups) groups.push_back(group_json(group));
        json["groups"] = std::move(groups);
    }
    json["next_group_id"] = data.next_group_id;
    if (!data.hidden.empty()) json["hidden"] = sorted_ids(data.hidden);
    if (!data.locked.empty()) json["locked"] = sorted_ids(data.locked);
    return json;
}

EditorData read_editor_data(const Json& json, const std::string& path, DiagnosticSink& sink) {
    EditorData data;
    SectionReader reader(json, path, sink, "the editor section");
    if (!reader.is_object()) return data;
    read_list(reader, "layers", data.layers, sink, read_layer);
    if (data.layers.size() > static_cast<size_t>(kMaxLayers)) {
        sink.warning(member_path(path, "layers"),
                     "more than " + std::to_string(kMaxLayers) + " layers; the rest are left out");
        data.layers.resize(kMaxLayers);
    }
    reader.integer("active_layer", data.active_layer, 0, kMaxLayers - 1);
    if (data.active_layer >= static_cast<int>(std::max<size_t>(data.layers.size(), 1))) {
        reader.warn("active_layer", "expected the index of one of the layers");
        data.active_layer = 0;
    }
    read_list(reader, "groups", data.groups, sink, read_group);
    reader.integer("next_group_id", data.next_group_id, 1, INT_MAX);
    reader.ids("hidden", data.hidden);
    reader.ids("locked", data.locked);
    reader.finish();
    return data;
}

void reconcile_editor_data(EditorData& data, const Level& level, const std::string& path,
                           DiagnosticSink& sink) {
    std::set<int> entity_ids;
    for (const Entity& e : level.entities) entity_ids.insert(e.id);
    const auto drop_unknown = [&](std::vector<int>& ids, const std::string& where) {
        sort_unique(ids);
        drop_ids(
            ids, [&](int id) { return !entity_ids.count(id); }, sink, where, "does not exist",
            "it is left out");
    };
    drop_unknown(data.hidden, member_path(path, "hidden"));
    drop_unknown(data.locked, member_path(path, "locked"));
    std::set<int> in_a_layer;
    for (size_t i = 0; i < data.layers.size(); ++i) {
        const std::string where = member_path(element_path(member_path(path, "layers"), i), "entities");
        drop_unknown(data.layers[i].entities, where);
        drop_ids(
            data.layers[i].entities, [&](int id) { return !in_a_layer.insert(id).second; }, sink, where,
            "is already in an earlier layer", "an entity is in one layer; it stays in the first");
    }
    // Groups: unique ids, members in one group only, children that exist and form no cycle.
    std::map<int, size_t> group_index;
    std::set<int> grouped_entities, child_groups;
    std::vector<Group> kept;
    for (size_t i = 0; i < data.groups.size(); ++i) {
        Group& group = data.groups[i];
        const std::string where = element_path(member_path(path, "groups"), i);
        if (group_index.count(group.id)) {
            sink.warning(member_path(where, "id"), "group id " + std::to_string(group.id) + " is used twice",
                         "the second group is left out");
            continue;
        }
        group_index[group.id] = kept.size();
        drop_unknown(group.entities, member_path(where, "entities"));
        drop_ids(
            group.entities, [&](int id) { return !grouped_entities.insert(id).second; }, sink,
            member_path(where, "entities"), "is already in another group", "it is left out here");
        if (group.has_prefab)
            for (int& member : group.prefab.members)
                if (member != 0 && !std::binary_search(group.entities.begin(), group.entities.end(), member))
                    member = 0; // gone from the level: deleted from this instance
        data.next_group_id = std::max(data.next_group_id, group.id + 1);
        kept.push_back(std::move(group));
    }
    for (size_t i = 0; i < kept.size(); ++i) {
        Group& group = kept[i];
        sort_unique(group.groups);
        const std::string where = member_path(element_path(member_path(path, "groups"), i), "groups");
        auto bad = std::remove_if(group.groups.begin(), group.groups.end(), [&](int child) {
            const bool ok =
                child != group.id && group_index.count(child) && child_groups.insert(child).second;
            if (!ok)
                sink.warning(where, "group " + std::to_string(child) + " is not a group of its own here",
                             "it names no group, this group, or a group already inside another; left out");
            return !ok;
        });
        group.groups.erase(bad, group.groups.end());
    }
    // A cycle (a inside b inside a) has no root: break it by cutting the link into its lowest id.
    for (Group& group : kept) {
        std::set<int> seen{group.id};
        int walk = group.id;
        for (bool found = true; found;) {
            found = false;
            for (Group& parent : kept)
                if (std::binary_search(parent.groups.begin(), parent.groups.end(), walk)) {
                    if (!seen.insert(parent.id).second) {
                        sink.warning(member_path(path, "groups"),
                                     "groups " + std::to_string(parent.id) + " and " + std::to_string(walk) +
                                         " are inside each other",
                                     "the loop is cut");
                        parent.groups.erase(std::find(parent.groups.begin(), parent.groups.end(), walk));
                        break;
                    }
                    walk = parent.id;
                    found = true;
                    break;
                }
        }
    }
    data.groups = std::move(kept);
    if (!data.layers.empty())
        data.active_layer = std::min<int>(data.active_layer, static_cast<int>(data.layers.size()) - 1);
}

} // namespace ks::level
