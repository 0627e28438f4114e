#pragma once
// What the player works with: doors (sliding leaves, a sensor, locks), floor and top lights, pickups and
// control panels; which of them E acts on now, with the HUD caption that says so ("Press E to open the
// door"); and the doors' polygons in the robots' navigation mesh, opened and closed as the doors move.
#include "core/result.h"
#include "game/caption.h"
#include "game/game_core.h"
#include "game/player_system.h"
#include "level/entity_shapes.h"

#include <span>
#include <vector>

namespace ks::nav {
class NavMesh;
}

namespace ks::game {

class LevelEdit; // live_carry.h

struct Door {
    int entity_id = 0;
    level::DoorProps props;
    geometry::Transform frame; // bottom centre, door yaw
    physics::BodyId leaves[2], sensor;
    float progress = 0.0f; // 0 closed .. 1 open (linear in time, as the reference)
    bool opening = false;  // where it is heading
    bool locked = false;   // the player's E does nothing (links still open and close it)
    bool player_inside = false;
    float leaf_offset() const { return level::door_leaf_slide(props, progress); } // each leaf slides this far
    // Where leaf `side` (0: local -x, 1: +x) is at the current progress (level::door_leaf_centre).
    geometry::Transform leaf_transform(int side) const {
        return {frame.to_world(level::door_leaf_centre(props, side, progress)), frame.rotation};
    }
};

struct Light {
    int entity_id = 0;
    bool floor = false; // floor lights toggle with E; top lights are fixed
    level::LightProps props;
    Vec3 position{0.0f}; // bottom centre (floor) or fixture (top)
    float yaw = 0.0f;
    float cone_angle = 35.0f;
    bool on = true;
    float intensity() const { return on ? props.intensity : 0.0f; }
    float emissive() const { return on ? 1.5f : 0.0f; }
};

struct Pickup {
    int entity_id = 0;
    PickupKind kind = PickupKind::Health;
    float amount = 10.0f;
    Vec3 centre{0.0f};
    physics::BodyId trigger;
    bool taken = false;
};

struct Panel {
    int entity_id = 0;
    Vec3 centre{0.0f};
    Vec3 size{0.0f};
    float yaw = 0.0f;
    physics::BodyId body;
};

class Interactables {
  public:
    // Pickups add to `player`; E is pressed from its eye.
    Interactables(GameCore& core, PlayerSystem& player);

    Result<void> add_door(const level::Entity& e);
    Result<void> add_pickup(const level::Entity& e);
    void add_light(const level::Entity& e);
    // A control panel's record for its (already built) body; next_panel() is its index in panels().
    std::uint32_t next_panel() const { return static_cast<std::uint32_t>(panels_.size()); }
    void add_panel(const Panel& panel) { panels_.push_back(panel); }

    // The doors slide toward where they are heading (and open or close their polygons in `navigation`).
    void update_doors(float dt, nav::NavMesh* navigation);
    // The object E acts on now, its caption, and E.
    void update_interaction(const Input& input);
    // What the physics reported: the player entered or left a door's sensor, or touched a pickup.
    void player_in_doorway(std::size_t door, bool inside) { doors_[door].player_inside = inside; }
    void take_pickup(std::size_t index);
    // A link's actions (LightToggled and DoorToggled say what changed).
    void set_door_opening(std::size_t door, bool opening);
    void set_door_locked(std::size_t door, bool locked) { doors_[door].locked = locked; }
    void set_light(std::size_t light, bool on);
    // The live play-test's rebuild (live_carry.h): doors (how open, lock; their polygons opened in
    // `navigation`), lights and pickups the edit kept take over their state in `previous`; returns how many.
    int carry_from(const Interactables& previous, const LevelEdit& edit, nav::NavMesh* navigation);

    std::span<const Door> doors() const { return doors_; }
    std::span<const Light> lights() const { return lights_; }
    std::span<const Pickup> pickups() const { return pickups_; }
    const std::vector<Panel>& panels() const { return panels_; }
    const Caption& caption() const { return caption_; }
    // The entity E would act on now (level id), or -1.
    int interact_target() const { return interact_target_; }

  private:
    void interact(int entity_id);

    GameCore& core_;
    PlayerSystem& player_;
    std::vector<Door> doors_;
    std::vector<Light> lights_;
    std::vector<Pickup> pickups_;
    std::vector<Panel> panels_;
    Caption caption_;
    int interact_target_ = -1;
};

} // namespace ks::game
