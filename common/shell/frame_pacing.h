#pragma once
// When the frame loop draws. While the app animates (play, a running job, a playing clip, a held key or
// button) it draws every frame, at most `max_fps` a second; otherwise it waits for events and draws only
// after input (and a few frames more, so ImGui shows what a click opened), when the app asks for a frame,
// or on a heartbeat (test modes that count frames). Plain time arithmetic: AppShell::run feeds it GLFW's
// clock and events; tests feed it numbers.
namespace ks::shell {

struct PacingSettings {
    double max_fps = 60.0;          // the cap while animating
    double idle_poll_seconds = 0.5; // while waiting: how often the app's cheap checks run (files, children)
    double heartbeat_seconds = 0.0; // > 0: a frame at least this often even when nothing changes
    int settle_frames = 4;          // frames drawn after an event (ImGui shows some changes a frame later)
};

class FramePacer {
  public:
    explicit FramePacer(PacingSettings settings);

    // An event arrived (input, expose, resize, focus): draw it and `settle_frames` more.
    void on_event() { settle_left_ = settings_.settle_frames + 1; }
    // The app has something new to show: one frame.
    void request_frame() { settle_left_ = settle_left_ > 1 ? settle_left_ : 1; }
    // Whether a frame is due at `now` (the cap aside: see cap_wait).
    bool frame_due(bool animating, double now) const;
    // While animating: seconds to sleep so that frames stay `1 / max_fps` apart (0: draw now).
    double cap_wait(double now) const;
    // While not drawing: how long to wait for events before looking again (the idle poll, the heartbeat).
    double wait_seconds(double now) const;
    // Whether the app's idle poll is due (and then marks it done).
    bool take_idle_poll(double now);
    // A frame was drawn (it started at `now`).
    void drew(double now);
    double frame_interval() const { return 1.0 / settings_.max_fps; }

  private:
    PacingSettings settings_;
    int settle_left_ = 0;
    double last_frame_ = -1e9;
    double last_poll_ = 0.0;
};

} // namespace ks::shell
