#pragma once
// The dojo's graph editor (the Curves page): several channels of the shown clip at once, each node's
// rotation and position axes toggled in a channel list (x red, y green, z blue; positions lighter and
// dashed), with fit (F), zoom (wheel; Shift: values only, Ctrl: time only) and pan (middle or right drag).
// Keys are selected by click, Shift+click, a box dragged on empty space, or A (all); dragging selected keys
// moves them, along the direction the drag starts in (Ctrl: both), the whole drag one undo step; Alt+drag
// anywhere on the graph scales them about their centre (right/left: times, up/down: values, Ctrl: both),
// their box and pivot drawn while Alt is held. The toolbar
// has numeric entry (a key's time and value; offsets and scale around the selection's centre for several),
// seconds or frames, and the selected key's easing: presets, and tangent handles drawn on the segment for
// the format's custom curves (Bezier control points, a power curve's point). The model is
// editor/model/dojo_graph.h and dojo_graph_ease.h; this class keeps the view (channels shown, range,
// selection, the drag in progress).
#include "model/dojo_graph.h"
#include "model/dojo_graph_ease.h"
#include "ui/dojo_context.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

struct ImDrawList;

namespace ks::editor::ui {

class DojoCurveView {
  public:
    void begin_frame() { handles_.clear(); }
    void draw(const DojoContext& dojo);
    // Shows only `channel` of rig node `node` (--dojo-view node=...,channel=...).
    void show(int node, CurveChannel channel);
    void show_channel(CurveChannel channel) { solo_channel_ = channel; }
    // Selects key `phase` once the clip's channels are shown, on the channel that changes most into it
    // (--dojo-view key=N).
    void select_key(std::size_t phase) { pending_key_ = phase; }
    // Status: the shown keys' handles as last drawn (channel by channel, key by key).
    const std::vector<Vec2>& handles() const { return handles_; }
    const GraphSelection& selection() const { return selection_; }

  private:
    // The plot's rectangle on screen and the range it shows.
    struct Plot {
        Vec2 lo, hi;
        GraphRange range;
        float x(double t) const;
        float y(double v) const;
        double time_at(float sx) const;
        double value_at(float sy) const;
    };
    void channel_list(const DojoContext& dojo, float height);
    void toolbar(const DojoContext& dojo);
    void frame_rate(const DojoContext& dojo);
    void key_fields(const DojoContext& dojo);
    void ease_menu(const DojoContext& dojo);
    bool refresh(const DojoContext& dojo, int samples);
    void plot(const DojoContext& dojo, Vec2 origin, Vec2 size);
    void mouse(const DojoContext& dojo, const Plot& plot);
    void press(const DojoContext& dojo, const Plot& plot, Vec2 mouse);
    void drag_keys(const DojoContext& dojo, const Plot& plot, Vec2 mouse);
    void drag_handle(const DojoContext& dojo, const Plot& plot, Vec2 mouse);
    void drag_scale(const DojoContext& dojo, Vec2 mouse);
    void draw_scale_box(ImDrawList* draw, const Plot& plot) const;
    void draw_handles(ImDrawList* draw, const Plot& plot);
    void zoom_and_pan(const Plot& plot);
    void edit(const DojoContext& dojo, const std::string& name, const GraphTransform& how);
    // The segment the tangent handles shape: the one ending at the single selected key (its node's).
    bool handle_segment(double& t0, double& v0, double& t1, double& v1, anim::Ease& ease) const;
    const GraphPoint* point(const GraphKey& key) const;

    std::vector<NodeChannel> channels_; // shown, in rig order
    int solo_node_ = -1;                // show(): only this node's solo_channel_
    CurveChannel solo_channel_ = CurveChannel::RotX;
    int chosen_for_ = -1;           // the clip the shown channels were picked for
    std::optional<bool> show_list_; // the animator's choice, else shown when the page is 560 px wide or more
    std::vector<ClipCurve> curves_; // channels_' curves, cached until the stamp changes
    std::vector<GraphPoint> points_;
    std::string error_;
    struct Stamp {
        std::uint64_t revision = ~0ull;
        int clip = -1, samples = 0;
        std::vector<NodeChannel> channels;
        bool operator==(const Stamp&) const = default;
    } stamp_;
    GraphRange range_;
    bool fit_pending_ = true;
    GraphSelection selection_;
    std::optional<std::size_t> pending_key_;

    enum class Gesture : std::uint8_t { None, Keys, Box, Handle, Pan, Scale };
    struct Drag {
        Gesture gesture = Gesture::None;
        Vec2 start{0};
        DragLock lock = DragLock::Undecided;
        std::size_t handle = 0;
        GraphKey pressed;           // the key the drag began on
        anim::AnimationFile origin; // the file when the drag began: each frame edits from it
        GraphRange range;           // the view when the drag began
        GraphRange bounds;          // Scale: the selected keys' box when it began (its centre: the pivot)
        std::string label;          // Scale: the factors now ("time x1.5  value x1")
    } drag_;
    // Numeric fields' text (typed, applied on Enter).
    char time_text_[32] = "", value_text_[32] = "", time_scale_[16] = "1", value_scale_[16] = "1";
    std::vector<GraphKey> fields_for_;      // the selection the fields show
    std::uint64_t fields_revision_ = ~0ull; // and the file's revision then
    std::vector<Vec2> handles_;
};

} // namespace ks::editor::ui
