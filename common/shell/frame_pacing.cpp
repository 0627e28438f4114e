#include "shell/frame_pacing.h"

#include <algorithm>

namespace ks::shell {

FramePacer::FramePacer(PacingSettings settings) : settings_(settings) {
    if (!(settings_.max_fps >= 1.0)) settings_.max_fps = 60.0;
    if (!(settings_.idle_poll_seconds > 0.0)) settings_.idle_poll_seconds = 0.5;
    settings_.settle_frames = std::max(0, settings_.settle_frames);
    on_event(); // the first frames: the window's first picture, and ImGui's windows sized
}

bool FramePacer::frame_due(bool animating, double now) const {
    if (animating || settle_left_ > 0) return true;
    return settings_.heartbeat_seconds > 0.0 && now - last_frame_ >= settings_.heartbeat_seconds;
}

double FramePacer::cap_wait(double now) const {
    return std::max(0.0, last_frame_ + frame_interval() - now);
}

double FramePacer::wait_seconds(double now) const {
    double wait = std::max(0.0, last_poll_ + settings_.idle_poll_seconds - now);
    if (settings_.heartbeat_seconds > 0.0)
        wait = std::min(wait, std::max(0.0, last_frame_ + settings_.heartbeat_seconds - now));
    return wait;
}

bool FramePacer::take_idle_poll(double now) {
    if (now - last_poll_ < settings_.idle_poll_seconds) return false;
    last_poll_ = now;
    return true;
}

void FramePacer::drew(double now) {
    last_frame_ = now;
    if (settle_left_ > 0) --settle_left_;
}

} // namespace ks::shell
