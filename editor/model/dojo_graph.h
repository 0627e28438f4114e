#pragma once
// The dojo's graph editor, free of any window: several channels (node x rotation/position axis) of one clip
// at once, their keys as points, a selection of keys (click, add/toggle, box, all), and the edits made on a
// selection: move (time and value offsets), scale around a pivot, and numeric entry, each one change of the
// file (wrap it in DojoEdits::apply or a drag for one undo step). Keys are independent: an edit sets only the
// selected keys' values (a key's time is its phase's end, shared by every node: moving it moves that key time
// on every channel, never another key time). Times snap to the frame grid in frames mode (dojo_frames.h).
#include "model/dojo_curves.h"
#include "model/dojo_frames.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace ks::editor {

// One key of one channel: the end of phase `phase` on that channel.
struct GraphKey {
    NodeChannel channel;
    std::size_t phase = 0;
    bool operator==(const GraphKey&) const = default;
    auto operator<=>(const GraphKey&) const = default;
};

// A key as the graph draws it: where it is (seconds; degrees or the offset from rest) and whether the node's
// target sets the channel there (hollow keys are phase ends the node is not keyed at: moving one keys it).
struct GraphPoint {
    GraphKey key;
    double time = 0, value = 0;
    bool keyed = false;
};

// Every key of `curves` (clip_curves of `channels`, same order).
std::vector<GraphPoint> graph_points(std::span<const NodeChannel> channels,
                                     std::span<const ClipCurve> curves);

// The keys selected in the graph, in order, each once.
class GraphSelection {
  public:
    const std::vector<GraphKey>& keys() const { return keys_; }
    bool empty() const { return keys_.empty(); }
    bool contains(const GraphKey& key) const;
    void clear() { keys_.clear(); }
    // A click on a key: it alone is selected; with `add` (Shift) it is toggled in or out.
    void click(const GraphKey& key, bool add);
    // Every point inside the box (corners in either order); with `add` they join the selection.
    void box(std::span<const GraphPoint> points, double t0, double v0, double t1, double v1, bool add);
    void all(std::span<const GraphPoint> points);
    // Forgets keys no longer shown (a channel hidden, a key removed).
    void keep_shown(std::span<const GraphPoint> points);
    // The selected keys' phases, each once, in order.
    std::vector<std::size_t> phases() const;

  private:
    void insert(const GraphKey& key);
    std::vector<GraphKey> keys_; // sorted
};

// How selected keys move: t' = pivot_time + (t - pivot_time) * time_scale + time_offset, and the same for
// values (degrees, or units of the offset from rest).
struct GraphTransform {
    double time_offset = 0, value_offset = 0;
    double pivot_time = 0, pivot_value = 0;
    double time_scale = 1, value_scale = 1;
};

// Applies `how` to `keys` of clip `clip`: each distinct key time moves once (snapped by `units`: a whole
// frame, or a microsecond), each key's value is set (a key the node lacks is added first, at the value it
// has, so only the moved channel changes). Values land on the key table's grids (1e-3 degree, 1e-5 unit).
// Refused, file unchanged, when a key time would pass an unselected one or go below 0, a scale would put two
// keys of different times on one time, a value is not finite, or the clip would get an issue it did not
// have (an event outside it, a zero-length loop).
Result<void> transform_graph_keys(anim::AnimationFile& file, std::size_t clip, std::span<const GraphKey> keys,
                                  const GraphTransform& how, const TimeUnits& units);

// Numeric entry for one key: its time and/or value set (nullopt keeps it).
Result<void> set_graph_key(anim::AnimationFile& file, std::size_t clip, const GraphKey& key,
                           std::optional<double> seconds, std::optional<double> value,
                           const TimeUnits& units);

// Which way a key drag moves, decided once the mouse has moved kDragDecidePixels from where it was pressed:
// mostly vertical moves values only (the key times stay exactly where they were), mostly horizontal moves
// times only; `free` (Ctrl held) moves both.
enum class DragLock : std::uint8_t { Undecided, Both, TimeOnly, ValueOnly };
inline constexpr float kDragDecidePixels = 5.0f;
DragLock decide_drag_lock(float dx_pixels, float dy_pixels, bool free);

// A view of the graph: the time and value ranges shown.
struct GraphRange {
    double t0 = 0, t1 = 1, v0 = -1, v1 = 1;
};

// The box around the selected keys among `points` (times and values); nullopt when none of them is shown.
std::optional<GraphRange> selection_bounds(std::span<const GraphPoint> points,
                                           std::span<const GraphKey> keys);

// Drag-to-scale (Alt+drag in the graph): the selected keys scaled about their pivot, the centre of their
// box `bounds`, by 2^(travel / kScaleDragPixels) along the drag's lock: right stretches times, left
// squeezes them (TimeOnly), up spreads values, down flattens them (ValueOnly), both with Both. Factors are
// rounded to hundredths (readable in the undo name) and kept in [0.01, 100]. Give the result to
// transform_graph_keys from the file as it was when the drag began: one undo step, unselected keys stay,
// times on the frame grid in frames mode, and a squeeze that would merge two keys is refused.
inline constexpr float kScaleDragPixels = 100.0f;
GraphTransform scale_drag(const GraphRange& bounds, DragLock lock, float dx_pixels, float dy_pixels);
// Everything: the clip's time and every curve's values with a margin, at least `least_height` high (20
// degrees, 0.2 units: a flat curve is not blown up).
GraphRange fit_graph(std::span<const ClipCurve> curves, double least_height);
// Around the selected points only (fit_graph's rules; the whole graph when none).
GraphRange frame_points(std::span<const GraphPoint> points, const GraphRange& all);

} // namespace ks::editor
