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
#include <iterator>
#include <sstream>

namespace ks::editor::ui {

namespace {
constexpr float kDojoBar = 212.0f; // transport, timeline (with its event lane) and transition tester
constexpr const char* kPageNames[] = {"keys", "curves", "blends", "events"};
constexpr const char* kSpotNames[] = {"add_key",     "duplicate_key", "new_clip",    "clip_name",
                                      "clip_ok",     "page_keys",     "page_curves", "page_blends",
                                      "page_events", "save",          "reload",      "reload_notice",
                                      "add_event",   "quit_cancel",   "quit_discard"};
static_assert(std::size(kSpotNames) == static_cast<size_t>(DojoSpot::Count));

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
        } else if (key == "page") {
            const auto* found = std::find(std::begin(kPageNames), std::end(kPageNames), value);
            if (found == std::end(kPageNames))
                return Error("--dojo-view: page=" + value + " is not a page", {},
                             "pages are keys, curves, blends, events");
            view.page = static_cast<DojoPage>(found - std::begin(kPageNames));
        } else if (key == "node" && !value.empty()) {
            view.node = value;
        } else if (key == "channel") {
            auto channel = curve_channel_from_name(value);
            if (!channel)
                return Error("--dojo-view: channel=" + value + " is not a channel", {},
                             "channels are rot.x, rot.y, rot.z, pos.x, pos.y, pos.z");
            view.channel = *channel;
        } else if (key == "robot") {
            char* end = nullptr;
            const long id = std::strtol(value.c_str(), &end, 10);
            if (value.empty() || *end != '\0' || id <= 0 || id > 1'000'000)
                return Error("--dojo-view: robot=" + value + " is not an entity id", {}, "e.g. robot=46");
            view.robot = static_cast<int>(id);
        } else if (key == "blend") {
            const auto arrow = value.find('>');
            if (arrow == std::string::npos || arrow == 0 || arrow + 1 == value.size())
                return Error("--dojo-view: blend=" + value + " is not a pair of clips", {},
                             "e.g. blend=idle>alert");
            view.blend_from = value.substr(0, arrow);
            view.blend_to = value.substr(arrow + 1);
        } else if (key == "onion") {
            auto on = parse_flag(key, value);
            if (!on) return on.error();
            view.onion = *on;
        } else {
            return Error("--dojo-view: unknown item '" + item + "'", {},
                         "items are clip=NAME, page=keys|curves|blends|events, node=NODE, channel=rot.x, "
                         "time=SECONDS, onion=1, robot=ID, blend=FROM>TO, separated by commas");
        }
    }
    return view;
}

const char* dojo_spot_name(DojoSpot spot) {
    return kSpotNames[static_cast<size_t>(spot)];
}

void dojo_preview_size(float tab_width, float tab_height, float& w, float& h) {
    w = std::max(64.0f, std::floor(tab_width * 0.5f));
    h = std::max(64.0f, std::floor(tab_height - kDojoBar));
}

DojoPanel::DojoPanel(render::AssetLibrary& assets, render::SceneRenderer& renderer, DojoSetup setup)
    : assets_(assets), renderer_(renderer),
      clip_file_(setup.clip_file.empty() ? paths::asset("animations/robot.json")
                                         : std::move(setup.clip_file)),
      audition_(std::move(setup.audition)), log_(std::move(setup.log)) {
    if (!log_) log_ = [](const std::string&, bool) {};
    render::MeshData floor;
    render::append_box(floor, Vec3(0, -0.05f, 0), Vec3(14, 0.1f, 14), Mat4(1.0f), 2.0f);
    floor_ = std::make_unique<render::GpuMesh>(floor);
    floor_material_ = &assets_.surface("tiles");
    lights_.push_back({render::Light::Type::Point, Vec3(3.0f, 5.0f, 4.0f), Vec3(0, -1, 0),
                       Vec3(1.0f, 0.85f, 0.7f), 1.2f, 20.0f, 0.8f, 0.9f});
    lights_.push_back({render::Light::Type::Point, Vec3(-4.0f, 3.0f, -2.0f), Vec3(0, -1, 0),
                       Vec3(0.5f, 0.7f, 1.0f), 0.8f, 20.0f, 0.8f, 0.9f});
}

void DojoPanel::load() {
    loaded_ = true;
    model_ = &assets_.model("robot");
    remember_disk();
    auto file = anim::load_animation_file(clip_file_);
    if (!file) {
        compile_error_ = file.error().str();
        log_(compile_error_, true);
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
    message_.clear();
    selected_event_ = -1;
    recompile();
    if (clips_.clips.size() > 1 && to_clip_ == 0) to_clip_ = 1;
}

void DojoPanel::ensure_loaded() {
    if (!loaded_) load();
}

void DojoPanel::apply_view(const DojoView& view) {
    ensure_loaded();
    if (!view.clip.empty()) {
        const int index = clips_.find(view.clip);
        if (index < 0)
            log_("--dojo-view: no clip '" + view.clip + "' in " + clip_file_.string(), true);
        else
            show_clip(index);
    }
    page_ = view.page;
    page_requested_ = true;
    curve_channel_ = view.channel;
    if (!view.node.empty()) {
        const auto found = std::find_if(file_.rig.begin(), file_.rig.end(),
                                        [&](const anim::RigNodeDef& n) { return n.name == view.node; });
        if (found == file_.rig.end())
            log_("--dojo-view: no node '" + view.node + "' in the rig", true);
        else
            curve_node_ = static_cast<int>(found - file_.rig.begin());
    }
    onion_ = view.onion;
    if (!view.blend_from.empty()) {
        const int from = clips_.find(view.blend_from), to = clips_.find(view.blend_to);
        if (from < 0 || to < 0)
            log_("--dojo-view: blend=" + view.blend_from + ">" + view.blend_to +
                     " names a clip the file lacks",
                 true);
        else
            blend_from_ = from, blend_to_ = to, test_transition(from, to);
    }
    if (view.time >= 0.0) {
        playing_ = false;
        restart_at(view.time);
    }
}

void DojoPanel::recompile() {
    ++revision_; // the file changed: cached ghosts and curves are stale, compiled or not
    issues_ = dojo_file_issues(file_);
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

void DojoPanel::show_clip(int index) {
    if (index < 0 || index >= static_cast<int>(clips_.clips.size())) return;
    clip_ = index;
    transition_mode_ = false;
    selected_phase_ = 0;
    selected_event_ = -1;
    playing_ = true;
    restart_at(0.0);
}

DojoPlayPlan DojoPanel::play_plan() const {
    DojoPlayPlan plan;
    plan.transition = transition_mode_;
    plan.clip = clip_;
    plan.from = from_clip_;
    plan.to = to_clip_;
    plan.switch_at = switch_time_;
    plan.blend = blend_time_;
    return plan;
}

void DojoPanel::restart_at(double seconds) {
    if (!player_ || clips_.clips.empty()) return;
    player_ = std::make_unique<anim::Player>(clips_, rig_);
    dojo_restart_at(*player_, play_plan(), seconds);
    time_ = seconds;
}

// Playback by dt: a Once clip (or the transition test) starts over when Loop is on; the transition test
// hands over to its `to` clip at the switch time; events the playhead passes are auditioned when they name
// a sound.
void DojoPanel::advance(double dt) {
    if (!player_ || !playing_ || !(dt > 0) || clips_.clips.empty()) return;
    const double step = dt * speed_;
    const double length = timeline_length();
    if (loop_ && length > 0 && time_ + step > length &&
        (transition_mode_ || clips_.clips[static_cast<size_t>(clip_)].loop == anim::LoopMode::Once)) {
        restart_at(0.0);
        return;
    }
    dojo_advance(*player_, play_plan(), time_, step, [this](const anim::Player& player) {
        if (!audition_ || !event_sounds_) return;
        for (const anim::FiredEvent& fired : player.fired_events())
            if (fired.event && !fired.event->sound.empty())
                audition_(fired.event->sound, 1.0f), ++auditioned_;
    });
    time_ += step;
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

void DojoPanel::refuse(const Error& error) {
    message_ = error.message + (error.hint.empty() ? "" : " (" + error.hint + ")");
    log_("dojo: " + error.str(), true);
}

void DojoPanel::begin_frame() {
    spots_ = {};
    curve_handles_.clear();
    event_flags_.clear();
}

void DojoPanel::mark(DojoSpot spot) {
    // Not while its window appears: a popup is only measured in its first frame, and a click that follows
    // the spot reported then comes too early for it (the quit question's Cancel was missed).
    if (ImGui::IsWindowAppearing()) return;
    const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    spots_[static_cast<size_t>(spot)] = Vec2((a.x + b.x) * 0.5f, (a.y + b.y) * 0.5f);
}

const anim::ClipDef* DojoPanel::shown_def() const {
    return static_cast<size_t>(clip_) < file_.clips.size() ? &file_.clips[static_cast<size_t>(clip_)]
                                                           : nullptr;
}

// The playhead within the shown clip: a looping clip's time within its pass, a ping-pong's folded back.
double DojoPanel::clip_time() const {
    const anim::ClipDef* def = shown_def();
    if (!def || transition_mode_) return 0.0;
    const double d = def->duration();
    if (d <= 0) return 0.0;
    switch (def->loop) {
    case anim::LoopMode::Loop:
        return std::fmod(time_, d);
    case anim::LoopMode::PingPong: {
        const double u = std::fmod(time_, 2.0 * d);
        return u <= d ? u : 2.0 * d - u;
    }
    default:
        return std::min(time_, d);
    }
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
    if (c < file_.clips.size()) {
        st.clip = file_.clips[c].name;
        st.events = file_.clips[c].events.size();
    }
    st.clips = file_.clips.size();
    st.page = kPageNames[static_cast<size_t>(page_)];
    st.undo_name = history_.undo_name();
    st.message = message_;
    st.spots = spots_;
    st.transition = transition_mode_;
    st.blend_from = blend_from_;
    st.blend_to = blend_to_;
    if (page_ == DojoPage::Blends && blend_centres_.size() == file_.clips.size() * file_.clips.size()) {
        for (const auto& clip : file_.clips) st.blend_clips.push_back(clip.name);
        st.blend_centres = blend_centres_;
    }
    if (page_ == DojoPage::Curves) st.curve_keys = curve_handles_;
    st.event_flags = event_flags_;
    st.dirty = dirty_;
    st.changed_on_disk = changed_on_disk_;
    st.onion = onion_;
    st.ghosts = ghost_instances_;
    st.auditioned = auditioned_;
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

void DojoPanel::panel(float x, float y, float width, float height) {
    ensure_loaded();
    watch_disk();
    if (!ImGui::IsAnyItemActive()) edit_open_ = false; // a drag is one undo step
    ImGui::SetNextWindowPos(ImVec2(x, y));
    ImGui::SetNextWindowSize(ImVec2(width, height));
    ImGui::Begin("Dojo", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                     ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoScrollbar);
    const ImVec2 start = ImGui::GetCursorPos();
    float pw = 0, ph = 0;
    dojo_preview_size(width, height, pw, ph);
    // The preview is rendered before the UI is built, so on the frame the tab is opened it has not been
    // rendered yet and its target has no size: lay the panel out at the size the preview is about to get.
    if (target_.width() > 0 && target_.height() > 0) {
        pw = std::min(pw, static_cast<float>(target_.width()));
        ph = std::min(ph, static_cast<float>(target_.height()));
    }
    ImGui::BeginGroup();
    draw_preview_image(pw, ph);
    if (clips_.clips.empty()) {
        ImGui::TextColored(ImVec4(1, 0.4f, 0.35f, 1), "%s", compile_error_.c_str());
        ImGui::EndGroup();
        ImGui::End();
        return;
    }
    transport();
    timeline(pw);
    ImGui::Spacing();
    transition_tester();
    ImGui::EndGroup();

    ImGui::SetCursorPos(ImVec2(start.x + pw + 12, start.y));
    ImGui::BeginChild("right", ImVec2(0, 0), false, ImGuiWindowFlags_NoScrollbar);
    clip_toolbar();
    clip_list();
    loop_row();
    right_pages();
    file_row();
    ImGui::EndChild();
    clip_dialog();
    add_event_popup();
    ImGui::End();
}

// Keys, Curves, Blends, Events: one page at a time, the file row kept below them.
void DojoPanel::right_pages() {
    const float file_row_height =
        ImGui::GetFrameHeightWithSpacing() *
        (1.0f + (changed_on_disk_ ? 1.0f : 0.0f) + static_cast<float>(issues_.size()) +
         (compile_error_.empty() ? 0.0f : 1.0f));
    if (!ImGui::BeginTabBar("pages")) return;
    constexpr const char* kTitles[] = {"Keys", "Curves", "Blends", "Events"};
    constexpr DojoSpot kSpots[] = {DojoSpot::PageKeys, DojoSpot::PageCurves, DojoSpot::PageBlends,
                                   DojoSpot::PageEvents};
    for (int i = 0; i < static_cast<int>(DojoPage::Count); ++i) {
        const auto page = static_cast<DojoPage>(i);
        const ImGuiTabItemFlags flags =
            page_requested_ && page == page_ ? ImGuiTabItemFlags_SetSelected : ImGuiTabItemFlags_None;
        const bool open = ImGui::BeginTabItem(kTitles[i], nullptr, flags);
        mark(kSpots[i]);
        if (!open) continue;
        if (!page_requested_) page_ = page;
        ImGui::BeginChild("page", ImVec2(0, -file_row_height), false);
        switch (page) {
        case DojoPage::Keys:
            key_table();
            break;
        case DojoPage::Curves:
            curve_view();
            break;
        case DojoPage::Blends:
            blend_grid();
            break;
        case DojoPage::Events:
            event_list();
            break;
        case DojoPage::Count:
            break;
        }
        ImGui::EndChild();
        ImGui::EndTabItem();
    }
    page_requested_ = false;
    ImGui::EndTabBar();
}

} // namespace ks::editor::ui
