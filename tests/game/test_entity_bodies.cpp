// The game builds its bodies from the level's entity shapes (level/entity_shapes.h): every static body of
// the shipped main level sits exactly where the shape says, and door leaves move by the shared formula.
#include "game/autoplay.h"
#include "game_test_levels.h"
#include "level/entity_shapes.h"
#include "level/level_io.h"

using namespace ks;
using namespace ks::game;
using namespace ks::game_test;

TEST_CASE("every static body of levels/main.json is its entity's static solid shape") {
    auto level = level::load_level_file(ks::test::source_dir() / "levels/main.json");
    REQUIRE(level);
    auto g = make_game(*level);
    const physics::World& world = g->world();
    int solids = 0, matched = 0;
    for (const level::Entity& e : level->entities) {
        const auto shape = level::static_solid_shape(e);
        if (!shape) continue;
        ++solids;
        const int matched_before = matched;
        // Find the body placed exactly as the shape (a fresh world's bodies are slots 0.. of generation 1).
        for (std::uint32_t i = 0; i < world.body_count(); ++i) {
            const physics::BodyId id{i, 1};
            REQUIRE(world.valid(id));
            const geometry::Transform xf = world.transform(id);
            // The world stores rotations normalised, so compare within float rounding.
            if (glm::length(xf.position - shape->centre()) < 1e-5f &&
                std::abs(glm::dot(xf.rotation, shape->rotation())) > 1.0f - 1e-6f) {
                ++matched;
                break;
            }
        }
        if (matched == matched_before) MESSAGE("no body for ", level::type_name(e.type()), " ", e.id);
    }
    CHECK(solids > 20); // walls, floors, stairs, lamp stands, cylinders, the panel
    CHECK(matched == solids);
}

TEST_CASE("door leaf bodies follow level::door_leaf_centre while the door opens") {
    auto lv = flat_level();
    auto& door = lv.add(level::EntityType::Door, Vec3(2, 0, -10), "door");
    door.rotation.x = 90.0f;
    door.as<level::DoorProps>().open_offset = 1.5f;
    auto g = make_game(lv);
    // In front of the turned door (its local +z is world +x), looking at it.
    g->teleport_player(Vec3(5, 0, -10), radians(90.0f));
    g->step({});
    Input e;
    e.interact = true;
    g->step(e);
    REQUIRE(g->doors()[0].opening);
    run_for(*g, 0.2);
    const Door& d = g->doors()[0];
    REQUIRE(d.progress > 0.1f);
    REQUIRE(d.progress < 0.9f);
    const geometry::Transform frame = level::upright_frame(lv.entities.back());
    for (int side = 0; side < 2; ++side) {
        const Vec3 expected = frame.to_world(level::door_leaf_centre(d.props, side, d.progress));
        const Vec3 actual = g->world().transform(d.leaves[side]).position;
        CHECK(glm::length(actual - expected) < 1e-5f);
    }
}

TEST_CASE("sound emitters make no body and leave the game as it would be without them") {
    auto level = level::load_level_file(ks::test::source_dir() / "levels/main.json");
    REQUIRE(level);
    level::Level silent = *level;
    const auto sounds = std::erase_if(
        silent.entities, [](const level::Entity& e) { return e.type() == level::EntityType::Sound; });
    REQUIRE(sounds >= 4); // the shipped level has emitters to ignore
    auto with = make_game(*level, 3), without = make_game(silent, 3);
    CHECK(with->world().body_count() == without->world().body_count());
    auto bot_with = Autoplay::create(*level, *with, 3), bot_without = Autoplay::create(silent, *without, 3);
    REQUIRE(bot_with);
    REQUIRE(bot_without);
    for (int i = 0; i < 3 * 120; ++i) {
        with->step(bot_with->decide(*with));
        without->step(bot_without->decide(*without));
    }
    CHECK(with->state_hash() == without->state_hash());
}
