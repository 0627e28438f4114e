// Entities and the level's own fields: edit_entities.h. Each builds one LevelChange and executes it through
// the Editor.
#include "model/edit_entities.h"

#include "level/level_io.h"
#include "model/groups.h"
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

Result<int> place(Editor& editor, EntityType type, Vec3 position, float yaw_degrees, std::string name) {
    const Document& doc = editor.doc();
    if (static_cast<size_t>(type) >= static_cast<size_t>(EntityType::Count))
        return Error("unknown entity type", Location{}, "use one of the palette's types");
    if (!is_finite(position) || !std::isfinite(yaw_degrees))
        return Error("place: position and yaw must be finite numbers");
    Entity e;
    e.id = doc.level.next_id;
    e.name = std::move(name);
    e.position = doc.grid.snap_point(position);
    e.rotation = {wrap_degrees(doc.grid.snap_angle(yaw_degrees)), 0, 0};
    e.props = level::default_props(type);
    if (auto r = set_entity_field(e, "position", e.position); !r)
        return Error("place: " + r.error().message, Location{}, r.error().hint);
    auto change = std::make_unique<LevelChange>();
    change->set_name("Place " + std::string(level::type_name(type)));
    change->insertions.push_back({doc.level.entities.size(), e});
    change->next_id = Change<int>{doc.level.next_id, doc.level.next_id + 1};
    editor.execute(std::move(change), {e.id});
    return e.id;
}

Result<void> set_field(Editor& editor, std::string_view name, const FieldValue& value,
                       std::string merge_key) {
    return editor.modify_selection(
        "Set " + std::string(name), [&](Entity& e) { return set_entity_field(e, name, value); },
        std::move(merge_key));
}

Result<void> set_field_text(Editor& editor, std::string_view name, std::string_view text) {
    return editor.modify_selection("Set " + std::string(name), [&](Entity& e) -> Result<void> {
        for (const auto& field : describe_entity_fields(e)) {
            if (field.name != name) continue;
            auto value = parse_field_value(field, text);
            if (!value) return value.error();
            return set_entity_field(e, name, *value);
        }
        return set_entity_field(e, name, FieldValue(0.0)); // reports the unknown field with the valid names
    });
}

Result<void> revert_field(Editor& editor, std::string_view name) {
    return editor.modify_selection("Revert " + std::string(name), [&](Entity& e) -> Result<void> {
        auto value = default_entity_field(e, name);
        if (!value) return value.error();
        return set_entity_field(e, name, *value);
    });
}

Result<void> rename(Editor& editor, int id, std::string name) {
    const Document& doc = editor.doc();
    const Entity* current = doc.level.find(id);
    if (!current) return Error("rename: no entity with id " + std::to_string(id));
    if (doc.locked.contains(id)) return Error("rename: entity " + std::to_string(id) + " is locked");
    Entity after = *current;
    if (auto r = set_entity_field(after, "name", name); !r) return r;
    if (after == *current) return ok();
    auto change = std::make_unique<LevelChange>();
    change->set_name("Rename " + describe(*current));
    change->updates.push_back({*current, std::move(after)});
    editor.execute(std::move(change), doc.selection);
    return ok();
}

Result<void> duplicate(Editor& editor, std::optional<Vec3> offset) {
    const Document& doc = editor.doc();
    const Vec3 delta = offset.value_or(Vec3(doc.grid.step, 0.0f, 0.0f));
    if (!is_finite(delta)) return Error("duplicate: the offset must be finite numbers");
    auto change = std::make_unique<LevelChange>();
    std::vector<int> new_ids;
    std::unordered_map<int, int> copies; // original id -> copy's id
    int next = doc.level.next_id;
    const std::unordered_set<int> selected(doc.selection.begin(), doc.selection.end());
    for (const auto& e : doc.level.entities) { // level order, so copies keep their relative order
        if (!selected.contains(e.id) || doc.locked.contains(e.id)) continue;
        Entity copy = e;
        copy.id = next++;
        if (auto r = set_entity_field(copy, "position", e.position + delta); !r)
            return Error("Duplicate: " + describe(e) + ": " + r.error().message, Location{}, r.error().hint);
        change->insertions.push_back({doc.level.entities.size() + new_ids.size(), copy});
        new_ids.push_back(copy.id);
        copies.emplace(e.id, copy.id);
    }
    if (new_ids.empty()) return Error("Duplicate: nothing is selected", Location{}, "select entities first");
    change->set_name(new_ids.size() == 1 ? "Duplicate"
                                         : "Duplicate " + std::to_string(new_ids.size()) + " entities");
    change->next_id = Change<int>{doc.level.next_id, next};
    if (!doc.level.editor.empty()) { // groups copied whole stay groups (a prefab instance stays linked)
        level::EditorData data = doc.level.editor;
        copy_structure(data, copies, delta);
        change->editor_data = Change<level::EditorData>{doc.level.editor, std::move(data)};
    }
    editor.execute(std::move(change), new_ids);
    return ok();
}

Result<void> delete_entities(Editor& editor, const std::vector<int>& ids) {
    const Document& doc = editor.doc();
    auto change = std::make_unique<LevelChange>();
    const std::unordered_set<int> doomed(ids.begin(), ids.end());
    for (size_t i = 0; i < doc.level.entities.size(); ++i) {
        const Entity& e = doc.level.entities[i];
        if (!doomed.contains(e.id) || doc.locked.contains(e.id)) continue;
        change->removals.push_back({i, e});
    }
    if (change->removals.empty())
        return Error("Delete: nothing to delete", Location{}, "select unlocked entities first");
    change->set_name(change->removals.size() == 1
                         ? "Delete " + describe(change->removals.front().entity)
                         : "Delete " + std::to_string(change->removals.size()) + " entities");
    std::vector<int> remaining;
    for (int id : doc.selection)
        if (!doomed.contains(id) || doc.locked.contains(id)) remaining.push_back(id);
    editor.execute(std::move(change), remaining);
    return ok();
}

Result<void> delete_selection(Editor& editor) {
    const Document& doc = editor.doc();
    return delete_entities(editor, doc.selection);
}

std::string copy(Editor& editor) {
    const Document& doc = editor.doc();
    nlohmann::json list = nlohmann::json::array();
    const std::unordered_set<int> selected(doc.selection.begin(), doc.selection.end());
    for (const auto& e : doc.level.entities)
        if (selected.contains(e.id)) list.push_back(level::entity_to_json(e));
    nlohmann::json clip = {{kClipboardKey, 1}, {"entities", std::move(list)}};
    if (nlohmann::json groups = copied_structure(doc); !groups.is_null()) clip["editor"] = std::move(groups);
    editor.set_clipboard(clip.dump(2));
    return editor.clipboard();
}

Result<void> paste(Editor& editor) {
    return paste_text(editor, editor.clipboard());
}

Result<void> paste_text(Editor& editor, std::string_view text) {
    const Document& doc = editor.doc();
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
    int next = doc.level.next_id;
    for (size_t i = 0; i < list.size(); ++i) {
        auto entity = level::entity_from_json(list[i], context + " entities[" + std::to_string(i) + "]");
        if (!entity)
            return Error("paste: " + entity.error().message, entity.error().where, entity.error().hint);
        entity->id = next++;
        change->insertions.push_back({doc.level.entities.size() + i, std::move(*entity)});
        new_ids.push_back(next - 1);
    }
    change->set_name(new_ids.size() == 1 ? "Paste" : "Paste " + std::to_string(new_ids.size()) + " entities");
    change->next_id = Change<int>{doc.level.next_id, next};
    if (json.is_object() && json.contains("editor")) { // groups and prefab instances copied whole
        std::unordered_map<int, int> pasted;
        for (size_t i = 0; i < list.size(); ++i)
            if (list[i].contains("id") && list[i]["id"].is_number_integer())
                pasted.emplace(list[i]["id"].get<int>(), new_ids[i]);
        level::EditorData data = doc.level.editor;
        paste_structure(data, json["editor"], pasted, doc.open_group);
        if (data != doc.level.editor)
            change->editor_data = Change<level::EditorData>{doc.level.editor, std::move(data)};
    }
    editor.execute(std::move(change), new_ids);
    return ok();
}

Result<void> set_setting(Editor& editor, std::string_view name, const FieldValue& value,
                         std::string merge_key) {
    const Document& doc = editor.doc();
    level::Settings after = doc.level.settings;
    if (auto r = set_settings_field(after, name, value); !r) return r;
    if (after == doc.level.settings) return ok();
    auto change = std::make_unique<LevelChange>();
    change->set_name("Set " + std::string(name));
    change->settings = Change<level::Settings>{doc.level.settings, after};
    change->merge_key = std::move(merge_key);
    editor.execute(std::move(change), doc.selection);
    return ok();
}

Result<void> set_setting_text(Editor& editor, std::string_view name, std::string_view text) {
    const Document& doc = editor.doc();
    for (const auto& field : describe_settings_fields()) {
        if (field.name != name) continue;
        auto value = parse_field_value(field, text);
        if (!value) return value.error();
        return set_setting(editor, name, *value);
    }
    level::Settings unchanged = doc.level.settings;
    return set_settings_field(unchanged, name, FieldValue(0.0)); // unknown: lists the valid names
}

Result<void> set_player_start(Editor& editor, const level::PlayerStart& start, std::string merge_key) {
    const Document& doc = editor.doc();
    if (!is_finite(start.position) || !std::isfinite(start.yaw))
        return Error("player start: position and yaw must be finite numbers");
    level::PlayerStart snapped{doc.grid.snap_point(start.position),
                               wrap_degrees(doc.grid.snap_angle(start.yaw))};
    if (snapped == doc.level.player_start) return ok();
    auto change = std::make_unique<LevelChange>();
    change->set_name("Move player start");
    change->player_start = Change<level::PlayerStart>{doc.level.player_start, snapped};
    change->merge_key = std::move(merge_key);
    editor.execute(std::move(change), doc.selection);
    return ok();
}

Result<void> rename_level(Editor& editor, std::string name) {
    const Document& doc = editor.doc();
    if (name == doc.level.name) return ok();
    auto change = std::make_unique<LevelChange>();
    change->set_name("Rename level");
    change->level_name = Change<std::string>{doc.level.name, std::move(name)};
    editor.execute(std::move(change), doc.selection);
    return ok();
}

} // namespace ks::editor
