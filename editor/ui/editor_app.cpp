// The editor window's frame: start-up, layout, shortcuts and the title. The panels are their own objects
// (inspector.h, outliner.h, prefab_palette.h, place_palette.h, bottom_panels.h, dojo_panel.h); the menus are
// in menus.cpp, the file prompts in file_prompts.cpp, the viewport in level_viewport.h.
#include "ui/editor_app.h"
#include "model/edit_entities.h"
#include "model/edit_files.h"
#include "model/edit_selection.h"
#include "model/edit_transforms.h"

#include "core/cli.h"
#include "core/files.h"
#include "core/log.h"
#include "core/paths.h"
#include "model/script.h"
#include "ui/dojo_panel.h"
#include "ui/layout.h"
#include "ui/structure_actions.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <cstdio>
#include <cstring>

namespace ks::editor::ui {
namespace fs = std::filesystem;

namespace {
EditorApp* g_app = nullptr; // the window-close callback has no user pointer to spare (ImGui's backend)

fs::path recent_files_path() {
    fs::path dir = paths::user_config_dir();
    if (dir.empty()) dir = fs::temp_directory_path() / "killswitch";
    return dir / "editor_recent.json";
}
} // namespace

EditorApp::EditorApp(shell::AppShell& shell, const AppOptions& options)
    : shell_(shell), options_(options), recent_(recent_files_path()), assets_(paths::asset("")) {}

EditorApp::~EditorApp() {
    log::set_sink(nullptr);
    if (g_app == this) g_app = nullptr;
}

Result<std::unique_ptr<EditorApp>> EditorApp::create(shell::AppShell& shell, const AppOptions& options) {
    std::unique_ptr<EditorApp> app(new EditorApp(shell, options));
    if (auto r = app->init(); !r) return r.error();
    return app;
}

Result<void> EditorApp::init() {
    // Everything the model logs (draft saves, load warnings) also shows in the log panel.
    log::set_sink([this](log::Level level, std::string_view text) {
        std::fprintf(stderr, "%.*s\n", static_cast<int>(text.size()), text.data());
        log_line(std::string(text), level != log::Level::Info);
    });
    if (auto r = recent_.load(); !r) log_line(r.error().str(), true);
    editor_.set_recent_files(&recent_);
    // The walk check builds a navigation mesh: in the window it must never hold up a frame.
    editor_.validation_options().background_reachability = true;
    if (auto r = scene_.init(shell_.gl_renderer()); !r) return r.error();
    if (options_.level) {
        if (auto r = open(editor_, *options_.level); !r) {
            log_line(r.error().str(), true);
            return r.error();
        }
        log_line("opened " + options_.level->string());
    } else if (!shell_.screenshot_mode()) {
        if (auto offer = find_untitled_recovery(autosaver_.config())) editor_.offer_recovery(*offer);
    }
    dojo_ = std::make_unique<DojoPanel>(
        assets_, scene_.renderer(),
        DojoSetup{options_.dojo_file, options_.audition,
                  [this](const std::string& line, bool error) { log_line(line, error); }});
    dojo_tab_ = options_.start_in_dojo;
    if (options_.dojo_view) {
        auto view = parse_dojo_view(*options_.dojo_view);
        if (!view) return view.error();
        dojo_->apply_view(*view);
        if (view->robot > 0) { // preview in context: select the robot and play the clip on it
            if (auto r = select(editor_, {view->robot}); !r) return r.error();
            if (ClipPreview::robot(editor_) != view->robot)
                return Error("--dojo-view: entity " + std::to_string(view->robot) + " is not a robot", {},
                             "give the id of a robot in the level (--level FILE)");
            clip_preview_.turn_on();
        }
    }
    viewport_.overlays().navmesh = options_.show_navmesh;
    if (options_.inspector_tab) inspector_.select_tab(*options_.inspector_tab);
    viewport_.set_view(options_.view.value_or(ViewMode::Perspective)); // perspective: from above one corner
    if (options_.camera) {
        const Result<PoseArgument> pose = parse_pose(*options_.camera);
        if (!pose)
            return Error("--camera '" + *options_.camera + "': " + pose.error().message, {},
                         pose.error().hint);
        geometry::Camera& camera = viewport_.camera().camera;
        camera.position = pose->position;
        camera.yaw = radians(pose->yaw_degrees);
        camera.pitch = radians(pose->pitch_degrees);
    }
    if (options_.quad_view) viewport_.toggle_quad();
    analysis_.runs = options_.analysis_runs;
    analysis_.update(editor_.level(), editor_.revision(), false, editor_.file_path()); // the report beside it
    if (options_.report) {
        if (!analysis_.load(*options_.report))
            return Error("--report " + options_.report->string() + ": cannot be read", {},
                         "give a report written by killswitch-editor --analyze or the Analyze button");
        log_line("play-test report " + options_.report->string());
    }
    if (options_.run_script) {
        auto text = files::read_text(*options_.run_script);
        if (!text) return text.error();
        auto ran = run_script_text(*text, options_.run_script->string(), options_.run_script->parent_path(),
                                   editor_);
        if (!ran) return ran.error();
        log_line("ran " + options_.run_script->string());
    }
    if (auto r = apply_start_ui_options(); !r) return r.error();
    start_tab_ = options_.left_tab.value_or(LeftTab::Outliner);
    editor_.prefabs().rescan(); // the Prefabs tab lists them from the first frame
    viewport_.rebuild_scene();
    g_app = this;
    glfwSetWindowCloseCallback(shell_.window(), [](GLFWwindow* window) {
        if (!g_app) return;
        glfwSetWindowShouldClose(window, GLFW_FALSE); // the app decides, after asking about unsaved work
        g_app->request(PendingAction::Quit);
    });
    return ok();
}

// --gizmo MODE[,local] and --textures: the viewport's gizmo and the texture browser as a screenshot or a
// test wants them.
Result<void> EditorApp::apply_start_ui_options() {
    if (options_.gizmo)
        if (auto r = viewport_.set_gizmo_option(*options_.gizmo); !r) return r.error();
    if (options_.texture_browser) {
        if (!selection_texture(editor_))
            return Error("--textures: the selection has no texture field", {},
                         "select a wall, floor or stair first (--run a script with 'select ID')");
        inspector_.texture_browser().open();
    }
    return ok();
}

int EditorApp::run() {
    shell::ShellHooks hooks;
    hooks.render = [this](const shell::FrameInfo& info) { render_views(info); };
    hooks.imgui = [this](const shell::FrameInfo& info) { build_ui(info); };
    hooks.wants_close = [this]() { return files_.quit(); };
    hooks.animating = [this]() { return animating(); };
    hooks.idle_poll = [this]() { return poll_background(); };
    return shell_.run(hooks);
}

PanelContext EditorApp::context() {
    return PanelContext{editor_, log_, spots_, assets_, options_.audition, *this};
}

// What changes on screen with no input: a playing clip, a background job whose result is awaited.
bool EditorApp::animating() const {
    const bool clip_playing =
        dojo_->playing() && (dojo_tab_ || (clip_preview_.on() && ClipPreview::robot(editor_) != 0));
    return clip_playing || analysis_.running() || editor_.validation().reachability_pending() ||
           viewport_.animating();
}

// Every frame, and while the window waits for input: the play-test's output, autosave, prefab files changed
// on disk. True when any of it changed what the window shows.
bool EditorApp::poll_background() {
    const std::uint64_t logged = log_.revision(), prefabs = editor_.prefabs().revision();
    const std::uint64_t revision = editor_.revision();
    const bool playing = play_.running();
    const bool edit_waiting = play_.poll(editor_.level(), editor_.revision());
    if (!shell_.screenshot_mode()) {
        if (auto r = autosaver_.update(editor_); !r)
            log_line("autosave: " + r.error().str(), true);
        else if (*r)
            log_line("autosaved to " + (*r)->string());
    }
    const std::uint64_t models = models_.models_revision();
    if (!dojo_tab_) {
        const bool focused = glfwGetWindowAttrib(shell_.window(), GLFW_FOCUSED) != 0;
        prefabs_.rescan(editor_, log_, focused);
        models_.rescan(focused);
        viewport_.set_models_revision(models_.models_revision()); // a model file changed: drawn anew
    }
    return log_.revision() != logged || editor_.prefabs().revision() != prefabs ||
           models_.models_revision() != models || editor_.revision() != revision ||
           play_.running() != playing || edit_waiting;
}

void EditorApp::update_title() {
    std::string title = editor::title(editor_);
    if (play_.running()) title += "  [playing]";
    if (title != last_title_) {
        glfwSetWindowTitle(shell_.window(), title.c_str());
        last_title_ = title;
    }
}

void EditorApp::render_views(const shell::FrameInfo& info) {
    const Layout layout = compute_layout(static_cast<float>(info.width), static_cast<float>(info.height),
                                         ImGui::GetFrameHeight());
    if (dojo_tab_) {
        dojo_->render(layout.bottom.w, layout.centre.h, info.frame_dt);
    } else {
        viewport_.rebuild_scene();
        clip_preview_.pose(editor_, *dojo_, scene_.scene(), info.frame_dt);
        prefabs_.render_thumbnails(editor_.prefabs(), scene_.renderer(), assets_);
        models_.render_thumbnails(scene_.renderer(), assets_);
        const int w = static_cast<int>(layout.centre.w), h = static_cast<int>(layout.centre.h - kViewportBar);
        viewport_.render(w, std::max(1, h));
    }
    RenderTarget::clear_window(info.width, info.height);
}

void EditorApp::build_ui(const shell::FrameInfo& info) {
    poll_background();
    const Layout layout = compute_layout(static_cast<float>(info.width), static_cast<float>(info.height),
                                         ImGui::GetFrameHeight());
    dojo_->begin_frame();
    spots_.enabled = options_.status_file.has_value();
    spots_.clear();
    logic_.refresh_problems();
    const PanelContext ctx = context();
    menu_bar();
    if (dojo_tab_) {
        dojo_->panel(layout.bottom.x, layout.centre.y, layout.bottom.w, layout.centre.h);
    } else {
        outliner_panel(layout.left.x, layout.left.y, layout.left.w, layout.left.h);
        viewport_.panel(layout.centre, [this](Vec2 origin, Vec2 size) {
            clip_preview_.draw(editor_, *dojo_, origin, size); // the selected robot's, across the bottom
        });
        // Wiring links and objectives takes more rows than an entity's fields: those tabs get more height.
        const float split = inspector_.shown_tab() == InspectorTab::Properties ? 0.62f : 0.74f;
        inspector_.draw(ctx, Rect{layout.right.x, layout.right.y, layout.right.w, layout.right.h * split});
        if (logic_.picking()) viewport_.disarm_tools(); // a pick the inspector began takes its clicks
        validation_.draw(ctx, Rect{layout.right.x, layout.right.y + layout.right.h * split, layout.right.w,
                                   layout.right.h * (1.0f - split)});
        // Over the viewport's right edge, beside the inspector whose texture field opened it.
        inspector_.texture_browser_window(ctx, Vec2(layout.right.x - TextureBrowser::width() - 8.0f,
                                                    layout.centre.y + kViewportBar + 8.0f));
    }
    // Along the bottom: history, the play-test report, the log.
    const Rect history_rect{layout.bottom.x, layout.bottom.y, layout.bottom.w * 0.2f, layout.bottom.h};
    if (dojo_tab_)
        history_panel_.draw(*dojo_, history_rect);
    else
        history_panel_.draw(editor_, history_rect);
    analysis_.window(editor_, spots_,
                     Rect{layout.bottom.x + layout.bottom.w * 0.2f, layout.bottom.y, layout.bottom.w * 0.4f,
                          layout.bottom.h});
    log_panel_.draw(log_, Rect{layout.bottom.x + layout.bottom.w * 0.6f, layout.bottom.y,
                               layout.bottom.w * 0.4f, layout.bottom.h});
    files_.draw();
    about_.draw(spots_);
    prefab_prompt_.draw(ctx);
    dojo_->prompts(); // the clip file's questions, whichever tab is shown
    if (dojo_->take_quit_answer() == DojoPanel::QuitAnswer::Go) {
        dojo_quit_confirmed_ = true;
        request(PendingAction::Quit); // on to the level's unsaved changes, if any
    }
    handle_shortcuts();
    update_title();
    ++frame_;
    if (options_.status_file) write_status();
}

void EditorApp::request(PendingAction action, fs::path path) {
    if (action == PendingAction::Quit && dojo_->dirty() && !dojo_quit_confirmed_) {
        dojo_->ask_before_quit(); // the clip file first; its answer comes back through dojo_->prompts()
        return;
    }
    dojo_quit_confirmed_ = false; // a confirmation counts for this one request
    files_.request(action, std::move(path));
}

void EditorApp::handle_shortcuts() {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantTextInput || ImGui::IsPopupOpen(nullptr, ImGuiPopupFlags_AnyPopupId)) return;
    // ImGui 1.86 indexes keys by the backend's codes: GLFW_KEY_* name physical positions (US layout).
    auto pressed = [](int key) { return ImGui::IsKeyPressed(key, false); };
    // Auto-repeat only for a key held down through more than one frame: ImGui 1.86 repeats by time, so one
    // slow frame (past the repeat delay) after a quick press repeated it at once: one Ctrl+Z undid twice.
    auto repeat = [&io](int key) {
        return ImGui::IsKeyPressed(key, true) &&
               (io.KeysDownDuration[key] == 0.0f || io.KeysDownDurationPrev[key] > 0.0f);
    };
    const bool ctrl = io.KeyCtrl, shift = io.KeyShift;
    if (ctrl && pressed(GLFW_KEY_N)) request(PendingAction::New);
    if (ctrl && pressed(GLFW_KEY_O)) request(PendingAction::Open);
    if (ctrl && pressed(GLFW_KEY_S)) {
        if (dojo_tab_)
            dojo_->save();
        else
            files_.save(shift);
    }
    // Shift decides between undo and redo for every Z event, including auto-repeat: testing only the first
    // press for redo let a held Ctrl+Shift+Z fall through to the repeating undo once the key-repeat delay
    // passed (one slow frame under Xvfb is enough), so the redo was undone straight away.
    // In the Dojo tab they act on the dojo's own history.
    auto undo = [this] { dojo_tab_ ? dojo_->undo() : editor_.undo(); };
    auto redo = [this] { dojo_tab_ ? dojo_->redo() : editor_.redo(); };
    if (ctrl && shift) {
        if (pressed(GLFW_KEY_Z)) redo();
    } else if (ctrl && pressed(GLFW_KEY_Y)) {
        redo();
    } else if (ctrl && repeat(GLFW_KEY_Z)) {
        undo();
    }
    if (pressed(GLFW_KEY_F5)) play_.start(editor_.level(), shift ? &viewport_.camera() : nullptr);
    if (dojo_tab_) {
        if (pressed(GLFW_KEY_DELETE)) dojo_->delete_selected();
        if (ctrl && pressed(GLFW_KEY_C)) dojo_->copy(shift);
        if (ctrl && pressed(GLFW_KEY_V)) dojo_->paste(shift);
        if (!ctrl && pressed(GLFW_KEY_K)) dojo_->key_pose();
        return; // the rest acts on the level viewport
    }
    if (viewport_.geometry_tool_keys(ctrl)) return;
    if (ctrl && pressed(GLFW_KEY_D)) report(duplicate(editor_), "duplicate");
    if (ctrl && pressed(GLFW_KEY_A)) select_all(editor_);
    if (ctrl && pressed(GLFW_KEY_C)) {
        const std::string text = copy(editor_);
        glfwSetClipboardString(shell_.window(), text.c_str());
        log_line("copied " + std::to_string(editor_.doc().selection.size()) + " entities as JSON");
    }
    if (ctrl && pressed(GLFW_KEY_V)) {
        const char* text = glfwGetClipboardString(shell_.window());
        report(text ? paste_text(editor_, text) : paste(editor_), "paste");
    }
    if (pressed(GLFW_KEY_DELETE)) report(delete_selection(editor_), "delete");
    if (pressed(GLFW_KEY_ESCAPE)) {
        if (inspector_.texture_browser().is_open())
            inspector_.texture_browser().close();
        else if (logic_.picking())
            logic_.end_pick();
        else if (!viewport_.escape()) { // escape(): a gizmo drag ends, or the armed tool disarms
            if (editor_.open_group() != 0)
                leave_group(editor_, log_);
            else
                editor_.clear_selection();
        }
    }
    if (ctrl && pressed(GLFW_KEY_G))
        shift ? ungroup_selection(editor_, log_) : group_selection(editor_, log_);
    if (viewport_.flying() || ctrl) return;
    if (repeat(GLFW_KEY_LEFT)) report(nudge(editor_, 0, -1), "nudge");
    if (repeat(GLFW_KEY_RIGHT)) report(nudge(editor_, 0, +1), "nudge");
    if (repeat(GLFW_KEY_UP)) report(nudge(editor_, 2, -1), "nudge");
    if (repeat(GLFW_KEY_DOWN)) report(nudge(editor_, 2, +1), "nudge");
    if (repeat(GLFW_KEY_PAGE_UP)) report(nudge(editor_, 1, +1), "nudge");
    if (repeat(GLFW_KEY_PAGE_DOWN)) report(nudge(editor_, 1, -1), "nudge");
    viewport_.shortcuts(); // F, the gizmo's mode and space, the numpad's views
}

} // namespace ks::editor::ui
