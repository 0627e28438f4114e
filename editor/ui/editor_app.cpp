// The editor window's frame: layout, menus, shortcuts, file prompts and the title. The viewport and the
// panels live in viewport.cpp and panels.cpp; the dojo tab in dojo_panel.cpp.
#include "ui/editor_app.h"

#include "core/files.h"
#include "core/log.h"
#include "core/paths.h"
#include "model/script.h"
#include "ui/dojo_panel.h"
#include "ui/layout.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <cstdio>
#include <cstring>

namespace ks::editor::ui {
namespace fs = std::filesystem;

namespace {
EditorApp* g_app = nullptr; // the window-close callback has no user pointer to spare (ImGui's backend)

Vec2 item_centre() {
    return Vec2((ImGui::GetItemRectMin().x + ImGui::GetItemRectMax().x) * 0.5f,
                (ImGui::GetItemRectMin().y + ImGui::GetItemRectMax().y) * 0.5f);
}

fs::path recent_files_path() {
    fs::path dir = default_config_dir();
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

void EditorApp::log_line(std::string line, bool error) {
    if (error) ++error_lines_, last_error_ = line;
    log_.emplace_back(std::move(line), error);
    while (log_.size() > 500) log_.pop_front();
    scroll_log_ = true;
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
    render::RendererSettings settings = render::renderer_settings_from_environment();
    settings.msaa_samples = render::default_msaa_for(shell_.gl_renderer());
    // Full resolution on software rasterisers too (the game's automatic choice there is 0.5): thin overlays
    // (eye radii, grid, gizmo) at half resolution turn to stairs, and the viewport is about 40 % of the
    // window (21.2-23.1 vs 17.6-22.3 ms per editor frame on llvmpipe: docs/performance.md, "Viewport
    // resolution"). KS_RENDER_SCALE still overrides (automatic_render_scale).
    settings.software_render_scale = 1.0f;
    auto renderer = render::SceneRenderer::create(assets_.textures(), settings);
    if (!renderer) return renderer.error();
    renderer_ = std::move(*renderer);
    if (options_.level) {
        if (auto r = editor_.open(*options_.level); !r) {
            log_line(r.error().str(), true);
            return r.error();
        }
        log_line("opened " + options_.level->string());
    } else if (!shell_.screenshot_mode()) {
        if (auto offer = find_untitled_recovery(autosaver_.config())) editor_.offer_recovery(*offer);
    }
    dojo_ = std::make_unique<DojoPanel>(
        assets_, *renderer_,
        DojoSetup{options_.dojo_file, options_.audition,
                  [this](const std::string& line, bool error) { log_line(line, error); }});
    dojo_tab_ = options_.start_in_dojo;
    if (options_.dojo_view) {
        auto view = parse_dojo_view(*options_.dojo_view);
        if (!view) return view.error();
        dojo_->apply_view(*view);
        if (view->robot > 0) { // preview in context: select the robot and play the clip on it
            if (auto r = editor_.select({view->robot}); !r) return r.error();
            if (preview_robot() != view->robot)
                return Error("--dojo-view: entity " + std::to_string(view->robot) + " is not a robot", {},
                             "give the id of a robot in the level (--level FILE)");
            clip_preview_ = true;
        }
    }
    overlays_.navmesh = options_.show_navmesh;
    set_view(options_.view.value_or(ViewMode::Perspective)); // perspective: from above one corner
    if (options_.camera) {
        float v[5];
        if (std::sscanf(options_.camera->c_str(), "%f,%f,%f,%f,%f", &v[0], &v[1], &v[2], &v[3], &v[4]) != 5)
            return Error("--camera '" + *options_.camera + "': expected x,y,z,yaw,pitch", {},
                         "e.g. --camera 0,30,40,0,-40 (degrees; yaw 0 looks along -z)");
        view_.camera.position = Vec3(v[0], v[1], v[2]);
        view_.camera.yaw = radians(v[3]);
        view_.camera.pitch = radians(v[4]);
    }
    if (options_.run_script) {
        auto text = files::read_text(*options_.run_script);
        if (!text) return text.error();
        auto ran = run_script_text(*text, options_.run_script->string(), options_.run_script->parent_path(),
                                   editor_);
        if (!ran) return ran.error();
        log_line("ran " + options_.run_script->string());
    }
    rebuild_scene_if_changed();
    g_app = this;
    glfwSetWindowCloseCallback(shell_.window(), [](GLFWwindow* window) {
        if (!g_app) return;
        glfwSetWindowShouldClose(window, GLFW_FALSE); // the app decides, after asking about unsaved work
        g_app->request(PendingAction::Quit);
    });
    return ok();
}

int EditorApp::run() {
    shell::ShellHooks hooks;
    hooks.render = [this](const shell::FrameInfo& info) { render_views(info); };
    hooks.imgui = [this](const shell::FrameInfo& info) { build_ui(info); };
    hooks.wants_close = [this]() { return quit_; };
    return shell_.run(hooks);
}

void EditorApp::report(const Result<void>& result, const char* what) {
    if (!result) log_line(std::string(what) + ": " + result.error().str(), true);
}

void EditorApp::update_title() {
    std::string title = editor_.title();
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
        rebuild_scene_if_changed();
        pose_preview_robot(info.frame_dt);
        const int w = static_cast<int>(layout.centre.w), h = static_cast<int>(layout.centre.h - kViewportBar);
        viewport_target_.ensure(w, h);
        view_.set_viewport(Vec2(static_cast<float>(w), static_cast<float>(std::max(1, h))));
        viewport_target_.bind();
        scene_->emit(instances_, lights_);
        debug_.clear();
        draw_overlays();
        render::SceneFrame frame;
        frame.camera = view_.camera;
        frame.camera.aspect = static_cast<float>(w) / static_cast<float>(std::max(1, h));
        frame.environment = scene_->environment();
        frame.instances = &instances_;
        frame.lights = &lights_;
        frame.debug = &debug_;
        frame.width = w;
        frame.height = h;
        renderer_->render(frame);
    }
    RenderTarget::clear_window(info.width, info.height);
}

void EditorApp::build_ui(const shell::FrameInfo& info) {
    std::vector<std::string> lines;
    play_.poll(lines);
    for (auto& l : lines) log_line("[game] " + l, l.find("error") != std::string::npos);
    if (!play_.running() && play_.last_exit_code() && !play_file_.empty()) {
        const int code = *play_.last_exit_code();
        log_line(code == 0 ? "play-test ended"
                           : "play-test FAILED with exit code " + std::to_string(code) +
                                 " (its messages are above)",
                 code != 0);
        play_exit_code_ = code;
        play_file_.clear();
    }
    if (!shell_.screenshot_mode()) {
        if (auto r = autosaver_.update(editor_); !r)
            log_line("autosave: " + r.error().str(), true);
        else if (*r)
            log_line("autosaved to " + (*r)->string());
    }
    wheel_ = ImGui::GetIO().MouseWheel;
    const Layout layout = compute_layout(static_cast<float>(info.width), static_cast<float>(info.height),
                                         ImGui::GetFrameHeight());
    dojo_->begin_frame();
    menu_bar();
    if (dojo_tab_) {
        dojo_->panel(layout.bottom.x, layout.centre.y, layout.bottom.w, layout.centre.h);
    } else {
        outliner_panel(layout.left.x, layout.left.y, layout.left.w, layout.left.h);
        viewport_panel(layout.centre.x, layout.centre.y, layout.centre.w, layout.centre.h);
        inspector_panel(layout.right.x, layout.right.y, layout.right.w, layout.right.h * 0.62f);
        validation_panel(layout.right.x, layout.right.y + layout.right.h * 0.62f, layout.right.w,
                         layout.right.h * 0.38f);
    }
    history_panel(layout.bottom.x, layout.bottom.y, layout.bottom.w * 0.32f, layout.bottom.h);
    log_panel(layout.bottom.x + layout.bottom.w * 0.32f, layout.bottom.y, layout.bottom.w * 0.68f,
              layout.bottom.h);
    modal_prompts();
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

void EditorApp::handle_shortcuts() {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantTextInput || ImGui::IsPopupOpen(nullptr, ImGuiPopupFlags_AnyPopupId)) return;
    // ImGui 1.86 indexes keys by the backend's codes: GLFW_KEY_* name physical positions (US layout).
    auto pressed = [](int key) { return ImGui::IsKeyPressed(key, false); };
    auto repeat = [](int key) { return ImGui::IsKeyPressed(key, true); };
    const bool ctrl = io.KeyCtrl, shift = io.KeyShift;
    if (ctrl && pressed(GLFW_KEY_N)) request(PendingAction::New);
    if (ctrl && pressed(GLFW_KEY_O)) request(PendingAction::Open);
    if (ctrl && pressed(GLFW_KEY_S)) {
        if (dojo_tab_)
            dojo_->save();
        else
            save(shift);
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
    if (pressed(GLFW_KEY_F5)) play_test(shift);
    if (dojo_tab_) {
        if (pressed(GLFW_KEY_DELETE)) dojo_->delete_selected();
        return; // the rest acts on the level viewport
    }
    if (ctrl && pressed(GLFW_KEY_D)) report(editor_.duplicate(), "duplicate");
    if (ctrl && pressed(GLFW_KEY_A)) editor_.select_all();
    if (ctrl && pressed(GLFW_KEY_C)) {
        const std::string text = editor_.copy();
        glfwSetClipboardString(shell_.window(), text.c_str());
        log_line("copied " + std::to_string(editor_.doc().selection.size()) + " entities as JSON");
    }
    if (ctrl && pressed(GLFW_KEY_V)) {
        const char* text = glfwGetClipboardString(shell_.window());
        report(text ? editor_.paste_text(text) : editor_.paste(), "paste");
    }
    if (pressed(GLFW_KEY_DELETE)) report(editor_.delete_selection(), "delete");
    if (pressed(GLFW_KEY_ESCAPE)) {
        if (gizmo_.dragging())
            gizmo_.cancel(editor_);
        else if (placing_)
            placing_.reset();
        else
            editor_.clear_selection();
    }
    if (flying_ || ctrl) return;
    if (repeat(GLFW_KEY_LEFT)) report(editor_.nudge(0, -1), "nudge");
    if (repeat(GLFW_KEY_RIGHT)) report(editor_.nudge(0, +1), "nudge");
    if (repeat(GLFW_KEY_UP)) report(editor_.nudge(2, -1), "nudge");
    if (repeat(GLFW_KEY_DOWN)) report(editor_.nudge(2, +1), "nudge");
    if (repeat(GLFW_KEY_PAGE_UP)) report(editor_.nudge(1, +1), "nudge");
    if (repeat(GLFW_KEY_PAGE_DOWN)) report(editor_.nudge(1, -1), "nudge");
    if (pressed(GLFW_KEY_F)) focus_selection();
    if (pressed(GLFW_KEY_W)) gizmo_.mode = GizmoMode::Move;
    if (pressed(GLFW_KEY_E)) gizmo_.mode = GizmoMode::Rotate;
    if (pressed(GLFW_KEY_R)) gizmo_.mode = GizmoMode::Scale;
    if (pressed(GLFW_KEY_KP_7)) set_view(ViewMode::Top);
    if (pressed(GLFW_KEY_KP_1)) set_view(ViewMode::Front);
    if (pressed(GLFW_KEY_KP_3)) set_view(ViewMode::Side);
    if (pressed(GLFW_KEY_KP_5)) set_view(ViewMode::Perspective);
}

void EditorApp::menu_bar() {
    if (!ImGui::BeginMainMenuBar()) return;
    const bool file_menu = ImGui::BeginMenu("File");
    menu_spots_[0] = item_centre();
    menu_spots_[1] = Vec2(0.0f);
    if (file_menu) {
        if (ImGui::MenuItem("New", "Ctrl+N")) request(PendingAction::New);
        if (ImGui::MenuItem("Open...", "Ctrl+O")) request(PendingAction::Open);
        if (ImGui::BeginMenu("Open Recent", !recent_.entries().empty())) {
            for (const auto& entry : recent_.entries())
                if (ImGui::MenuItem(entry.string().c_str())) request(PendingAction::OpenRecent, entry);
            ImGui::EndMenu();
        }
        if (ImGui::MenuItem("Save", "Ctrl+S")) save(false);
        if (ImGui::MenuItem("Save As...", "Ctrl+Shift+S")) save(true);
        ImGui::Separator();
        if (ImGui::MenuItem("Quit")) request(PendingAction::Quit);
        menu_spots_[1] = item_centre();
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Edit")) {
        if (dojo_tab_) { // the clip file's history, as Ctrl+Z in the tab
            const auto& h = dojo_->history();
            if (ImGui::MenuItem(("Undo " + h.undo_name()).c_str(), "Ctrl+Z", false, h.can_undo()))
                dojo_->undo();
            if (ImGui::MenuItem(("Redo " + h.redo_name()).c_str(), "Ctrl+Shift+Z", false, h.can_redo()))
                dojo_->redo();
        } else {
            const auto& h = editor_.history();
            if (ImGui::MenuItem(("Undo " + h.undo_name()).c_str(), "Ctrl+Z", false, h.can_undo()))
                editor_.undo();
            if (ImGui::MenuItem(("Redo " + h.redo_name()).c_str(), "Ctrl+Shift+Z", false, h.can_redo()))
                editor_.redo();
        }
        ImGui::Separator();
        const bool any = !editor_.doc().selection.empty();
        if (ImGui::MenuItem("Duplicate", "Ctrl+D", false, any)) report(editor_.duplicate(), "duplicate");
        if (ImGui::MenuItem("Delete", "Del", false, any)) report(editor_.delete_selection(), "delete");
        if (ImGui::MenuItem("Copy", "Ctrl+C", false, any))
            glfwSetClipboardString(shell_.window(), editor_.copy().c_str());
        if (ImGui::MenuItem("Paste", "Ctrl+V")) {
            const char* text = glfwGetClipboardString(shell_.window());
            report(text ? editor_.paste_text(text) : editor_.paste(), "paste");
        }
        ImGui::Separator();
        if (ImGui::MenuItem("Select All", "Ctrl+A")) editor_.select_all();
        if (ImGui::BeginMenu("Select All of Type")) {
            for (auto type : level::all_types())
                if (ImGui::MenuItem(std::string(level::type_name(type)).c_str()))
                    editor_.select_all_of_type(type);
            ImGui::EndMenu();
        }
        if (ImGui::MenuItem("Select None", "Esc")) editor_.clear_selection();
        ImGui::Separator();
        auto& grid = editor_.grid();
        ImGui::Checkbox("Snap to grid", &grid.snap);
        ImGui::SetNextItemWidth(90);
        ImGui::DragFloat("Grid step", &grid.step, 0.05f, 0.05f, 16.0f, "%.2f");
        ImGui::SetNextItemWidth(90);
        ImGui::DragFloat("Rotation step", &grid.rotation_step, 0.5f, 1.0f, 90.0f, "%.0f deg");
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("View")) {
        if (ImGui::MenuItem("Perspective", "Num 5")) set_view(ViewMode::Perspective);
        if (ImGui::MenuItem("Top", "Num 7")) set_view(ViewMode::Top);
        if (ImGui::MenuItem("Front", "Num 1")) set_view(ViewMode::Front);
        if (ImGui::MenuItem("Side", "Num 3")) set_view(ViewMode::Side);
        if (ImGui::MenuItem("Focus Selection", "F")) focus_selection();
        ImGui::Separator();
        ImGui::MenuItem("Grid", nullptr, &overlays_.grid);
        ImGui::MenuItem("Collision bounds", nullptr, &overlays_.collision);
        ImGui::MenuItem("Structure outlines (axis views)", nullptr, &overlays_.outlines);
        ImGui::MenuItem("Light ranges", nullptr, &overlays_.lights);
        ImGui::MenuItem("Robot eye / shooting radii", nullptr, &overlays_.robots);
        ImGui::MenuItem("Player start", nullptr, &overlays_.player_start);
        ImGui::MenuItem("All patrol routes", nullptr, &overlays_.patrols);
        ImGui::MenuItem("All sound radii", nullptr, &overlays_.sound_radii);
        ImGui::MenuItem("Navigation mesh", nullptr, &overlays_.navmesh);
        ImGui::MenuItem("Ceilings", nullptr, &overlays_.ceilings);
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Play")) {
        if (ImGui::MenuItem("Play from start", "F5", false, !play_.running())) play_test(false);
        if (ImGui::MenuItem("Play from camera", "Shift+F5", false, !play_.running())) play_test(true);
        if (ImGui::MenuItem("Stop", nullptr, false, play_.running())) play_.stop();
        ImGui::EndMenu();
    }
    ImGui::Separator();
    if (ImGui::RadioButton("Level", !dojo_tab_)) dojo_tab_ = false;
    if (ImGui::RadioButton("Dojo", dojo_tab_)) dojo_tab_ = true;
    ImGui::Separator();
    const std::string status = editor_.title();
    ImGui::TextDisabled("%s", status.c_str());
    ImGui::EndMainMenuBar();
}

void EditorApp::request(PendingAction action, fs::path path) {
    if (action == PendingAction::Quit && dojo_->dirty() && !dojo_quit_confirmed_) {
        dojo_->ask_before_quit(); // the clip file first; its answer comes back through modal_prompts
        return;
    }
    dojo_quit_confirmed_ = false; // a confirmation counts for this one request
    pending_ = action;
    pending_path_ = std::move(path);
    if (editor_.has_unsaved_changes())
        ask_unsaved_ = true;
    else
        perform(action);
}

void EditorApp::perform(PendingAction action) {
    switch (action) {
    case PendingAction::New:
        editor_.new_document();
        log_line("new level");
        break;
    case PendingAction::Open:
        path_for_save_ = false;
        ask_path_ = true;
        std::snprintf(path_input_, sizeof(path_input_), "%s",
                      editor_.file_path().empty() ? paths::level("").string().c_str()
                                                  : editor_.file_path().string().c_str());
        return; // pending_ stays until the path is given
    case PendingAction::OpenRecent:
        open_file(pending_path_);
        break;
    case PendingAction::Quit:
        quit_ = true;
        break;
    case PendingAction::None:
        break;
    }
    pending_ = PendingAction::None;
}

void EditorApp::open_file(const fs::path& path) {
    if (auto r = editor_.open(path); !r) {
        log_line(r.error().str(), true);
        if (!fs::exists(path)) recent_.remove(path);
        return;
    }
    log_line("opened " + path.string());
    if (editor_.recovery_offer()) log_line("an autosave newer than the file exists: recover it?");
    set_view(ViewMode::Perspective);
}

void EditorApp::save(bool save_as) {
    if (save_as || editor_.file_path().empty()) {
        path_for_save_ = true;
        ask_path_ = true;
        std::snprintf(path_input_, sizeof(path_input_), "%s",
                      editor_.file_path().empty() ? (paths::level("") / "untitled.json").string().c_str()
                                                  : editor_.file_path().string().c_str());
        return;
    }
    auto r = editor_.save();
    if (!r) {
        log_line(r.error().str(), true);
        if (editor_.disk_status() == DiskStatus::Modified) ask_overwrite_ = true;
        return;
    }
    log_line((r->draft ? "saved as DRAFT (" + std::to_string(r->error_count) + " design errors): "
                       : std::string("saved ")) +
                 r->path.string(),
             r->draft);
}

void EditorApp::modal_prompts() {
    if (ask_unsaved_) ImGui::OpenPopup("Unsaved changes");
    if (ask_path_) ImGui::OpenPopup(path_for_save_ ? "Save level as" : "Open level");
    if (ask_overwrite_) ImGui::OpenPopup("Overwrite?");
    if (editor_.recovery_offer() && !ask_unsaved_ && !ask_path_) ImGui::OpenPopup("Recover autosave");
    ask_unsaved_ = ask_path_ = ask_overwrite_ = false;

    const ImVec2 centre = ImGui::GetMainViewport()->GetCenter();
    ImGui::SetNextWindowPos(centre, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::Text("%s has unsaved changes.", editor_.file_path().empty()
                                                   ? "The untitled level"
                                                   : editor_.file_path().filename().string().c_str());
        ImGui::Text("Save them before going on?");
        if (ImGui::Button("Save")) {
            ImGui::CloseCurrentPopup();
            save(false);
            if (!editor_.has_unsaved_changes()) perform(pending_);
        }
        ImGui::SameLine();
        if (ImGui::Button("Discard")) {
            ImGui::CloseCurrentPopup();
            perform(pending_);
        }
        ImGui::SameLine();
        if (ImGui::Button("Cancel")) {
            ImGui::CloseCurrentPopup();
            pending_ = PendingAction::None;
        }
        ImGui::EndPopup();
    }
    for (const char* title : {"Open level", "Save level as"}) {
        ImGui::SetNextWindowPos(centre, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
        if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) continue;
        ImGui::Text("Level file (JSON):");
        ImGui::SetNextItemWidth(520);
        if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
        const bool entered = ImGui::InputText("##path", path_input_, sizeof(path_input_),
                                              ImGuiInputTextFlags_EnterReturnsTrue);
        if (!recent_.entries().empty()) {
            ImGui::TextDisabled("Recent:");
            for (const auto& entry : recent_.entries())
                if (ImGui::Selectable(entry.string().c_str()))
                    std::snprintf(path_input_, sizeof(path_input_), "%s", entry.string().c_str());
        }
        if (entered || ImGui::Button(path_for_save_ ? "Save" : "Open")) {
            const fs::path path = paths::resolve_user_path(path_input_);
            ImGui::CloseCurrentPopup();
            if (path_for_save_) {
                auto r = editor_.save_as(path);
                if (!r && fs::exists(path)) {
                    pending_path_ = path;
                    ask_overwrite_ = true;
                } else if (!r) {
                    log_line(r.error().str(), true);
                } else {
                    log_line((r->draft ? "saved as DRAFT: " : "saved ") + r->path.string(), r->draft);
                    if (pending_ != PendingAction::None) perform(pending_);
                }
            } else {
                open_file(path);
                pending_ = PendingAction::None;
            }
        }
        ImGui::SameLine();
        if (ImGui::Button("Cancel")) {
            ImGui::CloseCurrentPopup();
            pending_ = PendingAction::None;
        }
        ImGui::EndPopup();
    }
    ImGui::SetNextWindowPos(centre, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (ImGui::BeginPopupModal("Overwrite?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        const fs::path target = pending_path_.empty() ? editor_.file_path() : pending_path_;
        ImGui::Text("%s exists or was changed on disk since it was opened.", target.string().c_str());
        ImGui::Text("Overwrite it?");
        if (ImGui::Button("Overwrite")) {
            SaveOptions options;
            options.overwrite_existing = true;
            options.overwrite_external_changes = true;
            auto r = pending_path_.empty() ? editor_.save(options) : editor_.save_as(pending_path_, options);
            if (r)
                log_line((r->draft ? "saved as DRAFT: " : "saved ") + r->path.string(), r->draft);
            else
                log_line(r.error().str(), true);
            pending_path_.clear();
            ImGui::CloseCurrentPopup();
        }
        ImGui::SameLine();
        if (ImGui::Button("Cancel")) {
            pending_path_.clear();
            ImGui::CloseCurrentPopup();
        }
        ImGui::EndPopup();
    }
    ImGui::SetNextWindowPos(centre, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (ImGui::BeginPopupModal("Recover autosave", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        const auto& offer = editor_.recovery_offer();
        if (offer) {
            ImGui::Text("An autosave is newer than %s:", offer->level_file.empty()
                                                             ? "the untitled level"
                                                             : offer->level_file.string().c_str());
            ImGui::TextDisabled("%s", offer->autosave.string().c_str());
            ImGui::Text("The editor may have closed without saving. Recover it? (Undo returns to the file.)");
        }
        if (ImGui::Button("Recover")) {
            report(editor_.accept_recovery(), "recover");
            ImGui::CloseCurrentPopup();
        }
        ImGui::SameLine();
        if (ImGui::Button("Keep the file")) {
            editor_.decline_recovery();
            ImGui::CloseCurrentPopup();
        }
        if (!offer) ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    }
}

} // namespace ks::editor::ui
