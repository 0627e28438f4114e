// --status-file: a JSON snapshot of the editor session, rewritten every frame (temp file + rename, so a
// reader never sees half of it). Tests that drive the window with real X input (xdotool) read it to find
// where things are on screen (palette buttons, entities, gizmo handles) and to wait for the state an input
// should produce (selection, entity count, undo depth, dirty flag, play-test) instead of sleeping.
#include "level/level.h"
#include "model/edit_files.h"
#include "model/edit_groups.h"
#include "ui/dojo_panel.h"
#include "ui/editor_app.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <nlohmann/json.hpp>

#include <fstream>
#include <unistd.h>

namespace ks::editor::ui {

namespace {
nlohmann::json point(Vec2 p) {
    return nlohmann::json::array({p.x, p.y});
}

// The dojo tab: history, what is shown, the clip file's state, and where its buttons and blend cells are.
nlohmann::json dojo_status(const DojoPanel& dojo) {
    const auto d = dojo.status();
    nlohmann::json spots = nlohmann::json::object();
    for (size_t i = 0; i < d.spots.size(); ++i)
        if (d.spots[i] != Vec2(0.0f)) spots[dojo_spot_name(static_cast<DojoSpot>(i))] = point(d.spots[i]);
    for (const auto& [name, at] : d.named) spots[name] = point(at);
    nlohmann::json cells = nlohmann::json::object(); // "from>to": centre, while the Blends page is shown
    const size_t n = d.blend_clips.size();
    if (d.blend_centres.size() == n * n)
        for (size_t from = 0; from < n; ++from)
            for (size_t to = 0; to < n; ++to)
                if (d.blend_centres[from * n + to] != Vec2(0.0f)) // drawn (not scrolled out of the table)
                    cells[d.blend_clips[from] + ">" + d.blend_clips[to]] =
                        point(d.blend_centres[from * n + to]);
    nlohmann::json curve_keys = nlohmann::json::array();
    for (const Vec2& key : d.curve_keys) curve_keys.push_back(point(key));
    nlohmann::json event_flags = nlohmann::json::array();
    for (const Vec2& flag : d.event_flags) event_flags.push_back(point(flag));
    nlohmann::json joints = nlohmann::json::object();
    for (const auto& [name, at] : d.joints) joints[name] = point(at);
    nlohmann::json rings = nlohmann::json::array();
    for (const Vec2& ring : d.rings) rings.push_back(point(ring));
    return {{"undo", d.undo},
            {"redo", d.redo},
            {"undo_name", d.undo_name},
            {"keys", d.keys},
            {"phases", d.phases},
            {"phase", d.phase},
            {"clips", d.clips},
            {"clip", d.clip},
            {"events", d.events},
            {"page", d.page},
            {"message", d.message},
            {"transition", d.transition},
            {"blend_selected", {d.blend_from, d.blend_to}},
            {"dirty", d.dirty},
            {"changed_on_disk", d.changed_on_disk},
            {"onion", d.onion},
            {"ghosts", d.ghosts},
            {"auditioned", d.auditioned},
            {"file", dojo.clip_file().string()},
            {"spots", spots},
            {"blend_cells", cells},
            {"curve_keys", curve_keys},
            {"curve_selected", d.curve_selected},
            {"event_flags", event_flags},
            {"pose",
             {{"node", d.node},
              {"edits", d.pose_edits},
              {"auto_key", d.auto_key},
              {"ik", d.ik},
              {"joints", joints},
              {"rings", rings}}},
            // Kept from before the spots map (older tests read them).
            {"add_key", point(d.spots[static_cast<size_t>(DojoSpot::AddKey)])},
            {"duplicate_key", point(d.spots[static_cast<size_t>(DojoSpot::DuplicateKey)])}};
}
nlohmann::json links_json(const std::vector<level::Link>& links) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& l : links)
        out.push_back({{"event", l.event},
                       {"target", l.target},
                       {"action", l.action},
                       {"delay", l.delay},
                       {"once", l.once}});
    return out;
}

// The level logic: objectives, the level's links, pick mode and where the logic widgets are.
void logic_status(nlohmann::json& s, const Editor& editor, const LogicPanels& logic,
                  const UiSpots& ui_spots) {
    using nlohmann::json;
    json objectives = json::array();
    for (const auto& o : editor.level().objectives)
        objectives.push_back(
            {{"id", o.id}, {"text", o.text}, {"kill", o.kill}, {"links", links_json(o.links)}});
    s["objectives"] = objectives;
    s["level_links"] = links_json(editor.level().links);
    logic.pick_status(s);
    json spots = json::object();
    for (const auto& [name, at] : ui_spots.all()) spots[name] = point(at);
    s["spots"] = spots;
}

// The player start (where it is, whether it is selected; the viewport adds its body's centre on screen) and
// the texture browser.
void objects_status(nlohmann::json& s, const Editor& editor, const TextureBrowser& browser) {
    const level::PlayerStart& start = editor.level().player_start;
    s["player_start"] = {{"position", {start.position.x, start.position.y, start.position.z}},
                         {"yaw", start.yaw},
                         {"selected", editor.doc().player_start_selected()}};
    s["texture_browser"] = {
        {"open", browser.is_open()}, {"query", browser.query()}, {"shown", browser.shown()}};
}

// Groups, layers, the entered group and the prefab library, so tests can wait on the structure.
void structure_status(nlohmann::json& s, const Editor& editor, const Outliner& outliner,
                      const PrefabPalette& palette, const PrefabPrompt& prompt) {
    using nlohmann::json;
    const level::EditorData& data = editor.level().editor;
    json groups = json::array();
    for (const level::Group& g : data.groups)
        groups.push_back({{"id", g.id},
                          {"name", g.name},
                          {"entities", group_entities_deep(data, g.id)},
                          {"groups", g.groups},
                          {"prefab", g.has_prefab ? g.prefab.prefab : std::string()},
                          {"overrides", g.has_prefab ? json(g.prefab.overrides) : json::array()}});
    s["groups"] = groups;
    s["selected_groups"] = selected_groups(editor);
    s["open_group"] = editor.open_group();
    json layers = json::array();
    for (size_t i = 0; i < data.layers.size(); ++i) {
        const level::Layer& l = data.layers[i];
        layers.push_back({{"name", l.name},
                          {"visible", l.visible},
                          {"locked", l.locked},
                          {"count", i < outliner.layer_counts().size() ? outliner.layer_counts()[i] : 0}});
    }
    s["layers"] = layers;
    s["active_layer"] = data.active_layer;
    json hidden = json::array();
    for (const level::Entity& e : editor.level().entities)
        if (editor.doc().hidden.contains(e.id)) hidden.push_back(e.id);
    s["hidden"] = hidden;
    json prefabs = json::array();
    for (const PrefabEntry& entry : editor.prefabs().entries())
        prefabs.push_back({{"name", entry.name},
                           {"ok", entry.prefab.ok()},
                           {"entities", entry.prefab ? entry.prefab->entities.size() : 0},
                           {"error", entry.prefab ? std::string() : entry.prefab.error().str()}});
    s["prefabs"] = prefabs;
    s["prefab_thumbnails"] = palette.thumbnail_count();
    prompt.status(editor, s);
    s["prefab_folders"] = json::array();
    for (const auto& folder : editor.prefabs().folders()) s["prefab_folders"].push_back(folder.string());
}

// The session: the file, the entities and the selection's primary, the history.
void document_status(nlohmann::json& s, Editor& editor) { // title() takes the editor as it is
    s["title"] = title(editor);
    s["file"] = editor.file_path().string();
    s["entities"] = editor.level().entities.size();
    s["selection"] = editor.doc().selection;
    s["faces"] = face_status(editor);
    s["undo"] = editor.history().undo_count();
    s["undo_name"] = editor.history().undo_name();
    s["redo"] = editor.history().step_names().size() - editor.history().undo_count();
    s["dirty"] = editor.has_unsaved_changes();
    if (editor.doc().selection.empty()) return;
    if (const level::Entity* e = editor.level().find(editor.doc().selection.front())) {
        s["primary"] = {{"id", e->id},
                        {"type", std::string(level::type_name(e->type()))},
                        {"name", e->name},
                        {"position", {e->position.x, e->position.y, e->position.z}},
                        {"yaw", e->rotation.x},
                        {"rotation", {e->rotation.x, e->rotation.y, e->rotation.z}},
                        {"links", links_json(e->links)}};
        if (const auto texture = selection_texture(editor)) s["primary"]["texture"] = texture->name;
        nlohmann::json fields =
            nlohmann::json::object(); // every field as the inspector's text (what a typed edit set)
        for (const FieldDescriptor& field : describe_entity_fields(*e))
            if (const auto value = get_entity_field(*e, field.name))
                fields[field.name] = format_field_value(*value);
        s["primary"]["fields"] = fields;
    }
}

// The window and what input the editor sees, so that a test driving it with X events can say why a key did
// nothing.
void input_status(nlohmann::json& s, GLFWwindow* window) {
    int wx = 0, wy = 0;
    glfwGetWindowPos(window, &wx, &wy);
    s["window"] = {wx, wy};
    const ImGuiIO& io = ImGui::GetIO();
    // Keys other than the modifiers held in this frame: a test releases a key once the editor has seen it
    // pressed, before ImGui's key repeat could fire a second time on a slow frame.
    int keys_down = 0;
    for (int k = 0; k < IM_ARRAYSIZE(io.KeysDown); ++k)
        if (io.KeysDown[k] && (k < GLFW_KEY_LEFT_SHIFT || k > GLFW_KEY_RIGHT_SUPER)) ++keys_down;
    s["input"] = {
        {"focused", glfwGetWindowAttrib(window, GLFW_FOCUSED) != 0},
        {"keys_down", keys_down},
        {"ctrl", io.KeyCtrl},
        {"shift", io.KeyShift},
        {"alt", io.KeyAlt},
        // Where ImGui saw the pointer this frame and which buttons it saw held: a test waits on
        // these between the steps of a drag, since ImGui 1.86 polls the pointer once a frame and a
        // move and a release that land in one frame lose the move.
        {"mouse", {io.MousePos.x, io.MousePos.y}},
        {"buttons", (io.MouseDown[0] ? 1 : 0) | (io.MouseDown[1] ? 2 : 0) | (io.MouseDown[2] ? 4 : 0)},
        {"text_input", io.WantTextInput},
        {"active_item", ImGui::IsAnyItemActive()}};
}

// Temp file and rename, so a reader never sees half of it; false: not written (tried again next frame). A
// status file is a test aid: never an error for the user.
bool write_atomically(const std::filesystem::path& path, const std::string& text) {
    const auto temp = std::filesystem::path(path.string() + ".tmp");
    {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        out << text << '\n';
        if (!out) return false;
    }
    std::error_code ec;
    std::filesystem::rename(temp, path, ec);
    return true;
}
} // namespace

// Each panel writes its own part; the keys do not depend on who writes them.
void EditorApp::write_status() {
    nlohmann::json s;
    s["frame"] = frame_;
    s["pid"] = static_cast<long>(getpid());
    document_status(s, editor_);
    input_status(s, shell_.window());
    s["tab"] = dojo_tab_ ? "dojo" : "level";
    s["left_tab"] = left_tab_name(shown_left_tab_);
    s["inspector_tab"] = inspector_tab_name(inspector_.shown_tab());
    s["menu"] = {{"file", point(menu_spots_[0])}, {"quit", point(menu_spots_[1])}};
    s["about"] = about_.status();
    if (dojo_) s["dojo"] = dojo_status(*dojo_);
    palette_.status(s);
    clip_preview_.status(s);
    objects_status(s, editor_, inspector_.texture_browser());
    scene_.status(s);
    viewport_.status(s, !dojo_tab_); // after objects_status: it adds the player start's place on screen
    structure_status(s, editor_, outliner_, prefabs_, prefab_prompt_);
    logic_status(s, editor_, logic_, spots_);
    analysis_.status(s);
    play_.status(s);
    s["error_lines"] = log_.error_lines();
    s["last_error"] = log_.last_error();
    s["log_lines"] = log_.lines().size();
    std::string text = s.dump();
    if (text == last_status_) return;
    if (write_atomically(*options_.status_file, text)) last_status_ = std::move(text);
}

} // namespace ks::editor::ui
