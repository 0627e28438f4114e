#pragma once
// The GameApp class behind run_game_app (game_app.h): the screens' state machine, the loaded session and
// the automation hooks. Shared by game_app.cpp (the state machine), game_app_frame.cpp (one frame: keys,
// scene, HUD, menus), game_app_start.cpp (the automation's first screen), game_app_campaign.cpp (the
// campaign and the custom level list), game_app_names.cpp (option
// names), game_script.cpp (--input-script), game_status.cpp (--status-file) and run_game_app.cpp (the
// command line); not for other code.
#include "game_app.h"

#include "anim/dojo.h"
#include "app_audio.h"
#include "campaign_screens.h"
#include "controls_screen.h"
#include "core/files.h"
#include "core/log.h"
#include "core/paths.h"
#include "dojo_legend.h"
#include "game/game.h"
#include "hud_feedback.h"
#include "input_events.h"
#include "level/level_io.h"
#include "logic_debug_overlay.h"
#include "logic_hud.h"
#include "menu_style.h"
#include "player_input.h"
#include "render/scene_renderer.h"
#include "render_scale_control.h"
#include "runtime/model/campaign_progress.h"
#include "runtime/model/campaign_save.h"
#include "runtime/model/input_script.h"
#include "runtime/model/live_edits.h"
#include "runtime/model/options.h"
#include "runtime/model/screen_table.h"
#include "runtime/model/step_budget.h"
#include "screens.h"
#include "shell/hud.h"
#include "soundscape/soundscape.h"
#include "world_view.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <future>
#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <optional>
#include <sstream>

namespace ks::runtime {

// At most this many fixed steps per frame (0.25 s of game time; runtime/model/step_budget.h says why): 4
// frames per second still play in real time, slower machines in slow motion.
constexpr int kMaxStepsPerFrame = 30;

// One loaded level with its game and view. The Dojo's controller borrows the game's clips, so it goes first.
struct Session {
    std::filesystem::path file; // the level file (Retry loads it again)
    level::Level level;
    // The robots' navigation mesh, built on a worker from the moment the level is read while the models load
    // (declared after `level`, which it reads: destroyed first, so it waits for the worker).
    std::future<Result<std::unique_ptr<nav::NavMesh>>> navigation;
    bool dojo = false;
    std::unique_ptr<game::Game> game;
    std::unique_ptr<WorldView> view;
    std::unique_ptr<soundscape::Soundscape> sounds; // null when the app has no audio engine
    std::optional<anim::DojoController> dojo_controller;
    DojoDummy dummy;
    ObjectiveFlash objective_flash;
    double play_seconds = 0.0;
    ~Session() { dojo_controller.reset(); }
};

// Loading in steps, one per frame, so the progress bar moves while assets load.
struct Loader {
    struct Step {
        std::string label;
        std::function<Result<void>()> run;
    };
    std::vector<Step> steps;
    std::size_t next = 0;
    Screen then = Screen::Menu;
    Screen on_failure = Screen::Menu; // where a file that fails to load sends the player (with the error)
    int frames = 0; // loading screens drawn (a player's start: GameApp::step_loader_for_frame)
    float fraction() const { return steps.empty() ? 1.0f : static_cast<float>(next) / steps.size(); }
    bool done() const { return next >= steps.size(); }
    std::string label() const { return done() ? "Ready" : steps[next].label; }
};

class GameApp {
  public:
    GameApp(shell::AppShell& shell, render::SceneRenderer& renderer, render::AssetLibrary& assets,
            std::filesystem::path level_path, std::uint64_t seed)
        : shell_(shell), renderer_(renderer), assets_(assets), level_path_(std::move(level_path)),
          seed_(seed) {
        options_ = load_options(options_path());
        campaign_save_ = load_campaign_save(campaign_save_path());
        std::error_code ec;
        save_unreadable_ = !campaign_save_ && std::filesystem::exists(campaign_save_path(), ec);
        apply_render_options();
        logic_debug_visible_ = options_.logic_debugger;
        events_.install(shell_.window());
        start_live();
    }

    // Command-line automation: the screen to show and the scenario to set up (tests and screenshots).
    struct Automation {
        std::optional<Screen> screen; // --screen (runtime/model/screen_table.h)
        bool dojo = false;            // --dojo, or --screen dojo
        std::optional<std::array<float, 5>> warp;
        char dojo_key = 0;
        double dojo_time = -1.0;
        bool fire = false; // one shot on the first step (to see the muzzle flash, impacts, explosions)
        std::filesystem::path status_file; // rewritten each frame with the screen and the game's state
        std::vector<ScriptEvent> script;   // --input-script
        bool scripted = false;
        std::filesystem::path audio_out; // --audio-out: record the mix to this WAV instead of playing it
        std::filesystem::path campaign;  // --campaign: start this campaign (else levels/campaign.json)
        bool start_campaign = false;     // --campaign given: play it from its first level at once
        std::filesystem::path
            logic_trace; // --logic-trace: the logic trace of each level played ("-": stdout)
        std::optional<LogicBreak> logic_break; // --logic-break: the debugger shown, halting at this event
        // --difficulty: played instead of the options' choice (the Options screen shows it; it is written to
        // the file only when the player changes the options there).
        std::optional<game::Difficulty> difficulty;
        // --target-fps: the frame rate Auto's dynamic resolution holds (default 60); it also turns the
        // dynamic resolution on in a screenshot run, whose pictures otherwise keep a fixed scale.
        std::optional<double> target_fps;
    };
    Result<void> start(const Automation& a);
    Result<void> set_up_scenario(const Automation& a, std::optional<Screen> screen);
    int run();

  private:
    void load(const std::filesystem::path& path, bool dojo, Screen then, Screen on_failure = Screen::Menu);
    Result<void> finish_loading_now();
    void step_loader();
    void step_loader_for_frame(); // the loading steps of one frame (render())
    // KS_STARTUP_TRACE (core/startup_trace.h): "frame: SCREEN" the first time each screen is drawn.
    void mark_first_frame_of_screen();
    void fixed_update(double dt);
    bool animating() const; // the shell draws frame after frame while true
    // One game step with its view and sounds (every caller: play, warp, pause, the automation); false when
    // the logic debugger holds the game.
    bool advance(const game::Input& in, float dt);
    void update_audio(const shell::FrameInfo& info);
    void render(const shell::FrameInfo& info);
    void imgui(const shell::FrameInfo& info);
    void draw_world_overlay(float w, float h);
    MenuAction draw_screen(float w, float h);
    void apply_menu_action(MenuAction action);
    void handle_keys();
    // The Controls screen waiting for a key: the next key or button goes to it (true: this frame's keys are
    // spent).
    bool handle_rebind_keys();
    void go_back();
    void enter_play();
    void toggle_dojo_picking();
    void pause();
    void resume();
    void to_menu();
    void retry();
    // The campaign and the custom level list (game_app_campaign.cpp).
    // Campaign: the choice screen when a run is saved, else a new run of campaign_path_.
    void open_campaign();
    // A new run of campaign_path_ (its save replaced), or the saved run at its next level.
    Result<void> start_campaign(bool resume = false);
    void write_save();
    void level_won();
    void next_level();
    void open_custom_levels();
    void play_custom(const level::LevelFileEntry& entry);
    LevelResult result_now() const;
    // The automation's way to win: stand at a control panel, face it, press E (--screen win, summary).
    Result<void> win_at_panel();
    void open_sub(Screen s) {
        return_to_ = screen_;
        screen_ = s;
    }
    void save_options_now();
    void apply_render_options();
    bool in_world() const { return screen_ == Screen::Playing; }
    void apply_warp();
    void run_script(long long frame);
    void write_status(const shell::FrameInfo& info);
    // F3 and the debugger's keys while playing; the mouse freed while it is halted (logic_debug_overlay.h).
    void handle_logic_debug_keys();
    // The live play-test (game_app_live.cpp): the editor's edits, their toast, Back to editor.
    void start_live();
    void poll_live();
    void draw_live_toast(float w);
    void back_to_editor();
    void write_logic_status(std::string& s) const;
    void write_campaign_status(std::string& s) const;
    // Real input drives the app: not a screenshot run, or a screenshot run driven by --input-script.
    bool interactive() const { return !shell_.screenshot_mode() || scripted_; }

    shell::AppShell& shell_;
    render::SceneRenderer& renderer_;
    render::AssetLibrary& assets_;
    std::filesystem::path level_path_;
    std::uint64_t seed_;
    Options options_;
    bool options_dirty_ = false;
    ControlsState controls_;
    std::unique_ptr<AppAudio> audio_; // before the sessions: their Soundscapes play through it
    InputEvents events_;
    PlayerInput input_;
    StepBudget budget_{kMaxStepsPerFrame};
    std::optional<std::array<float, 5>> pending_warp_; // interactive --warp: applied when the level loads
    std::filesystem::path status_path_;
    std::string status_last_;
    std::vector<ScriptEvent> script_;
    std::size_t script_next_ = 0;
    bool scripted_ = false;
    bool click_next_frame_ = false;
    unsigned pad_release_next_ = 0; // --input-script: pad buttons tapped last frame (bit per button)
    int exit_code_ = 0;
    Screen screen_ = Screen::Loading, return_to_ = Screen::Menu;
    std::unique_ptr<Session> session_, pending_;
    Loader loader_;
    bool freeze_loader_ = false, freeze_dojo_ = false;
    std::uint64_t traced_screens_ = 0; // bit per Screen already marked in the start-up trace
    bool dojo_picking_ = false;        // the Dojo's mouse is free to click a clip in the list (Tab)
    std::string error_;
    bool quit_ = false;
    bool pause_requested_ = false;
    render::FrameStats stats_;
    RenderScaleControl scale_control_; // the options' render scale, or Auto's dynamic resolution
    LevelResult win_;                  // the level just won (the win screen; the campaign keeps its own)
    std::filesystem::path campaign_path_;
    std::optional<CampaignProgress> campaign_;  // while a campaign is played
    std::optional<CampaignSave> campaign_save_; // the saved run (campaign_save.h), if it read
    bool save_unreadable_ = false; // a save exists but did not read: kept aside before a new one is written
    std::vector<LevelGroup> custom_levels_;               // the custom level list, scanned when it opens
    const level::LevelFileEntry* picked_level_ = nullptr; // in custom_levels_: the one clicked this frame
    LogicDebugOverlay logic_debug_;
    bool logic_debug_visible_ = false;     // options_.logic_debugger, or --logic-break
    bool logic_debug_freed_mouse_ = false; // the halted debugger released the mouse (taken back on resume)
    std::optional<LiveEdits> live_;        // started from the editor, live (game_app_live.cpp)
    live::LiveNote live_toast_;
    double live_toast_until_ = 0.0;
    std::vector<render::MeshInstance> no_instances_;
    std::vector<render::Light> no_lights_;
};

} // namespace ks::runtime
