// The graph editor's drag-to-scale (Alt+drag, model/dojo_graph.h scale_drag) and the clip's stored frame
// rate (model/dojo_frames.h): the factor the mouse's travel gives along the drag's direction, the pivot at
// the selection's centre, key times kept on the frame grid, unselected keys never moved, a squeeze that
// merges keys refused, the whole drag one undo step; frames mode saved with the clip, its times exact.
#include "dojo_test_util.h"
#include "model/dojo_edits.h"
#include "model/dojo_frames.h"
#include "model/dojo_graph.h"

#include <cmath>
#include <string>
#include <vector>

using namespace ks;
using namespace ks::editor;
using ks::dojo_test::nod_file;
using ks::dojo_test::text;

namespace {
const NodeChannel kScaleChestZ{"chest", CurveChannel::RotZ}, kScaleHeadY{"head", CurveChannel::RotY};

// nod with four keys, each 6 frames at 24 fps (0.25 s), stored in frames: chest z 30, 10, -20, 0; head y
// relative 90 at key 2 (as nod). Key times 6, 12, 18 and 24 f.
anim::AnimationFile wave_file() {
    anim::AnimationFile f = nod_file();
    auto& clip = f.clips[0];
    clip.events.clear();
    clip.phases[0].duration = 0.25;
    clip.phases[1].duration = 0.25;
    anim::PhaseDef down{0.25, anim::Ease::linear(), {}};
    anim::TargetDef chest;
    chest.node = "chest";
    chest.rot = DVec3(0, 0, -20);
    down.targets.push_back(chest);
    anim::PhaseDef home = down;
    home.targets[0].rot = DVec3(0, 0, 0);
    clip.phases.push_back(down);
    clip.phases.push_back(home);
    clip.frame_rate = 24;
    REQUIRE(anim::validate(f).empty());
    return f;
}

double key_seconds(const anim::AnimationFile& file, std::size_t phase) {
    double t = 0;
    for (std::size_t p = 0; p <= phase; ++p) t += file.clips[0].phases[p].duration;
    return t;
}

double key_frames(const anim::AnimationFile& file, std::size_t phase) {
    return key_seconds(file, phase) * *file.clips[0].frame_rate;
}

std::vector<GraphPoint> scale_points(const anim::AnimationFile& file,
                                     const std::vector<NodeChannel>& channels) {
    auto curves = clip_curves(file, 0, channels, 9);
    REQUIRE_MESSAGE(curves.ok(), (curves.ok() ? std::string() : curves.error().str()));
    return graph_points(channels, *curves);
}

double chest_z(const anim::AnimationFile& file, double seconds) {
    auto v = curve_value(file, 0, "chest", CurveChannel::RotZ, seconds);
    REQUIRE(v.ok());
    return *v;
}
} // namespace

TEST_CASE("graph scale drag: the factor follows the travel along the drag's direction, about the centre") {
    const GraphRange box{0.5, 0.75, 10.0, 30.0};
    const GraphTransform right = scale_drag(box, DragLock::TimeOnly, 100.0f, 7.0f);
    CHECK(right.time_scale == 2.0);
    CHECK(right.value_scale == 1.0); // the vertical wobble of a horizontal drag does nothing
    CHECK(right.pivot_time == 0.625);
    CHECK(right.pivot_value == 20.0);
    CHECK(scale_drag(box, DragLock::TimeOnly, -100.0f, 0.0f).time_scale == 0.5);
    CHECK(scale_drag(box, DragLock::TimeOnly, 58.5f, 0.0f).time_scale == 1.5);     // rounded to hundredths
    const GraphTransform up = scale_drag(box, DragLock::ValueOnly, 3.0f, -100.0f); // screen y grows down
    CHECK(up.value_scale == 2.0);
    CHECK(up.time_scale == 1.0);
    CHECK(scale_drag(box, DragLock::ValueOnly, 0.0f, 100.0f).value_scale == 0.5);
    const GraphTransform both = scale_drag(box, DragLock::Both, 100.0f, 100.0f);
    CHECK(both.time_scale == 2.0);
    CHECK(both.value_scale == 0.5);
    CHECK(scale_drag(box, DragLock::TimeOnly, -5000.0f, 0.0f).time_scale == 0.01);
    CHECK(scale_drag(box, DragLock::TimeOnly, 5000.0f, 0.0f).time_scale == 100.0);
    const GraphTransform none = scale_drag(box, DragLock::Undecided, 100.0f, 100.0f);
    CHECK(none.time_scale == 1.0);
    CHECK(none.value_scale == 1.0);
    // The box of the selected keys only.
    const auto file = wave_file();
    const auto points = scale_points(file, {kScaleChestZ, kScaleHeadY});
    const std::vector<GraphKey> keys{{kScaleChestZ, 1}, {kScaleChestZ, 2}};
    const auto bounds = selection_bounds(points, keys);
    REQUIRE(bounds);
    CHECK(bounds->t0 == 0.5);
    CHECK(bounds->t1 == 0.75);
    CHECK(bounds->v0 == doctest::Approx(-20.0));
    CHECK(bounds->v1 == doctest::Approx(10.0));
    CHECK_FALSE(selection_bounds(points, std::vector<GraphKey>{{kScaleChestZ, 9}}));
}

TEST_CASE("graph scale drag: times on whole frames, unselected keys unmoved, one undo step, merges refused") {
    DojoPlayback playback;
    DojoEdits edits{playback, [](const std::string&, bool) {}};
    const anim::AnimationFile origin = wave_file();
    auto rig = anim::build_rig(origin);
    REQUIRE(rig.ok());
    playback.set_rig(*rig);
    edits.reset(origin);
    const TimeUnits units = clip_time_units(origin.clips[0]);
    REQUIRE(units.frames);
    REQUIRE(units.fps == 24.0);
    const std::vector<GraphKey> keys{{kScaleChestZ, 1}, {kScaleChestZ, 2}}; // 12 f (10) and 18 f (-20)
    const auto bounds = selection_bounds(scale_points(origin, {kScaleChestZ}), keys);
    REQUIRE(bounds);
    // The drag's frames, each from the file as it was when it began (as the graph does), then released.
    for (const float dx : {20.0f, 60.0f, 100.0f}) {
        anim::AnimationFile edited = origin;
        REQUIRE(transform_graph_keys(edited, 0, keys, scale_drag(*bounds, DragLock::TimeOnly, dx, 0), units));
        edits.record_drag(origin, "scale 2 keys");
        edits.replace(std::move(edited));
    }
    edits.end_drag();
    CHECK(edits.history().undo_count() == 1);
    const anim::AnimationFile& scaled = edits.file();
    // x2 about 15 f: 12 -> 9 f, 18 -> 21 f; keys 1 and 4 stay at 6 and 24 f.
    CHECK(key_frames(scaled, 0) == 6.0);
    CHECK(key_frames(scaled, 1) == 9.0);
    CHECK(key_frames(scaled, 2) == 21.0);
    CHECK(key_frames(scaled, 3) == 24.0);
    for (const anim::PhaseDef& phase : scaled.clips[0].phases) // every duration a whole number of frames
        CHECK(phase.duration * 24.0 == std::round(phase.duration * 24.0));
    // Values untouched by a time scale; the unselected keys' values and head's relative key reach the same.
    CHECK(chest_z(scaled, 0.25) == doctest::Approx(30.0));
    CHECK(chest_z(scaled, 9.0 / 24.0) == doctest::Approx(10.0));
    CHECK(chest_z(scaled, 21.0 / 24.0) == doctest::Approx(-20.0));
    CHECK(chest_z(scaled, 1.0) == doctest::Approx(0.0));
    auto head = curve_value(scaled, 0, "head", CurveChannel::RotY, 9.0 / 24.0);
    REQUIRE(head.ok());
    CHECK(*head == doctest::Approx(90.0));
    REQUIRE(edits.undo());
    CHECK(text(edits.file()) == text(origin));

    // Values: up 100 px doubles the spread about the centre (-5): 10 -> 25, -20 -> -35; times stay exact.
    anim::AnimationFile values = origin;
    REQUIRE(
        transform_graph_keys(values, 0, keys, scale_drag(*bounds, DragLock::ValueOnly, 0, -100.0f), units));
    CHECK(values.clips[0].phases[1].targets[0].rot->z == 25.0);
    CHECK(values.clips[0].phases[2].targets[0].rot->z == -35.0);
    CHECK(values.clips[0].phases[0].targets[0].rot->z == 30.0); // unselected
    CHECK(values.clips[0].phases[3].targets[0].rot->z == 0.0);
    for (std::size_t p = 0; p < 4; ++p)
        CHECK(values.clips[0].phases[p].duration == origin.clips[0].phases[p].duration);

    // Squeezed until the two keys would share a frame: refused, the file as it was.
    anim::AnimationFile squeezed = origin;
    auto merged =
        transform_graph_keys(squeezed, 0, keys, scale_drag(*bounds, DragLock::TimeOnly, -700.0f, 0), units);
    REQUIRE_FALSE(merged);
    CHECK(merged.error().message == "key 2 and key 3 would meet at 15 f");
    CHECK(text(squeezed) == text(origin));
    // Stretched past an unselected key: refused too (keys keep their order).
    auto passed =
        transform_graph_keys(squeezed, 0, keys, scale_drag(*bounds, DragLock::TimeOnly, 200.0f, 0), units);
    REQUIRE_FALSE(passed);
    CHECK(passed.error().message.find("would pass key") != std::string::npos);
}

TEST_CASE("a clip's stored frame rate: frames mode saved with it, its times exact, refused rates") {
    anim::AnimationFile file = nod_file();
    CHECK_FALSE(clip_time_units(file.clips[0]).frames); // an old file without a rate: seconds
    CHECK(clip_time_units(file.clips[0]).fps == 30.0);  // its guessed rate when switched to frames
    DojoHistory history;
    REQUIRE(apply_dojo_edit(file, history, "frames at 30 fps",
                            [&] { return set_clip_frame_rate(file, 0, 30.0); }));
    CHECK(clip_time_units(file.clips[0]).frames);
    // Keys moved in frames land on k / 30 and are written as their shortest round-trip text.
    const std::vector<GraphKey> first{{kScaleChestZ, 0}};
    GraphTransform later;
    later.time_offset = 0.1 + 1e-4; // a drag's 3.003 frames
    REQUIRE(transform_graph_keys(file, 0, first, later, clip_time_units(file.clips[0])));
    CHECK(file.clips[0].phases[0].duration == 15.0 / 30.0);
    CHECK(file.clips[0].phases[1].duration == 15.0 / 30.0);
    const std::string saved = text(file);
    CHECK(saved.find("\"frame_rate\": 30,") != std::string::npos);
    auto reloaded = anim::load_animation_string(saved, "wave.json");
    REQUIRE(reloaded.ok());
    CHECK(reloaded->clips[0].frame_rate == 30.0);
    CHECK(clip_time_units(reloaded->clips[0]).frames);
    CHECK(reloaded->clips[0].phases[0].duration == 15.0 / 30.0);
    CHECK(text(*reloaded) == saved);
    // A rate the file refuses is refused here with the file's message; the clip keeps its rate.
    for (const double bad : {0.0, -24.0, std::nan(""), 1e9}) {
        auto refused = set_clip_frame_rate(file, 0, bad);
        REQUIRE_FALSE(refused);
        CHECK(refused.error().hint.find("frames per second in [1, 1000]") != std::string::npos);
    }
    CHECK(file.clips[0].frame_rate == 30.0);
    CHECK_FALSE(set_clip_frame_rate(file, 3, 24.0)); // no such clip
    REQUIRE(apply_dojo_edit(file, history, "times in seconds",
                            [&] { return set_clip_frame_rate(file, 0, std::nullopt); }));
    CHECK(text(file).find("frame_rate") == std::string::npos);
    REQUIRE(history.undo(file));
    CHECK(file.clips[0].frame_rate == 30.0);
}

TEST_CASE("a timeline scrub lands on a key within reach (Key then writes that key), else on a frame") {
    const anim::AnimationFile file = wave_file(); // keys at 0.25, 0.5, 0.75 and 1 s, stored at 24 fps
    const anim::ClipDef& def = file.clips[0];
    const TimeUnits frames = clip_time_units(def), seconds{};
    CHECK(scrub_time(def, frames, 0.51, 0.02) == 0.5); // exactly the key's time
    CHECK(scrub_time(def, seconds, 0.49, 0.02) == 0.5);
    CHECK(scrub_time(def, frames, 0.6, 0.02) == 14.0 / 24.0); // 14.4 frames: frame 14
    CHECK(scrub_time(def, seconds, 0.6, 0.02) == 0.6);        // seconds: where the mouse is
    CHECK(scrub_time(def, seconds, 0.37, 0.2) == 0.25);       // the nearest key of two in reach
    CHECK(scrub_time(def, seconds, 1.3, 0.02) == 1.0);        // kept inside the clip
    CHECK(scrub_time(def, seconds, -0.1, 0.02) == 0.0);
}
