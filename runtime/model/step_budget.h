#pragma once
// How many fixed steps one frame may run. The shell's clock asks for every step the frame time covers; after
// a hitch (a level loading, a window drag) or below a few frames per second that is a burst of steps with no
// input between them, and when steps are slow, a spiral (each frame slower than the last, so it asks for
// more steps still). The budget runs at most `max_steps` per frame and drops the rest: below
// 1 / (max_steps · step) frames per second the game runs in slow motion instead.
namespace ks::runtime {

class StepBudget {
  public:
    explicit StepBudget(int max_steps) : max_(max_steps < 1 ? 1 : max_steps) {}
    // Call once per frame, before (or after) that frame's steps.
    void new_frame() { used_ = 0; }
    // True when one more step may run this frame; false counts a dropped step.
    bool take();
    int max_steps() const { return max_; }
    long long dropped() const { return dropped_; }

  private:
    int max_;
    int used_ = 0;
    long long dropped_ = 0;
};

} // namespace ks::runtime
