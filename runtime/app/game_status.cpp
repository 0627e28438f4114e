// GameApp's --status-file: the screen, buttons, options and game state as text, rewritten when they change.
#include "game_app_internal.h"

#include "anim/rotation.h"
#include "core/files.h"
#include "core/log.h"

#include <algorithm>
#include <cstdio>

namespace ks::runtime {

void GameApp::write_status(const shell::FrameInfo& info) {
    if (status_path_.empty()) return;
    std::string s;
    char line[256];
    auto add = [&](const char* fmt, auto... args) {
        std::snprintf(line, sizeof(line), fmt, args...);
        s += line;
        s += '\n';
    };
    add("screen %s", std::string(status_name(screen_)).c_str());
    add("captured %d", input_.captured() ? 1 : 0);
    // The menu's error (a level or campaign that would not load): its first line, as the menu shows it.
    s += "error " + (error_.empty() ? std::string("-") : error_.substr(0, error_.find('\n'))) + "\n";
    add("options sensitivity %.2f fov %.0f invert_y %d render_scale %.2f quality %s",
        options_.mouse_sensitivity, options_.fov_degrees, options_.invert_y ? 1 : 0, options_.render_scale,
        quality_name(options_.quality));
    // What the renderer made of them (automatic values resolved for this GL driver).
    add("renderer render_scale %.2f quality %s dynamic %d", renderer_.render_scale(),
        renderer_.quality() == render::RenderQuality::Fast ? "fast" : "full",
        scale_control_.dynamic() ? 1 : 0);
    add("pad connected %d look %.2f dead_zone %.2f", shell_.gamepad().connected ? 1 : 0,
        options_.pad_look_sensitivity, options_.pad_dead_zone);
    add("controls waiting %s",
        controls_.waiting() ? action_info(static_cast<Action>(controls_.waiting_action)).id : "-");
    for (std::size_t a = 0; a < kActionCount; ++a)
        add("bind %s %s", kActionInfo[a].id, keys_text(options_.bindings, static_cast<Action>(a)).c_str());
    add("sound master %.2f effects %.2f ambience %.2f muted %d", options_.master_volume,
        options_.effects_volume, options_.ambience_volume, options_.muted ? 1 : 0);
    add("difficulty %s", game::difficulty_name(options_.difficulty));
    if (live_) // started from the editor: the live play-test's channel and the edits played
        add("live %s applied %d refused %d", live_->connected() ? "connected" : "waiting", live_->applied(),
            live_->refused());
    if (audio_) {
        const audio::AudioStats a = audio_->engine().stats();
        add("audio output %d voices %d cues %d", a.output ? 1 : 0, a.active_voices,
            session_ && session_->sounds ? session_->sounds->cues_played() : 0);
    }
    for (const auto& b : ui::buttons_drawn())
        add("button %.0f %.0f %.0f %.0f %s", b.x0, b.y0, b.x1, b.y1, b.label.c_str());
    for (const auto& b : ui::buttons_drawn())
        if (b.focused) add("focus %s", b.label.c_str());
    for (const auto& t : ui::texts_drawn())
        add("text %.0f %.0f %.0f %.0f %s", t.x0, t.y0, t.x1, t.y1, t.label.c_str());
    if (session_ && session_->game) {
        const auto& g = *session_->game;
        const auto& p = g.player();
        add("level %s", session_->dojo ? "dojo" : "play");
        add("phase %s", g.phase() == game::Phase::Playing ? "playing"
                        : g.phase() == game::Phase::Dead  ? "dead"
                                                          : "won");
        add("paused %d", g.paused() ? 1 : 0);
        add("feet %.3f %.3f %.3f", p.feet.x, p.feet.y, p.feet.z);
        add("yaw %.2f", degrees(p.yaw));
        add("pitch %.2f", degrees(p.pitch));
        add("health %.1f", p.health);
        add("shield %.1f", p.shield);
        add("ammo %d", p.ammo);
        add("shots %d", p.shots);
        add("hits %d", p.hits);
        int alive = 0;
        for (const auto& r : g.robots()) alive += r.alive() ? 1 : 0;
        add("robots %d alive %d killed %d", static_cast<int>(g.robots().size()), alive, g.robots_killed());
        for (const auto& d : g.doors()) add("door %d %.3f", d.entity_id, d.progress);
        for (const auto& l : g.lights())
            if (l.floor) add("light %d %s", l.entity_id, l.on ? "on" : "off");
        for (const auto& k : g.pickups()) add("pickup %d %s", k.entity_id, k.taken ? "taken" : "present");
        for (const auto& c : g.cylinders())
            add("cylinder %d %s", c.entity_id, c.exploded ? "exploded" : "standing");
        add("caption %s", g.caption().visible() ? g.caption().text().c_str() : "-");
        write_logic_status(s);
        if (session_->view) {
            add("camera_roll %.2f", degrees(session_->view->camera().roll));
            add("view baking %d", session_->view->baking() ? 1 : 0); // a live edit's light map on a worker
            // The last frame's draws and triangles (props at their levels of detail).
            add("view draws %d triangles %lld", stats_.draw_calls, stats_.triangles);
            const auto& fb = session_->view->feedback();
            add("feedback arcs %d shakes %d lights %d", static_cast<int>(fb.live_arcs()),
                static_cast<int>(fb.live_shakes()), static_cast<int>(fb.live_lights()));
        }
        if (const auto* dojo = session_->dojo_controller ? &*session_->dojo_controller : nullptr) {
            // How far the test robot is from its rest pose: the largest node rotation away from rest.
            anim::Pose rest;
            rest.set_rest(g.animations().rig);
            float moved = 0.0f;
            for (int n = 0; n < rest.size() && n < dojo->pose().size(); ++n) {
                const auto i = static_cast<std::size_t>(n);
                moved = std::max(moved, anim::angle_between(dojo->pose().rotation[i], rest.rotation[i]));
            }
            const int playing = dojo->playing_entry();
            add("dojo clips %d playing %s picking %d moved %.1f", static_cast<int>(dojo->entries().size()),
                playing < 0 ? "-" : dojo->entries()[static_cast<std::size_t>(playing)].clip.c_str(),
                dojo_picking_ ? 1 : 0, degrees(moved));
        }
        add("game_steps %lld", static_cast<long long>(g.steps()));
    }
    write_campaign_status(s);
    add("dropped_steps %lld", budget_.dropped());
    if (s == status_last_) return;
    status_last_ = s;
    // The frame goes last and does not count as a change: the file changes when the state does.
    add("frame %lld", info.frame_index);
    if (auto written = files::write_atomic(status_path_, s); !written) {
        log::warn(written.error().str(), " (--status-file: no more status written)");
        status_path_.clear();
    }
}

// What the HUD shows of the level logic: each objective's state, the message line and the banner.
void GameApp::write_logic_status(std::string& s) const {
    const game::Game& g = *session_->game;
    const int current = g.logic().current_objective();
    int index = 0;
    for (const game::ObjectiveState& o : g.logic().objectives()) {
        s += "objective " + std::to_string(index) + " " +
             (o.completed        ? "done"
              : index == current ? "current"
                                 : "open") +
             " " + o.id + " " + o.text + "\n";
        ++index;
    }
    const game::ShownMessage& message = g.logic().message();
    s += "message " + (message.visible() ? std::string(message.text) : std::string("-")) + "\n";
    const ObjectiveFlash& flash = session_->objective_flash;
    s += "objective_flash " + (flash.visible() ? flash.text() : std::string("-")) + "\n";
    s += "level_file " + session_->file.string() + "\n";
    s += "level_name " + session_->level.name + "\n";
}

// The campaign in play (its level, the results so far) and the custom level list while it is open.
void GameApp::write_campaign_status(std::string& s) const {
    auto result_line = [&s](const char* key, const LevelResult& r) {
        char numbers[96];
        std::snprintf(numbers, sizeof(numbers), " %.2f %d %d %d %d ", r.seconds, r.robots_killed,
                      r.robots_total, r.shots, r.hits);
        s += key + std::string(numbers) + r.title + "\n";
    };
    if (campaign_) {
        s += "campaign " + std::to_string(campaign_->index() + 1) + " " + std::to_string(campaign_->count()) +
             " " + campaign_->current().file + " " + campaign_->current().title + "\n";
        for (const LevelResult& r : campaign_->results()) result_line("campaign_result", r);
        if (campaign_->finished()) result_line("campaign_total", campaign_->totals());
    } else {
        s += "campaign -\n";
    }
    if (campaign_save_)
        s += "campaign_save " + std::to_string(campaign_save_->won.size()) + " " +
             std::to_string(campaign_save_->level_count) + " " + campaign_save_->campaign.string() + "\n";
    else
        s += "campaign_save -\n";
    if (screen_ == Screen::Won) result_line("win_result", win_);
    if (screen_ != Screen::CustomLevels) return;
    for (std::size_t group = 0; group < custom_levels_.size(); ++group)
        for (const level::LevelFileEntry& e : custom_levels_[group].folder.levels)
            s += "custom_level " + std::to_string(group) + " " + (e.ok() ? "ok " : "error ") +
                 e.file.filename().string() + " " + e.name + "\n";
}

} // namespace ks::runtime
