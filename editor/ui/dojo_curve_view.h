#pragma once
// The dojo's curve view: one node's channel (rotation x/y/z in degrees, position x/y/z as the offset from
// rest) over the shown clip's time, each eased segment drawn in its own shade with its easing named, and the
// keys (the phase ends) as handles. Dragging a handle moves the key in time (model: move_key_time) and in
// value (set_key_value; a node with no key in that phase is keyed first), the whole drag one undo step.
#include "model/dojo_curves.h"
#include "ui/dojo_context.h"

#include <cstdint>
#include <string>
#include <vector>

namespace ks::editor::ui {

class DojoCurveView {
  public:
    void begin_frame() { handles_.clear(); }
    void draw(const DojoContext& dojo);
    // The node (index into the file's rig; -1: the first the clip keys) and channel shown (--dojo-view).
    void show(int node, CurveChannel channel) { node_ = node, channel_ = channel; }
    void show_channel(CurveChannel channel) { channel_ = channel; }
    // Status: the key handles as last drawn.
    const std::vector<Vec2>& handles() const { return handles_; }

  private:
    void picker(const DojoContext& dojo);
    bool refresh(const DojoContext& dojo, int samples);
    void fit_axes();
    void drag(const DojoContext& dojo, std::size_t key, double seconds, double value, bool shift);

    int node_ = -1; // index into the file's rig
    CurveChannel channel_ = CurveChannel::RotX;
    ClipCurve curve_; // sampled, cached until the stamp changes
    std::string error_;
    struct Stamp {
        std::uint64_t revision = ~0ull;
        int clip = -1, node = -1, samples = 0;
        CurveChannel channel = CurveChannel::RotX;
        bool operator==(const Stamp&) const = default;
    } stamp_;
    struct Drag {
        bool active = false;
        std::size_t key = 0;
        double time = 0, value = 0, target = 0; // the key at the drag's start
        bool keyed = false;
        anim::AnimationFile origin;            // the file at the drag's start: each frame edits from it
        double t0 = 0, t1 = 1, v0 = 0, v1 = 1; // the axes, frozen while dragging
    } drag_;
    std::vector<Vec2> handles_;
};

} // namespace ks::editor::ui
