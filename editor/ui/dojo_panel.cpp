#include "ui/dojo_panel.h"

#include "anim/gltf_rig.h"
#include "core/paths.h"
#include "model/dojo_keys.h"
#include "render/level_scene.h"
#include "render/mesh_data.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ks::editor::ui {

namespace {
constexpr float kDojoBar = 190.0f; // transport, timeline and transition tester under the preview

const char* loop_name(anim::LoopMode m) {
    return m == anim::LoopMode::Loop ? "loop" : m == anim::LoopMode::Next ? "next" : "once";
}
} // namespace

void dojo_preview_size(float tab_width, float tab_height, float& w, float& h) {
    w = std::max(64.0f, std::floor(tab_width * 0.5f));
    h = std::max(64.0f, std::floor(tab_height - kDojoBar));
}

DojoPanel::DojoPanel(render::AssetLibrary& assets, render::SceneRenderer& renderer,
                     std::filesystem::path clip_file)
    : assets_(assets), renderer_(renderer),
      clip_file_(clip_file.empty() ? paths::asset("animations/robot.json") : std::move(clip_file)) {
    render::MeshData floor;
    render::append_box(floor, Vec3(0, -0.05f, 0), Vec3(14, 0.1f, 14), Mat4(1.0f), 2.0f);
    floor_ = std::make_unique<render::GpuMesh>(floor);
    floor_material_ = &assets_.surface("tiles");
    lights_.push_back({render::Light::Type::Point, Vec3(3.0f, 5.0f, 4.0f), Vec3(0, -1, 0),
                       Vec3(1.0f, 0.85f, 0.7f), 1.2f, 20.0f, 0.8f, 0.9f});
    lights_.push_back({render::Light::Type::Point, Vec3(-4.0f, 3.0f, -2.0f), Vec3(0, -1, 0),
                       Vec3(0.5f, 0.7f, 1.0f), 0.8f, 20.0f, 0.8f, 0.9f});
}

void DojoPanel::load(const LogFn* log) {
    loaded_ = true;
    model_ = &assets_.model("robot");
    auto file = anim::load_animation_file(clip_file_);
    if (!file) {
        compile_error_ = file.error().str();
        if (log) (*log)(compile_error_, true);
        return;
    }
    file_ = std::move(*file);
    auto rig = anim::load_gltf_rig(model_->path);
    if (!rig) {
        compile_error_ = "robot model: " + rig.error().str();
        return;
    }
    rig_ = std::move(*rig);
    binding_ = anim::RigBinding(rig_, model_->node_names());
    model_pose_ = model_->rest_pose();
    dirty_ = false;
    recompile();
    if (clips_.clips.size() > 1) to_clip_ = 1;
}

void DojoPanel::recompile() {
    issues_ = anim::validate(file_);
    compile_error_.clear();
    if (!issues_.empty()) return; // keep the last good clips playing until the file is valid again
    auto compiled = anim::compile(file_, rig_);
    if (!compiled) {
        compile_error_ = compiled.error().str();
        return;
    }
    clips_ = std::move(*compiled);
    const int last = std::max(0, static_cast<int>(clips_.clips.size()) - 1);
    clip_ = std::clamp(clip_, 0, last);
    from_clip_ = std::clamp(from_clip_, 0, last);
    to_clip_ = std::clamp(to_clip_, 0, last);
    player_ = std::make_unique<anim::Player>(clips_, rig_);
    restart_at(time_);
}

// A pose is a pure function of the time since play() from the rest pose, so scrubbing replays from the start.
void DojoPanel::restart_at(double seconds) {
    if (!player_ || clips_.clips.empty()) return;
    player_ = std::make_unique<anim::Player>(clips_, rig_);
    if (transition_mode_) {
        player_->play(from_clip_, 0.0f);
        player_->advance(std::min<double>(seconds, switch_time_));
        if (seconds > switch_time_) {
            player_->play(to_clip_, blend_time_);
            player_->advance(seconds - switch_time_);
        }
    } else {
        player_->play(clip_, 0.0f);
        player_->advance(seconds);
    }
    time_ = seconds;
}

void DojoPanel::evaluate_pose() {
    if (player_) binding_.write_locals(player_->pose(), model_pose_.local);
}

void DojoPanel::render(float width, float height, double dt) {
    if (!loaded_) load(nullptr);
    dojo_preview_size(width, height, preview_w_, preview_h_);
    if (player_ && playing_ && dt > 0) {
        const double step = dt * speed_;
        const double length = transition_mode_ ? switch_time_ + blend_time_ + clips_.clips[to_clip_].duration
                                               : clips_.clips[clip_].duration;
        if (loop_ && length > 0 && time_ + step > length &&
            (transition_mode_ || clips_.clips[clip_].loop == anim::LoopMode::Once))
            restart_at(0.0);
        else {
            player_->advance(step);
            time_ += step;
        }
    }
    evaluate_pose();
    target_.ensure(static_cast<int>(preview_w_), static_cast<int>(preview_h_));
    target_.bind();
    instances_.clear();
    if (model_) model_->emit(Mat4(1.0f), model_pose_, scratch_, instances_);
    instances_.push_back({floor_.get(), floor_material_, Mat4(1.0f), 1.0f, false});
    const Vec3 target(0.0f, 1.6f, 0.0f);
    geometry::Camera camera;
    camera.fov_y = radians(40.0f);
    camera.aspect = preview_w_ / preview_h_;
    camera.yaw = orbit_yaw_;
    camera.pitch = -orbit_pitch_;
    camera.position = target - camera.forward() * 8.5f;
    const render::Environment env = render::preview_environment(0.02f);
    debug_.clear();
    for (int i = -3; i <= 3; ++i) { // a floor grid, one unit apart, to read motion against
        debug_.line(Vec3(i, 0.01f, -3), Vec3(i, 0.01f, 3), Vec4(0.6f, 0.7f, 0.8f, 0.25f));
        debug_.line(Vec3(-3, 0.01f, i), Vec3(3, 0.01f, i), Vec4(0.6f, 0.7f, 0.8f, 0.25f));
    }
    render::SceneFrame frame;
    frame.camera = camera;
    frame.environment = env;
    frame.instances = &instances_;
    frame.lights = &lights_;
    frame.debug = &debug_;
    frame.width = target_.width();
    frame.height = target_.height();
    renderer_.invalidate_shadows(); // the level viewport shares the renderer's shadow cache
    renderer_.render(frame);
    renderer_.invalidate_shadows();
}

void DojoPanel::curve(const anim::Ease& ease, float size) {
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImVec2 p = ImGui::GetCursorScreenPos();
    const float h = size * 0.6f, pad = h * 0.25f;
    draw->AddRectFilled(p, ImVec2(p.x + size, p.y + h + 2 * pad), IM_COL32(20, 22, 28, 255), 3.0f);
    draw->AddLine(ImVec2(p.x, p.y + pad), ImVec2(p.x + size, p.y + pad), IM_COL32(80, 80, 90, 255));
    draw->AddLine(ImVec2(p.x, p.y + pad + h), ImVec2(p.x + size, p.y + pad + h), IM_COL32(80, 80, 90, 255));
    ImVec2 points[64];
    for (int i = 0; i < 64; ++i) {
        const double t = i / 63.0;
        points[i] =
            ImVec2(p.x + static_cast<float>(t) * size, p.y + pad + h - static_cast<float>(ease(t)) * h);
    }
    draw->AddPolyline(points, 64, IM_COL32(120, 200, 255, 255), 0, 2.0f);
    ImGui::Dummy(ImVec2(size, h + 2 * pad));
}

void DojoPanel::timeline(float width) {
    if (clips_.clips.empty()) return;
    const double length = transition_mode_ ? switch_time_ + blend_time_ + clips_.clips[to_clip_].duration
                                           : std::max(0.01, clips_.clips[clip_].duration);
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImVec2 p = ImGui::GetCursorScreenPos();
    const float h = 34.0f;
    ImGui::InvisibleButton("timeline", ImVec2(width, h));
    if (ImGui::IsItemActive()) { // scrub
        const float u = std::clamp((ImGui::GetIO().MousePos.x - p.x) / width, 0.0f, 1.0f);
        playing_ = false;
        restart_at(u * length);
    }
    draw->AddRectFilled(p, ImVec2(p.x + width, p.y + h), IM_COL32(28, 31, 38, 255), 4.0f);
    for (int s = 0; s <= static_cast<int>(length * 10); ++s) { // ticks every 0.1 s, labels every second
        const float x = p.x + static_cast<float>(s / 10.0 / length) * width;
        const bool second = s % 10 == 0;
        draw->AddLine(ImVec2(x, p.y + h - (second ? 12 : 6)), ImVec2(x, p.y + h),
                      IM_COL32(110, 115, 130, 255));
        if (second) {
            char t[16];
            std::snprintf(t, sizeof(t), "%ds", s / 10);
            draw->AddText(ImVec2(x + 2, p.y + h - 26), IM_COL32(150, 155, 170, 255), t);
        }
    }
    // Key markers: the end of every phase (where its targets are reached).
    auto markers = [&](const anim::ClipDef& def, double offset, ImU32 colour) {
        double t = 0;
        for (size_t i = 0; i < def.phases.size(); ++i) {
            t += def.phases[i].duration;
            const float x = p.x + static_cast<float>((offset + t) / length) * width;
            if (x > p.x + width + 1) break;
            const bool sel = !transition_mode_ && static_cast<int>(i) == selected_phase_;
            draw->AddQuadFilled(ImVec2(x, p.y + 3), ImVec2(x + 5, p.y + 9), ImVec2(x, p.y + 15),
                                ImVec2(x - 5, p.y + 9), sel ? IM_COL32(255, 210, 80, 255) : colour);
        }
    };
    if (transition_mode_) {
        markers(file_.clips[static_cast<size_t>(from_clip_)], 0.0, IM_COL32(150, 200, 255, 255));
        markers(file_.clips[static_cast<size_t>(to_clip_)], switch_time_, IM_COL32(255, 150, 120, 255));
        const float xs = p.x + static_cast<float>(switch_time_ / length) * width;
        const float xb = p.x + static_cast<float>((switch_time_ + blend_time_) / length) * width;
        draw->AddRectFilled(ImVec2(xs, p.y), ImVec2(xb, p.y + h), IM_COL32(255, 200, 80, 50));
    } else if (static_cast<size_t>(clip_) < file_.clips.size()) {
        markers(file_.clips[static_cast<size_t>(clip_)], 0.0, IM_COL32(150, 200, 255, 255));
    }
    const float x = p.x + static_cast<float>(std::fmod(time_, length + 1e-9) / length) * width;
    draw->AddLine(ImVec2(x, p.y), ImVec2(x, p.y + h), IM_COL32(255, 80, 80, 255), 2.0f);
}

void DojoPanel::transition_tester() {
    if (clips_.clips.empty()) return;
    ImGui::Checkbox("Transition test", &transition_mode_);
    if (ImGui::IsItemEdited()) restart_at(0.0);
    auto clip_combo = [&](const char* label, int& index) {
        bool changed = false;
        ImGui::SetNextItemWidth(140);
        if (ImGui::BeginCombo(label, clips_.clips[static_cast<size_t>(index)].name.c_str())) {
            for (int i = 0; i < static_cast<int>(clips_.clips.size()); ++i)
                if (ImGui::Selectable(clips_.clips[static_cast<size_t>(i)].name.c_str(), i == index))
                    index = i, changed = true;
            ImGui::EndCombo();
        }
        return changed;
    };
    bool changed = clip_combo("from", from_clip_);
    ImGui::SameLine();
    changed |= clip_combo("to", to_clip_);
    ImGui::SetNextItemWidth(140);
    changed |= ImGui::DragFloat("switch at", &switch_time_, 0.01f, 0.0f, 10.0f, "%.2f s");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(140);
    changed |= ImGui::DragFloat("blend", &blend_time_, 0.01f, 0.0f, 5.0f, "%.2f s");
    ImGui::SameLine();
    if (ImGui::SmallButton("file's blend"))
        blend_time_ = clips_.blend_time(from_clip_, to_clip_), changed = true;
    if (changed && transition_mode_) restart_at(0.0);
}

bool DojoPanel::phase_buttons(const LogFn& log) {
    const auto c = static_cast<std::size_t>(clip_), p = static_cast<std::size_t>(selected_phase_);
    const std::size_t count = file_.clips[c].phases.size();
    const std::string key = "key " + std::to_string(p + 1);
    auto apply = [&](const std::string& name, auto&& edit) {
        anim::AnimationFile before = file_;
        if (auto r = edit(); !r) {
            log("dojo: " + r.error().str(), true);
            return false;
        }
        history_.record(before, name);
        return true;
    };
    bool changed = false;
    const bool duplicate_clicked = ImGui::SmallButton("Duplicate key");
    duplicate_key_x_ = (ImGui::GetItemRectMin().x + ImGui::GetItemRectMax().x) * 0.5f;
    duplicate_key_y_ = (ImGui::GetItemRectMin().y + ImGui::GetItemRectMax().y) * 0.5f;
    if (duplicate_clicked)
        changed = apply("duplicate " + key, [&]() -> Result<void> {
            auto copy = duplicate_phase(file_, c, p);
            if (!copy) return copy.error();
            selected_phase_ = static_cast<int>(*copy);
            return {};
        });
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Insert a copy of this key after it: absolute targets hold the pose (a pause), "
                          "relative ones repeat the motion");
    ImGui::SameLine();
    ImGui::BeginDisabled(count <= 1);
    if (ImGui::SmallButton("Remove key"))
        changed = apply("remove " + key, [&]() -> Result<void> {
            auto r = remove_phase(file_, c, p);
            if (r) selected_phase_ = std::max(0, selected_phase_ - 1);
            return r;
        });
    ImGui::EndDisabled();
    for (int offset : {-1, +1}) {
        ImGui::SameLine();
        ImGui::BeginDisabled(offset < 0 ? p == 0 : p + 1 >= count);
        if (ImGui::SmallButton(offset < 0 ? "Earlier" : "Later"))
            changed = apply("move " + key + (offset < 0 ? " earlier" : " later"), [&]() -> Result<void> {
                auto moved = move_phase(file_, c, p, offset);
                if (!moved) return moved.error();
                selected_phase_ = static_cast<int>(*moved);
                return {};
            });
        ImGui::EndDisabled();
    }
    return changed;
}

void DojoPanel::begin_edit(const std::string& name) {
    if (!edit_open_) history_.record(file_, name);
    edit_open_ = true;
}

DojoPanel::Status DojoPanel::status() const {
    Status st;
    st.undo = history_.undo_count();
    st.redo = history_.redo_count();
    const auto c = static_cast<std::size_t>(clip_), p = static_cast<std::size_t>(selected_phase_);
    if (c < file_.clips.size() && p < file_.clips[c].phases.size()) {
        st.keys = file_.clips[c].phases[p].targets.size();
        st.phases = file_.clips[c].phases.size();
        st.phase = p;
    }
    st.duplicate_key_x = duplicate_key_x_;
    st.duplicate_key_y = duplicate_key_y_;
    st.add_key_x = add_key_x_;
    st.add_key_y = add_key_y_;
    return st;
}

bool DojoPanel::undo() {
    if (!history_.undo(file_)) return false;
    dirty_ = true;
    recompile();
    return true;
}

bool DojoPanel::redo() {
    if (!history_.redo(file_)) return false;
    dirty_ = true;
    recompile();
    return true;
}

void DojoPanel::key_table(const LogFn& log) {
    if (static_cast<size_t>(clip_) >= file_.clips.size()) return;
    anim::ClipDef& def = file_.clips[static_cast<size_t>(clip_)];
    if (!ImGui::IsAnyItemActive()) edit_open_ = false; // a dragged field is one undo step
    ImGui::Text("Clip '%s': %s, %zu phases, %.2f s", def.name.c_str(), loop_name(def.loop), def.phases.size(),
                def.duration());
    if (def.phases.empty()) return;
    selected_phase_ = std::clamp(selected_phase_, 0, static_cast<int>(def.phases.size()) - 1);
    for (int i = 0; i < static_cast<int>(def.phases.size()); ++i) {
        char label[32];
        std::snprintf(label, sizeof(label), "key %d", i + 1);
        if (i) ImGui::SameLine();
        if (ImGui::RadioButton(label, selected_phase_ == i)) selected_phase_ = i;
    }
    if (phase_buttons(log)) {
        dirty_ = true;
        recompile();
        return; // the phase list changed under this frame's references: draw the table next frame
    }
    anim::PhaseDef& phase = def.phases[static_cast<size_t>(selected_phase_)];
    bool edited = phase_timing(phase);
    std::string remove_node; // a key to remove, applied after the table (the rows reference the targets)
    edited |= target_rows(phase, remove_node);
    const auto clip_index = static_cast<std::size_t>(clip_),
               phase_index = static_cast<std::size_t>(selected_phase_);
    if (!remove_node.empty()) {
        history_.record(file_, "remove key " + remove_node);
        if (auto r = remove_node_key(file_, clip_index, phase_index, remove_node); !r)
            log("dojo: " + r.error().str(), true);
        else
            edited = true;
    }
    edited |= add_key_row(log);
    if (edited) {
        dirty_ = true;
        recompile();
    }
    save_row(log);
}

// The selected key's duration and easing (with its curve); true when either changed.
bool DojoPanel::phase_timing(anim::PhaseDef& phase) {
    bool edited = false;
    ImGui::BeginGroup();
    float duration = static_cast<float>(phase.duration);
    ImGui::SetNextItemWidth(120);
    if (ImGui::DragFloat("duration", &duration, 0.005f, 0.0f, 30.0f, "%.3f s", ImGuiSliderFlags_AlwaysClamp))
        begin_edit("key duration"), phase.duration = duration, edited = true;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Seconds to reach this key's targets; a key with no targets is a delay.");
    ImGui::SetNextItemWidth(170);
    const std::string current = anim::ease_name(phase.ease);
    if (ImGui::BeginCombo("easing", current.empty() ? "custom" : current.c_str())) {
        for (const auto& name : anim::known_ease_names())
            if (ImGui::Selectable(name.c_str(), name == current))
                if (auto e = anim::parse_ease_name(name))
                    begin_edit("key easing"), phase.ease = *e, edited = true;
        ImGui::EndCombo();
    }
    ImGui::EndGroup();
    ImGui::SameLine();
    curve(phase.ease, 96.0f);

    return edited;
}

// One row per keyed node: rotation, position offset, mode and a remove button (`remove_node` names it).
bool DojoPanel::target_rows(anim::PhaseDef& phase, std::string& remove_node) {
    bool edited = false;
    if (ImGui::BeginTable("targets", 5,
                          ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY |
                              ImGuiTableFlags_SizingStretchProp,
                          ImVec2(0, std::max(80.0f, ImGui::GetContentRegionAvail().y - 64.0f)))) {
        ImGui::TableSetupColumn("node", ImGuiTableColumnFlags_WidthFixed, 90);
        ImGui::TableSetupColumn("rotation (deg, XYZ)");
        ImGui::TableSetupColumn("position offset");
        ImGui::TableSetupColumn("mode", ImGuiTableColumnFlags_WidthFixed, 60);
        ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthFixed, 24);
        ImGui::TableHeadersRow();
        for (size_t t = 0; t < phase.targets.size(); ++t) {
            anim::TargetDef& target = phase.targets[t];
            ImGui::PushID(static_cast<int>(t));
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(target.node.c_str());
            ImGui::TableNextColumn();
            auto& rot = target.rot ? target.rot : target.add_rot;
            if (rot) {
                float v[3] = {static_cast<float>(rot->x), static_cast<float>(rot->y),
                              static_cast<float>(rot->z)};
                ImGui::SetNextItemWidth(-1);
                if (ImGui::DragFloat3("##rot", v, 0.5f, -3600.0f, 3600.0f, "%.1f"))
                    begin_edit("rotate " + target.node), *rot = DVec3(v[0], v[1], v[2]), edited = true;
            } else if (ImGui::SmallButton("+ rot")) {
                begin_edit("rotate " + target.node), target.rot = DVec3(0.0), edited = true;
            }
            ImGui::TableNextColumn();
            auto& pos = target.pos ? target.pos : target.add_pos;
            if (pos) {
                float v[3] = {static_cast<float>(pos->x), static_cast<float>(pos->y),
                              static_cast<float>(pos->z)};
                ImGui::SetNextItemWidth(-1);
                if (ImGui::DragFloat3("##pos", v, 0.01f, -100.0f, 100.0f, "%.2f"))
                    begin_edit("move " + target.node), *pos = DVec3(v[0], v[1], v[2]), edited = true;
            } else if (ImGui::SmallButton("+ pos")) {
                begin_edit("move " + target.node), target.pos = DVec3(0.0), edited = true;
            }
            ImGui::TableNextColumn();
            ImGui::TextDisabled("%s", target.add_rot || target.add_pos ? "relative" : "absolute");
            ImGui::TableNextColumn();
            if (ImGui::SmallButton("x")) remove_node = target.node;
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("Remove this node's key from this phase");
            ImGui::PopID();
        }
        ImGui::EndTable();
    }
    return edited;
}

// The node combo and "Add key" button; true when a key was added.
bool DojoPanel::add_key_row(const LogFn& log) {
    bool edited = false;
    const auto clip_index = static_cast<std::size_t>(clip_),
               phase_index = static_cast<std::size_t>(selected_phase_);
    const auto free_nodes = unkeyed_nodes(file_, clip_index, phase_index);
    add_node_ = std::clamp(add_node_, 0, std::max(0, static_cast<int>(free_nodes.size()) - 1));
    ImGui::BeginDisabled(free_nodes.empty());
    ImGui::SetNextItemWidth(140);
    if (ImGui::BeginCombo("##add_node", free_nodes.empty()
                                            ? "(every node keyed)"
                                            : free_nodes[static_cast<size_t>(add_node_)].c_str())) {
        for (int i = 0; i < static_cast<int>(free_nodes.size()); ++i)
            if (ImGui::Selectable(free_nodes[static_cast<size_t>(i)].c_str(), i == add_node_)) add_node_ = i;
        ImGui::EndCombo();
    }
    ImGui::SameLine();
    const bool add_clicked = ImGui::Button("Add key");
    add_key_x_ = (ImGui::GetItemRectMin().x + ImGui::GetItemRectMax().x) * 0.5f;
    add_key_y_ = (ImGui::GetItemRectMin().y + ImGui::GetItemRectMax().y) * 0.5f;
    if (add_clicked && !free_nodes.empty()) {
        const std::string& node = free_nodes[static_cast<size_t>(add_node_)];
        history_.record(file_, "add key " + node);
        if (auto r = add_node_key(file_, clip_index, phase_index, node); !r)
            log("dojo: " + r.error().str(), true);
        else
            edited = true;
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "Key this node in this phase (holds its pose until you edit the key); Ctrl+Z undoes");
    ImGui::EndDisabled();
    return edited;
}

// The clip file's problems, Save (disabled while it has any) and Reload.
void DojoPanel::save_row(const LogFn& log) {
    for (const auto& issue : issues_)
        ImGui::TextColored(ImVec4(1, 0.4f, 0.35f, 1), "%s: %s (%s)", issue.path.str().c_str(),
                           issue.message.c_str(), issue.hint.c_str());
    if (!compile_error_.empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.35f, 1), "%s", compile_error_.c_str());
    ImGui::BeginDisabled(!issues_.empty());
    if (ImGui::Button(dirty_ ? "Save robot.json *" : "Save robot.json")) {
        if (auto r = save_dojo_file(clip_file_, file_); !r)
            log("dojo: " + r.error().str(), true);
        else {
            dirty_ = false;
            log("dojo: saved " + clip_file_.string() + " (the runtime's Dojo and robots load it)", false);
        }
    }
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (ImGui::Button("Reload")) load(&log);
}

void DojoPanel::panel(float x, float y, float width, float height, const LogFn& log) {
    if (!loaded_) load(&log);
    ImGui::SetNextWindowPos(ImVec2(x, y));
    ImGui::SetNextWindowSize(ImVec2(width, height));
    ImGui::Begin("Dojo", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                     ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoScrollbar);
    const ImVec2 start = ImGui::GetCursorPos();
    float pw = 0, ph = 0;
    dojo_preview_size(width, height, pw, ph);
    pw = std::min(pw, static_cast<float>(target_.width()));
    ph = std::min(ph, static_cast<float>(target_.height()));
    ImGui::BeginGroup();
    ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(target_.texture())), ImVec2(pw, ph),
                 ImVec2(0, 1), ImVec2(1, 0));
    if (ImGui::IsItemHovered() && ImGui::IsMouseDragging(ImGuiMouseButton_Left)) { // orbit the preview
        const ImVec2 d = ImGui::GetIO().MouseDelta;
        orbit_yaw_ -= d.x * 0.01f;
        orbit_pitch_ = std::clamp(orbit_pitch_ + d.y * 0.01f, -0.2f, 1.3f);
    }
    if (clips_.clips.empty()) {
        ImGui::TextColored(ImVec4(1, 0.4f, 0.35f, 1), "%s", compile_error_.c_str());
        ImGui::EndGroup();
        ImGui::End();
        return;
    }
    // Transport.
    if (ImGui::Button(playing_ ? "Pause" : "Play")) playing_ = !playing_;
    ImGui::SameLine();
    if (ImGui::Button("Stop")) playing_ = false, restart_at(0.0);
    ImGui::SameLine();
    if (ImGui::Button("Step")) playing_ = false, restart_at(time_ + 1.0 / 30.0);
    ImGui::SameLine();
    ImGui::Checkbox("Loop", &loop_);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(90);
    ImGui::DragFloat("speed", &speed_, 0.01f, 0.05f, 4.0f, "%.2fx");
    ImGui::SameLine();
    ImGui::Text("t = %.3f s%s", time_, player_ && player_->blending() ? "  (blending)" : "");
    timeline(pw);
    ImGui::Spacing();
    transition_tester();
    ImGui::EndGroup();

    ImGui::SetCursorPos(ImVec2(start.x + pw + 12, start.y));
    ImGui::BeginChild("clips", ImVec2(0, 0), false);
    ImGui::TextDisabled("Clips (%s)", clip_file_.filename().string().c_str());
    if (ImGui::BeginListBox(
            "##clips", ImVec2(-1, ImGui::GetTextLineHeightWithSpacing() *
                                          std::min<float>(4.5f, static_cast<float>(clips_.clips.size())) +
                                      6))) {
        for (int i = 0; i < static_cast<int>(clips_.clips.size()); ++i) {
            char label[96];
            std::snprintf(label, sizeof(label), "%-20s %5.2f s  %s",
                          clips_.clips[static_cast<size_t>(i)].name.c_str(),
                          clips_.clips[static_cast<size_t>(i)].duration,
                          loop_name(clips_.clips[static_cast<size_t>(i)].loop));
            if (ImGui::Selectable(label, i == clip_ && !transition_mode_)) {
                clip_ = i;
                transition_mode_ = false;
                selected_phase_ = 0;
                playing_ = true;
                restart_at(0.0);
            }
        }
        ImGui::EndListBox();
    }
    key_table(log);
    ImGui::EndChild();
    ImGui::End();
}

} // namespace ks::editor::ui
