#include "model/dojo_graph.h"

#include "model/dojo_edit_support.h"
#include "model/dojo_keys.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace ks::editor {
namespace {

anim::TargetDef* target_in(anim::PhaseDef& phase, const std::string& node) {
    for (anim::TargetDef& t : phase.targets)
        if (t.node == node) return &t;
    return nullptr;
}

// The component the file stores for a keyed channel (absolute, or a relative offset); nullopt when the
// target does not set it.
std::optional<double> stored_component(const anim::TargetDef& target, CurveChannel channel) {
    const bool position = is_position(channel);
    const auto& absolute = position ? target.pos : target.rot;
    const auto& relative = position ? target.add_pos : target.add_rot;
    if (absolute) return (*absolute)[component(channel)];
    if (relative) return (*relative)[component(channel)];
    return std::nullopt;
}

double value_grid(CurveChannel channel) {
    return is_position(channel) ? kUnitFieldSteps : kDegreeFieldSteps;
}

std::string key_name(std::size_t phase) {
    return "key " + std::to_string(phase + 1);
}

// The clip's key times with the selected ones moved; refused when one passes an unselected key or 0.
Result<void> move_times(anim::AnimationFile& file, std::size_t clip, std::span<const std::size_t> phases,
                        const GraphTransform& how, const TimeUnits& units) {
    auto& def = file.clips[clip];
    std::vector<double> ends;
    double end = 0;
    for (const anim::PhaseDef& phase : def.phases) ends.push_back(end += phase.duration);
    std::vector<double> moved = ends;
    std::vector<bool> changed(ends.size(), false);
    for (const std::size_t p : phases) {
        const double t = how.pivot_time + (ends[p] - how.pivot_time) * how.time_scale + how.time_offset;
        if (!std::isfinite(t)) return Error("key time is not a number", {}, "seconds from the clip's start");
        moved[p] = units.snap(t);
        changed[p] = moved[p] != ends[p];
        if (moved[p] < 0)
            return Error(key_name(p) + " cannot move to " + units.text(moved[p]) +
                             ": that is before the clip's start",
                         {}, "move the keys later, or less far");
    }
    for (std::size_t p = 1; p < moved.size(); ++p) {
        // A scale squeezed so far that two keys meet cannot be undone by scaling back: refused.
        if (how.time_scale != 1.0 && moved[p] == moved[p - 1] && ends[p] != ends[p - 1])
            return Error(key_name(p - 1) + " and " + key_name(p) + " would meet at " + units.text(moved[p]),
                         {},
                         "scale the times less" + std::string(units.frames ? " (in frames, keys stay whole "
                                                                             "frames apart)"
                                                                           : ""));
        if (moved[p] < moved[p - 1]) {
            const bool later_moved = changed[p];
            const std::size_t mover = later_moved ? p : p - 1, other = later_moved ? p - 1 : p;
            return Error(key_name(mover) + " cannot move to " + units.text(moved[mover]) +
                             ": it would pass " + key_name(other) + " at " + units.text(moved[other]),
                         {}, "keys keep their order: select both to move them together");
        }
    }
    for (std::size_t p = 0; p < moved.size(); ++p) {
        if (!changed[p] && !(p + 1 < moved.size() && changed[p + 1])) continue;
        const double start = p == 0 ? 0.0 : moved[p - 1];
        // Whole frames (k / fps) in frames mode, else the microsecond grid, so the file reads as typed.
        const double duration = moved[p] - start;
        def.phases[p].duration =
            units.frames ? std::round(duration * units.fps) / units.fps : snap(duration, kTimeSteps);
        if (p + 1 < moved.size() && !changed[p + 1]) {
            const double next = moved[p + 1] - moved[p];
            def.phases[p + 1].duration =
                units.frames ? std::round(next * units.fps) / units.fps : snap(next, kTimeSteps);
        }
    }
    return ok();
}

// Sets one key's shown value: the target's stored component moves by the same amount (a relative offset
// too, set_key_value then keeping later keys in place); a key the node lacks is added where it is first.
Result<void> set_value(anim::AnimationFile& file, std::size_t clip, const GraphPoint& point, double value) {
    const GraphKey& key = point.key;
    if (!std::isfinite(value)) return Error("key value is not a number", {}, "a finite number");
    const double delta = value - point.value;
    if (std::abs(delta) < 1e-12) return ok();
    auto& phase = file.clips[clip].phases[key.phase];
    if (!target_in(phase, key.channel.node))
        if (auto added = add_node_key(file, clip, key.phase, key.channel.node); !added) return added.error();
    const anim::TargetDef* target = target_in(file.clips[clip].phases[key.phase], key.channel.node);
    const std::optional<double> stored = stored_component(*target, key.channel.channel);
    const double grid = value_grid(key.channel.channel);
    // Unkeyed for this kind: set_key_value makes an absolute key at the node's values; this one is `value`.
    const double wanted = stored ? snap(*stored + delta, grid) : snap(value, grid);
    if (auto set = set_key_value(file, clip, key.phase, key.channel.node, key.channel.channel, wanted); !set)
        return set;
    // A key made here: a later key relative to this one (a root node's) still reaches what it did.
    if (!point.keyed)
        keep_later_keys(file, clip, key.phase, key.channel.node, key.channel.channel,
                        (stored ? wanted - *stored : wanted - point.value));
    return ok();
}

} // namespace

std::vector<GraphPoint> graph_points(std::span<const NodeChannel> channels,
                                     std::span<const ClipCurve> curves) {
    std::vector<GraphPoint> points;
    for (std::size_t c = 0; c < channels.size() && c < curves.size(); ++c)
        for (const CurveKey& key : curves[c].keys)
            points.push_back({{channels[c], key.phase}, key.time, key.value, key.keyed});
    return points;
}

bool GraphSelection::contains(const GraphKey& key) const {
    return std::binary_search(keys_.begin(), keys_.end(), key);
}

void GraphSelection::insert(const GraphKey& key) {
    const auto at = std::lower_bound(keys_.begin(), keys_.end(), key);
    if (at == keys_.end() || *at != key) keys_.insert(at, key);
}

void GraphSelection::click(const GraphKey& key, bool add) {
    if (!add) {
        keys_ = {key};
        return;
    }
    const auto at = std::lower_bound(keys_.begin(), keys_.end(), key);
    if (at != keys_.end() && *at == key)
        keys_.erase(at);
    else
        keys_.insert(at, key);
}

void GraphSelection::box(std::span<const GraphPoint> points, double t0, double v0, double t1, double v1,
                         bool add) {
    if (!add) keys_.clear();
    const double tl = std::min(t0, t1), th = std::max(t0, t1), vl = std::min(v0, v1), vh = std::max(v0, v1);
    for (const GraphPoint& p : points)
        if (p.time >= tl && p.time <= th && p.value >= vl && p.value <= vh) insert(p.key);
}

void GraphSelection::all(std::span<const GraphPoint> points) {
    keys_.clear();
    for (const GraphPoint& p : points) insert(p.key);
}

void GraphSelection::keep_shown(std::span<const GraphPoint> points) {
    std::erase_if(keys_, [&](const GraphKey& key) {
        return std::none_of(points.begin(), points.end(), [&](const GraphPoint& p) { return p.key == key; });
    });
}

std::vector<std::size_t> GraphSelection::phases() const {
    std::vector<std::size_t> out;
    for (const GraphKey& key : keys_) out.push_back(key.phase);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

Result<void> transform_graph_keys(anim::AnimationFile& file, std::size_t clip, std::span<const GraphKey> keys,
                                  const GraphTransform& how, const TimeUnits& units) {
    auto found = dojo_support::clip_at(file, clip);
    if (!found) return found.error();
    if (keys.empty()) return Error("no keys selected", {}, "click a key, or drag a box around keys");
    // Where each key is now, from the file as it is (each channel's curve once).
    std::vector<NodeChannel> channels;
    for (const GraphKey& key : keys)
        if (std::find(channels.begin(), channels.end(), key.channel) == channels.end())
            channels.push_back(key.channel);
    auto curves = clip_curves(file, clip, channels, 2);
    if (!curves) return curves.error();
    const std::vector<GraphPoint> points = graph_points(channels, *curves);
    std::vector<GraphPoint> selected;
    std::vector<std::size_t> phases;
    for (const GraphKey& key : keys) {
        const auto point =
            std::find_if(points.begin(), points.end(), [&](const GraphPoint& p) { return p.key == key; });
        if (point == points.end())
            return Error("clip '" + (*found)->name + "' has no " + key_name(key.phase), {},
                         "it has " + std::to_string((*found)->phases.size()) + " keys");
        selected.push_back(*point);
        if (std::find(phases.begin(), phases.end(), key.phase) == phases.end()) phases.push_back(key.phase);
    }
    anim::AnimationFile edited = file;
    const bool times = how.time_offset != 0.0 || how.time_scale != 1.0;
    if (times)
        if (auto moved = move_times(edited, clip, phases, how, units); !moved) return moved.error();
    if (how.value_offset != 0.0 || how.value_scale != 1.0) {
        // In phase order, so a relative key's change taken back by a later one is counted before it.
        std::sort(selected.begin(), selected.end(),
                  [](const GraphPoint& a, const GraphPoint& b) { return a.key.phase < b.key.phase; });
        for (const GraphPoint& point : selected) {
            const double value =
                how.pivot_value + (point.value - how.pivot_value) * how.value_scale + how.value_offset;
            if (auto set = set_value(edited, clip, point, value); !set)
                return Error("cannot set " + point.key.channel.node + " " +
                                 curve_channel_name(point.key.channel.channel) + " at " +
                                 key_name(point.key.phase) + ": " + set.error().message,
                             {}, set.error().hint);
        }
    }
    if (auto valid = dojo_support::no_new_clip_issues(file, edited, clip); !valid) return valid.error();
    file = std::move(edited);
    return ok();
}

Result<void> set_graph_key(anim::AnimationFile& file, std::size_t clip, const GraphKey& key,
                           std::optional<double> seconds, std::optional<double> value,
                           const TimeUnits& units) {
    if (auto found = dojo_support::clip_at(file, clip); !found) return found.error();
    auto curves = clip_curves(file, clip, std::span(&key.channel, 1), 2);
    if (!curves) return curves.error();
    const auto& curve_keys = curves->front().keys;
    if (key.phase >= curve_keys.size())
        return Error("clip '" + file.clips[clip].name + "' has no " + key_name(key.phase), {},
                     "it has " + std::to_string(curve_keys.size()) + " keys");
    const CurveKey& now = curve_keys[key.phase];
    GraphTransform how;
    if (seconds) how.time_offset = *seconds - now.time;
    if (value) how.value_offset = *value - now.value;
    if (seconds && !std::isfinite(*seconds))
        return Error("key time is not a number", {}, "seconds from the clip's start");
    return transform_graph_keys(file, clip, std::span(&key, 1), how, units);
}

DragLock decide_drag_lock(float dx, float dy, bool free) {
    if (std::hypot(dx, dy) < kDragDecidePixels) return DragLock::Undecided;
    if (free) return DragLock::Both;
    return std::abs(dy) >= std::abs(dx) ? DragLock::ValueOnly : DragLock::TimeOnly;
}

std::optional<GraphRange> selection_bounds(std::span<const GraphPoint> points,
                                           std::span<const GraphKey> keys) {
    std::optional<GraphRange> box;
    for (const GraphPoint& p : points) {
        if (std::find(keys.begin(), keys.end(), p.key) == keys.end()) continue;
        if (!box) box = GraphRange{p.time, p.time, p.value, p.value};
        box->t0 = std::min(box->t0, p.time), box->t1 = std::max(box->t1, p.time);
        box->v0 = std::min(box->v0, p.value), box->v1 = std::max(box->v1, p.value);
    }
    return box;
}

GraphTransform scale_drag(const GraphRange& bounds, DragLock lock, float dx, float dy) {
    const auto factor = [](float pixels) {
        const double f =
            std::round(std::exp2(static_cast<double>(pixels) / kScaleDragPixels) * 100.0) / 100.0;
        return std::clamp(f, 0.01, 100.0);
    };
    GraphTransform how;
    how.pivot_time = (bounds.t0 + bounds.t1) * 0.5;
    how.pivot_value = (bounds.v0 + bounds.v1) * 0.5;
    if (lock == DragLock::TimeOnly || lock == DragLock::Both) how.time_scale = factor(dx);
    if (lock == DragLock::ValueOnly || lock == DragLock::Both)
        how.value_scale = factor(-dy); // screen y is down
    return how;
}

namespace {
GraphRange padded(double t0, double t1, double lo, double hi, double least) {
    if (hi - lo < least) lo -= (least - (hi - lo)) * 0.5, hi = lo + least;
    const double pad = (hi - lo) * 0.12, tpad = (t1 - t0) * 0.04;
    return {t0 - tpad, t1 + tpad, lo - pad, hi + pad};
}
} // namespace

GraphRange fit_graph(std::span<const ClipCurve> curves, double least_height) {
    double duration = 0, lo = 0, hi = 0;
    bool any = false;
    for (const ClipCurve& curve : curves) {
        duration = std::max(duration, curve.duration);
        for (const CurvePoint& point : curve.points) {
            lo = any ? std::min(lo, point.value) : point.value;
            hi = any ? std::max(hi, point.value) : point.value;
            any = true;
        }
    }
    return padded(0.0, std::max(duration, 0.01), lo, hi, least_height);
}

GraphRange frame_points(std::span<const GraphPoint> points, const GraphRange& all) {
    if (points.empty()) return all;
    double t0 = points[0].time, t1 = t0, lo = points[0].value, hi = lo;
    for (const GraphPoint& p : points)
        t0 = std::min(t0, p.time), t1 = std::max(t1, p.time), lo = std::min(lo, p.value),
        hi = std::max(hi, p.value);
    if (t1 - t0 < 0.1) t0 -= 0.05, t1 += 0.05;
    return padded(t0, t1, lo, hi, (all.v1 - all.v0) * 0.1);
}

} // namespace ks::editor
