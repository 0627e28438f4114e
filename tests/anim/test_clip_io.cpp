#include "anim/clip_io.h"
#include "anim_test_support.h"
#include "core/files.h"
#include "core/log.h"
#include "core/paths.h"
#include "jsonio/bad_documents.h"
#include "test_support.h"

#include <cmath>
#include <doctest/doctest.h>
#include <string>
#include <vector>

using namespace ks;
using namespace ks::anim;

TEST_CASE("the shipped robot clip file loads, and saving it reproduces it byte for byte") {
    const auto path = paths::asset("animations/robot.json");
    auto text = files::read_text(path);
    REQUIRE(text.ok());
    auto file = load_animation_string(*text, path.string());
    REQUIRE_MESSAGE(file.ok(), (file.ok() ? std::string() : file.error().str()));
    CHECK(save_animation_string(*file) == *text);
}

TEST_CASE("load -> save -> load -> save is byte-identical for every feature of the format") {
    AnimationFile f;
    f.rig = {{"root", "", DVec3(0), DVec3(0)},
             {"a", "root", DVec3(0.1, 0.25, -3), DVec3(0, 90, 0)},
             {"b", "a", DVec3(0), DVec3(1e-7, -0.3, 12345.5)}};
    f.rest_nodes = {"a", "b"};
    f.node_ease = {{"b", Ease::linear()}, {"a", Ease::power(1.5f, EaseMode::Out)}};
    f.default_blend = 0.2;
    f.blends = {{"*", "two", 0}, {"one", "two", 0.05}};
    f.wrap_captured_angles = false;
    ClipDef one;
    one.name = "one";
    one.loop = LoopMode::Next;
    one.next = "two";
    one.unlisted = UnlistedRule::Hold;
    PhaseDef p;
    p.duration = 1.0 / 3.0; // not short in decimal: must still round-trip exactly
    p.ease = Ease::power(2.5f, EaseMode::InOut);
    TargetDef t;
    t.node = "b";
    t.add_rot = DVec3(0, 720, 0);
    t.pos = DVec3(0.1, 0, 0);
    t.ease = Ease::bezier(0.42f, 0, 0.58f, 1);
    p.targets.push_back(t);
    TargetDef u;
    u.node = "a";
    u.rot = DVec3(-22.5, 0.13 * 180, 1e-3);
    u.add_pos = DVec3(0, -0.7, 0);
    p.targets.push_back(u);
    one.phases.push_back(p);
    one.phases.push_back(PhaseDef{0, Ease::named(EaseFamily::Elastic, EaseMode::Out), {}});
    ClipDef two;
    two.name = "two \"quoted\"";
    two.loop = LoopMode::Loop;
    two.phases.push_back(PhaseDef{0.5, Ease::linear(), {}});
    two.events = {{0.0, "muzzle_flash", "robot_shot"}, {1.0 / 3.0, "step \"left\"", ""}};
    ClipDef three;
    three.name = "three";
    three.loop = LoopMode::PingPong;
    three.phases.push_back(PhaseDef{0.25, Ease::linear(), {}});
    three.frame_rate = 24;
    two.frame_rate = 30000.0 / 1001.0; // NTSC's 29.97: shortest round trip, not "29.97"
    f.clips = {one, two, three};
    f.clips[0].next = two.name;
    f.blends[1].to = two.name;
    f.blends[0].to = two.name;

    const std::string first = save_animation_string(f);
    auto reloaded = load_animation_string(first, "memory.json");
    REQUIRE_MESSAGE(reloaded.ok(), (reloaded.ok() ? std::string() : reloaded.error().str()));
    CHECK(save_animation_string(*reloaded) == first);
    CHECK(reloaded->clips[0].phases[0].duration == 1.0 / 3.0);
    CHECK(reloaded->clips[0].phases[0].ease == Ease::power(2.5f, EaseMode::InOut));
    CHECK(reloaded->clips[0].phases[0].targets[0].ease == Ease::bezier(0.42f, 0, 0.58f, 1));
    CHECK(reloaded->clips[0].phases[0].targets[1].rot->y == 0.13 * 180);
    CHECK(reloaded->clips[1].name == "two \"quoted\"");
    CHECK(reloaded->clips[1].events == f.clips[1].events);
    CHECK(reloaded->clips[0].events.empty());
    CHECK(reloaded->clips[2].loop == LoopMode::PingPong);
    CHECK(reloaded->clips[2].frame_rate == 24.0);
    CHECK(reloaded->clips[1].frame_rate == 30000.0 / 1001.0);
    CHECK_FALSE(reloaded->clips[0].frame_rate); // none stored: seconds
    CHECK(first.find("\"frame_rate\": 24,") != std::string::npos);
    CHECK_FALSE(reloaded->wrap_captured_angles);
    REQUIRE(reloaded->node_ease.size() == 2);
    CHECK(reloaded->node_ease[1].ease == Ease::power(1.5f, EaseMode::Out));
}

TEST_CASE("saving is atomic: a failed write leaves the old file whole") {
    ks::test::ScratchDir dir;
    const auto path = dir / "clips.json";
    const auto& lib = ks::anim::test::robot_library();
    REQUIRE(save_animation_file(path, lib.file).ok());
    const std::string before = ks::test::read_file(path);
    AnimationFile changed = lib.file;
    changed.default_blend = 0.5;
    files::inject_fault(files::Fault::ShortWrite);
    auto failed = save_animation_file(path, changed);
    files::inject_fault(files::Fault::None);
    CHECK_FALSE(failed.ok());
    CHECK(ks::test::read_file(path) == before);
    REQUIRE(save_animation_file(path, changed).ok());
    auto reread = load_animation_file(path);
    REQUIRE(reread.ok());
    CHECK(reread->default_blend == 0.5);
}

TEST_CASE("a missing clip file is a clear error naming the file") {
    auto missing = load_animation_file("/nonexistent/robot.json");
    REQUIRE_FALSE(missing.ok());
    CHECK(missing.error().str().find("/nonexistent/robot.json") != std::string::npos);
}

namespace {
struct BadCase {
    const char* file;
    std::vector<const char*> expected; // substrings of the error text
};
} // namespace

TEST_CASE("malformed clip files give clear errors: file, line:column, JSON path, what would be valid") {
    const std::vector<BadCase> cases = {
        {"empty.json", {"empty.json:1:1", "file is empty", "\"format\""}},
        {"syntax_error.json", {"syntax_error.json:9:", "JSON syntax error", "fix the JSON syntax"}},
        {"nan_duration.json", {"nan_duration.json:16:", "JSON syntax error", "no NaN or Infinity"}},
        {"overflow_number.json",
         {"overflow_number.json:19:34", "number 1e999 overflows to infinity", "finite number"}},
        {"unknown_node.json",
         {"unknown_node.json:19:22", "clips[0].phases[0].targets.elbow", "unknown node 'elbow'",
          "known nodes: robot, chest, head"}},
        {"unknown_easing.json",
         {"unknown_easing.json:17:19", "clips[0].phases[0].ease", "unknown easing 'Quadratic.Inn'",
          "did you mean 'Quadratic.In'?", "Quadratic.In, Quadratic.Out", "Bounce.InOut", "bezier"}},
        {"negative_duration.json",
         {"negative_duration.json:16:23", "clips[0].phases[0].duration", "duration -0.3 s is negative",
          "seconds in [0, 600]"}},
        {"duration_string.json", {"duration_string.json:16:23", "must be a number, not a string"}},
        {"wrong_types.json", {"wrong_types.json:19:29", "targets.head.rot", "array of 3 numbers"}},
        {"bad_vector_size.json", {"bad_vector_size.json:19:29", "an array of 2"}},
        {"unknown_key.json", {"unknown_key.json:15:9", "phase has no \"duration\""}},
        {"unknown_next.json",
         {"unknown_next.json:14:15", "clips[0].next", "unknown clip 'ghost'", "known clips: nod"}},
        {"unknown_loop_mode.json",
         {"unknown_loop_mode.json:13:15", "unknown loop mode 'pingpong'", "did you mean 'ping_pong'?",
          "one of once, loop, ping_pong, next"}},
        {"parent_after_child.json",
         {"parent_after_child.json:6:32", "rig[1].parent",
          "parent 'chest' is not a node listed before 'head'", "earlier nodes: robot"}},
        {"absurd_angle.json", {"absurd_angle.json:19:34", "rot[1]", "out of range", "36000 degrees"}},
        {"not_an_object.json",
         {"not_an_object.json:1:1", "expected the animation as a JSON object {...}, found an array"}},
        {"wrong_format.json",
         {"wrong_format.json:2:13", "format is 'killswitch-level'", "killswitch-animations"}},
        {"wrong_version.json", {"wrong_version.json:3:14", "unsupported version 7", "version 1"}},
        {"duplicate_clip.json", {"duplicate_clip.json:25:15", "clips[1].name", "duplicate clip 'nod'"}},
        {"zero_length_loop.json", {"zero_length_loop.json:14:17", "looping clip 'nod' has zero length"}},
        {"zero_length_ping_pong.json",
         {"zero_length_ping_pong.json:14:17", "ping-pong clip 'nod' has zero length"}},
        {"bad_bezier.json", {"bad_bezier.json:17:19", "x1 and x2 must be in [0, 1]"}},
        {"rot_and_add_rot.json", {"rot_and_add_rot.json:19:21", "both \"rot\" and \"add_rot\""}},
        {"unknown_rest_node.json", {"unknown_rest_node.json:9:27", "rest_nodes[1]", "unknown node 'neck'"}},
        {"missing_clips.json", {"missing_clips.json:1:1", "missing \"clips\""}},
        {"bad_node_ease.json",
         {"2 problems", "bad_node_ease.json:10:25", "node_ease.haed", "unknown node 'haed'",
          "did you mean 'head'?", "bad_node_ease.json:10:49", "unknown easing 'Bouncy.Out'",
          "did you mean 'Bounce.Out'?"}},
        {"bad_events.json",
         {"bad_events.json:18:18", "clips[0].events[0].time",
          "event time 0.75 s is outside clip 'nod' (0..0.5 s)", "clips[0].events[1].name",
          "event name is empty", "sound name 'Robot Shot.wav' has characters", "event has no \"name\""}},
        {"repeated_event.json",
         {"repeated_event.json:20:9", "clips[0].events[2]",
          "event 'muzzle_flash' is listed twice at 0.25 s in clip 'nod' (also events[0])", "two shots"}},
        {"too_many_events.json",
         {"too_many_events.json:17:17", "clips[0].events", "clip 'nod' has 65 events; at most 64"}},
        {"frame_rate_zero.json",
         {"frame_rate_zero.json:14:21", "clips[0].frame_rate", "frame rate 0 of clip 'nod' is not positive",
          "frames per second in [1, 1000], e.g. 24, 30 or 60", "remove \"frame_rate\" to work in seconds"}},
        {"frame_rate_negative.json",
         {"frame_rate_negative.json:14:21", "frame rate -24 of clip 'nod' is not positive"}},
        {"frame_rate_absurd.json",
         {"frame_rate_absurd.json:14:21", "frame rate 1e+09 of clip 'nod' is out of range",
          "[1, 1000]"}},
        {"frame_rate_string.json",
         {"frame_rate_string.json:14:21", "clips[0].frame_rate", "must be a number, not a string"}},
        {"many_problems.json",
         {"3 problems", "duration -1 s is negative", "unknown easing 'Springy.Out'", "unknown node 'neck'"}},
    };
    const auto dir = ks::test::data_dir() / "anim" / "bad";
    int files_seen = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        (void)entry;
        ++files_seen;
    }
    CHECK(files_seen == static_cast<int>(cases.size())); // every corpus file has an expectation
    for (const BadCase& c : cases) {
        auto result = load_animation_file(dir / c.file);
        INFO("file: ", std::string(c.file));
        REQUIRE_FALSE(result.ok());
        const std::string text = result.error().str();
        INFO("error: ", text);
        for (const char* expected : c.expected)
            CHECK_MESSAGE(text.find(expected) != std::string::npos, std::string(expected));
    }
}

TEST_CASE(
    "unknown keys in a clip file are warnings with a did-you-mean, as in every file the programs read") {
    const auto dir = ks::test::data_dir() / "anim" / "bad";
    log::Capture capture;
    auto result = load_animation_file(dir / "missing_clips.json");
    REQUIRE_FALSE(result.ok()); // for the missing "clips", not for the unknown key
    CHECK(result.error().str().find("clipz") == std::string::npos);
    CHECK(capture.text().find("missing_clips.json:10:12: clipz: unknown field \"clipz\" is ignored") !=
          std::string::npos);
    CHECK(capture.text().find("did you mean \"clips\"?") != std::string::npos);
}

TEST_CASE("every bad document is refused with its line:column, as in every file kind") {
    for (const ks::test::BadDocument& bad : ks::test::bad_documents()) {
        CAPTURE(bad.name);
        auto result = load_animation_string(bad.text, "robot.json");
        REQUIRE_FALSE(result.ok());
        const std::string text = result.error().str();
        CAPTURE(text);
        CHECK(text.find("robot.json" + bad.place + bad.message) != std::string::npos);
    }
}

TEST_CASE("names in clip messages are escaped: an embedded NUL does not cut the message short") {
    const std::string text =
        std::string(R"({"format": "killswitch-animations", "version": 1, "rig": [{"name": "robot"}],
        "clips": [{"name": "a", "loop": "pi\u0000ng", "phases": [{"duration": 1}]}]})");
    auto result = load_animation_string(text, "robot.json");
    REQUIRE_FALSE(result.ok());
    CHECK(result.error().str().find("unknown loop mode 'pi\\u0000ng'") != std::string::npos);
}

TEST_CASE("validate() reports problems of an in-memory file with JSON paths (the editor's live check)") {
    AnimationFile f = ks::anim::test::robot_library().file;
    CHECK(validate(f).empty());
    f.clips[1].phases[0].duration = -1;
    f.clips[2].phases[0].targets[0].node = "tail";
    f.blends.push_back({"alert", "nope", 0.1});
    auto issues = validate(f);
    REQUIRE(issues.size() == 3);
    CHECK(issues[0].path.str() == "blend.pairs[5].to");
    CHECK(issues[1].path.str() == "clips[1].phases[0].duration");
    CHECK(issues[2].path.str() == "clips[2].phases[0].targets.tail");
    CHECK(issues[2].hint.find("arm_r") != std::string::npos);
    // A frame rate that is not a number (only an in-memory file can hold NaN) is refused at its place.
    f = ks::anim::test::robot_library().file;
    f.clips[0].frame_rate = std::nan("");
    issues = validate(f);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].path.str() == "clips[0].frame_rate");
    CHECK(issues[0].message.find("out of range") != std::string::npos);
    f.clips[0].frame_rate = 60;
    CHECK(validate(f).empty());
}
