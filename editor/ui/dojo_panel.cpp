// The dojo panel: the start view (--dojo-view), the context its parts share, loading the clip file and the
// robot's rig, playback with the events' sounds, the status, and the tab's layout. The parts live beside it
// (see dojo_panel.h).
#include "ui/dojo_panel.h"

#include "anim/gltf_rig.h"
#include "core/paths.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <sstream>

namespace ks::editor::ui {

namespace {
constexpr const char* kPageNames[] = {"keys", "curves", "blends", "events"};
constexpr const char* kSpotNames[] = {
    "add_key",     "duplicate_key", "new_clip",     "clip_name", "clip_ok",  "page_keys",
    "page_curves", "page_blends",   "page_events",  "save",      "reload",   "reload_notice",
    "add_event",   "quit_cancel",   "quit_discard", "key_pose",  "auto_key", "ik"};
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
        } else if (key == "key") {
            char* end = nullptr;
            const long n = std::strtol(value.c_str(), &end, 10);
            if (value.empty() || *end != '\0' || n <= 0 || n > 10'000)
                return Error("--dojo-view: key=" + value + " is not a key number", {}, "e.g. key=2 (from 1)");
            view.key = static_cast<int>(n);
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
                         "key=N, time=SECONDS, onion=1, robot=ID, blend=FROM>TO, separated by commas");
        }
    }
    return view;
}

const char* dojo_spot_name(DojoSpot spot) {
    return kSpotNames[static_cast<size_t>(spot)];
}

const char* dojo_page_name(DojoPage page) {
    return kPageNames[static_cast<size_t>(page)];
}

const anim::ClipDef* DojoContext::shown_def() const {
    const auto& clips = edits.file().clips;
    return clip_index() < clips.size() ? &clips[clip_index()] : nullptr;
}

double DojoContext::clip_time() const {
    const anim::ClipDef* def = shown_def();
    if (!def || playback.transition()) return 0.0;
    return dojo_pass_time(def->loop, def->duration(), playback.time());
}

void DojoContext::show_clip(int index) const {
    if (!playback.show_clip(index)) return;
    selection.phase = 0;
    selection.event = -1;
}

void DojoContext::mark(DojoSpot spot) const {
    if (ImGui::IsWindowAppearing()) return;
    const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    spots[static_cast<size_t>(spot)] = Vec2((a.x + b.x) * 0.5f, (a.y + b.y) * 0.5f);
}

DojoPanel::DojoPanel(render::AssetLibrary& assets, render::SceneRenderer& renderer, DojoSetup setup)
    : audition_(std::move(setup.audition)), log_(std::move(setup.log)), edits_(playback_, log_),
      preview_(assets, renderer),
      file_(setup.clip_file.empty() ? paths::asset("animations/robot.json") : std::move(setup.clip_file),
            [this] { load(); }) {
    if (!log_) log_ = [](const std::string&, bool) {};
}

DojoContext DojoPanel::context() {
    return {edits_, playback_, selection_, spots_, named_spots_, log_, audition_, file_.path()};
}

void DojoPanel::load() {
    loaded_ = true;
    const render::Model& model = preview_.model();
    file_.remember_disk();
    auto file = anim::load_animation_file(file_.path());
    if (!file) {
        edits_.set_load_error(file.error().str());
        log_(file.error().str(), true);
        return;
    }
    auto rig = anim::load_gltf_rig(model.path);
    if (!rig) {
        edits_.set_load_error("robot model: " + rig.error().str());
        return;
    }
    if (const std::size_t made = make_keys_absolute(*file))
        log_("dojo: " + std::to_string(made) + " relative keys of " + file_.path().filename().string() +
                 " made absolute (the same poses; Save writes them)",
             false);
    playback_.set_rig(std::move(*rig));
    preview_.bind(playback_.rig());
    selection_.event = -1;
    edits_.reset(std::move(*file));
    const DojoPlayPlan& plan = playback_.plan();
    if (playback_.clips().clips.size() > 1 && plan.to == 0)
        playback_.set_transition(plan.transition, plan.from, 1, plan.switch_at, plan.blend);
}

void DojoPanel::ensure_loaded() {
    if (!loaded_) load();
}

void DojoPanel::apply_view(const DojoView& view) {
    ensure_loaded();
    const DojoContext dojo = context();
    if (!view.clip.empty()) {
        const int index = playback_.clips().find(view.clip);
        if (index < 0)
            log_("--dojo-view: no clip '" + view.clip + "' in " + file_.path().string(), true);
        else
            dojo.show_clip(index);
    }
    selection_.request_page(view.page);
    curve_view_.show_channel(view.channel);
    if (!view.node.empty()) {
        const auto& rig = edits_.file().rig;
        const auto found = std::find_if(rig.begin(), rig.end(),
                                        [&](const anim::RigNodeDef& n) { return n.name == view.node; });
        if (found == rig.end()) {
            log_("--dojo-view: no node '" + view.node + "' in the rig", true);
        } else {
            curve_view_.show(static_cast<int>(found - rig.begin()), view.channel);
            selection_.node = view.node; // posed in the preview too
        }
    }
    if (view.key > 0)
        selection_.phase = view.key - 1, curve_view_.select_key(static_cast<size_t>(view.key - 1));
    preview_.set_onion(view.onion);
    if (!view.blend_from.empty()) {
        const int from = playback_.clips().find(view.blend_from), to = playback_.clips().find(view.blend_to);
        if (from < 0 || to < 0)
            log_("--dojo-view: blend=" + view.blend_from + ">" + view.blend_to +
                     " names a clip the file lacks",
                 true);
        else
            blend_grid_.select(dojo, from, to);
    }
    if (view.time >= 0.0) {
        playback_.set_playing(false);
        playback_.restart_at(view.time);
    }
}

void DojoPanel::show_clip(int index) {
    context().show_clip(index);
}

// Playback by dt; events the playhead passes are auditioned when they name a sound.
void DojoPanel::advance(double dt) {
    playback_.advance(dt, [this](const anim::Player& player) {
        if (!audition_ || !timeline_.event_sounds()) return;
        for (const anim::FiredEvent& fired : player.fired_events())
            if (fired.event && !fired.event->sound.empty())
                audition_(fired.event->sound, 1.0f), ++auditioned_;
    });
}

void DojoPanel::tick(double dt) {
    advance(dt);
    if (playback_.player()) preview_.pose_from(*playback_.player());
}

void DojoPanel::render(float width, float height, double dt) {
    ensure_loaded();
    tick(dt);
    preview_.render(context(), width, height);
}

void DojoPanel::begin_frame() {
    spots_ = {};
    named_spots_.enabled = true;
    named_spots_.clear();
    curve_view_.begin_frame();
    events_.begin_frame();
}

void DojoPanel::save() {
    file_.save(context());
}

void DojoPanel::reload() {
    file_.reload(context());
}

void DojoPanel::prompts() {
    file_.prompts(context());
}

bool DojoPanel::delete_selected() {
    return events_.delete_selected(context());
}

void DojoPanel::copy(bool pose) {
    const DojoContext dojo = context();
    if (dojo.shown_def() == nullptr || playback_.player() == nullptr) return;
    const auto key = static_cast<std::size_t>(selection_.phase);
    if (pose) {
        clipboard_ = copy_pose(pose_values(playback_.rig(), playback_.player()->pose()));
        log_("dojo: copied the pose at " + std::to_string(dojo.clip_time()) + " s", false);
        return;
    }
    auto copied = copy_key(edits_.file(), dojo.clip_index(), key);
    if (!copied) return edits_.refuse(copied.error());
    clipboard_ = std::move(*copied);
    log_("dojo: copied key " + std::to_string(key + 1) + " of " + dojo.shown_def()->name, false);
}

void DojoPanel::paste(bool mirror) {
    const DojoContext dojo = context();
    if (dojo.shown_def() == nullptr) return;
    const std::size_t clip = dojo.clip_index(), key = static_cast<std::size_t>(selection_.phase);
    const DojoKeyClipboard values = mirror ? mirrored(clipboard_, edits_.file()) : clipboard_;
    edits_.apply(mirror ? "paste mirrored" : "paste",
                 [&](anim::AnimationFile& file) { return paste_key(file, clip, key, values); });
}

DojoPanel::Status DojoPanel::status() const {
    Status st;
    const anim::AnimationFile& file = edits_.file();
    st.undo = edits_.history().undo_count();
    st.redo = edits_.history().redo_count();
    const auto c = static_cast<std::size_t>(playback_.clip()), p = static_cast<std::size_t>(selection_.phase);
    if (c < file.clips.size() && p < file.clips[c].phases.size()) {
        st.keys = file.clips[c].phases[p].targets.size();
        st.phases = file.clips[c].phases.size();
        st.phase = p;
    }
    if (c < file.clips.size()) {
        st.clip = file.clips[c].name;
        st.events = file.clips[c].events.size();
    }
    st.clips = file.clips.size();
    st.page = dojo_page_name(selection_.page);
    st.undo_name = edits_.history().undo_name();
    st.message = edits_.message();
    st.spots = spots_;
    st.named = named_spots_.all();
    st.transition = playback_.transition();
    st.blend_from = blend_grid_.from();
    st.blend_to = blend_grid_.to();
    if (selection_.page == DojoPage::Blends &&
        blend_grid_.centres().size() == file.clips.size() * file.clips.size()) {
        for (const auto& clip : file.clips) st.blend_clips.push_back(clip.name);
        st.blend_centres = blend_grid_.centres();
    }
    if (selection_.page == DojoPage::Curves) st.curve_keys = curve_view_.handles();
    st.curve_selected = curve_view_.selection().keys().size();
    st.event_flags = events_.flags();
    st.dirty = edits_.dirty();
    st.changed_on_disk = file_.changed_on_disk();
    st.onion = preview_.onion();
    st.ghosts = preview_.ghost_instances();
    st.auditioned = auditioned_;
    pose_status(st);
    return st;
}

void DojoPanel::key_pose() {
    preview_.pose_tools().key(context());
}

// The posing tools' part: the selected node, the joints and rings on screen, the unkeyed edits.
void DojoPanel::pose_status(Status& st) const {
    const DojoPoseTools& tools = preview_.pose_tools();
    st.node = selection_.node;
    st.pose_edits = tools.edits().edits().size();
    st.auto_key = tools.settings().auto_key;
    st.ik = tools.settings().ik;
    const anim::Rig& rig = playback_.rig();
    for (int i = 0; i < rig.size() && i < static_cast<int>(tools.joints().size()); ++i)
        st.joints.emplace_back(rig.node(i).name, tools.joints()[static_cast<std::size_t>(i)]);
    st.rings = tools.rings();
}

bool DojoPanel::undo() {
    return edits_.undo();
}

bool DojoPanel::redo() {
    return edits_.redo();
}

void DojoPanel::panel(float x, float y, float width, float height) {
    ensure_loaded();
    file_.watch_disk();
    if (!ImGui::IsAnyItemActive()) edits_.end_drag(); // a drag is one undo step
    const DojoContext dojo = context();
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
    if (preview_.target_width() > 0 && preview_.target_height() > 0) {
        pw = std::min(pw, static_cast<float>(preview_.target_width()));
        ph = std::min(ph, static_cast<float>(preview_.target_height()));
    }
    ImGui::BeginGroup();
    preview_.draw(dojo, pw, ph);
    if (playback_.clips().clips.empty()) {
        ImGui::TextColored(ImVec4(1, 0.4f, 0.35f, 1), "%s", edits_.compile_error().c_str());
        ImGui::EndGroup();
        ImGui::End();
        return;
    }
    timeline_.transport(dojo);
    timeline_.timeline(dojo, pw, [&](Vec2 origin, float w, float h, double length) {
        events_.lane(dojo, origin, w, h, length);
    });
    ImGui::Spacing();
    dojo_transition_tester(dojo);
    ImGui::EndGroup();

    ImGui::SetCursorPos(ImVec2(start.x + pw + 12, start.y));
    ImGui::BeginChild("right", ImVec2(0, 0), false, ImGuiWindowFlags_NoScrollbar);
    clip_list_.toolbar(dojo);
    clip_list_.list(dojo);
    clip_list_.loop_row(dojo);
    right_pages(dojo);
    file_.row(dojo);
    gltf_.buttons(dojo);
    ImGui::EndChild();
    clip_list_.dialog(dojo);
    gltf_.prompt(dojo);
    events_.popup(dojo);
    ImGui::End();
}

// Keys, Curves, Blends, Events: one page at a time, the file row kept below them.
void DojoPanel::right_pages(const DojoContext& dojo) {
    const float file_row_height =
        ImGui::GetFrameHeightWithSpacing() *
        (1.0f + (file_.changed_on_disk() ? 1.0f : 0.0f) + static_cast<float>(edits_.issues().size()) +
         (edits_.compile_error().empty() ? 0.0f : 1.0f));
    if (!ImGui::BeginTabBar("pages")) return;
    constexpr const char* kTitles[] = {"Keys", "Curves", "Blends", "Events"};
    constexpr DojoSpot kSpots[] = {DojoSpot::PageKeys, DojoSpot::PageCurves, DojoSpot::PageBlends,
                                   DojoSpot::PageEvents};
    for (int i = 0; i < static_cast<int>(DojoPage::Count); ++i) {
        const auto page = static_cast<DojoPage>(i);
        const ImGuiTabItemFlags flags = selection_.page_requested && page == selection_.page
                                            ? ImGuiTabItemFlags_SetSelected
                                            : ImGuiTabItemFlags_None;
        const bool open = ImGui::BeginTabItem(kTitles[i], nullptr, flags);
        dojo.mark(kSpots[i]);
        if (!open) continue;
        if (!selection_.page_requested) selection_.page = page;
        ImGui::BeginChild("page", ImVec2(0, -file_row_height), false);
        switch (page) {
        case DojoPage::Keys:
            key_table_.draw(dojo);
            break;
        case DojoPage::Curves:
            curve_view_.draw(dojo);
            break;
        case DojoPage::Blends:
            blend_grid_.draw(dojo);
            break;
        case DojoPage::Events:
            events_.list(dojo);
            break;
        case DojoPage::Count:
            break;
        }
        ImGui::EndChild();
        ImGui::EndTabItem();
    }
    selection_.page_requested = false;
    ImGui::EndTabBar();
}

} // namespace ks::editor::ui
