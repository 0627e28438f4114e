#pragma once
// The game's screens as immediate-mode functions: each draws itself centred in the window and returns what
// the player chose this frame. The app's state machine (game_app.cpp) decides what each choice does.
#include "runtime/model/campaign_progress.h"
#include "runtime/model/options.h"
#include "shell/app_shell.h"

#include <string>

namespace ks::runtime {

enum class MenuAction {
    None,
    Play,
    Campaign,
    CustomLevels,
    PlayCustom, // a level picked in the custom level list
    NextLevel,
    Dojo,
    HowTo,
    Credits,
    Options,
    Controls, // Options > Controls (key bindings, gamepad)
    Continue, // Campaign > Continue: the saved campaign at its next level
    NewCampaign,
    Quit,
    Resume,
    MainMenu,
    Retry,
    Back,
    BackToEditor // the pause menu of a game the editor started live
};

void loading_screen(float fraction, const std::string& step, const shell::Fonts& fonts, float w, float h);
MenuAction main_menu(const std::string& error, const shell::Fonts& fonts, float w, float h);
MenuAction pause_menu(const shell::Fonts& fonts, float w, float h, bool back_to_editor = false);
MenuAction death_menu(const shell::Fonts& fonts, float w, float h);
// A single level won (Play, a custom level): its time, robots and accuracy, Play Again or Main Menu.
MenuAction win_menu(const LevelResult& result, const shell::Fonts& fonts, float w, float h);
// The goal and the controls: the player's current key bindings and the gamepad's layout.
MenuAction how_to_play(const Options& options, const shell::Fonts& fonts, float w, float h);
MenuAction credits(const shell::Fonts& fonts, float w, float h);
// Edits `options` in place; `changed` is set when a value moved this frame.
MenuAction options_panel(Options& options, bool& changed, const shell::Fonts& fonts, float w, float h);

} // namespace ks::runtime
