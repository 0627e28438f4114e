// The clips the game looks up by name are the required list's (anim::required_robot_clips): the game
// refuses clips without any one of them and accepts clips without any other (reset is the Dojo's, not the
// game's). A new lookup in the game without a required entry, or a required entry the game dropped, fails.
#include "anim/required_clips.h"
#include "core/log.h"
#include "game_test_levels.h"

#include <doctest/doctest.h>

#include <memory>
#include <string>

using namespace ks;

namespace {

// The library made from `file` as if read from `source`.
std::shared_ptr<const anim::AnimationLibrary> library_of(const anim::AnimationFile& file,
                                                         const std::filesystem::path& source) {
    auto rig = anim::build_rig(file);
    REQUIRE_MESSAGE(rig.ok(), (rig.ok() ? std::string() : rig.error().str()));
    auto clips = anim::compile(file, *rig);
    REQUIRE_MESSAGE(clips.ok(), (clips.ok() ? std::string() : clips.error().str()));
    return std::make_shared<const anim::AnimationLibrary>(
        anim::AnimationLibrary{file, std::move(*rig), std::move(clips).value(), source});
}

anim::AnimationFile shipped_file() {
    auto loaded = anim::load_animation_library(ks::test::source_dir() / "assets/animations/robot.json");
    REQUIRE(loaded.ok());
    CHECK(loaded->source == ks::test::source_dir() / "assets/animations/robot.json");
    return loaded->file;
}

std::shared_ptr<const anim::AnimationLibrary> library_without(const std::string& clip) {
    auto loaded = anim::load_animation_library(ks::test::source_dir() / "assets/animations/robot.json");
    REQUIRE(loaded.ok());
    anim::AnimationFile file = loaded->file;
    std::erase_if(file.clips, [&](const anim::ClipDef& c) { return c.name == clip; });
    std::erase_if(file.blends, [&](const anim::BlendPair& p) { return p.from == clip || p.to == clip; });
    auto clips = anim::compile(file, loaded->rig);
    REQUIRE_MESSAGE(clips.ok(), (clips.ok() ? std::string() : clips.error().str()));
    return std::make_shared<const anim::AnimationLibrary>(
        anim::AnimationLibrary{file, loaded->rig, std::move(clips).value(), loaded->source});
}

} // namespace

TEST_CASE("the game needs exactly the required robot clips (but reset, the Dojo's)") {
    auto loaded = anim::load_animation_library(ks::test::source_dir() / "assets/animations/robot.json");
    REQUIRE(loaded.ok());
    level::Level lv = game_test::flat_level();
    game_test::add_robot(lv, Vec3(0, 0, -10));
    for (const anim::ClipDef& clip : loaded->file.clips) {
        game::GameOptions options;
        options.animations = library_without(clip.name);
        const auto game = game::Game::create(lv, options);
        const bool game_needs = anim::find_required_clip(clip.name) && clip.name != "reset";
        INFO(clip.name << ": " << (game ? std::string("built") : game.error().str()));
        CHECK(game.ok() == !game_needs);
        if (!game) CHECK(game.error().str().find("\"" + clip.name + "\"") != std::string::npos);
    }
}

TEST_CASE("problems with the robot's clips name the file that was read, not the shipped one") {
    level::Level lv = game_test::flat_level();
    game_test::add_robot(lv, Vec3(0, 0, -10));
    anim::AnimationFile file = shipped_file();
    std::erase_if(file.clips, [](const anim::ClipDef& c) { return c.name == "death"; });
    std::erase_if(file.blends, [](const anim::BlendPair& p) { return p.from == "death" || p.to == "death"; });
    game::GameOptions options;
    options.animations = library_of(file, "/designer/my_robot.json");
    const auto game = game::Game::create(lv, options);
    REQUIRE_FALSE(game.ok());
    CHECK(game.error().where.file == "/designer/my_robot.json");
    CHECK(game.error().str().find("\"death\"") != std::string::npos);
}

TEST_CASE("a clip event's sound that is not in assets/sounds, and a rig without hand_r_tip, are warned of") {
    level::Level lv = game_test::flat_level();
    game_test::add_robot(lv, Vec3(0, 0, -10));
    anim::AnimationFile file = shipped_file();
    for (anim::ClipDef& c : file.clips)
        if (c.name == "idle") c.events.push_back({0.0, "footstep", "no_such_sound"});
    for (anim::RigNodeDef& node : file.rig)
        if (node.name == "hand_r_tip") node.name = "hand_r_end";
    for (anim::RigNodeDef& node : file.rig)
        if (node.parent == "hand_r_tip") node.parent = "hand_r_end";
    game::GameOptions options;
    options.animations = library_of(file, "/designer/my_robot.json");
    log::Capture capture;
    const auto game = game::Game::create(lv, options);
    REQUIRE_MESSAGE(game.ok(), (game.ok() ? std::string() : game.error().str()));
    const std::string text = capture.text();
    CHECK_MESSAGE(text.find("/designer/my_robot.json: clip \"idle\", event \"footstep\" plays sound "
                            "\"no_such_sound\", which is not in assets/sounds") != std::string::npos,
                  text);
    CHECK_MESSAGE(
        text.find("/designer/my_robot.json: the rig has no \"hand_r_tip\" node, so robot shots start "
                  "at \"hand_r\"") != std::string::npos,
        text);
}

TEST_CASE("the shipped clips load without a warning about sounds or the hand") {
    level::Level lv = game_test::flat_level();
    game_test::add_robot(lv, Vec3(0, 0, -10));
    log::Capture quiet;
    REQUIRE(game::Game::create(lv, game::GameOptions{}).ok());
    CHECK(quiet.text().find("assets/sounds") == std::string::npos);
    CHECK(quiet.text().find("hand_r_tip") == std::string::npos);
}
