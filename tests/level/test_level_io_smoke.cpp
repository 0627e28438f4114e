// Save and load agree; the smallest valid file loads.
#include "level/level_io.h"

#include <doctest/doctest.h>

using namespace ks::level;

TEST_CASE("a minimal level file loads with defaults") {
    const char* text = R"({"format": "killswitch-level", "version": 2, "entities": [
        {"id": 1, "type": "wall", "position": [0, 0, -5]}]})";
    LoadReport report;
    auto level = load_level_string(text, "minimal.json", &report);
    REQUIRE_MESSAGE(level.ok(), report.str());
    CHECK(report.diagnostics.empty());
    REQUIRE(level->entities.size() == 1);
    CHECK(level->entities[0].as<WallProps>() == WallProps{});
    CHECK(level->next_id == 2);
}

TEST_CASE("save then load gives the same level") {
    Level level;
    level.name = "Smoke";
    level.add(EntityType::Wall, {1, 0, 2}, "A wall").as<WallProps>().size = {12.5f, 16, 0.5f};
    level.add(EntityType::Pickup, {0, 6, 0}, "Ammo").as<PickupProps>().kind.value = "ammo";
    const std::string text = save_level_string(level);
    auto back = load_level_string(text, "smoke.json");
    REQUIRE_MESSAGE(back.ok(), back.error().str());
    CHECK(back->entities == level.entities);
    CHECK(save_level_string(*back) == text);
}
