// The dojo's clips to and from glTF: every shipped clip exported on the model's rig and imported back holds
// the same pose at every frame (1e-5 rad); what does not map is reported; bad files change nothing.
#include "anim/gltf_rig.h"
#include "anim/player.h"
#include "anim/rotation.h"
#include "dojo_test_util.h"
#include "model/dojo_gltf.h"

#include <algorithm>
#include <cmath>

using namespace ks;

namespace {

anim::Rig model_rig() {
    auto rig = anim::load_gltf_rig(test::source_dir() / "assets" / "models" / "robot.gltf");
    REQUIRE(rig.ok());
    return *rig;
}

struct PoseDifference {
    double angle = 0, distance = 0;
};

// The largest difference between two clips' poses (played from rest) over the times given.
PoseDifference compare(const anim::Clip& a, const anim::Clip& b, const anim::Rig& rig,
                       const std::vector<double>& times) {
    anim::Pose rest, pa, pb;
    rest.set_rest(rig);
    pa = pb = rest;
    PoseDifference worst;
    for (const double t : times) {
        anim::sample_clip(a, rest.euler, rest.position, t, pa.euler, pa.position);
        anim::sample_clip(b, rest.euler, rest.position, t, pb.euler, pb.position);
        for (int n = 0; n < rig.size(); ++n) {
            const auto i = static_cast<std::size_t>(n);
            worst.angle = std::max(
                worst.angle, static_cast<double>(anim::angle_between(anim::euler_xyz_to_quat(pa.euler[i]),
                                                                     anim::euler_xyz_to_quat(pb.euler[i]))));
            worst.distance =
                std::max(worst.distance, static_cast<double>(glm::length(pa.position[i] - pb.position[i])));
        }
    }
    return worst;
}

std::vector<double> times_at(double duration, double rate) {
    std::vector<double> times;
    for (long k = 0; static_cast<double>(k) / rate <= duration + 1e-9; ++k)
        times.push_back(static_cast<double>(k) / rate);
    return times;
}

modelio::AnimatedScene head_scene(const std::string& node, modelio::KeyInterpolation how) {
    modelio::AnimatedScene s;
    s.nodes.push_back({"robot", -1, Vec3(0), Quat(1, 0, 0, 0), Vec3(1)});
    s.nodes.push_back({node, 0, Vec3(0, 1, 0), Quat(1, 0, 0, 0), Vec3(1)});
    modelio::NodeTrack t;
    t.node = node;
    t.rotation_times = {0, 0.5, 1.0};
    t.rotations = {Quat(1, 0, 0, 0), glm::angleAxis(1.0f, Vec3(0, 1, 0)),
                   glm::angleAxis(2.0f, Vec3(0, 1, 0))};
    t.rotation_interpolation = how;
    s.animations.push_back({"turn", {t}});
    return s;
}

} // namespace

TEST_CASE("dojo glTF: every shipped clip exported and imported back holds its pose at every frame") {
    test::ScratchDir dir;
    const anim::AnimationFile original = dojo_test::shipped_clips();
    const anim::Rig rig = model_rig();
    const auto file = dir / "robot_clips.glb";
    REQUIRE(editor::export_clips_gltf(original, rig, {}, file).ok());
    anim::AnimationFile imported = original;
    auto report = editor::import_clips_gltf(imported, rig, file);
    REQUIRE_MESSAGE(report.ok(), (report.ok() ? std::string() : report.error().str()));
    CHECK(report->added.empty());
    CHECK(report->replaced.size() == original.clips.size());
    CHECK(report->unmapped.empty());

    auto a = anim::compile(original, rig);
    auto b = anim::compile(imported, rig);
    REQUIRE(a.ok());
    REQUIRE(b.ok());
    double between_frames = 0;
    for (std::size_t c = 0; c < a->clips.size(); ++c) {
        const anim::Clip& before = a->clips[c];
        const anim::Clip& after = b->clips[c];
        INFO(before.name);
        CHECK(after.duration == doctest::Approx(before.duration).epsilon(1e-9));
        // Every key on the 60 Hz grid: stored at 60 fps, each duration a whole number of frames (a clip of
        // zero length, reset, has no rate to find).
        CHECK(imported.clips[c].frame_rate ==
              (before.duration > 0 ? std::optional<double>(60.0) : std::nullopt));
        for (const anim::PhaseDef& phase : imported.clips[c].phases)
            CHECK(phase.duration * 60.0 == std::round(phase.duration * 60.0));
        const PoseDifference at_frames =
            compare(before, after, rig, times_at(before.duration, editor::kGltfExportFps));
        CHECK(at_frames.angle < 1e-5);
        CHECK(at_frames.distance < 1e-5);
        between_frames =
            std::max(between_frames, compare(before, after, rig, times_at(before.duration, 240)).angle);
    }
    // Between 60 Hz keys the linear keys depart from the eases by at most this (docs/animation.md).
    MESSAGE("largest angle between frames: " << between_frames << " rad");
    CHECK(between_frames < 0.1);
}

TEST_CASE("dojo glTF: nodes the rig has not are reported; a file matching no node changes nothing") {
    test::ScratchDir dir;
    const anim::AnimationFile original = dojo_test::shipped_clips();
    const anim::Rig rig = model_rig();

    modelio::AnimatedScene both = head_scene("head", modelio::KeyInterpolation::Linear);
    both.nodes.push_back({"tail", 0, Vec3(0), Quat(1, 0, 0, 0), Vec3(1)});
    modelio::NodeTrack tail = both.animations[0].tracks[0];
    tail.node = "tail";
    both.animations[0].tracks.push_back(tail);
    both.animations[0].name = "Turn.001";
    anim::AnimationFile file = original;
    auto report = editor::import_clips_gltf(file, rig, both, "turn.glb");
    REQUIRE(report.ok());
    REQUIRE(report->added.size() == 1);
    CHECK(report->added[0] == "Turn_001");
    REQUIRE(report->unmapped.size() == 1);
    CHECK(test::contains_text(report->unmapped[0], "'tail'"));
    CHECK(test::contains_text(report->summary(), "not mapped"));
    CHECK(file.clips.size() == original.clips.size() + 1);

    file = original;
    auto refused = editor::import_clips_gltf(file, rig, head_scene("tail", modelio::KeyInterpolation::Linear),
                                             "tail.glb");
    REQUIRE_FALSE(refused.ok());
    CHECK(refused.error().where.file == "tail.glb");
    CHECK(test::contains_text(refused.error().str(), "no node the file animates is in the rig"));
    CHECK(dojo_test::text(file) == dojo_test::text(original));

    const auto cut = dir / "cut.glb";
    REQUIRE(modelio::write_gltf_animations(cut, head_scene("head", modelio::KeyInterpolation::Linear)).ok());
    std::filesystem::resize_file(cut, std::filesystem::file_size(cut) / 2);
    auto truncated = editor::import_clips_gltf(file, rig, cut);
    REQUIRE_FALSE(truncated.ok());
    CHECK(truncated.error().where.file == cut.string());
    CHECK(dojo_test::text(file) == dojo_test::text(original));
}

TEST_CASE("dojo glTF: step keys hold, then jump") {
    const anim::Rig rig = model_rig();
    anim::AnimationFile file = dojo_test::shipped_clips();
    REQUIRE(
        editor::import_clips_gltf(file, rig, head_scene("head", modelio::KeyInterpolation::Step), "step.glb")
            .ok());
    auto compiled = anim::compile(file, rig);
    REQUIRE(compiled.ok());
    const anim::Clip& clip = compiled->clips[static_cast<std::size_t>(compiled->find("turn"))];
    const int head = rig.find("head");
    anim::Pose rest, pose;
    rest.set_rest(rig);
    pose = rest;
    auto head_angle = [&](double t) {
        anim::sample_clip(clip, rest.euler, rest.position, t, pose.euler, pose.position);
        return anim::angle_between(anim::euler_xyz_to_quat(pose.euler[static_cast<std::size_t>(head)]),
                                   Quat(1, 0, 0, 0));
    };
    CHECK(head_angle(0.49) == doctest::Approx(0.0).epsilon(1e-5));
    CHECK(head_angle(0.51) == doctest::Approx(1.0).epsilon(1e-5));
    CHECK(head_angle(1.0) == doctest::Approx(2.0).epsilon(1e-5));
}
