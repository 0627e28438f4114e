// The script language's dojo context: every clip-file edit as a command (one undo step each), expectations,
// refusals naming the line and the fix, parse errors at their column, and `dojo save` checking before it
// writes. Scripts edit a scratch copy of the robot's clips, never assets/animations/robot.json.
#include "core/files.h"
#include "dojo_test_util.h"
#include "model/script.h"

using namespace ks;
using namespace ks::editor;

namespace {

// A scratch folder holding a copy of the shipped robot clips as robot.json.
struct ScratchClips {
    ks::test::ScratchDir dir;
    ScratchClips() {
        auto shipped = files::read_text(ks::test::source_dir() / "assets" / "animations" / "robot.json");
        REQUIRE(shipped.ok());
        REQUIRE(files::write_atomic(dir / "robot.json", *shipped).ok());
    }
};

Result<ScriptReport> run_dojo(const std::string& text, const std::filesystem::path& base) {
    Editor editor;
    return run_script_text(text, "dojo.kss", base, editor);
}

std::string error_of(const Result<ScriptReport>& r) {
    REQUIRE_FALSE(r.ok());
    return r.error().str();
}

} // namespace

TEST_CASE("dojo script: make a clip, loop it, blend it, give it an event and a key, save, reload") {
    ScratchClips scratch;
    const char* script = R"(dojo open robot.json
expect dojo clean
clip new wave
clip loop wave ping_pong
expect clip wave loop ping_pong
blend default 0.2
blend idle wave 0.25
expect blend idle wave 0.25
expect blend alert wave 0.2
blend * wave 0.3
expect blend alert wave 0.3
blend clear * wave
expect blend alert wave 0.2
event add wave 0.25 wave_peak robot_shot
event add wave 0.1 lift
expect events wave 2
expect event wave 1 0.1 lift none
expect event wave 2 0.25 wave_peak robot_shot
event move wave 1 0.4
expect event wave 2 0.4 lift
event rename wave 2 raise
event sound wave 2 robot_step
expect event wave 2 0.4 raise robot_step
key add wave 1 arm_r
key value wave 1 arm_r rot.z 90
expect key wave 1 arm_r rot.z 90
expect curve wave arm_r rot.z 0.5 90
expect curve wave arm_r rot.z 0.25 22.5   # Quadratic.In from rest: 90 * 0.5^2
expect curve wave arm_r rot.z 0.75 22.5   # ping-pong: the way back
key time wave 1 0.6
expect key wave 1 time 0.6
expect clip wave duration 0.6
clip duplicate wave
expect clip wave_copy exists
clip rename wave_copy wave2
expect clip wave_copy missing
expect blend idle wave2 0.2
clip delete wave2
expect clip wave2 missing
dojo undo
expect clip wave2 exists
dojo redo
expect clip wave2 missing
clip new pose_of_death from death
clip new half_dead from death 0.9
expect clip pose_of_death exists
expect dojo dirty
expect dojo valid
dojo save saved.json
expect dojo clean
)";
    auto r = run_dojo(script, scratch.dir.path());
    REQUIRE_MESSAGE(r.ok(), (r.ok() ? std::string() : r.error().str()));
    CHECK(r->expectations_checked == 27);
    REQUIRE(r->saved.size() == 1);
    CHECK(r->saved[0] == scratch.dir / "saved.json");

    auto saved = anim::load_animation_file(scratch.dir / "saved.json");
    REQUIRE(saved.ok());
    const anim::ClipDef* wave = saved->find_clip("wave");
    REQUIRE(wave);
    CHECK(wave->loop == anim::LoopMode::PingPong);
    CHECK(wave->duration() == doctest::Approx(0.6));
    REQUIRE(wave->events.size() == 2);
    CHECK(wave->events[1].name == "raise");
    CHECK(saved->default_blend == 0.2);
    CHECK(std::any_of(saved->blends.begin(), saved->blends.end(), [](const anim::BlendPair& p) {
        return p.from == "idle" && p.to == "wave" && p.time == 0.25;
    }));
    CHECK(saved->find_clip("wave2") == nullptr);
    CHECK(saved->find_clip("half_dead") != nullptr);
    // The copy it was opened from is untouched (save went to another file).
    CHECK(anim::load_animation_file(scratch.dir / "robot.json")->find_clip("wave") == nullptr);
}

TEST_CASE("dojo script: each edit is one undo step; undo all returns to the file as opened") {
    ScratchClips scratch;
    auto r = run_dojo(
        "dojo open robot.json\nblend default 0.5\nclip new a\nclip new b\nblend a b 1\n"
        "event add a 0.1 x\ndojo undo 2\nexpect clip b exists\nexpect events a 0\nexpect blend a b 0.5\n"
        "dojo undo all\nexpect clip a missing\ndojo redo all\nexpect events a 1\n"
        "dojo undo all\ndojo save\nexpect dojo clean\n",
        scratch.dir.path());
    REQUIRE_MESSAGE(r.ok(), (r.ok() ? std::string() : r.error().str()));
    // Saved back where it came from, byte for byte as it was (the shipped file is canonical).
    CHECK(*files::read_text(scratch.dir / "robot.json") ==
          *files::read_text(ks::test::source_dir() / "assets" / "animations" / "robot.json"));
    CHECK(error_of(run_dojo("dojo open robot.json\nclip new a\ndojo undo 2\n", scratch.dir.path()))
              .find("dojo.kss:3: nothing to undo in the dojo (step 2 of 2)") != std::string::npos);
}

TEST_CASE("dojo script: refused edits stop at their line with the reason and the fix") {
    ScratchClips scratch;
    const auto base = scratch.dir.path();
    struct Case {
        const char* lines;
        const char* expected;
    };
    const Case cases[] = {
        {"clip delete death", "dojo.kss:2: cannot delete 'death': the game plays 'death' when a robot dies"},
        {"clip rename reset home", "cannot rename 'reset': the Dojo's key 0 plays 'reset'"},
        {"clip new idle", "a clip named 'idle' already exists (pick another name, e.g. 'idle_copy')"},
        {"clip loop reset loop", "clip 'reset' has zero length, so it cannot loop"},
        {"clip delete idel", "no clip 'idel' (did you mean 'idle'?"},
        {"blend idle alert 11", "blend time 11 s is out of range"},
        {"blend clear alert idle", "no blend is set for alert -> idle"},
        {"event add shoot_pose 2 late", "event time 2 s is outside clip 'shoot_pose'"},
        {"event remove shoot_pose 1", "clip 'shoot_pose' has no event 1"},
        {"key time shoot_pose 1 -1", "key 1 cannot move to -1 s: that is before the clip's start"},
        {"key value shoot_pose 1 head rot.y 5", "node 'head' has no key in key 1 of 'shoot_pose'"},
        {"key add shoot_pose 1 arm_r", "node 'arm_r' already has a key here"},
        {"expect clip death missing", "expectation failed: clip 'death' exists"},
        {"expect blend idle alert 3", "expectation failed: blend idle -> alert is"},
        {"expect dojo issue nonsense", "no clip file issue mentions 'nonsense'"},
    };
    for (const Case& c : cases) {
        INFO(c.lines);
        const std::string text =
            error_of(run_dojo(std::string("dojo open robot.json\n") + c.lines + "\n", base));
        INFO(text);
        CHECK(text.find(c.expected) != std::string::npos);
        CHECK(text.find("dojo.kss:2") != std::string::npos);
    }
    const std::string unopened = error_of(run_dojo("clip new wave\n", base));
    CHECK(unopened.find("dojo.kss:1: no clip file is open") != std::string::npos);
    CHECK(unopened.find("dojo open") != std::string::npos);
    CHECK(error_of(run_dojo("dojo open missing.json\n", base)).find("missing.json") != std::string::npos);
}

TEST_CASE("dojo script: parse errors name the line and column, all at once, before anything runs") {
    ScratchClips scratch;
    const char* text = "dojo open robot.json\n"
                       "clip loop wave pingpong\n"
                       "key value wave 1 arm_r rot.w 3\n"
                       "event move wave 0 1\n"
                       "blend idle wave fast\n"
                       "clip frobnicate x\n"
                       "expect clip wave exist\n"
                       "dojo reopen\n"
                       "clip loop wave next\n"
                       "expect events wave many\n"
                       "dojo save broken.json\n";
    auto parsed = parse_script(text, "dojo.kss");
    REQUIRE_FALSE(parsed.ok());
    const std::string all = parsed.error().str();
    INFO(all);
    CHECK(all.find("dojo.kss:2:16: unknown loop mode 'pingpong' (once, loop, ping_pong or next)") !=
          std::string::npos);
    CHECK(all.find("dojo.kss:3:24: unknown channel 'rot.w'") != std::string::npos);
    CHECK(all.find("dojo.kss:4:17: expected an event number (1 is the first)") != std::string::npos);
    CHECK(all.find("dojo.kss:5:17: expected seconds, got 'fast'") != std::string::npos);
    CHECK(all.find("dojo.kss:6:6: unknown clip action 'frobnicate'") != std::string::npos);
    CHECK(all.find("dojo.kss:7:18: unknown clip expectation 'exist'") != std::string::npos);
    CHECK(all.find("dojo.kss:8:6: unknown dojo action 'reopen'") != std::string::npos);
    CHECK(all.find("dojo.kss:9:20: loop mode next needs the clip to play next") != std::string::npos);
    CHECK(all.find("dojo.kss:10:20: expected a count of events") != std::string::npos);
    CHECK(run_dojo(text, scratch.dir.path()).ok() == false);
    CHECK_FALSE(std::filesystem::exists(scratch.dir / "broken.json")); // line 11 never ran
    // The level parser's hint lists the dojo words too.
    CHECK(parse_script("clop new x\n", "a.kss").error().str().find("dojo clip blend event key") !=
          std::string::npos);
}

TEST_CASE("dojo script: save refuses a file missing required clips and writes nothing") {
    ks::test::ScratchDir dir;
    REQUIRE(anim::save_animation_file(dir / "nod.json", dojo_test::nod_file()).ok());
    auto r =
        run_dojo("dojo open nod.json\nexpect dojo issue required clips\nclip new wave\ndojo save out.json\n",
                 dir.path());
    const std::string text = error_of(r);
    INFO(text);
    CHECK(text.find("dojo.kss:4") != std::string::npos);
    CHECK(text.find("not saved: the robot's required clips 'idle', 'alert'") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(dir / "out.json"));
}

TEST_CASE("dojo script: 'dojo open' without a file opens the robot's clips") {
    auto r = run_dojo("dojo open\nexpect clip death exists\nexpect dojo valid\nexpect dojo clean\n", {});
    REQUIRE_MESSAGE(r.ok(), (r.ok() ? std::string() : r.error().str()));
    CHECK(r->expectations_checked == 3);
}

TEST_CASE("dojo script: a clip exported to glTF and imported back as a new clip; a missing file refused") {
    ScratchClips clips;
    auto r = run_dojo("dojo open robot.json\n"
                      "dojo export idle.glb idle\n"
                      "clip duplicate alert\n"
                      "dojo export alert.gltf alert_copy\n"
                      "clip delete alert_copy\n"
                      "dojo import alert.gltf\n"
                      "expect clip alert_copy exists\n"
                      "expect clip alert_copy duration 0.6\n"
                      "dojo undo\n"
                      "expect clip alert_copy missing\n",
                      clips.dir.path());
    REQUIRE_MESSAGE(r.ok(), (r.ok() ? std::string() : r.error().str()));
    REQUIRE(r->saved.size() == 2);
    CHECK(std::filesystem::exists(clips.dir / "idle.glb"));
    CHECK(std::filesystem::exists(clips.dir / "alert.gltf"));
    const std::string error =
        error_of(run_dojo("dojo open robot.json\ndojo import missing.glb\n", clips.dir.path()));
    CHECK(ks::test::contains_text(error, "missing.glb"));
}
