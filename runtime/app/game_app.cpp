// The runtime's state machine: Loading → Menu ⇄ (How to Play, Credits, Options) → Playing ⇄ Paused →
// Dead / Won → Menu or a fresh game; the Dojo is Playing on levels/dojo.json with the test robot driven by
// number keys. The game advances only in the shell's fixed steps (the game's 120 Hz); the picture is drawn
// once per frame, interpolated between the last two steps.
#include "game_app_internal.h"

#include <cstdio>
#include <sstream>

namespace ks::runtime {

const std::vector<std::string>& game_app_options() {
    static const std::vector<std::string> names = {
        "level", "dojo", "screen", "warp",        "dojo-key",     "dojo-time", "seed",
        "msaa",  "help", "fire",   "status-file", "input-script", "audio-out"};
    return names;
}
const std::vector<std::string>& game_app_flags() {
    static const std::vector<std::string> flags = {"dojo", "help", "fire"};
    return flags;
}
const std::vector<std::string>& game_app_screens() {
    static const std::vector<std::string> screens = {"loading", "menu",  "howto", "credits", "options",
                                                     "pause",   "death", "win",   "play",    "dojo"};
    return screens;
}

const char* screen_name(Screen s) {
    switch (s) {
    case Screen::Loading:
        return "loading";
    case Screen::Menu:
        return "menu";
    case Screen::HowTo:
        return "howto";
    case Screen::Credits:
        return "credits";
    case Screen::Options:
        return "options";
    case Screen::Playing:
        return "playing";
    case Screen::Paused:
        return "paused";
    case Screen::Dead:
        return "dead";
    case Screen::Won:
        return "won";
    }
    return "?";
}

bool parse_floats(const std::string& text, float* out, int count) {
    std::stringstream ss(text);
    std::string item;
    int n = 0;
    while (std::getline(ss, item, ',')) {
        if (n >= count) return false;
        char* end = nullptr;
        out[n] = std::strtof(item.c_str(), &end);
        if (end == item.c_str() || *end != '\0' || !is_finite(out[n])) return false;
        ++n;
    }
    return n == count;
}

void GameApp::load(const std::filesystem::path& path, bool dojo, Screen then) {
    pending_ = std::make_unique<Session>();
    pending_->dojo = dojo;
    loader_ = Loader{};
    loader_.then = then;
    Session* s = pending_.get();
    loader_.steps.push_back({"Reading " + path.filename().string(), [s, path]() -> Result<void> {
                                 level::LoadReport report;
                                 auto loaded = level::load_level_file(path, &report);
                                 if (!loaded) return loaded.error();
                                 for (const auto& d : report.diagnostics) log::warn(d.error.str());
                                 s->level = std::move(*loaded);
                                 return {};
                             }});
    loader_.steps.push_back({"Building the simulation", [this, s]() -> Result<void> {
                                 game::GameOptions go;
                                 go.seed = seed_;
                                 auto g = game::Game::create(s->level, go);
                                 if (!g) return g.error();
                                 s->game = std::move(*g);
                                 return {};
                             }});
    // Models one per frame: their textures are the slow part of loading.
    for (const char* model : {"robot", "rifle", "door", "gas_cylinder", "floor_light", "top_light",
                              "control_panel", "pickup_health", "pickup_ammo", "pickup_shield"}) {
        loader_.steps.push_back({std::string("Loading model ") + model, [this, model]() -> Result<void> {
                                     (void)assets_.model(model);
                                     return {};
                                 }});
    }
    loader_.steps.push_back({"Building the level scene", [this, s]() -> Result<void> {
                                 s->view =
                                     WorldView::build(s->level, *s->game, assets_,
                                                      render::level_scene_options(renderer_.settings()));
                                 if (audio_)
                                     s->sounds =
                                         std::make_unique<soundscape::Soundscape>(audio_->engine(), s->level);
                                 return {};
                             }});
    if (dojo) {
        loader_.steps.push_back({"Waking the test robot", [s]() -> Result<void> {
                                     const auto& lib = s->game->animations();
                                     auto c = anim::DojoController::create(lib.clips, lib.rig,
                                                                           anim::dojo_key_clips(lib.clips));
                                     if (!c) return c.error();
                                     s->dojo_controller.emplace(std::move(*c));
                                     for (const auto& e : s->level.entities)
                                         if (const auto* r = e.try_as<level::RobotProps>(); r && r->dummy) {
                                             s->dummy.feet = e.position;
                                             s->dummy.yaw = radians(e.rotation.x);
                                         }
                                     s->dummy.pose = &s->dojo_controller->pose();
                                     return {};
                                 }});
    }
    screen_ = Screen::Loading;
}

void GameApp::step_loader() {
    if (screen_ != Screen::Loading || loader_.done() || freeze_loader_) return;
    auto result = loader_.steps[loader_.next].run();
    if (!result) {
        error_ = "Could not load: " + result.error().str();
        log::error(result.error().str());
        pending_.reset();
        screen_ = session_ ? Screen::Menu : Screen::Menu;
        loader_ = Loader{};
        return;
    }
    ++loader_.next;
    if (loader_.done()) {
        session_ = std::move(pending_);
        error_.clear();
        apply_warp();
        if (loader_.then == Screen::Playing)
            enter_play();
        else
            screen_ = loader_.then;
    }
}

Result<void> GameApp::finish_loading_now() {
    while (screen_ == Screen::Loading && !loader_.done()) {
        step_loader();
        if (!error_.empty()) return Error(error_, Location(level_path_.string()), "see the message above");
    }
    return {};
}

void GameApp::apply_warp() {
    if (!pending_warp_ || !session_ || session_->dojo) return;
    const auto v = *pending_warp_;
    pending_warp_.reset(); // once: Retry and Main Menu start from the level's own start
    auto& g = *session_->game;
    g.teleport_player(Vec3(v[0], v[1], v[2]), radians(v[3]), radians(v[4]));
    // A few steps so the caption and interaction target settle at the new place.
    for (int i = 0; i < 12; ++i) {
        advance({}, static_cast<float>(g.settings().step));
    }
}

void GameApp::enter_play() {
    screen_ = Screen::Playing;
    pause_requested_ = false;
    dojo_picking_ = false;
    if (interactive()) input_.capture(shell_.window(), events_.state());
}

// Tab in the Dojo: the mouse is freed to click a clip in the list, or taken back to look around.
void GameApp::toggle_dojo_picking() {
    if (!dojo_picking_) {
        dojo_picking_ = true;
        input_.release(shell_.window(), events_.state());
    } else {
        enter_play();
    }
}

void GameApp::pause() {
    if (screen_ != Screen::Playing) return;
    screen_ = Screen::Paused;
    input_.release(shell_.window(), events_.state());
    if (session_ && session_->game && !session_->game->paused()) {
        game::Input in;
        in.pause = true;
        advance(in, 0.0f);
    }
}

void GameApp::resume() {
    if (session_ && session_->game && session_->game->paused()) {
        game::Input in;
        in.pause = true; // toggles back
        advance(in, 0.0f);
    }
    enter_play();
}

void GameApp::to_menu() {
    input_.release(shell_.window(), events_.state());
    // The menu shows the main level behind it; a finished or Dojo session is replaced by a fresh main one.
    if (!session_ || session_->dojo || session_->game->phase() != game::Phase::Playing ||
        session_->play_seconds > 0.0)
        load(level_path_, false, Screen::Menu);
    else
        screen_ = Screen::Menu;
}

void GameApp::retry() {
    load(level_path_, session_ && session_->dojo, Screen::Playing);
}

// The options a slow machine needs, passed to the renderer (at start and whenever the panel changes them).
void GameApp::apply_render_options() {
    renderer_.set_render_scale(options_.render_scale);
    renderer_.set_quality(options_.quality == QualityOption::Full   ? render::RenderQuality::Full
                          : options_.quality == QualityOption::Fast ? render::RenderQuality::Fast
                                                                    : render::RenderQuality::Auto);
}

void GameApp::save_options_now() {
    if (!options_dirty_) return;
    options_dirty_ = false;
    if (auto saved = save_options(options_path(), options_); !saved) log::warn(saved.error().str());
}

void GameApp::fixed_update(double dt) {
    if (!session_ || !session_->game) return;
    auto& g = *session_->game;
    if (!budget_.take()) return;
    const bool world_runs = screen_ == Screen::Playing || (screen_ == Screen::Dead && interactive());
    if (session_->dojo_controller && !freeze_dojo_ && screen_ == Screen::Playing)
        session_->dojo_controller->advance(dt);
    if (!world_runs) return;
    game::Input in = screen_ == Screen::Playing ? input_.gather(events_.state(), options_) : game::Input{};
    advance(in, static_cast<float>(dt));
    if (g.phase() == game::Phase::Playing) session_->play_seconds += dt;
    if (g.phase() == game::Phase::Dead && g.death_camera().menu_ready && screen_ == Screen::Playing) {
        screen_ = Screen::Dead;
        input_.release(shell_.window(), events_.state());
    }
    if (g.phase() == game::Phase::Won && screen_ == Screen::Playing) {
        win_ = {session_->play_seconds, g.robots_killed(), static_cast<int>(g.robots().size())};
        screen_ = Screen::Won;
        input_.release(shell_.window(), events_.state());
    }
}

void GameApp::advance(const game::Input& in, float dt) {
    auto& g = *session_->game;
    session_->view->before_step(g);
    g.step(in);
    session_->view->after_step(g, dt);
    if (session_->sounds) session_->sounds->after_step(g);
}

// The listener is the camera the frame was drawn with; the engine's update (occlusion, gains) runs once.
void GameApp::update_audio(const shell::FrameInfo& info) {
    if (!audio_) return;
    bool updated = false;
    if (session_ && session_->sounds && session_->view && screen_ != Screen::Loading) {
        const geometry::Camera& cam = session_->view->camera();
        session_->sounds->update(*session_->game, {cam.position, cam.forward(), cam.up()},
                                 static_cast<float>(info.frame_dt));
        updated = true;
    }
    audio_->end_frame(info.frame_dt, updated);
}

void GameApp::handle_keys() {
    GLFWwindow* w = shell_.window();
    InputState& keys = events_.state();
    const bool esc_pressed = keys.take_press(GLFW_KEY_ESCAPE);
    if (!interactive()) return;
    if (keys.take_press(GLFW_KEY_M)) { // mute from anywhere, remembered
        options_.muted = !options_.muted;
        options_dirty_ = true;
        save_options_now();
        if (audio_) audio_->apply_options(options_);
    }
    // Losing the focus pauses (the mouse is no longer ours); a script's input does not depend on it.
    const bool focus_lost = !scripted_ && !glfwGetWindowAttrib(w, GLFW_FOCUSED);
    if (screen_ == Screen::Playing && (esc_pressed || focus_lost)) {
        pause();
        return;
    }
    if (esc_pressed) {
        if (screen_ == Screen::Paused)
            resume();
        else if (screen_ == Screen::HowTo || screen_ == Screen::Credits || screen_ == Screen::Options) {
            save_options_now();
            screen_ = return_to_;
        }
    }
    if (screen_ == Screen::Playing && session_ && session_->dojo_controller) {
        for (int k = 0; k <= 9; ++k)
            if (keys.take_press(GLFW_KEY_0 + k)) session_->dojo_controller->press(static_cast<char>('0' + k));
        if (keys.take_press(GLFW_KEY_TAB)) toggle_dojo_picking();
    }
}

void GameApp::render(const shell::FrameInfo& info) {
    if (scripted_) run_script(info.frame_index);
    step_loader();
    handle_keys();
    budget_.new_frame(); // the next frame's fixed steps come after this call
    if (!session_ || !session_->view || screen_ == Screen::Loading) {
        // Nothing loaded yet: an empty scene clears to the fog colour behind the loading panel.
        render::SceneFrame empty;
        empty.width = info.width;
        empty.height = info.height;
        empty.environment.fog_color = Vec3(0.02f, 0.025f, 0.04f);
        empty.instances = &no_instances_;
        empty.lights = &no_lights_;
        stats_ = renderer_.render(empty);
        update_audio(info);
        return;
    }
    render::SceneFrame frame;
    frame.width = info.width;
    frame.height = info.height;
    const DojoDummy* dummy = session_->dojo_controller ? &session_->dummy : nullptr;
    session_->view->fill(*session_->game, static_cast<float>(info.alpha), options_.fov_degrees, dummy, frame);
    if (screen_ != Screen::Playing && screen_ != Screen::Paused && screen_ != Screen::Dead)
        frame.view_model = nullptr;
    stats_ = renderer_.render(frame);
    update_audio(info);
}

void GameApp::imgui(const shell::FrameInfo& info) {
    const float w = static_cast<float>(info.width), h = static_cast<float>(info.height);
    ImGuiIO& io = ImGui::GetIO();
    ui::begin_frame();
    if (input_.captured())
        io.ConfigFlags |= ImGuiConfigFlags_NoMouse;
    else
        io.ConfigFlags &= ~ImGuiConfigFlags_NoMouse;
    draw_world_overlay(w, h);
    apply_menu_action(draw_screen(w, h));
    if (audio_ && screen_ != Screen::Playing) audio_->menu_sounds(ui::buttons_drawn());
    write_status(info);
    if (!shell_.screenshot_mode() && screen_ == Screen::Playing) {
        char text[128];
        std::snprintf(text, sizeof(text), "%.1f ms  %d draws", info.frame_dt * 1000.0, stats_.draw_calls);
        ImGui::GetForegroundDrawList()->AddText(shell_.fonts().mono, 0.0f, ImVec2(10.0f, h - 22.0f),
                                                IM_COL32(255, 255, 255, 140), text);
    }
}

// The HUD, hit marker and Dojo legend over the world while it is on screen.
void GameApp::draw_world_overlay(float w, float h) {
    const auto& fonts = shell_.fonts();
    const bool world_visible =
        session_ && session_->game &&
        (screen_ == Screen::Playing || screen_ == Screen::Paused || screen_ == Screen::Dead);
    if (world_visible) {
        const auto& p = session_->game->player();
        const auto& st = session_->game->settings();
        shell::HudState hud;
        hud.health = p.health;
        hud.health_max = st.max_health;
        hud.shield = p.shield;
        hud.shield_max = st.max_shield;
        hud.ammo = static_cast<float>(p.ammo);
        hud.ammo_max = static_cast<float>(st.max_ammo);
        const auto& caption = session_->game->caption();
        if (caption.visible() && screen_ == Screen::Playing) hud.caption = caption.text();
        hud.damage_flash = std::clamp(p.damage_flash / 0.4f, 0.0f, 1.0f);
        hud.crosshair = screen_ == Screen::Playing && session_->game->phase() == game::Phase::Playing;
        ImDrawList* fg = ImGui::GetForegroundDrawList();
        if (screen_ == Screen::Playing) {
            shell::draw_hud(fg, hud, shell::HudFonts{fonts.hud}, w, h);
            draw_hit_marker(fg, std::clamp(p.hit_marker / 0.3f, 0.0f, 1.0f), w, h);
            std::array<feedback::DamageArc, feedback::Feedback::kMaxArcs> arcs;
            const std::size_t n = session_->view->feedback().damage_arcs(p.yaw, p.eye(), arcs);
            draw_damage_arcs(fg, std::span(arcs.data(), n), w, h);
        }
        if (session_->dojo_controller && screen_ == Screen::Playing) {
            const int clicked = dojo_legend(*session_->dojo_controller, dojo_picking_, fonts, w, h);
            if (clicked >= 0)
                session_->dojo_controller->play_entry(static_cast<std::size_t>(clicked));
            else if (dojo_picking_ && ImGui::IsMouseClicked(0) && !ImGui::GetIO().WantCaptureMouse)
                enter_play(); // a click in the world: back to looking around
        }
    }
}

// The current screen's menu or panel; returns what the player chose on it.
MenuAction GameApp::draw_screen(float w, float h) {
    const auto& fonts = shell_.fonts();
    const ImGuiIO& io = ImGui::GetIO();
    MenuAction action = MenuAction::None;
    switch (screen_) {
    case Screen::Loading:
        loading_screen(loader_.fraction(), loader_.label(), fonts, w, h);
        break;
    case Screen::Menu:
        action = main_menu(error_, fonts, w, h);
        break;
    case Screen::HowTo:
        action = how_to_play(fonts, w, h);
        break;
    case Screen::Credits:
        action = credits(fonts, w, h);
        break;
    case Screen::Options: {
        bool changed = false;
        action = options_panel(options_, changed, fonts, w, h);
        options_dirty_ |= changed;
        if (changed) apply_render_options();
        if (changed && audio_) audio_->apply_options(options_);
        break;
    }
    case Screen::Paused:
        action = pause_menu(fonts, w, h);
        // Clicking back into the game (outside the panel) resumes, as the reference's pointer lock.
        if (action == MenuAction::None && interactive() && ImGui::IsMouseClicked(0) && !io.WantCaptureMouse)
            action = MenuAction::Resume;
        break;
    case Screen::Dead:
        if (session_ && session_->game && session_->game->death_camera().menu_ready)
            action = death_menu(fonts, w, h);
        break;
    case Screen::Won:
        action = win_menu(win_, fonts, w, h);
        break;
    case Screen::Playing:
        break;
    }
    return action;
}

void GameApp::apply_menu_action(MenuAction action) {
    switch (action) {
    case MenuAction::Play:
        if (session_ && !session_->dojo && session_->play_seconds == 0.0 &&
            session_->game->phase() == game::Phase::Playing)
            enter_play();
        else
            load(level_path_, false, Screen::Playing);
        break;
    case MenuAction::Dojo:
        load(paths::level("dojo.json"), true, Screen::Playing);
        break;
    case MenuAction::HowTo:
        open_sub(Screen::HowTo);
        break;
    case MenuAction::Credits:
        open_sub(Screen::Credits);
        break;
    case MenuAction::Options:
        open_sub(Screen::Options);
        break;
    case MenuAction::Back:
        save_options_now();
        screen_ = return_to_;
        break;
    case MenuAction::Quit:
        quit_ = true;
        break;
    case MenuAction::Resume:
        resume();
        break;
    case MenuAction::MainMenu:
        to_menu();
        break;
    case MenuAction::Retry:
        retry();
        break;
    case MenuAction::None:
        break;
    }
}

Result<void> GameApp::start(const Automation& a) {
    auto opened = AppAudio::open(a.audio_out);
    if (!opened) return opened.error();
    audio_ = std::move(*opened);
    audio_->apply_options(options_);
    status_path_ = a.status_file;
    script_ = a.script;
    scripted_ = a.scripted;
    // A screenshot without --screen shows the game (what the render-only view used to show, now playable);
    // a scripted screenshot run starts where a player does, at the loading screen.
    const std::string screen =
        a.screen.empty() && shell_.screenshot_mode() && !a.scripted ? "play" : a.screen;
    const bool dojo = a.dojo || screen == "dojo";
    const bool wants_world =
        screen == "play" || screen == "pause" || screen == "death" || screen == "win" || dojo;
    load(dojo ? paths::level("dojo.json") : level_path_, dojo, wants_world ? Screen::Playing : Screen::Menu);
    if (screen == "loading") {
        // Stop half way: the bar shows progress and the label the step in hand.
        for (int i = 0; i < 6; ++i) step_loader();
        freeze_loader_ = true;
        return {};
    }
    if (screen.empty() && !dojo) {
        pending_warp_ = a.warp; // interactive: load across frames with the bar, then warp
        return {};
    }
    if (auto done = finish_loading_now(); !done) return done;
    if (!session_) return Error("loading failed", Location(level_path_.string()));
    auto& g = *session_->game;
    if (a.warp) {
        const auto& v = *a.warp;
        g.teleport_player(Vec3(v[0], v[1], v[2]), radians(v[3]), radians(v[4]));
        // A few steps so the caption and interaction target settle at the new place.
        for (int i = 0; i < 12; ++i) {
            advance({}, static_cast<float>(g.settings().step));
        }
    }
    if (a.fire) {
        game::Input in;
        in.fire = true;
        advance(in, static_cast<float>(g.settings().step));
    }
    if (session_->dojo_controller && a.dojo_key) {
        if (!session_->dojo_controller->press(a.dojo_key)) {
            std::string bound;
            for (const anim::DojoKey& k : session_->dojo_controller->entries())
                if (k.key != 0) bound += (bound.empty() ? "" : ", ") + std::string(1, k.key) + " " + k.clip;
            return Error(std::string("--dojo-key '") + a.dojo_key + "' is not bound", Location("--dojo-key"),
                         "the Dojo's keys: " + bound);
        }
    }
    if (session_->dojo_controller && a.dojo_time >= 0.0) {
        session_->dojo_controller->advance(a.dojo_time);
        freeze_dojo_ = true;
    }
    if (screen == "menu") screen_ = Screen::Menu;
    if (screen == "howto") open_sub(Screen::HowTo);
    if (screen == "credits") open_sub(Screen::Credits);
    if (screen == "options") open_sub(Screen::Options);
    if (screen == "pause") pause();
    if (screen == "death") {
        g.damage_player(1.0e6f);
        // Run the death camera to its end so the menu shows.
        for (int i = 0; i < 1000 && !g.death_camera().menu_ready; ++i) {
            advance({}, static_cast<float>(g.settings().step));
        }
        screen_ = Screen::Dead;
    }
    if (screen == "win") {
        // Win for real: stand in front of the control panel (trying each side), face it and press E.
        for (const auto& panel : g.panels()) {
            for (int side = 0; side < 4 && g.phase() != game::Phase::Won; ++side) {
                const float a = panel.yaw + static_cast<float>(side) * kPi * 0.5f;
                const Vec3 out(-std::sin(a), 0.0f, -std::cos(a)); // yaw 0 faces -z
                const float reach = std::max(panel.size.x, panel.size.z) * 0.5f + 2.0f;
                const Vec3 feet(panel.centre.x + out.x * reach, panel.centre.y - panel.size.y * 0.5f,
                                panel.centre.z + out.z * reach);
                g.teleport_player(feet, a + kPi, -0.3f); // turned round: facing the panel
                for (int i = 0; i < 4 && g.phase() != game::Phase::Won; ++i) {
                    game::Input in;
                    in.interact = i == 3;
                    advance(in, static_cast<float>(g.settings().step));
                }
            }
        }
        if (g.phase() != game::Phase::Won)
            return Error("--screen win: could not reach a control panel in this level",
                         Location(level_path_.string()),
                         "use a level with a control panel (levels/main.json has one)");
        win_ = {session_->play_seconds, g.robots_killed(), static_cast<int>(g.robots().size())};
        screen_ = Screen::Won;
    }
    return {};
}

int GameApp::run() {
    shell::ShellHooks hooks;
    hooks.fixed_update = [this](double dt) { fixed_update(dt); };
    hooks.render = [this](const shell::FrameInfo& info) { render(info); };
    hooks.imgui = [this](const shell::FrameInfo& info) { imgui(info); };
    hooks.wants_close = [this]() { return quit_; };
    int code = shell_.run(hooks);
    if (code == 0) code = exit_code_;
    events_.uninstall();
    save_options_now();
    session_.reset();
    pending_.reset();
    if (audio_)
        if (auto finished = audio_->finish(); !finished) {
            log::error(finished.error().str());
            if (code == 0) code = 1;
        }
    return code;
}

} // namespace ks::runtime
