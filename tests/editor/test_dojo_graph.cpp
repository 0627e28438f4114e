// The dojo's graph editor without a window: several channels' keys at once, selection (click, Shift, box,
// all), moving and scaling the selected keys (key times snapped to frames in frames mode, other keys
// untouched), numeric entry, the drag's axis lock, tangent handles of the format's custom eases and what
// they do to the evaluated curve, each edit one undo step.
#include "dojo_test_util.h"
#include "model/dojo_clips.h"
#include "model/dojo_graph.h"
#include "model/dojo_graph_ease.h"

#include <algorithm>
#include <cmath>

using namespace ks;
using namespace ks::editor;
using ks::dojo_test::nod_file;
using ks::dojo_test::text;

namespace {
const NodeChannel kGraphChestZ{"chest", CurveChannel::RotZ}, kGraphChestX{"chest", CurveChannel::RotX},
    kGraphHeadY{"head", CurveChannel::RotY};

std::vector<GraphPoint> graph_points_of(const anim::AnimationFile& file,
                                        const std::vector<NodeChannel>& channels) {
    auto curves = clip_curves(file, 0, channels, 11);
    REQUIRE_MESSAGE(curves.ok(), (curves.ok() ? std::string() : curves.error().str()));
    return graph_points(channels, *curves);
}

double graph_value_at(const anim::AnimationFile& file, const NodeChannel& c, double t) {
    auto v = curve_value(file, 0, c.node, c.channel, t);
    REQUIRE(v.ok());
    return *v;
}

double graph_key_time(const anim::AnimationFile& file, std::size_t phase) {
    double t = 0;
    for (std::size_t p = 0; p <= phase; ++p) t += file.clips[0].phases[p].duration;
    return t;
}
} // namespace

TEST_CASE("graph: several channels' keys at once; click, Shift+click, box and select all") {
    const auto file = nod_file();
    const auto pts = graph_points_of(file, {kGraphChestZ, kGraphChestX, kGraphHeadY});
    REQUIRE(pts.size() == 6); // two keys on each channel
    CHECK(pts[0].value == doctest::Approx(30.0));
    CHECK(pts[0].keyed);
    CHECK(pts[5].value == doctest::Approx(90.0)); // head's relative 90 degrees from rest
    GraphSelection sel;
    sel.click(pts[0].key, false);
    sel.click(pts[1].key, true); // Shift adds
    CHECK(sel.keys().size() == 2);
    sel.click(pts[0].key, true); // and toggles out
    CHECK(sel.keys() == std::vector<GraphKey>{pts[1].key});
    sel.click(pts[4].key, false); // a plain click selects it alone
    CHECK(sel.keys() == std::vector<GraphKey>{pts[4].key});
    // A box over the late keys between 5 and 95 degrees: chest z at 1 s (10) and head y at 1 s (90).
    sel.box(pts, 1.1, 95.0, 0.7, 5.0, false);
    CHECK(sel.keys().size() == 2);
    CHECK(sel.contains({kGraphChestZ, 1}));
    CHECK(sel.contains({kGraphHeadY, 1}));
    CHECK(sel.phases() == std::vector<std::size_t>{1});
    sel.box(pts, 0.3, 25.0, 0.5, 35.0, true); // Shift+box adds chest z's first key
    CHECK(sel.keys().size() == 3);
    sel.all(pts);
    CHECK(sel.keys().size() == 6);
    sel.keep_shown(graph_points_of(file, {kGraphChestZ})); // other channels hidden
    CHECK(sel.keys().size() == 2);
}

TEST_CASE("graph: a drag mostly vertical moves values only, mostly horizontal times only, Ctrl both") {
    CHECK(decide_drag_lock(1, 2, false) == DragLock::Undecided);
    CHECK(decide_drag_lock(1, -40, false) == DragLock::ValueOnly);
    CHECK(decide_drag_lock(3, -6, false) == DragLock::ValueOnly);
    CHECK(decide_drag_lock(30, 8, false) == DragLock::TimeOnly);
    CHECK(decide_drag_lock(30, 8, true) == DragLock::Both);
    // A value-only move leaves every key time exactly where it was (the issue: 0.75 became 0.748).
    auto file = nod_file();
    const std::vector<GraphKey> keys{{kGraphChestZ, 0}};
    GraphTransform up;
    up.value_offset = 12.5;
    REQUIRE(transform_graph_keys(file, 0, keys, up, {}));
    CHECK(file.clips[0].phases[0].duration == 0.4);
    CHECK(file.clips[0].phases[1].duration == 0.6);
    CHECK(file.clips[0].phases[0].targets[0].rot->z == 42.5);
    CHECK(file.clips[0].phases[1].targets[0].rot->z == 10.0); // the next key did not move
}

TEST_CASE("graph: moving selected keys moves their times and values together; passing a key is refused") {
    auto file = nod_file();
    const std::vector<GraphKey> keys{{kGraphChestZ, 0}, {kGraphChestX, 0}};
    GraphTransform how;
    how.time_offset = 0.1;
    how.value_offset = -5.0;
    REQUIRE(transform_graph_keys(file, 0, keys, how, {}));
    CHECK(graph_key_time(file, 0) == doctest::Approx(0.5));
    CHECK(graph_key_time(file, 1) == doctest::Approx(1.0)); // the next key stays at 1 s
    CHECK(file.clips[0].phases[1].duration == 0.5);
    CHECK(file.clips[0].phases[0].targets[0].rot->z == 25.0);
    CHECK(file.clips[0].phases[0].targets[0].rot->x == -5.0);
    CHECK(graph_value_at(file, kGraphHeadY, 1.0) == doctest::Approx(90.0)); // head's key untouched
    // Past key 2 (at 1 s) without it: refused, unchanged.
    const std::string before = text(file);
    how.time_offset = 0.6;
    how.value_offset = 0;
    auto refused = transform_graph_keys(file, 0, keys, how, {});
    REQUIRE_FALSE(refused);
    CHECK(refused.error().message.find("would pass key 2") != std::string::npos);
    CHECK(text(file) == before);
    // A hollow key (head is not keyed at key 1) moved up gets a key there; only head's y changes.
    GraphTransform up;
    up.value_offset = 20;
    REQUIRE(transform_graph_keys(file, 0, std::vector<GraphKey>{{kGraphHeadY, 0}}, up, {}));
    CHECK(graph_value_at(file, kGraphHeadY, 0.5) == doctest::Approx(20.0));
    CHECK(graph_value_at(file, kGraphChestZ, 0.5) == doctest::Approx(25.0));
    CHECK(graph_value_at(file, kGraphHeadY, 1.0) ==
          doctest::Approx(90.0)); // the later relative key still reaches 90
}

TEST_CASE("graph: scaling around a pivot, with times snapped to whole frames in frames mode") {
    auto file = nod_file();
    const std::vector<GraphKey> keys{{kGraphChestZ, 0}, {kGraphChestZ, 1}};
    GraphTransform how;
    how.pivot_time = 0;
    how.pivot_value = 10;
    how.time_scale = 1.5;
    how.value_scale = 2;
    const TimeUnits frames{true, 24.0};
    REQUIRE(transform_graph_keys(file, 0, keys, how, frames));
    // 0.4 * 1.5 = 0.6 s = 14.4 frames -> 14 frames; 1.5 s = 36 frames.
    CHECK(graph_key_time(file, 0) == 14.0 / 24.0);
    CHECK(graph_key_time(file, 1) == doctest::Approx(36.0 / 24.0));
    CHECK(std::abs(graph_key_time(file, 1) * 24.0 - 36.0) < 1e-9);
    CHECK(file.clips[0].phases[0].targets[0].rot->z == 50.0); // 10 + (30 - 10) * 2
    CHECK(file.clips[0].phases[1].targets[0].rot->z == 10.0); // at the pivot
    // A negative time scale would reverse the keys: refused.
    how.time_scale = -1;
    CHECK_FALSE(transform_graph_keys(file, 0, keys, how, frames));
    // The clip's frame rate: 14/24 and 36/24 s fit 24 fps, not 30; nod's 0.4, 1 and 0.9 s fit 30.
    file.clips[0].events.clear();
    CHECK(clip_frame_rate(file.clips[0]) == 24.0);
    CHECK(clip_frame_rate(nod_file().clips[0]) == 30.0);
    CHECK(frames.text(0.5) == "12 f");
    CHECK(TimeUnits{}.text(0.25) == "0.25 s");
    CHECK(parse_time_text("15 f", TimeUnits{}) == doctest::Approx(0.5));
    CHECK(parse_time_text("12", frames) == 0.5);
    CHECK_FALSE(parse_time_text("x1", frames));
}

TEST_CASE("graph: numeric entry sets a key's time and value exactly; several keys take offsets; undo") {
    auto file = nod_file();
    DojoHistory history;
    REQUIRE(apply_dojo_edit(file, history, "set key", [&] {
        return set_graph_key(file, 0, {kGraphChestZ, 0}, 0.25, -12.5, {});
    }));
    CHECK(graph_key_time(file, 0) == 0.25);
    CHECK(file.clips[0].phases[1].duration == 0.75); // key 2 stays at 1 s
    CHECK(file.clips[0].phases[0].targets[0].rot->z == -12.5);
    CHECK(graph_value_at(file, kGraphChestZ, 0.25) == doctest::Approx(-12.5));
    REQUIRE(apply_dojo_edit(file, history, "offset keys", [&] {
        GraphTransform how;
        how.value_offset = 2;
        return transform_graph_keys(file, 0, std::vector<GraphKey>{{kGraphChestZ, 0}, {kGraphChestZ, 1}}, how,
                                    {});
    }));
    CHECK(file.clips[0].phases[0].targets[0].rot->z == -10.5);
    CHECK(file.clips[0].phases[1].targets[0].rot->z == 12.0);
    CHECK(history.undo_count() == 2);
    REQUIRE(history.undo(file));
    REQUIRE(history.undo(file));
    CHECK(text(file) == text(nod_file()));
    CHECK_FALSE(set_graph_key(file, 0, {kGraphChestZ, 5}, 0.1, std::nullopt, {}));
    CHECK_FALSE(set_graph_key(file, 0, {kGraphChestZ, 0}, std::nullopt, NAN, {}));
    CHECK(text(file) == text(nod_file()));
}

TEST_CASE("graph: tangent handles shape the format's custom eases, and the curve follows") {
    auto file = nod_file();
    // Key 1 of chest z: 0 -> 30 over 0.4 s, Linear. A Bezier preset, then its first handle dragged up.
    const auto& presets = ease_presets();
    const auto bezier = std::find_if(presets.begin(), presets.end(),
                                     [](const EasePreset& p) { return p.label == "Bezier: ease in-out"; });
    REQUIRE(bezier != presets.end());
    REQUIRE(set_segment_ease(file, 0, 0, "chest", bezier->ease));
    const auto handles = ease_handles(file.clips[0].phases[0].targets[0].ease.value());
    REQUIRE(handles.size() == 2);
    CHECK(handles[0].u == doctest::Approx(0.42));
    CHECK(handles[1].y == doctest::Approx(1.0));
    const double eased = graph_value_at(file, kGraphChestZ, 0.1);
    CHECK(eased < 30.0 * 0.25); // ease-in-out starts slower than linear
    const auto dragged = drag_ease_handle(*file.clips[0].phases[0].targets[0].ease, 0, 1.4, 0.9);
    REQUIRE(dragged);
    CHECK(dragged->params[0] == 1.0f); // x kept inside the segment
    CHECK(dragged->params[1] == 0.9f);
    REQUIRE(set_segment_ease(file, 0, 0, "chest", *dragged));
    CHECK(graph_value_at(file, kGraphChestZ, 0.2) == doctest::Approx(30.0 * (*dragged)(0.5)).epsilon(1e-4));
    CHECK(graph_value_at(file, kGraphChestZ, 0.4) == doctest::Approx(30.0)); // the key itself stays
    // A power curve's handle: dragging it to progress 0.125 at u = 0.5 makes the exponent 3.
    const auto power = drag_ease_handle(anim::Ease::power(2.0f, anim::EaseMode::In), 0, 0.5, 0.125);
    REQUIRE(power);
    CHECK(power->params[0] == 3.0f);
    CHECK(ease_handles(*power)[0].y == doctest::Approx(0.125));
    const auto out = drag_ease_handle(anim::Ease::power(2.0f, anim::EaseMode::InOut), 0, 0.25, 0.0625);
    REQUIRE(out);
    CHECK(out->params[0] == 3.0f);
    CHECK_FALSE(drag_ease_handle(anim::Ease::linear(), 0, 0.5, 0.5));
    // The head had no key at key 1: its easing keys it where it is (no pose changes), one node only.
    REQUIRE(set_segment_ease(file, 0, 0, "head", anim::Ease::power(2.0f, anim::EaseMode::Out)));
    CHECK(graph_value_at(file, kGraphHeadY, 1.0) == doctest::Approx(90.0));
    // An invalid curve is refused with validate_ease's reason.
    auto bad = set_segment_ease(file, 0, 0, "chest", anim::Ease::bezier(1.5f, 0, 0.5f, 1));
    REQUIRE_FALSE(bad);
    CHECK(bad.error().message.find("x1 and x2") != std::string::npos);
}

TEST_CASE("graph: fit all and frame selected") {
    const auto file = nod_file();
    auto curves = clip_curves(file, 0, std::vector<NodeChannel>{kGraphChestZ, kGraphHeadY}, 11);
    REQUIRE(curves);
    const GraphRange all = fit_graph(*curves, 20.0);
    CHECK(all.t0 < 0.0);
    CHECK(all.t1 > 1.0);
    CHECK(all.v0 < 0.0);
    CHECK(all.v1 > 90.0);
    const auto pts = graph_points_of(file, {kGraphChestZ});
    const GraphRange framed = frame_points(pts, all);
    CHECK(framed.v1 < all.v1);
    CHECK(framed.v0 < 10.0);
    CHECK(framed.v1 > 30.0);
}
