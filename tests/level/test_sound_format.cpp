// The sound emitter entity and the level's ambient_sound setting: what the file holds, that it loads back
// exactly, and the message for every bad value, each naming the file, the place and the fix.
#include "level/entity_shapes.h"
#include "level/level_io.h"
#include "level/sound_name.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <limits>

using namespace ks::level;

namespace {

// A level whose second entity is a sound emitter with `props` (JSON text), on line 3 of the file.
std::string sound_level_text(const std::string& props, const std::string& settings = "{}") {
    return R"({"format": "killswitch-level", "version": 2, "settings": )" + settings + R"(, "entities": [
  {"id": 1, "type": "floor", "position": [0, 0, 0], "props": {"size": [40, 40]}},
  {"id": 7, "type": "sound", "name": "hum", "position": [0, 2, 0], "props": )" +
           props + "}\n]}\n";
}

// Loads `text` expecting it to fail with exactly one error, and returns the report's text.
std::string only_error(const std::string& text) {
    LoadReport report;
    auto level = load_level_string(text, "bad.json", &report);
    CHECK_FALSE(level.ok());
    CHECK_MESSAGE(report.error_count() == 1, report.str());
    return report.str();
}

} // namespace

TEST_CASE("a sound emitter saves its four fields and loads back exactly") {
    Level level;
    auto& emitter = level.add(EntityType::Sound, {90, 5, 50}, "beeps").as<SoundProps>();
    emitter.sound.value = "computer_beeps";
    emitter.volume = 0.6f;
    emitter.radius = 25;
    emitter.loop = false;
    const std::string text = save_level_string(level);
    CHECK_MESSAGE(ks::test::contains_text(text, R"("type": "sound",
      "name": "beeps",
      "position": [90, 5, 50],
      "rotation": [0, 0, 0],
      "props": {
        "sound": "computer_beeps",
        "volume": 0.6,
        "radius": 25,
        "loop": false
      })"),
                  text);
    LoadReport report;
    auto back = load_level_string(text, "sound.json", &report);
    REQUIRE_MESSAGE(back.ok(), report.str());
    CHECK(report.diagnostics.empty());
    CHECK(*back == level);
    CHECK(save_level_string(*back) == text);
}

TEST_CASE("a fresh sound emitter has the documented defaults and a marker but no solid") {
    Level level;
    const Entity& e = level.add(EntityType::Sound, {1, 2, 3});
    const auto& sound = e.as<SoundProps>();
    CHECK(sound.sound.value == "machine_hum");
    CHECK(sound.volume == 1.0f);
    CHECK(sound.radius == 40.0f);
    CHECK(sound.loop);
    CHECK(type_name(EntityType::Sound) == "sound");
    CHECK(validate(level).diagnostics.empty());
    // Heard, never touched: no body for the game or the navigation mesh; the editor's box is centred on the
    // point the sound comes from and stays upright when the entity is turned.
    CHECK_FALSE(static_solid_shape(e).has_value());
    Entity turned = e;
    turned.rotation = {45, 30, 10};
    const PlacedShape box = bounding_shape(turned);
    CHECK(box.centre() == ks::Vec3(1, 2, 3));
    CHECK(box.half == ks::Vec3(kSoundMarkerHalfSize));
    CHECK(box.rotation() == ks::Quat(1, 0, 0, 0));
}

TEST_CASE("ambient_sound: left out at its default, written otherwise, empty for none") {
    Level level;
    CHECK(level.settings.ambient_sound.value == "ambient_facility");
    const std::string plain = save_level_string(level);
    CHECK(plain.find("ambient_sound") ==
          std::string::npos); // files from before the field re-save as they were

    level.settings.ambient_sound.value = "ambient_dojo";
    const std::string dojo = save_level_string(level);
    CHECK(ks::test::contains_text(dojo, "\"gravity\": -25,\n    \"ambient_sound\": \"ambient_dojo\"\n  }"));
    auto back = load_level_string(dojo, "dojo.json");
    REQUIRE(back.ok());
    CHECK(back->settings.ambient_sound.value == "ambient_dojo");

    level.settings.ambient_sound.value = "";
    const std::string silent = save_level_string(level);
    CHECK(ks::test::contains_text(silent, "\"ambient_sound\": \"\""));
    LoadReport report;
    back = load_level_string(silent, "silent.json", &report);
    REQUIRE_MESSAGE(back.ok(), report.str());
    CHECK(report.diagnostics.empty());
    CHECK(back->settings.ambient_sound.value.empty());
    CHECK(save_level_string(*back) == silent);
}

TEST_CASE("every bad sound field is an error naming the file, line, column, field and fix") {
    std::string r = only_error(sound_level_text(R"({"volume": 1.5})"));
    CHECK_MESSAGE(ks::test::contains_text(
                      r, "bad.json:3:78: entities[1].props.volume: 1.5 is out of range (valid: 0 .. 1; "
                         "Loudness at the emitter"),
                  r);
    r = only_error(sound_level_text(R"({"volume": -0.1})"));
    CHECK_MESSAGE(ks::test::contains_text(r, "entities[1].props.volume: -0.1 is out of range (valid: 0 .. 1"),
                  r);
    r = only_error(sound_level_text(R"({"volume": "nan"})"));
    CHECK_MESSAGE(ks::test::contains_text(
                      r, "bad.json:3:78: entities[1].props.volume: \"nan\" is not a finite number (NaN and "
                         "infinity are not allowed) (write a finite number; valid: 0 .. 1)"),
                  r);
    r = only_error(sound_level_text(R"({"radius": -5})"));
    CHECK_MESSAGE(
        ks::test::contains_text(
            r, "bad.json:3:78: entities[1].props.radius: -5 is out of range (valid: 0.5 .. 500 units"),
        r);
    r = only_error(sound_level_text(R"({"radius": 0})"));
    CHECK_MESSAGE(
        ks::test::contains_text(r, "entities[1].props.radius: 0 is out of range (valid: 0.5 .. 500 units"),
        r);
    r = only_error(sound_level_text(R"({"radius": 1e6})"));
    CHECK_MESSAGE(ks::test::contains_text(r, "entities[1].props.radius: 1000000 is out of range"), r);
    r = only_error(sound_level_text(R"({"radius": "inf"})"));
    CHECK_MESSAGE(ks::test::contains_text(r, "entities[1].props.radius: \"inf\" is not a finite number"), r);

    r = only_error(sound_level_text(R"({"sound": ""})"));
    CHECK_MESSAGE(ks::test::contains_text(
                      r, "bad.json:3:78: entities[1].props.sound: sound name is empty (name a file in "
                         "assets/sounds without its .wav, e.g. \"machine_hum\")"),
                  r);
    r = only_error(sound_level_text(R"({"sound": "Machine Hum.wav"})"));
    CHECK_MESSAGE(ks::test::contains_text(
                      r,
                      "bad.json:3:78: entities[1].props.sound: sound name \"Machine Hum.wav\" has characters "
                      "other than a-z, 0-9 and _ (write \"machine_hum\" (the file "
                      "assets/sounds/machine_hum.wav); sound names hold only a-z, 0-9 and _)"),
                  r);
    r = only_error(sound_level_text(R"({"sound": "vent-loop"})"));
    CHECK_MESSAGE(ks::test::contains_text(r, "write \"vent_loop\""), r);
    r = only_error(sound_level_text(R"({"sound": ")" + std::string(65, 'a') + R"("})"));
    CHECK_MESSAGE(
        ks::test::contains_text(r, "entities[1].props.sound: sound name is 65 characters long; at most 64"),
        r);
    r = only_error(sound_level_text(R"({"sound": 5})"));
    CHECK_MESSAGE(
        ks::test::contains_text(
            r,
            "entities[1].props.sound: expected a string, found the number 5 (put the text in double quotes)"),
        r);
    r = only_error(sound_level_text(R"({"loop": "yes"})"));
    CHECK_MESSAGE(
        ks::test::contains_text(
            r,
            "entities[1].props.loop: expected true or false, found the string \"yes\" (valid: true, false)"),
        r);

    r = only_error(sound_level_text("{}", R"({"ambient_sound": "Ambient Dojo"})"));
    CHECK_MESSAGE(
        ks::test::contains_text(
            r, "bad.json:1:59: settings.ambient_sound: sound name \"Ambient Dojo\" has characters other "
               "than a-z, 0-9 and _ (write \"ambient_dojo\""),
        r);
    r = only_error(sound_level_text("{}", R"({"ambient_sound": null})"));
    CHECK_MESSAGE(ks::test::contains_text(r, "settings.ambient_sound: expected a string, found null"), r);
}

TEST_CASE("a misspelt sound field name is a warning with a did-you-mean, and loading goes on") {
    LoadReport report;
    auto level = load_level_string(sound_level_text(R"({"volum": 0.5, "raduis": 12})"), "typo.json", &report);
    REQUIRE_MESSAGE(level.ok(), report.str());
    CHECK(report.warning_count() == 2);
    CHECK_MESSAGE(
        ks::test::contains_text(report.str(),
                                "typo.json:3:78: entities[1].props.volum: unknown field \"volum\" is ignored "
                                "(did you mean \"volume\"? known sound fields: sound, volume, radius, loop)"),
        report.str());
    CHECK(ks::test::contains_text(
        report.str(), "typo.json:3:92: entities[1].props.raduis: unknown field \"raduis\" is ignored (did "
                      "you mean \"radius\"?"));
    CHECK(level->entities[1].as<SoundProps>() == SoundProps{});
}

TEST_CASE("validate finds a sound emitter's NaN, negative radius and bad name in memory") {
    Level level;
    auto& emitter = level.add(EntityType::Sound, {0, 2, 0}, "hum").as<SoundProps>();
    emitter.volume = std::numeric_limits<float>::quiet_NaN();
    emitter.radius = -3;
    emitter.sound.value = "hum!";
    level.settings.ambient_sound.value = "UPPER";
    const std::string report = validate(level, "draft.json").str();
    CHECK_MESSAGE(
        ks::test::contains_text(report, "entities[0].props.volume: value is NaN (not a finite number)"),
        report);
    CHECK_MESSAGE(ks::test::contains_text(
                      report, "entities[0].props.radius: -3 is out of range (valid: 0.5 .. 500 units"),
                  report);
    CHECK_MESSAGE(ks::test::contains_text(
                      report, "entities[0].props.sound: sound name \"hum!\" has characters other than"),
                  report);
    CHECK_MESSAGE(ks::test::contains_text(
                      report, "settings.ambient_sound: sound name \"UPPER\" has characters other than"),
                  report);
    CHECK(validate(level).error_count() == 4);
}

TEST_CASE("the sound name rule and its respelling") {
    CHECK(is_valid_sound_name("machine_hum", 1, 64));
    CHECK(is_valid_sound_name("a1_b2", 1, 64));
    CHECK(is_valid_sound_name("", 0, 64));
    CHECK_FALSE(is_valid_sound_name("", 1, 64));
    CHECK_FALSE(is_valid_sound_name("Machine", 1, 64));
    CHECK_FALSE(is_valid_sound_name("hum.wav", 1, 64));
    CHECK_FALSE(is_valid_sound_name("../secret", 1, 64));
    CHECK_FALSE(is_valid_sound_name("abc", 1, 2));
    CHECK(respelled_sound_name("Machine Hum.WAV") == "machine_hum");
    CHECK(respelled_sound_name("  vent -- loop ") == "vent_loop");
    CHECK(respelled_sound_name("alarm_loop") == "alarm_loop");
    CHECK(respelled_sound_name("!!!") == "");
    CHECK(sound_name_problem("machine_hum", 1, 64).message.empty());
    // Nothing to respell into: the hint still says what is allowed.
    const auto problem = sound_name_problem("???", 1, 64);
    CHECK(problem.message == "sound name \"???\" has characters other than a-z, 0-9 and _");
    CHECK(problem.hint == "sound names hold only a-z, 0-9 and _");
}
