// The clips the game looks up by name are the required list's (anim::required_robot_clips): the game
// refuses clips without any one of them and accepts clips without any other (reset is the Dojo's, not the
// game's). A new lookup in the game without a required entry, or a required entry the game dropped, fails.
#include "anim/required_clips.h"
#include "game_test_levels.h"

#include <doctest/doctest.h>

#include <memory>
#include <string>

using namespace ks;

namespace {

std::shared_ptr<const anim::AnimationLibrary> library_without(const std::string& clip) {
    auto loaded = anim::load_animation_library(ks::test::source_dir() / "assets/animations/robot.json");
    REQUIRE(loaded.ok());
    anim::AnimationFile file = loaded->file;
    std::erase_if(file.clips, [&](const anim::ClipDef& c) { return c.name == clip; });
    std::erase_if(file.blends, [&](const anim::BlendPair& p) { return p.from == clip || p.to == clip; });
    auto clips = anim::compile(file, loaded->rig);
    REQUIRE_MESSAGE(clips.ok(), (clips.ok() ? std::string() : clips.error().str()));
    return std::make_shared<const anim::AnimationLibrary>(
        anim::AnimationLibrary{file, loaded->rig, std::move(clips).value()});
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
