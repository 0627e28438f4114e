// The runtime's state machine: Loading → Menu ⇄ (How to Play, Credits, Options) → Playing ⇄ Paused →
// Dead / Won → Menu or a fresh game; the Dojo is Playing on levels/dojo.json with the test robot driven by
// number keys. The game advances only in the shell's fixed steps (the game's 120 Hz); the picture is drawn
// once per frame, interpolated between the last two steps. One frame's work (keys, scene, HUD, the screen's
// menu) is in game_app_frame.cpp, the automation's start in game_app_start.cpp.
#include "game_app_internal.h"

#include "core/startup_trace.h"
#include "game/robot_system.h"
#include "shell/app_shell.h"

#include <chrono>

namespace ks::runtime {

void GameApp::load(const std::filesystem::path& path, bool dojo, Screen then, Screen on_failure) {
    pending_ = std::make_unique<Session>();
    pending_->file = path;
    pending_->dojo = dojo;
    loader_ = Loader{};
    loader_.then = then;
    loader_.on_failure = on_failure;
    Session* s = pending_.get();
    loader_.steps.push_back({"Reading " + path.filename().string(), [s, path]() -> Result<void> {
                                 level::LoadReport report;
                                 auto loaded = level::load_level_file(path, &report);
                                 if (!loaded) return loaded.error();
                                 for (const auto& d : report.diagnostics) log::warn(d.error.str());
                                 s->level = std::move(*loaded);
                                 // The navigation mesh (on a cold start, Recast's whole build) is
                                 // built on a worker while the models load on this thread.
                                 s->navigation = std::async(std::launch::async, [s] {
                                     return game::build_robot_navigation(s->level);
                                 });
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
    loader_.steps.push_back({"Building the simulation", [this, s]() -> Result<void> {
                                 game::GameOptions go;
                                 go.seed = seed_;
                                 go.settings.difficulty = options_.difficulty;
                                 if (s->navigation.valid()) {
                                     auto mesh = s->navigation.get();
                                     startup::mark("navigation mesh (waited for)");
                                     // A mesh that failed is built again by the game, which reports why.
                                     if (mesh) go.navigation = std::move(*mesh);
                                 }
                                 auto g = game::Game::create(s->level, go);
                                 if (!g) return g.error();
                                 s->game = std::move(*g);
                                 return {};
                             }});
    loader_.steps.push_back({"Building the level scene", [this, s]() -> Result<void> {
                                 auto scene_options = render::level_scene_options(renderer_.settings());
                                 scene_options.cache_bake = true; // each launch would bake the same again
                                 // A player's start shows the direct light until the full bake is done; a
                                 // screenshot run (tests, benches) waits for it, its picture the same each
                                 // run.
                                 scene_options.background_bake = !shell_.screenshot_mode();
                                 // An idle menu draws once more when the full bake is ready, to show it.
                                 s->view = WorldView::build(s->level, *s->game, assets_, scene_options,
                                                            [] { shell::AppShell::wake(); });
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
    if (startup::enabled()) startup::mark("loaded: " + loader_.steps[loader_.next].label);
    if (!result) {
        error_ = "Could not load: " + result.error().str();
        log::error(result.error().str());
        pending_.reset();
        screen_ = loader_.on_failure;
        if (screen_ == Screen::Menu) campaign_.reset(); // a campaign whose level fails cannot go on
        loader_ = Loader{};
        return;
    }
    ++loader_.next;
    if (loader_.done()) {
        session_ = std::move(pending_);
        error_.clear();
        logic_debug_.start(session_->level, *session_->game);
        apply_warp();
        if (loader_.then == Screen::Playing)
            enter_play();
        else
            screen_ = loader_.then;
    }
}

void GameApp::step_loader_for_frame() {
    // A screenshot run (tests' input scripts count frames) takes one step a frame, always the same frames.
    if (shell_.screenshot_mode()) return step_loader();
    // A player's: steps until a tenth of a second went on them, so the bar still moves but quick steps (a
    // model whose textures come from the disk cache) do not each wait for a loading screen's frame; before
    // the first loading screen, 0.4 s: a load that fits (a warm disk cache) shows none at all.
    const auto start = std::chrono::steady_clock::now();
    const auto budget = std::chrono::milliseconds(loader_.frames == 0 ? 400 : 100);
    do {
        step_loader();
    } while (screen_ == Screen::Loading && !loader_.done() && !freeze_loader_ &&
             std::chrono::steady_clock::now() - start < budget);
    if (screen_ == Screen::Loading) ++loader_.frames;
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
    campaign_.reset();
    // The menu shows the main level behind it; a finished or Dojo session is replaced by a fresh main one.
    if (!session_ || session_->dojo || session_->game->phase() != game::Phase::Playing ||
        session_->play_seconds > 0.0 || session_->file != level_path_)
        load(level_path_, false, Screen::Menu);
    else
        screen_ = Screen::Menu;
}

// The same level again (a campaign stays on it).
void GameApp::retry() {
    load(session_ ? session_->file : level_path_, session_ && session_->dojo, Screen::Playing);
}

// The options a slow machine needs, passed to the renderer (at start and whenever the panel changes them).
void GameApp::apply_render_options() {
    scale_control_.apply(renderer_, options_.render_scale);
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
    game::Input in = screen_ == Screen::Playing
                         ? input_.gather(events_.state(), options_, static_cast<float>(dt))
                         : game::Input{};
    if (!advance(in, static_cast<float>(dt))) return;
    if (g.phase() == game::Phase::Playing) session_->play_seconds += dt;
    if (g.phase() == game::Phase::Dead && g.death_camera().menu_ready && screen_ == Screen::Playing) {
        screen_ = Screen::Dead;
        input_.release(shell_.window(), events_.state());
    }
    if (g.phase() == game::Phase::Won && screen_ == Screen::Playing) {
        input_.release(shell_.window(), events_.state());
        level_won();
    }
}

bool GameApp::advance(const game::Input& in, float dt) {
    if (!logic_debug_.may_step()) return false; // halted by the logic debugger (a pause waits too)
    auto& g = *session_->game;
    session_->view->before_step(g);
    g.step(in);
    logic_debug_.after_step(g);
    session_->view->after_step(g, dt);
    session_->objective_flash.after_step(g, dt);
    if (session_->sounds) session_->sounds->after_step(g);
    return true;
}

// What moves with no input: the world (play, the death camera), the loader's steps, a script's frames, a
// recording's time. The menus and the pause screen wait for input.
bool GameApp::animating() const {
    return (screen_ == Screen::Loading && !freeze_loader_) || screen_ == Screen::Playing ||
           (screen_ == Screen::Dead && interactive()) || scripted_ || (audio_ && audio_->recording());
}

int GameApp::run() {
    shell::ShellHooks hooks;
    hooks.fixed_update = [this](double dt) { fixed_update(dt); };
    hooks.render = [this](const shell::FrameInfo& info) { render(info); };
    hooks.imgui = [this](const shell::FrameInfo& info) { imgui(info); };
    hooks.wants_close = [this]() { return quit_; };
    hooks.animating = [this]() { return animating(); };
    hooks.idle_poll = [this]() { return live_.has_value(); }; // paused: the editor's edits still arrive
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
