#pragma once
// A level's scenery: what a running game's view draws of the level as a still scene (render::LevelScene
// built from it, with its light bake): walls, floors, stairs, brushes, doors, floor and top lights, the
// control panel and designers' models, and the level's light and fog settings. Not in it: the things the
// game draws from its own state (robots, pickups, gas cylinders), the invisible logic entities (sounds,
// triggers, spawners, messages), names, links, objectives, the player start, gravity, the ambient sound,
// and the switches the game sets on the scene every frame (a light's `on`, a door's `open` and `locked`).
// The live play-test (docs/game.md, "Live edits") keeps the running view's scene and bake when an edit
// leaves the scenery as it was.
#include "level/level.h"

namespace ks::level {

// Whether the game's view draws this type as part of the still scene.
bool is_scenery(EntityType type);

// The same scenery: the same scenery entities in the same order with the same id, place, turn and props
// (the switches above aside), and the same light and fog settings.
bool same_scenery(const Level& a, const Level& b);

} // namespace ks::level
