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
            {"event_flags", event_flags},
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
} // namespace

// The level logic: objectives, the level's links, pick mode and where the logic widgets are.
void EditorApp::logic_status(nlohmann::json& s) const {
    using nlohmann::json;
    json objectives = json::array();
    for (const auto& o : editor_.level().objectives)
        objectives.push_back(
            {{"id", o.id}, {"text", o.text}, {"kill", o.kill}, {"links", links_json(o.links)}});
    s["objectives"] = objectives;
    s["level_links"] = links_json(editor_.level().links);
    logic_.pick_status(s);
    json spots = json::object();
    for (const auto& [name, at] : spots_.all()) spots[name] = point(at);
    s["spots"] = spots;
    s["show_links"] = overlays_.links;
    s["link_arrows"] = logic_overlay_.arrow_count();
}

// The player start (where it is, whether it is selected, its body's centre on screen), the gizmo's
// rotation space and the texture browser.
void EditorApp::objects_status(nlohmann::json& s) const {
    const level::PlayerStart& start = editor_.level().player_start;
    nlohmann::json player_start = {{"position", {start.position.x, start.position.y, start.position.z}},
                                   {"yaw", start.yaw},
                                   {"selected", editor_.doc().player_start_selected()}};
    Vec2 p;
    if (!dojo_tab_ && view_.project(player_obb(start).center, p))
        player_start["screen"] = point(p + viewport_origin_);
    s["player_start"] = player_start;
    s["gizmo_space"] = rotation_space_name(gizmo_.space);
    const TextureBrowser& browser = inspector_.texture_browser();
    s["texture_browser"] = {
        {"open", browser.is_open()}, {"query", browser.query()}, {"shown", browser.shown()}};
}

// Groups, layers, the entered group and the prefab library, so tests can wait on the structure.
void EditorApp::structure_status(nlohmann::json& s) const {
    using nlohmann::json;
    const level::EditorData& data = editor_.level().editor;
    json groups = json::array();
    for (const level::Group& g : data.groups)
        groups.push_back({{"id", g.id},
                          {"name", g.name},
                          {"entities", group_entities_deep(data, g.id)},
                          {"groups", g.groups},
                          {"prefab", g.has_prefab ? g.prefab.prefab : std::string()},
                          {"overrides", g.has_prefab ? json(g.prefab.overrides) : json::array()}});
    s["groups"] = groups;
    s["selected_groups"] = selected_groups(editor_);
    s["open_group"] = editor_.open_group();
    json layers = json::array();
    for (size_t i = 0; i < data.layers.size(); ++i) {
        const level::Layer& l = data.layers[i];
        layers.push_back({{"name", l.name},
                          {"visible", l.visible},
                          {"locked", l.locked},
                          {"count", i < outliner_.layer_counts().size() ? outliner_.layer_counts()[i] : 0}});
    }
    s["layers"] = layers;
    s["active_layer"] = data.active_layer;
    json hidden = json::array();
    for (const level::Entity& e : editor_.level().entities)
        if (editor_.doc().hidden.contains(e.id)) hidden.push_back(e.id);
    s["hidden"] = hidden;
    json prefabs = json::array();
    for (const PrefabEntry& entry : editor_.prefabs().entries())
        prefabs.push_back({{"name", entry.name},
                           {"ok", entry.prefab.ok()},
                           {"entities", entry.prefab ? entry.prefab->entities.size() : 0},
                           {"error", entry.prefab ? std::string() : entry.prefab.error().str()}});
    s["prefabs"] = prefabs;
    s["prefab_thumbnails"] = prefabs_.thumbnail_count();
    prefab_prompt_.status(editor_, s);
    s["prefab_folders"] = json::array();
    for (const auto& folder : editor_.prefabs().folders()) s["prefab_folders"].push_back(folder.string());
}

void EditorApp::write_status() {
    using nlohmann::json;
    json s;
    s["frame"] = frame_;
    s["pid"] = static_cast<long>(getpid());
    s["title"] = title(editor_);
    s["file"] = editor_.file_path().string();
    s["entities"] = editor_.level().entities.size();
    s["selection"] = editor_.doc().selection;
    s["faces"] = face_status(editor_);
    s["undo"] = editor_.history().undo_count();
    s["undo_name"] = editor_.history().undo_name();
    s["redo"] = editor_.history().step_names().size() - editor_.history().undo_count();
    s["dirty"] = editor_.has_unsaved_changes();
    s["placing"] = placing_.type ? std::string(level::type_name(*placing_.type)) : std::string();
    s["placing_prefab"] = placing_.prefab;
    s["gizmo"] = gizmo_mode_name(gizmo_.mode);
    s["dragging"] = gizmo_.dragging();
    s["render_scale"] = renderer_ ? renderer_->render_scale() : 0.0f;
    s["navmesh"] = {{"shown", overlays_.navmesh},
                    {"builds", nav_preview_.stats().builds},
                    {"last_build_ms", nav_preview_.stats().last_build_ms},
                    {"triangles", nav_preview_.stats().triangles},
                    {"error", nav_preview_.error()}};
    s["scene"] = {{"builds", scene_stats_.builds},
                  {"bakes", scene_stats_.bakes},
                  {"last_build_cpu_ms", scene_stats_.last_build_cpu_ms}};
    s["view"] = view_mode_name(view_.mode);
    s["tab"] = dojo_tab_ ? "dojo" : "level";
    s["left_tab"] = left_tab_name(shown_left_tab_);
    s["inspector_tab"] = inspector_tab_name(inspector_.shown_tab());
    s["menu"] = {{"file", point(menu_spots_[0])}, {"quit", point(menu_spots_[1])}};
    s["about"] = about_.status();
    s["clip_preview"] = {{"on", clip_preview_.on()},
                         {"robot", clip_preview_.posed_robot()},
                         {"toggle", point(clip_preview_.toggle_centre())}};
    if (dojo_) s["dojo"] = dojo_status(*dojo_);
    int wx = 0, wy = 0;
    glfwGetWindowPos(shell_.window(), &wx, &wy);
    s["window"] = {wx, wy};
    // What input the editor sees, so that a test driving it with X events can say why a key did nothing.
    const ImGuiIO& io = ImGui::GetIO();
    // Keys other than the modifiers held in this frame: a test releases a key once the editor has seen it
    // pressed, before ImGui's key repeat could fire a second time on a slow frame.
    int keys_down = 0;
    for (int k = 0; k < IM_ARRAYSIZE(io.KeysDown); ++k)
        if (io.KeysDown[k] && (k < GLFW_KEY_LEFT_SHIFT || k > GLFW_KEY_RIGHT_SUPER)) ++keys_down;
    s["input"] = {{"focused", glfwGetWindowAttrib(shell_.window(), GLFW_FOCUSED) != 0},
                  {"keys_down", keys_down},
                  {"ctrl", io.KeyCtrl},
                  {"shift", io.KeyShift},
                  {"text_input", io.WantTextInput},
                  {"active_item", ImGui::IsAnyItemActive()}};
    s["viewport"] = {viewport_origin_.x, viewport_origin_.y, viewport_size_.x, viewport_size_.y};
    json palette = json::object();
    for (auto type : level::all_types()) {
        const PlacePalette::ScreenRect& r = palette_.rect(type);
        if (r.max.x > r.min.x) palette[std::string(level::type_name(type))] = point((r.min + r.max) * 0.5f);
    }
    s["palette"] = palette;
    // Entity centres on screen (window pixels), for the first 64 entities.
    json screen = json::object();
    int listed = 0;
    for (const auto& e : editor_.level().entities) {
        if (listed++ >= 64) break;
        Vec2 p;
        if (view_.project(entity_obb(e).center, p))
            screen[std::to_string(e.id)] = point(p + viewport_origin_);
    }
    s["screen"] = screen;
    if (!editor_.doc().selection.empty() && !dojo_tab_) {
        const GizmoShape g = gizmo_shape(view_, gizmo_frame());
        if (g.valid) {
            json handles;
            handles["centre"] = point(g.centre + viewport_origin_);
            const char* axes[3] = {"x", "y", "z"};
            for (int i = 0; i < 3; ++i) {
                if (g.axis_visible[i]) // the middle of the arrow: a safe place to grab it
                    handles[axes[i]] = point((g.centre + g.tips[i]) * 0.5f + viewport_origin_);
                if (g.ring_visible[i] && gizmo_.mode == GizmoMode::Rotate) // where the ring starts
                    handles[std::string("ring_") + axes[i]] = point(g.rings[i][0] + viewport_origin_);
            }
            s["gizmo_handles"] = handles;
        }
    }
    if (!editor_.doc().selection.empty())
        if (const level::Entity* e = editor_.level().find(editor_.doc().selection.front())) {
            s["primary"] = {{"id", e->id},
                            {"type", std::string(level::type_name(e->type()))},
                            {"name", e->name},
                            {"position", {e->position.x, e->position.y, e->position.z}},
                            {"yaw", e->rotation.x},
                            {"rotation", {e->rotation.x, e->rotation.y, e->rotation.z}},
                            {"links", links_json(e->links)}};
            if (const auto texture = selection_texture(editor_)) s["primary"]["texture"] = texture->name;
        }
    objects_status(s);
    structure_status(s);
    logic_status(s);
    panes_status(s);
    analysis_.status(s);
    play_.status(s);
    s["error_lines"] = log_.error_lines();
    s["last_error"] = log_.last_error();
    s["log_lines"] = log_.lines().size();
    std::string text = s.dump();
    if (text == last_status_) return;
    const auto& path = *options_.status_file;
    const auto temp = std::filesystem::path(path.string() + ".tmp");
    {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        out << text << '\n';
        if (!out) return; // a status file is a test aid: never an error for the user
    }
    std::error_code ec;
    std::filesystem::rename(temp, path, ec);
    last_status_ = std::move(text);
}

} // namespace ks::editor::ui
