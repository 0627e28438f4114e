#pragma once
// The graph editor's tangent handles: a segment's easing (the curve from one key to the next for one node)
// shaped by dragging. The format's custom curves are the handles: a cubic Bezier's two control points
// (CSS cubic-bezier(x1, y1, x2, y2): x in segment time, y in segment progress, so a handle above the end
// value overshoots) and a power curve's one point on the curve (dragging it up or down changes the
// exponent). Named Tween.js curves have no handles; the presets menu turns any segment into a named or custom
// curve. An easing belongs to a node's key (its target), so it shapes every channel of that node in that
// segment; setting one keys the node there first if it was not (at the value it has: no pose changes).
#include "anim/clip.h"
#include "core/result.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace ks::editor {

// A handle in segment units: u the fraction of the segment's time, y the progress (0 at the segment's start
// value, 1 at its end value).
struct EaseHandle {
    double u = 0, y = 0;
};

// The handles of `ease`: two for a Bezier (its control points), one for a power curve (on the curve at
// u = 0.5, or 0.25 for InOut, where the exponent shows), none for a named curve.
std::vector<EaseHandle> ease_handles(const anim::Ease& ease);
// `ease` with handle `handle` dragged to (u, y): a Bezier's control point (x kept in [0, 1], y in [-2, 3],
// both to a thousandth); a power curve's exponent through that point's height (u stays; in [0.05, 64], to a
// hundredth). nullopt for a named curve or a handle it lacks.
std::optional<anim::Ease> drag_ease_handle(const anim::Ease& ease, std::size_t handle, double u, double y);

// The segment ending at key `phase` for `node` gets `ease` (its target's easing; a key is added where the
// node is when it has none there). Refused, file unchanged, for an invalid custom curve (the reason is
// validate_ease's), a clip, key or node out of range.
Result<void> set_segment_ease(anim::AnimationFile& file, std::size_t clip, std::size_t phase,
                              const std::string& node, const anim::Ease& ease);

// The presets menu: named curves an animator reaches for and custom ones with handles to shape.
struct EasePreset {
    std::string label;
    anim::Ease ease;
};
const std::vector<EasePreset>& ease_presets();

} // namespace ks::editor
