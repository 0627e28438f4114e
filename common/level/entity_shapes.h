#pragma once
// Where an entity's pieces are: the one place that turns an entity's properties into shapes and model
// placements. The game builds its physics bodies from these shapes, the editor its boxes and picking, the
// renderer's level scene and the runtime's world view their model transforms, so the four cannot disagree.
// Pure functions of the entity (and, for things that move, of the game's state), no module above level.
#include "brush/brush.h"
#include "geometry/transform.h"
#include "level/level.h"

#include <optional>

namespace ks::level {

// The entity's position with its full orientation (yaw, pitch, roll).
geometry::Transform entity_frame(const Entity& entity);
// The entity's position turned by its yaw only: doors, lights and props stand upright whatever their pitch.
geometry::Transform upright_frame(const Entity& entity);

// Whether the game turns this type's body by its pitch and roll too: walls, floors, stairs, the control
// panel (their solid shapes use entity_frame) and brushes (world_brush). Every other type stands upright and
// turns by its yaw alone, so the editor offers it only the yaw ring.
bool keeps_pitch_and_roll(EntityType type);

enum class ShapeKind : std::uint8_t {
    Box,      // half extents `half`
    Wedge,    // a ramp in a box of half extents `half`, rising toward local -z (physics::Shape::wedge)
    Cylinder, // upright: radius half.x (== half.z), half height half.y
};

// A shape placed in the world: its kind and half extents, centred at `local_centre` in `frame`.
struct PlacedShape {
    ShapeKind kind = ShapeKind::Box;
    geometry::Transform frame;
    Vec3 local_centre{0.0f};
    Vec3 half{0.0f};
    Vec3 centre() const { return frame.to_world(local_centre); }
    const Quat& rotation() const { return frame.rotation; }
};

// ---- facts of the shipped bodies and models (seed facts §4-5, asset conventions) ----------------------
inline constexpr float kRobotRadius = 0.8f; // the robot's collision capsule
inline constexpr float kRobotHeight = 3.0f;
inline constexpr float kPlayerRadius = 1.0f; // the player's body (seed facts §5.1)
inline constexpr float kPlayerHeight = 3.0f;
inline constexpr float kDoorLeafHalfThickness = 0.07f; // each sliding leaf is 0.14 thick
inline constexpr float kDoorSensorHalfDepth = 7.0f;    // the reference's 5 x 5 x 14 interaction box
inline constexpr float kLampStandRadius = 0.5f;        // a floor light's solid post
inline constexpr float kPickupCentreHeight = 0.8f;     // a pickup's trigger cube floats this far up
inline constexpr float kPickupHalfSize = 0.4f;
inline constexpr float kPickupModelLift = 0.4f;      // the pickup model's origin above the entity
inline constexpr float kSoundMarkerHalfSize = 0.75f; // the editor's box around a sound emitter's point
inline constexpr float kLogicMarkerHalfSize = 0.75f; // the editor's box on a message's position

// The solid static body of walls, floors, stairs, floor-light stands, control panels and gas cylinders;
// nullopt for entities that have none (doors, robots, pickups and top lights are built otherwise; sound
// emitters are heard, never touched).
std::optional<PlacedShape> static_solid_shape(const Entity& entity);

// A brush entity's brush in the world: its faces (in the entity's frame) turned by the entity's full
// rotation and moved to its position, texture lock on (the texture travels with the brush). An Error for
// other types, and where the turned brush would leave the brush module's world (brush::kMaxCoordinate).
Result<brush::Brush> world_brush(const Entity& entity);

// A floor or a brush marked as a ceiling: it casts no sun shadow, and the editor hides it with its ceilings.
bool is_ceiling(const Entity& entity);

// Door leaves, indexed by side: 0 is the leaf on the door's local -x, 1 the one on +x. Each slides outward
// along local x by open_offset times the open fraction (0 closed, 1 open); the result is in the door's
// upright frame (upright_frame), so physics and drawing place the leaves by the same formula.
float door_leaf_slide(const DoorProps& door, float open_fraction);
Vec3 door_leaf_centre(const DoorProps& door, int side, float open_fraction);
Vec3 door_leaf_half(const DoorProps& door);
// The interaction box around the doorway, in the door's upright frame.
Vec3 door_sensor_centre(const DoorProps& door);
Vec3 door_sensor_half(const DoorProps& door);

// A pickup's trigger centre, from the entity's position.
Vec3 pickup_centre(const Vec3& position);
// A gas cylinder's centre (its body's), from the entity's position (the cylinder's bottom centre).
Vec3 gas_cylinder_centre(const Vec3& position, const GasCylinderProps& cylinder);

// A trigger's volume: its size standing on its position, turned by its yaw only (the game tests characters
// against it, the editor draws and picks it).
PlacedShape trigger_box(const Entity& trigger);

// The box the editor selects, picks and checks overlaps with: the solid shape where there is one (a stair
// as the box around its wedge), otherwise the doorway with closed leaves, the robot's body, the pickup's
// cube, the top light's hanging bulb, the sound emitter's marker (an upright cube around its point), the
// trigger's volume, a robot's body where a spawner makes them, a cube on a message's position, the box
// around a brush's faces in the entity's frame.
PlacedShape bounding_shape(const Entity& entity);

// ---- model placements: the transform from a generated model's frame to the world -----------------------
// The robot model faces its local +x; a level yaw of 0 faces -z, so the model is turned a quarter turn more
// than the entity (the reference's rotY). Robots stand upright: only the yaw turns them.
inline constexpr float kRobotModelYawOffset = kPi * 0.5f;
inline float robot_model_yaw(float level_yaw) {
    return level_yaw + kRobotModelYawOffset;
}
Mat4 robot_model_matrix(const Vec3& feet, float level_yaw);
// A gas cylinder's model (radius 0.5, height 2, origin at the bottom) scaled to its properties, given the
// body's centre and the entity's yaw.
Mat4 gas_cylinder_model_matrix(const Vec3& centre, float yaw, const GasCylinderProps& cylinder);
// A pickup's model, given its trigger centre and the model's turn (the game spins pickups).
Mat4 pickup_model_matrix(const Vec3& centre, const Quat& turn);
// The door model (5 x 5, leaves door_l on +x and door_r on -x) scaled to the doorway.
Mat4 door_model_matrix(const Entity& door);
// How far the door model's leaf on local +x (side 1) moves in the model's own units at an open fraction.
float door_model_leaf_shift(const DoorProps& door, float open_fraction);
Mat4 floor_light_model_matrix(const Entity& light);
Mat4 top_light_model_matrix(const Entity& light);
Mat4 control_panel_model_matrix(const Entity& panel);

} // namespace ks::level
