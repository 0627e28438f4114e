// The data model: type names, default props, ids.
#include "level/level.h"

#include <doctest/doctest.h>

using namespace ks::level;

TEST_CASE("type names round-trip through type_from_name for every type") {
    CHECK(all_types().size() == static_cast<size_t>(EntityType::Count));
    for (EntityType type : all_types()) {
        EntityType back{};
        REQUIRE(type_from_name(type_name(type), back));
        CHECK(back == type);
        CHECK(default_props(type).index() == static_cast<size_t>(type));
    }
    CHECK(type_name(EntityType::FloorLight) == "floor_light");
    CHECK(type_name(EntityType::ControlPanel) == "control_panel");
    EntityType out = EntityType::Wall;
    CHECK_FALSE(type_from_name("Wall", out)); // names are case-sensitive
    CHECK_FALSE(type_from_name("", out));
    CHECK_FALSE(type_from_name("barrel", out));
}

TEST_CASE("default props carry the struct defaults") {
    CHECK(std::get<WallProps>(default_props(EntityType::Wall)).size == ks::Vec3(10, 16, 0.5f));
    CHECK(std::get<FloorLightProps>(default_props(EntityType::FloorLight)).light.intensity == 0.8f);
    CHECK(std::get<PickupProps>(default_props(EntityType::Pickup)).kind.options.size() == 3);
}

TEST_CASE("Level::add hands out fresh ids and find locates them") {
    Level level;
    Entity& a = level.add(EntityType::Wall, {1, 2, 3}, "West wall");
    CHECK(a.id == 1);
    CHECK(a.name == "West wall");
    CHECK(a.type() == EntityType::Wall);
    CHECK(a.position == ks::Vec3(1, 2, 3));
    const int b_id = level.add(EntityType::Robot).id;
    CHECK(b_id == 2);
    CHECK(level.next_id == 3);
    CHECK_FALSE(level.find(b_id)->name.empty()); // unnamed entities get a readable default name
    CHECK(level.find(1)->name == "West wall");
    CHECK(level.find(99) == nullptr);
    const Level& const_level = level;
    CHECK(const_level.find(2)->type() == EntityType::Robot);

    // An id set by hand above next_id is never handed out again.
    level.entities.back().id = 10;
    CHECK(level.add(EntityType::Door).id == 11);
    CHECK(level.next_id == 12);
}
