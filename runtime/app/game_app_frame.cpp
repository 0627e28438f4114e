// One frame of the game app: the keys it handles itself (Esc, M, the Dojo's), the scene, the HUD over the
// world and the current screen's menu, and what each menu choice does.
#include "game_app_internal.h"

#include "core/startup_trace.h"

#include <cstdio>

namespace ks::runtime {

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

bool GameApp::handle_rebind_keys() {
    InputState& keys = events_.state();
    if (screen_ != Screen::Controls || !controls_.waiting()) return false;
    GamepadInput& pad = input_.pad();
    if (keys.take_press(GLFW_KEY_ESCAPE) || pad.take_press(shell::kPadB)) {
        controls_.cancel(); // Esc or B cancels the rebind, it does not leave the screen
        return true;
    }
    if (finish_rebind(options_, controls_, keys.take_any_press())) {
        options_dirty_ = true;
        save_options_now();
    }
    return true;
}

// Esc or the pad's B on a sub-screen: the screen it was opened from (Controls goes back to Options).
void GameApp::go_back() {
    save_options_now();
    controls_.cancel();
    screen_ = screen_ == Screen::Controls ? Screen::Options : return_to_;
}

void GameApp::handle_keys() {
    GLFWwindow* w = shell_.window();
    InputState& keys = events_.state();
    GamepadInput& pad = input_.pad();
    pad.poll(shell_.gamepad());
    if (handle_rebind_keys()) return;
    const bool esc_pressed = keys.take_press(GLFW_KEY_ESCAPE);
    const bool pause_pressed = action_pressed(keys, options_.bindings, Action::Pause);
    const bool start_pressed = pad.take_press(shell::kPadStart), b_pressed = pad.take_press(shell::kPadB);
    if (!interactive()) return;
    if (action_pressed(keys, options_.bindings, Action::Mute)) { // mute from anywhere, remembered
        options_.muted = !options_.muted;
        options_dirty_ = true;
        save_options_now();
        if (audio_) audio_->apply_options(options_);
    }
    // Losing the focus pauses (the mouse is no longer ours); a script's input does not depend on it.
    const bool focus_lost = !scripted_ && !glfwGetWindowAttrib(w, GLFW_FOCUSED);
    if (screen_ == Screen::Playing && (esc_pressed || pause_pressed || start_pressed || focus_lost)) {
        pause();
        return;
    }
    if (screen_ == Screen::Paused && (esc_pressed || pause_pressed || start_pressed || b_pressed)) {
        resume();
    } else if (esc_pressed || b_pressed) {
        if (screen_ == Screen::HowTo || screen_ == Screen::Credits || screen_ == Screen::Options ||
            screen_ == Screen::Controls)
            go_back();
        else if (screen_ == Screen::CustomLevels || screen_ == Screen::CampaignChoice)
            screen_ = return_to_;
    }
    handle_logic_debug_keys();
    if (screen_ == Screen::Playing && session_ && session_->dojo_controller) {
        for (int k = 0; k <= 9; ++k)
            if (keys.take_press(GLFW_KEY_0 + k)) session_->dojo_controller->press(static_cast<char>('0' + k));
        if (keys.take_press(GLFW_KEY_TAB)) toggle_dojo_picking();
    }
}

void GameApp::handle_logic_debug_keys() {
    if (screen_ != Screen::Playing || !session_ || session_->dojo) return;
    if (logic_debug_.handle_keys(events_.state(), logic_debug_visible_)) {
        options_.logic_debugger = logic_debug_visible_;
        options_dirty_ = true;
        save_options_now();
    }
    const bool free_mouse = logic_debug_.wants_mouse(logic_debug_visible_);
    if (free_mouse && input_.captured()) {
        input_.release(shell_.window(), events_.state());
        logic_debug_freed_mouse_ = true;
    } else if (!free_mouse && std::exchange(logic_debug_freed_mouse_, false)) {
        enter_play();
    }
}

void GameApp::mark_first_frame_of_screen() {
    if (!startup::enabled()) return;
    const std::uint64_t bit = std::uint64_t{1} << static_cast<unsigned>(screen_);
    if (traced_screens_ & bit) return;
    traced_screens_ |= bit;
    startup::mark("frame: " + std::string(status_name(screen_)));
}

void GameApp::render(const shell::FrameInfo& info) {
    if (scripted_) run_script(info.frame_index);
    step_loader_for_frame();
    mark_first_frame_of_screen();
    handle_keys();
    budget_.new_frame(); // the next frame's fixed steps come after this call
    scale_control_.frame(renderer_, info.previous_work, info.frame_dt);
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
    poll_live();
    ui::begin_frame();
    // While a rebind waits (and until the mouse button it bound is let go) ImGui must not see the keys and
    // clicks: they are the binding, not menu input.
    if (controls_.hold_mouse && !events_.state().any_button_held()) controls_.hold_mouse = false;
    const bool menu_input_off = controls_.waiting() || controls_.hold_mouse;
    if (input_.captured() || menu_input_off)
        io.ConfigFlags |= ImGuiConfigFlags_NoMouse;
    else
        io.ConfigFlags &= ~ImGuiConfigFlags_NoMouse;
    // Menus are played with the keyboard (arrows, Enter or Space, Esc) and the pad (d-pad or left stick, A,
    // B) too; not while playing, where those keys are the game's.
    constexpr ImGuiConfigFlags kNav = ImGuiConfigFlags_NavEnableKeyboard | ImGuiConfigFlags_NavEnableGamepad;
    if (input_.captured() || menu_input_off || screen_ == Screen::Playing)
        io.ConfigFlags &= ~kNav;
    else
        io.ConfigFlags |= kNav;
    draw_world_overlay(w, h);
    draw_live_toast(w);
    apply_menu_action(draw_screen(w, h));
    if (audio_ && screen_ != Screen::Playing) audio_->menu_sounds(ui::buttons_drawn());
    write_status(info);
    if (!shell_.screenshot_mode() && screen_ == Screen::Playing) {
        char text[128];
        // The 3D scene's share of the window's pixels each way: the dynamic resolution's pick under Auto.
        std::snprintf(text, sizeof(text), "%.1f ms  %d draws  %.0f %%", info.frame_dt * 1000.0,
                      stats_.draw_calls, renderer_.render_scale() * 100.0f);
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
            if (!session_->dojo) draw_logic_hud(fg, *session_->game, session_->objective_flash, fonts, w, h);
            if (logic_debug_visible_ && !session_->dojo)
                logic_debug_.draw(fg, *session_->game, session_->view->camera(), fonts, w, h);
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
        action = how_to_play(options_, fonts, w, h);
        break;
    case Screen::Credits:
        action = credits(fonts, w, h);
        break;
    case Screen::Options: {
        bool changed = false;
        action = options_panel(options_, changed, fonts, w, h);
        options_dirty_ |= changed;
        if (changed) logic_debug_visible_ = options_.logic_debugger;
        if (changed) apply_render_options();
        if (changed && audio_) audio_->apply_options(options_);
        break;
    }
    case Screen::Paused:
        action = pause_menu(fonts, w, h, live_.has_value());
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
    case Screen::Summary:
        if (campaign_) action = summary_screen(*campaign_, fonts, w, h);
        break;
    case Screen::CampaignComplete:
        if (campaign_) action = campaign_complete_screen(*campaign_, fonts, w, h);
        break;
    case Screen::Controls: {
        bool changed = false;
        const bool was_waiting = controls_.waiting();
        action = controls_screen(options_, controls_, changed, fonts, w, h);
        // The click (or Space, Enter) that asked for a key must not be taken as the key.
        if (!was_waiting && controls_.waiting()) events_.state().clear_latches();
        options_dirty_ |= changed;
        break;
    }
    case Screen::CampaignChoice:
        if (campaign_save_) action = campaign_choice_screen(*campaign_save_, fonts, w, h);
        break;
    case Screen::CustomLevels:
        action = custom_levels_screen(custom_levels_, picked_level_, fonts, w, h);
        break;
    case Screen::Playing:
        break;
    }
    return action;
}

void GameApp::apply_menu_action(MenuAction action) {
    switch (action) {
    case MenuAction::Play:
        if (session_ && !session_->dojo && session_->play_seconds == 0.0 && session_->file == level_path_ &&
            session_->game->phase() == game::Phase::Playing)
            enter_play();
        else
            load(level_path_, false, Screen::Playing);
        break;
    case MenuAction::Campaign:
        open_campaign();
        break;
    case MenuAction::Continue:
    case MenuAction::NewCampaign:
        if (auto started = start_campaign(action == MenuAction::Continue); !started) {
            error_ = "Could not start the campaign: " + started.error().str();
            screen_ = Screen::Menu;
        }
        break;
    case MenuAction::CustomLevels:
        open_custom_levels();
        break;
    case MenuAction::PlayCustom:
        if (picked_level_) play_custom(*picked_level_);
        break;
    case MenuAction::NextLevel:
        next_level();
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
    case MenuAction::Controls:
        controls_.cancel();
        screen_ = Screen::Controls; // from Options: Back comes back to it
        break;
    case MenuAction::Back:
        go_back();
        break;
    case MenuAction::Quit:
        quit_ = true;
        break;
    case MenuAction::BackToEditor:
        back_to_editor();
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

} // namespace ks::runtime
