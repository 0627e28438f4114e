// Sound emitters in the editor: placed from the palette, edited field by field with undo, picked by their
// marker, drawn as a speaker and a sphere, and checked against the files in assets/sounds.
#include "core/files.h"
#include "editor_test_util.h"
#include "model/edit_entities.h"
#include "model/edit_selection.h"
#include "model/quick_fix.h"
#include "model/script.h"
#include "model/sound_names.h"
#include "view/picking.h"
#include "view/sound_marker.h"

#include <algorithm>
#include <cmath>

using namespace ks;
using namespace ks::editor;

using editor_test::all_shown;

namespace {

// The sound names of the audio plan (AUDIO_PLAN.md), as assets/sounds will hold them.
const std::vector<std::string> kPlanSounds = {"ambient_dojo",   "ambient_facility", "alarm_loop",
                                              "computer_beeps", "machine_hum",      "robot_motor",
                                              "vent_loop",      "rifle_shot"};

std::vector<Issue> sound_issues(Editor& editor) {
    std::vector<Issue> out;
    for (const Issue& issue : editor.issues())
        if (issue.rule == Rule::Sound) out.push_back(issue);
    return out;
}

Editor editor_with_floor() {
    Editor editor;
    editor.validation_options().check_reachability = false;
    editor.validation_options().sound_names = kPlanSounds;
    editor.grid().step = 1.0f;
    REQUIRE(place(editor, level::EntityType::Floor, Vec3(0.0f)).ok());
    REQUIRE(set_field(editor, "size", Vec2(40, 40)).ok());
    return editor;
}

} // namespace

TEST_CASE("a palette click places a sound emitter above the surface under the cursor, as one step") {
    Editor editor = editor_with_floor();
    ViewCamera top;
    top.set_viewport({960, 540});
    top.set_view(ViewMode::Top, Vec3(0.0f), 60.0f);
    Vec2 cursor;
    REQUIRE(top.project(Vec3(6, 0, -4), cursor));
    const Vec3 surface = place_point(editor.doc(), top.ray(cursor), all_shown, Vec3(0.0f));
    CHECK(surface.y == doctest::Approx(0.0f));
    const size_t steps = editor.history().undo_count();
    auto placed = place(editor, level::EntityType::Sound,
                        placement_for(editor.doc(), level::EntityType::Sound, surface));
    REQUIRE(placed.ok());
    const level::Entity& e = *editor.level().find(*placed);
    CHECK(e.type() == level::EntityType::Sound);
    CHECK(e.position == Vec3(6, kSoundPlaceHeight, -4));
    CHECK(e.as<level::SoundProps>() == level::SoundProps{});
    CHECK(editor.doc().selection == std::vector<int>{*placed});
    CHECK(editor.history().undo_count() == steps + 1);
    CHECK(editor.history().undo_name() == "Place sound");
    // Every other type lands on the surface itself.
    CHECK(placement_for(editor.doc(), level::EntityType::Robot, surface) == surface);
    REQUIRE(editor.undo());
    CHECK(editor.level().find(*placed) == nullptr);
    CHECK(sound_issues(editor).empty());
}

TEST_CASE("the inspector's sound fields: a sound-name kind, sliders, one undo step per edit, refusals") {
    Editor editor = editor_with_floor();
    const int id = *place(editor, level::EntityType::Sound, Vec3(0, 2, 0));
    const auto fields = describe_entity_fields(*editor.level().find(id));
    auto field = [&](const char* name) {
        auto it = std::find_if(fields.begin(), fields.end(),
                               [&](const FieldDescriptor& f) { return f.name == name; });
        REQUIRE(it != fields.end());
        return *it;
    };
    CHECK(field("sound").kind == FieldKind::Sound);
    CHECK(field("volume").slider);
    CHECK(field("volume").max == 1.0);
    CHECK(field("radius").slider);
    CHECK(field("radius").unit == "units");
    CHECK(field("loop").kind == FieldKind::Bool);
    CHECK_FALSE(field("position").slider);

    const std::string placed = editor_test::text_of(editor);
    const size_t steps = editor.history().undo_count();
    REQUIRE(set_field(editor, "sound", FieldValue(std::string("vent_loop"))).ok());
    REQUIRE(set_field(editor, "volume", FieldValue(0.25)).ok());
    REQUIRE(set_field_text(editor, "radius", "12.5").ok());
    REQUIRE(set_field(editor, "loop", FieldValue(false)).ok());
    CHECK(editor.history().undo_count() == steps + 4);
    const level::SoundProps edited = editor.level().find(id)->as<level::SoundProps>();
    CHECK(edited == level::SoundProps{{"vent_loop"}, 0.25f, 12.5f, false});
    const std::string after = editor_test::text_of(editor);

    // Bad values change nothing and record no step; the messages say what would be right.
    auto bad_name = set_field(editor, "sound", FieldValue(std::string("Vent Loop")));
    REQUIRE_FALSE(bad_name.ok());
    CHECK(bad_name.error().message ==
          "Set sound: sound 2: 'sound': sound name \"Vent Loop\" has characters other "
          "than a-z, 0-9 and _");
    CHECK(bad_name.error().hint.find("write \"vent_loop\"") != std::string::npos);
    CHECK_FALSE(set_field(editor, "sound", FieldValue(std::string())).ok());
    auto loud = set_field(editor, "volume", FieldValue(1.5));
    REQUIRE_FALSE(loud.ok());
    CHECK(loud.error().message == "Set volume: sound 2: 'volume' = 1.5 is out of range");
    CHECK(loud.error().hint == "valid range is 0 .. 1");
    CHECK_FALSE(set_field(editor, "radius", FieldValue(-1.0)).ok());
    CHECK_FALSE(set_field(editor, "radius", FieldValue(std::nan(""))).ok());
    CHECK(editor.history().undo_count() == steps + 4);
    CHECK(editor_test::text_of(editor) == after);

    for (int i = 0; i < 4; ++i) REQUIRE(editor.undo());
    CHECK(editor_test::text_of(editor) == placed);
    for (int i = 0; i < 4; ++i) REQUIRE(editor.redo());
    CHECK(editor_test::text_of(editor) == after);
    REQUIRE(revert_field(editor, "volume").ok());
    CHECK(editor.level().find(id)->as<level::SoundProps>().volume == 1.0f);
}

TEST_CASE("the level's ambient_sound is a setting: set, emptied for none, undone") {
    Editor editor = editor_with_floor();
    const std::string before = editor_test::text_of(editor);
    REQUIRE(set_setting_text(editor, "ambient_sound", "ambient_dojo").ok());
    CHECK(editor.level().settings.ambient_sound.value == "ambient_dojo");
    REQUIRE(set_setting(editor, "ambient_sound", FieldValue(std::string())).ok());
    CHECK(editor.level().settings.ambient_sound.value.empty());
    CHECK_FALSE(set_setting_text(editor, "ambient_sound", "Ambient Dojo").ok());
    REQUIRE(editor.undo());
    REQUIRE(editor.undo());
    CHECK(editor_test::text_of(editor) == before);
}

TEST_CASE("a click on a sound emitter's marker picks it; a click beside it does not") {
    Editor editor = editor_with_floor();
    const int id = *place(editor, level::EntityType::Sound, Vec3(5, 2, 5));
    editor.clear_selection();
    ViewCamera top;
    top.set_viewport({960, 540});
    top.set_view(ViewMode::Top, Vec3(0.0f), 60.0f);
    Vec2 at;
    REQUIRE(top.project(Vec3(5, 2, 5), at));
    const PickHit hit = pick_entity(editor.doc(), top.ray(at), all_shown);
    CHECK(hit.id == id); // above the floor, so it is hit first
    REQUIRE(select(editor, {hit.id}).ok());
    CHECK(selected_entities(editor).front()->type() == level::EntityType::Sound);
    Vec2 beside;
    REQUIRE(top.project(Vec3(5 + 2 * level::kSoundMarkerHalfSize, 2, 5), beside));
    CHECK(pick_entity(editor.doc(), top.ray(beside), all_shown).id != id);
}

TEST_CASE("the marker: a speaker inside the pick box from any view, and the radius as a wire sphere") {
    const Vec3 centre(3, 4, -5);
    const float half = level::kSoundMarkerHalfSize;
    const Vec3 views[][2] = {{{1, 0, 0}, {0, 1, 0}}, {{1, 0, 0}, {0, 0, -1}}, {{0.6f, 0, 0.8f}, {0, 1, 0}}};
    for (const auto& basis : views) {
        std::vector<MarkerLine> lines;
        speaker_icon(centre, basis[0], basis[1], half, lines);
        CHECK(lines.size() > 10);
        for (const MarkerLine& line : lines)
            for (const Vec3& p : {line.a, line.b}) {
                const Vec3 d = p - centre;
                CHECK(std::abs(glm::dot(d, basis[0])) <= half + 1e-5f);
                CHECK(std::abs(glm::dot(d, basis[1])) <= half + 1e-5f);
                CHECK(glm::length(d) <= half * std::sqrt(2.0f) + 1e-5f);
            }
    }
    std::vector<MarkerLine> sphere;
    wire_sphere(centre, 25.0f, 32, sphere);
    CHECK(sphere.size() == 3 * 32);
    float lowest = 1e9f, highest = -1e9f;
    for (const MarkerLine& line : sphere) {
        CHECK(glm::length(line.a - centre) == doctest::Approx(25.0f));
        CHECK(glm::length(line.b - centre) == doctest::Approx(25.0f));
        lowest = std::min(lowest, line.a.y), highest = std::max(highest, line.a.y);
    }
    CHECK(lowest == doctest::Approx(centre.y - 25.0f)); // reaches the poles: a sphere, not one circle
    CHECK(highest == doctest::Approx(centre.y + 25.0f));
}

TEST_CASE("validation: an unknown sound is an error with a did-you-mean and a fix; known ones pass") {
    Editor editor = editor_with_floor();
    const int id = *place(editor, level::EntityType::Sound, Vec3(0, 2, 0), 0, "hum");
    CHECK(sound_issues(editor).empty()); // machine_hum, the default, is known; so is ambient_facility

    REQUIRE(set_field(editor, "sound", FieldValue(std::string("machine_hmu"))).ok());
    auto issues = sound_issues(editor);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].severity == IssueSeverity::Error);
    CHECK(issues[0].entity_id == id);
    CHECK(issues[0].message ==
          "sound " + std::to_string(id) +
              " 'hum' plays \"machine_hmu\", which is not a file in assets/sounds; did you "
              "mean \"machine_hum\"?");
    CHECK(issues[0].fix.is<fixes::SetField>());
    REQUIRE(apply_quick_fix(editor, issues[0]).ok());
    CHECK(editor.level().find(id)->as<level::SoundProps>().sound.value == "machine_hum");
    CHECK(sound_issues(editor).empty());

    // Nothing close: the message lists the sounds there are, and there is no fix to guess.
    REQUIRE(set_field(editor, "sound", FieldValue(std::string("thunder"))).ok());
    issues = sound_issues(editor);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].message.find(
              "\"thunder\", which is not a file in assets/sounds (known sounds: ambient_dojo, "
              "ambient_facility, alarm_loop,") != std::string::npos);
    CHECK(!issues[0].fix.available());
    REQUIRE(editor.undo());

    // The level's ambient loop, fixed through the settings (one undoable step).
    REQUIRE(set_setting_text(editor, "ambient_sound", "ambient_facilty").ok());
    issues = sound_issues(editor);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].entity_id == 0);
    CHECK(issues[0].message == "the level's ambient_sound is \"ambient_facilty\", which is not a file in "
                               "assets/sounds; did you mean \"ambient_facility\"?");
    CHECK(issues[0].fix.is<fixes::SetSetting>());
    REQUIRE(apply_quick_fix(editor, issues[0]).ok());
    CHECK(editor.level().settings.ambient_sound.value == "ambient_facility");
    CHECK(sound_issues(editor).empty());
    REQUIRE(set_setting(editor, "ambient_sound", FieldValue(std::string())).ok());
    CHECK(sound_issues(editor).empty()); // none is allowed

    // A name the format refuses is the format rule's, not reported twice.
    level::Level draft = editor.level();
    draft.find(id)->as<level::SoundProps>().sound.value = "Machine Hum";
    ValidationOptions options = editor.validation_options();
    const auto draft_issues = validate_design(draft, options);
    CHECK(std::count_if(draft_issues.begin(), draft_issues.end(),
                        [](const Issue& i) { return i.rule == Rule::Sound; }) == 0);
    CHECK(std::count_if(draft_issues.begin(), draft_issues.end(), [](const Issue& i) {
              return i.rule == Rule::Format && i.message.find("props.sound") != std::string::npos;
          }) == 1);

    // No sounds known (no folder, no files): the rule is skipped rather than failing every name.
    draft.find(id)->as<level::SoundProps>().sound.value = "thunder";
    options.sound_names = std::vector<std::string>{};
    for (const Issue& issue : validate_design(draft, options)) CHECK(issue.rule != Rule::Sound);
}

TEST_CASE("sound names are the .wav files of the folder; a missing folder gives none") {
    ks::test::ScratchDir dir;
    for (const char* name : {"vent_loop.wav", "alarm_loop.wav", "notes.txt", "hum.WAV.bak"})
        REQUIRE(files::write_atomic(dir / name, "RIFF").ok());
    std::filesystem::create_directory(dir / "folder.wav");
    CHECK(sound_names_in(dir.path()) == std::vector<std::string>{"alarm_loop", "vent_loop"});
    CHECK(sound_names_in(dir / "missing").empty());

    // Validation against that folder's names, as the window passes them.
    Editor editor = editor_with_floor();
    editor.validation_options().sound_names = sound_names_in(dir.path());
    REQUIRE(place(editor, level::EntityType::Sound, Vec3(0, 2, 0)).ok()); // machine_hum: not in this folder
    REQUIRE(set_setting_text(editor, "ambient_sound", "").ok());
    const auto issues = sound_issues(editor);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].message.find("\"machine_hum\", which is not a file in assets/sounds (known sounds: "
                                 "alarm_loop, vent_loop)") != std::string::npos);
}

TEST_CASE("scripts place and edit sound emitters and expect the sound rule") {
    Editor editor;
    editor.validation_options().check_reachability = false;
    editor.validation_options().sound_names = kPlanSounds;
    ks::test::ScratchDir dir;
    const char* script = R"(place floor at 0,0,0
set size 40,40
place sound at 4,2,-6 name Vent
set sound vent_lop
expect issue sound 2
set sound vent_loop
set volume 0.4
set radius 18
set loop false
expect no_issue sound
expect field 2 sound vent_loop
expect field 2 volume 0.4
expect field 2 radius 18
expect field 2 loop false
expect count sound 1
setting ambient_sound ambient_dojo
expect no_issue sound
setting ambient_sound nowhere
expect issue sound
undo
expect no_issue sound
)";
    auto report = run_script_text(script, "sound.kss", dir.path(), editor);
    REQUIRE_MESSAGE(report.ok(), report.error().str());
    const auto& sound = editor.level().find(2)->as<level::SoundProps>();
    CHECK(sound == level::SoundProps{{"vent_loop"}, 0.4f, 18.0f, false});
    CHECK(editor.level().settings.ambient_sound.value == "ambient_dojo");
}
