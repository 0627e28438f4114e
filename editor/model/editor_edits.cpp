// Editor: the edit operations. Each builds one LevelChange and executes it through History.
#include "model/editor.h"

#include "level/level_io.h"
#include "model/rotation.h"

#include <cmath>
#include <nlohmann/json.hpp>
#include <unordered_map>
#include <unordered_set>

namespace ks::editor {
namespace {
using level::Entity;
using level::EntityType;

std::string describe(const Entity& e) {
    return std::string(level::type_name(e.type())) + " " + std::to_string(e.id);
}

constexpr const char* kClipboardKey = "killswitch-clipboard";
} // namespace

void Editor::execute(std::unique_ptr<LevelChange> change, std::vector<int> selection_after) {
    follow_entity_renames(doc_.level, *change);
    follow_structure(*change);
    change->selection_after = std::move(selection_after);
    history_.execute(doc_, std::move(change));
}

bool Editor::undo() {
    return history_.undo(doc_);
}
bool Editor::redo() {
    return history_.redo(doc_);
}

Result<void> Editor::modify_selection(std::string name, const std::function<Result<void>(Entity&)>& edit,
                                      std::string merge_key, const StartEdit& start_edit,
                                      const FrameEdit& frame_edit) {
    if (doc_.selection.empty())
        return Error(name + ": nothing is selected", Location{}, "select entities first");
    auto change = std::make_unique<LevelChange>();
    // Selection order (the primary first), with one id lookup table instead of a scan per entity.
    std::unordered_map<int, const Entity*> by_id;
    by_id.reserve(doc_.level.entities.size());
    for (const auto& e : doc_.level.entities) by_id.emplace(e.id, &e);
    for (int id : doc_.selection) {
        auto found = by_id.find(id);
        const Entity* current = found == by_id.end() ? nullptr : found->second;
        if (!current || doc_.locked.contains(id)) continue;
        Entity after = *current;
        if (auto r = edit(after); !r) {
            Error e = r.error();
            e.message = name + ": " + describe(*current) + ": " + e.message;
            return e;
        }
        if (!(after == *current)) change->updates.push_back({*current, std::move(after)});
    }
    if (start_edit && doc_.player_start_selected()) {
        level::PlayerStart after = doc_.level.player_start;
        if (auto r = start_edit(after); !r) {
            Error e = r.error();
            e.message = name + ": player start: " + e.message;
            return e;
        }
        if (!is_finite(after.position) || !std::isfinite(after.yaw))
            return Error(name + ": the player start would leave the finite numbers");
        if (!(after == doc_.level.player_start))
            change->player_start = Change<level::PlayerStart>{doc_.level.player_start, after};
    }
    if (frame_edit && !change->updates.empty() && !doc_.level.editor.groups.empty()) {
        std::vector<int> moved;
        for (const EntityUpdate& u : change->updates) moved.push_back(u.after.id);
        std::sort(moved.begin(), moved.end());
        level::EditorData data = doc_.level.editor;
        for (int id : groups_wholly_in(data, moved)) frame_edit(*data.find_group(id));
        if (data != doc_.level.editor)
            change->editor_data = Change<level::EditorData>{doc_.level.editor, data};
    }
    if (change->empty()) return ok(); // nothing actually changed: no history step
    change->set_name(std::move(name));
    change->merge_key = std::move(merge_key);
    execute(std::move(change), doc_.selection);
    return ok();
}

Result<int> Editor::place(EntityType type, Vec3 position, float yaw_degrees, std::string name) {
    if (static_cast<size_t>(type) >= static_cast<size_t>(EntityType::Count))
        return Error("unknown entity type", Location{}, "use one of the palette's types");
    if (!is_finite(position) || !std::isfinite(yaw_degrees))
        return Error("place: position and yaw must be finite numbers");
    Entity e;
    e.id = doc_.level.next_id;
    e.name = std::move(name);
    e.position = doc_.grid.snap_point(position);
    e.rotation = {wrap_degrees(doc_.grid.snap_angle(yaw_degrees)), 0, 0};
    e.props = level::default_props(type);
    if (auto r = set_entity_field(e, "position", e.position); !r)
        return Error("place: " + r.error().message, Location{}, r.error().hint);
    auto change = std::make_unique<LevelChange>();
    change->set_name("Place " + std::string(level::type_name(type)));
    change->insertions.push_back({doc_.level.entities.size(), e});
    change->next_id = Change<int>{doc_.level.next_id, doc_.level.next_id + 1};
    execute(std::move(change), {e.id});
    return e.id;
}

Result<void> Editor::move_selection(Vec3 delta, bool snap, std::string merge_key) {
    if (!is_finite(delta)) return Error("move: the offset must be finite numbers");
    if (snap && !doc_.selection.empty()) {
        if (doc_.selection.front() == kPlayerStartId) {
            const Vec3 start = doc_.level.player_start.position;
            delta = doc_.grid.snap_point(start + delta) - start;
        } else if (const Entity* primary = doc_.level.find(doc_.selection.front())) {
            delta = doc_.grid.snap_point(primary->position + delta) - primary->position;
        }
    }
    return modify_selection(
        "Move", [&](Entity& e) { return set_entity_field(e, "position", e.position + delta); },
        std::move(merge_key),
        [&](level::PlayerStart& start) -> Result<void> {
            start.position += delta;
            return ok();
        },
        [&](level::Group& group) { group.position += delta; });
}

Result<void> Editor::nudge(int axis, int direction) {
    if (axis < 0 || axis > 2 || (direction != 1 && direction != -1))
        return Error("nudge: axis must be 0..2 and direction +1 or -1");
    Vec3 delta(0.0f);
    delta[axis] = static_cast<float>(direction) * doc_.grid.step;
    return move_selection(delta, false, "nudge");
}

Result<void> Editor::scale_selection(Vec3 factors, std::string merge_key) {
    if (!is_finite(factors) || factors.x <= 0 || factors.y <= 0 || factors.z <= 0)
        return Error("scale: factors must be positive finite numbers");
    bool any = false;
    auto result = modify_selection(
        "Scale",
        [&](Entity& e) -> Result<void> {
            auto scale_field = [&](const char* field, auto scaled) -> Result<void> {
                any = true;
                auto current = get_entity_field(e, field);
                if (!current) return current.error();
                return set_entity_field(e, field, scaled(*current));
            };
            auto vec3 = [&](const FieldValue& v) { return FieldValue(std::get<Vec3>(v) * factors); };
            auto by = [](float f) {
                return [f](const FieldValue& v) {
                    return FieldValue(std::get<double>(v) * static_cast<double>(f));
                };
            };
            switch (e.type()) {
            case EntityType::Wall:
            case EntityType::Stair:
            case EntityType::ControlPanel:
                return scale_field("size", vec3);
            case EntityType::Floor:
                return scale_field("size", [&](const FieldValue& v) {
                    return FieldValue(std::get<Vec2>(v) * Vec2(factors.x, factors.z));
                });
            case EntityType::Door:
                if (auto r = scale_field("width", by(factors.x)); !r) return r;
                return scale_field("height", by(factors.y));
            case EntityType::GasCylinder:
                if (auto r = scale_field("radius", by(factors.x)); !r) return r;
                return scale_field("height", by(factors.y));
            default:
                return ok(); // no size fields: robots, pickups and lights keep their model size
            }
        },
        std::move(merge_key));
    if (result && !any && !doc_.selection.empty())
        return Error("Scale: none of the selected entities has size fields", Location{},
                     "walls, floors, stairs, doors, gas cylinders and the control panel can be scaled");
    return result;
}

Result<void> Editor::set_field(std::string_view name, const FieldValue& value, std::string merge_key) {
    return modify_selection(
        "Set " + std::string(name), [&](Entity& e) { return set_entity_field(e, name, value); },
        std::move(merge_key));
}

Result<void> Editor::set_field_text(std::string_view name, std::string_view text) {
    return modify_selection("Set " + std::string(name), [&](Entity& e) -> Result<void> {
        for (const auto& field : describe_entity_fields(e)) {
            if (field.name != name) continue;
            auto value = parse_field_value(field, text);
            if (!value) return value.error();
            return set_entity_field(e, name, *value);
        }
        return set_entity_field(e, name, FieldValue(0.0)); // reports the unknown field with the valid names
    });
}

Result<void> Editor::revert_field(std::string_view name) {
    return modify_selection("Revert " + std::string(name), [&](Entity& e) -> Result<void> {
        auto value = default_entity_field(e, name);
        if (!value) return value.error();
        return set_entity_field(e, name, *value);
    });
}

Result<void> Editor::rename(int id, std::string name) {
    const Entity* current = doc_.level.find(id);
    if (!current) return Error("rename: no entity with id " + std::to_string(id));
    if (doc_.locked.contains(id)) return Error("rename: entity " + std::to_string(id) + " is locked");
    Entity after = *current;
    if (auto r = set_entity_field(after, "name", name); !r) return r;
    if (after == *current) return ok();
    auto change = std::make_unique<LevelChange>();
    change->set_name("Rename " + describe(*current));
    change->updates.push_back({*current, std::move(after)});
    execute(std::move(change), doc_.selection);
    return ok();
}

Result<void> Editor::duplicate(std::optional<Vec3> offset) {
    const Vec3 delta = offset.value_or(Vec3(doc_.grid.step, 0.0f, doc_.grid.step));
    if (!is_finite(delta)) return Error("duplicate: the offset must be finite numbers");
    auto change = std::make_unique<LevelChange>();
    std::vector<int> new_ids;
    std::unordered_map<int, int> copies; // original id -> copy's id
    int next = doc_.level.next_id;
    const std::unordered_set<int> selected(doc_.selection.begin(), doc_.selection.end());
    for (const auto& e : doc_.level.entities) { // level order, so copies keep their relative order
        if (!selected.contains(e.id) || doc_.locked.contains(e.id)) continue;
        Entity copy = e;
        copy.id = next++;
        if (auto r = set_entity_field(copy, "position", e.position + delta); !r)
            return Error("Duplicate: " + describe(e) + ": " + r.error().message, Location{}, r.error().hint);
        change->insertions.push_back({doc_.level.entities.size() + new_ids.size(), copy});
        new_ids.push_back(copy.id);
        copies.emplace(e.id, copy.id);
    }
    if (new_ids.empty()) return Error("Duplicate: nothing is selected", Location{}, "select entities first");
    change->set_name(new_ids.size() == 1 ? "Duplicate"
                                         : "Duplicate " + std::to_string(new_ids.size()) + " entities");
    change->next_id = Change<int>{doc_.level.next_id, next};
    if (!doc_.level.editor.empty()) { // groups copied whole stay groups (a prefab instance stays linked)
        level::EditorData data = doc_.level.editor;
        copy_structure(data, copies, delta);
        change->editor_data = Change<level::EditorData>{doc_.level.editor, std::move(data)};
    }
    execute(std::move(change), new_ids);
    return ok();
}

Result<void> Editor::delete_entities(const std::vector<int>& ids) {
    auto change = std::make_unique<LevelChange>();
    const std::unordered_set<int> doomed(ids.begin(), ids.end());
    for (size_t i = 0; i < doc_.level.entities.size(); ++i) {
        const Entity& e = doc_.level.entities[i];
        if (!doomed.contains(e.id) || doc_.locked.contains(e.id)) continue;
        change->removals.push_back({i, e});
    }
    if (change->removals.empty())
        return Error("Delete: nothing to delete", Location{}, "select unlocked entities first");
    change->set_name(change->removals.size() == 1
                         ? "Delete " + describe(change->removals.front().entity)
                         : "Delete " + std::to_string(change->removals.size()) + " entities");
    std::vector<int> remaining;
    for (int id : doc_.selection)
        if (!doomed.contains(id) || doc_.locked.contains(id)) remaining.push_back(id);
    execute(std::move(change), remaining);
    return ok();
}

Result<void> Editor::delete_selection() {
    return delete_entities(doc_.selection);
}

std::string Editor::copy() {
    nlohmann::json list = nlohmann::json::array();
    const std::unordered_set<int> selected(doc_.selection.begin(), doc_.selection.end());
    for (const auto& e : doc_.level.entities)
        if (selected.contains(e.id)) list.push_back(level::entity_to_json(e));
    nlohmann::json clip = {{kClipboardKey, 1}, {"entities", std::move(list)}};
    if (nlohmann::json groups = copied_structure(doc_); !groups.is_null()) clip["editor"] = std::move(groups);
    clipboard_ = clip.dump(2);
    return clipboard_;
}

Result<void> Editor::paste() {
    return paste_text(clipboard_);
}

Result<void> Editor::paste_text(std::string_view text) {
    const std::string context = "clipboard";
    nlohmann::json json = nlohmann::json::parse(text, nullptr, false);
    if (json.is_discarded())
        return Error("paste: the clipboard does not hold JSON", Location{context},
                     "copy entities in the editor first (Ctrl+C), or paste one entity's JSON object");
    nlohmann::json list;
    if (json.is_object() && json.contains(kClipboardKey))
        list = json.value("entities", nlohmann::json::array());
    else if (json.is_object())
        list = nlohmann::json::array({json});
    else if (json.is_array())
        list = json;
    if (!list.is_array() || list.empty())
        return Error(
            "paste: no entities in the clipboard", Location{context},
            "expected {\"killswitch-clipboard\":1,\"entities\":[...]}, an entity object or an array of them");
    auto change = std::make_unique<LevelChange>();
    std::vector<int> new_ids;
    int next = doc_.level.next_id;
    for (size_t i = 0; i < list.size(); ++i) {
        auto entity = level::entity_from_json(list[i], context + " entities[" + std::to_string(i) + "]");
        if (!entity)
            return Error("paste: " + entity.error().message, entity.error().where, entity.error().hint);
        entity->id = next++;
        change->insertions.push_back({doc_.level.entities.size() + i, std::move(*entity)});
        new_ids.push_back(next - 1);
    }
    change->set_name(new_ids.size() == 1 ? "Paste" : "Paste " + std::to_string(new_ids.size()) + " entities");
    change->next_id = Change<int>{doc_.level.next_id, next};
    if (json.is_object() && json.contains("editor")) { // groups and prefab instances copied whole
        std::unordered_map<int, int> pasted;
        for (size_t i = 0; i < list.size(); ++i)
            if (list[i].contains("id") && list[i]["id"].is_number_integer())
                pasted.emplace(list[i]["id"].get<int>(), new_ids[i]);
        level::EditorData data = doc_.level.editor;
        paste_structure(data, json["editor"], pasted, doc_.open_group);
        if (data != doc_.level.editor)
            change->editor_data = Change<level::EditorData>{doc_.level.editor, std::move(data)};
    }
    execute(std::move(change), new_ids);
    return ok();
}

Result<void> Editor::set_setting(std::string_view name, const FieldValue& value, std::string merge_key) {
    level::Settings after = doc_.level.settings;
    if (auto r = set_settings_field(after, name, value); !r) return r;
    if (after == doc_.level.settings) return ok();
    auto change = std::make_unique<LevelChange>();
    change->set_name("Set " + std::string(name));
    change->settings = Change<level::Settings>{doc_.level.settings, after};
    change->merge_key = std::move(merge_key);
    execute(std::move(change), doc_.selection);
    return ok();
}

Result<void> Editor::set_setting_text(std::string_view name, std::string_view text) {
    for (const auto& field : describe_settings_fields()) {
        if (field.name != name) continue;
        auto value = parse_field_value(field, text);
        if (!value) return value.error();
        return set_setting(name, *value);
    }
    return set_settings_field(doc_.level.settings, name, FieldValue(0.0)); // unknown: lists the valid names
}

Result<void> Editor::set_player_start(const level::PlayerStart& start, std::string merge_key) {
    if (!is_finite(start.position) || !std::isfinite(start.yaw))
        return Error("player start: position and yaw must be finite numbers");
    level::PlayerStart snapped{doc_.grid.snap_point(start.position),
                               wrap_degrees(doc_.grid.snap_angle(start.yaw))};
    if (snapped == doc_.level.player_start) return ok();
    auto change = std::make_unique<LevelChange>();
    change->set_name("Move player start");
    change->player_start = Change<level::PlayerStart>{doc_.level.player_start, snapped};
    change->merge_key = std::move(merge_key);
    execute(std::move(change), doc_.selection);
    return ok();
}

Result<void> Editor::rename_level(std::string name) {
    if (name == doc_.level.name) return ok();
    auto change = std::make_unique<LevelChange>();
    change->set_name("Rename level");
    change->level_name = Change<std::string>{doc_.level.name, std::move(name)};
    execute(std::move(change), doc_.selection);
    return ok();
}

} // namespace ks::editor
