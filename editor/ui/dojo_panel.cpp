// The dojo panel's core: loading the clip file and the robot's rig, recompiling after edits, playback and
// the history, and the tab's layout. The parts live beside it (see dojo_panel.h).
#include "ui/dojo_panel.h"

#include "anim/gltf_rig.h"
#include "core/paths.h"
#include "render/mesh_data.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace ks::editor::ui {

namespace {
constexpr float kDojoBar = 190.0f; // transport, timeline and transition tester under the preview

const char* loop_name(anim::LoopMode m) {
    return m == anim::LoopMode::Loop ? "loop" : m == anim::LoopMode::Next ? "next" : "once";
}

Result<bool> parse_flag(const std::string& key, const std::string& value) {
    if (value == "1" || value == "on" || value == "true") return true;
    if (value == "0" || value == "off" || value == "false") return false;
    return Error("--dojo-view: " + key + "=" + value + " is not on or off", {}, "use " + key + "=1 or 0");
}
} // namespace

Result<DojoView> parse_dojo_view(const std::string& text) {
    DojoView view;
    std::stringstream items(text);
    std::string item;
    while (std::getline(items, item, ',')) {
        const auto eq = item.find('=');
        const std::string key = item.substr(0, eq),
                          value = eq == std::string::npos ? "" : item.substr(eq + 1);
        if (key == "clip" && !value.empty()) {
            view.clip = value;
        } else if (key == "time") {
            char* end = nullptr;
            view.time = std::strtod(value.c_str(), &end);
            if (value.empty() || *end != '\0' || !std::isfinite(view.time) || view.time < 0.0)
                return Error("--dojo-view: time=" + value + " is not a time in seconds", {},
                             "e.g. time=0.25");
        } else if (key == "onion") {
            auto on = parse_flag(key, value);
            if (!on) return on.error();
            view.onion = *on;
        } else {
            return Error("--dojo-view: unknown item '" + item + "'", {},
                         "items are clip=NAME, time=SECONDS, onion=1, separated by commas");
        }
    }
    return view;
}

void dojo_preview_size(float tab_width, float tab_height, float& w, float& h) {
    w = std::max(64.0f, std::floor(tab_width * 0.5f));
    h = std::max(64.0f, std::floor(tab_height - kDojoBar));
}

DojoPanel::DojoPanel(render::AssetLibrary& assets, render::SceneRenderer& renderer,
                     std::filesystem::path clip_file, SoundAudition audition)
    : assets_(assets), renderer_(renderer),
      clip_file_(clip_file.empty() ? paths::asset("animations/robot.json") : std::move(clip_file)),
      audition_(std::move(audition)) {
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
    remember_disk();
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
    history_.clear();
    edit_open_ = false;
    recompile();
    if (clips_.clips.size() > 1 && to_clip_ == 0) to_clip_ = 1;
}

void DojoPanel::ensure_loaded(const LogFn& log) {
    if (!loaded_) load(&log);
}

void DojoPanel::apply_view(const DojoView& view, const LogFn& log) {
    ensure_loaded(log);
    if (!view.clip.empty()) {
        const int index = clips_.find(view.clip);
        if (index < 0)
            log("--dojo-view: no clip '" + view.clip + "' in " + clip_file_.string(), true);
        else
            show_clip(index);
    }
    onion_ = view.onion;
    if (view.time >= 0.0) {
        playing_ = false;
        restart_at(view.time);
    }
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
    ++revision_;
    const int last = std::max(0, static_cast<int>(clips_.clips.size()) - 1);
    clip_ = std::clamp(clip_, 0, last);
    from_clip_ = std::clamp(from_clip_, 0, last);
    to_clip_ = std::clamp(to_clip_, 0, last);
    player_ = std::make_unique<anim::Player>(clips_, rig_);
    restart_at(time_);
}

void DojoPanel::show_clip(int index) {
    if (index < 0 || index >= static_cast<int>(clips_.clips.size())) return;
    clip_ = index;
    transition_mode_ = false;
    selected_phase_ = 0;
    playing_ = true;
    restart_at(0.0);
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

// Playback by dt: a Once clip (or the transition test) starts over when Loop is on; events the playhead
// passes are auditioned when they name a sound.
void DojoPanel::advance(double dt) {
    if (!player_ || !playing_ || !(dt > 0) || clips_.clips.empty()) return;
    const double step = dt * speed_;
    const double length = timeline_length();
    if (loop_ && length > 0 && time_ + step > length &&
        (transition_mode_ || clips_.clips[static_cast<size_t>(clip_)].loop == anim::LoopMode::Once)) {
        restart_at(0.0);
        return;
    }
    player_->advance(step);
    time_ += step;
    if (!audition_) return;
    for (const anim::FiredEvent& fired : player_->fired_events())
        if (fired.event && !fired.event->sound.empty()) audition_(fired.event->sound, 1.0f);
}

void DojoPanel::evaluate_pose() {
    if (player_) binding_.write_locals(player_->pose(), model_pose_.local);
}

void DojoPanel::tick(double dt) {
    advance(dt);
    evaluate_pose();
}

void DojoPanel::begin_edit(const std::string& name) {
    if (!edit_open_) history_.record(file_, name);
    edit_open_ = true;
}

void DojoPanel::after_edit() {
    dirty_ = true;
    recompile();
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
    if (c < file_.clips.size()) st.clip = file_.clips[c].name;
    st.clips = file_.clips.size();
    st.duplicate_key_x = duplicate_key_x_;
    st.duplicate_key_y = duplicate_key_y_;
    st.add_key_x = add_key_x_;
    st.add_key_y = add_key_y_;
    st.dirty = dirty_;
    st.changed_on_disk = changed_on_disk_;
    st.onion = onion_;
    st.ghosts = ghost_instances_;
    return st;
}

bool DojoPanel::undo() {
    if (!history_.undo(file_)) return false;
    after_edit();
    return true;
}

bool DojoPanel::redo() {
    if (!history_.redo(file_)) return false;
    after_edit();
    return true;
}

void DojoPanel::clip_list() {
    ImGui::TextDisabled("Clips (%s)", clip_file_.filename().string().c_str());
    const float rows = std::min<float>(4.5f, static_cast<float>(clips_.clips.size()));
    if (!ImGui::BeginListBox("##clips", ImVec2(-1, ImGui::GetTextLineHeightWithSpacing() * rows + 6))) return;
    for (int i = 0; i < static_cast<int>(clips_.clips.size()); ++i) {
        const anim::Clip& clip = clips_.clips[static_cast<size_t>(i)];
        char label[96];
        std::snprintf(label, sizeof(label), "%-20s %5.2f s  %s", clip.name.c_str(), clip.duration,
                      loop_name(clip.loop));
        if (ImGui::Selectable(label, i == clip_ && !transition_mode_)) show_clip(i);
    }
    ImGui::EndListBox();
}

void DojoPanel::panel(float x, float y, float width, float height, const LogFn& log) {
    ensure_loaded(log);
    watch_disk();
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
    draw_preview_image(pw, ph);
    if (clips_.clips.empty()) {
        ImGui::TextColored(ImVec4(1, 0.4f, 0.35f, 1), "%s", compile_error_.c_str());
        ImGui::EndGroup();
        file_prompts(log);
        ImGui::End();
        return;
    }
    transport();
    timeline(pw);
    ImGui::Spacing();
    transition_tester();
    ImGui::EndGroup();

    ImGui::SetCursorPos(ImVec2(start.x + pw + 12, start.y));
    ImGui::BeginChild("clips", ImVec2(0, 0), false);
    clip_list();
    key_table(log);
    file_row(log);
    ImGui::EndChild();
    file_prompts(log);
    ImGui::End();
}

} // namespace ks::editor::ui
