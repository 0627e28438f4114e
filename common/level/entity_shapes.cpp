#include "level/entity_shapes.h"

#include "level/model_entity.h"

#include "brush/texture_mapping.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>

namespace ks::level {
namespace {

constexpr Quat kIdentity{1.0f, 0.0f, 0.0f, 0.0f};

// The generated models' own sizes (assets/generator): a model is scaled by the entity's size over these.
constexpr float kDoorModelSize = 5.0f;
constexpr float kFloorLightModelHeight = 4.0f;
constexpr float kTopLightModelHang = 2.0f;
constexpr float kCylinderModelRadius = 0.5f;
constexpr float kCylinderModelHeight = 2.0f;
constexpr Vec3 kControlPanelModelSize{2.94f, 4.0f, 5.34f};

PlacedShape placed(ShapeKind kind, const geometry::Transform& frame, const Vec3& local_centre,
                   const Vec3& half) {
    return {kind, frame, local_centre, half};
}

// Lamp stands, cylinders and pickups keep their axes upright and unturned, whatever the entity's rotation.
PlacedShape unturned(ShapeKind kind, const Vec3& origin, const Vec3& local_centre, const Vec3& half) {
    return {kind, geometry::Transform{origin, kIdentity}, local_centre, half};
}

float top_light_hang(const TopLightProps& light) {
    return std::max(light.hang, 0.1f);
}

} // namespace

geometry::Transform entity_frame(const Entity& entity) {
    return {entity.position, entity.orientation()};
}

geometry::Transform upright_frame(const Entity& entity) {
    return {entity.position, glm::angleAxis(radians(entity.rotation.x), Vec3(0, 1, 0))};
}

bool keeps_pitch_and_roll(EntityType type) {
    switch (type) {
    case EntityType::Wall:
    case EntityType::Floor:
    case EntityType::Stair:
    case EntityType::ControlPanel:
    case EntityType::Brush:
    case EntityType::Model:
        return true;
    default:
        return false;
    }
}

std::optional<PlacedShape> static_solid_shape(const Entity& e) {
    switch (e.type()) {
    case EntityType::Wall: {
        const Vec3 size = e.as<WallProps>().size;
        return placed(ShapeKind::Box, entity_frame(e), Vec3(0, size.y * 0.5f, 0), size * 0.5f);
    }
    case EntityType::Floor: { // the walking surface is at position.y; a ceiling's underside is
        const auto& f = e.as<FloorProps>();
        const float half_t = f.thickness * 0.5f;
        return placed(ShapeKind::Box, entity_frame(e), Vec3(0, f.ceiling ? half_t : -half_t, 0),
                      {f.size.x * 0.5f, half_t, f.size.y * 0.5f});
    }
    case EntityType::Stair: {
        const Vec3 size = e.as<StairProps>().size;
        return placed(ShapeKind::Wedge, entity_frame(e), Vec3(0, size.y * 0.5f, 0), size * 0.5f);
    }
    case EntityType::FloorLight: { // the lamp stand: solid and shootable, as in the reference
        const float height = e.as<FloorLightProps>().height;
        return unturned(ShapeKind::Cylinder, e.position, Vec3(0, height * 0.5f, 0),
                        {kLampStandRadius, height * 0.5f, kLampStandRadius});
    }
    case EntityType::GasCylinder: {
        const auto& g = e.as<GasCylinderProps>();
        return unturned(ShapeKind::Cylinder, e.position, Vec3(0, g.height * 0.5f, 0),
                        {g.radius, g.height * 0.5f, g.radius});
    }
    case EntityType::ControlPanel: {
        const Vec3 size = e.as<ControlPanelProps>().size;
        return placed(ShapeKind::Box, entity_frame(e), Vec3(0, size.y * 0.5f, 0), size * 0.5f);
    }
    case EntityType::Door:
    case EntityType::TopLight:
    case EntityType::Robot:
    case EntityType::Pickup:
    case EntityType::Sound:
    case EntityType::Trigger:
    case EntityType::Spawner:
    case EntityType::Message:
    case EntityType::Brush: // not a box: world_brush
    case EntityType::Model: // not a box: model_collision (level/model_entity.h)
    case EntityType::Count:
        break;
    }
    return std::nullopt;
}

Result<brush::Brush> world_brush(const Entity& entity) {
    const auto* props = entity.try_as<BrushProps>();
    if (!props)
        return Error(std::string(type_name(entity.type())) + " " + std::to_string(entity.id) +
                     " is not a brush");
    const glm::dmat3 rotation = glm::mat3_cast(dquat_from_ypr_degrees(DVec3(entity.rotation)));
    return brush::placed(props->brush, rotation, DVec3(entity.position));
}

bool is_ceiling(const Entity& entity) {
    if (const auto* floor = entity.try_as<FloorProps>()) return floor->ceiling;
    if (const auto* brush = entity.try_as<BrushProps>()) return brush->ceiling;
    return false;
}

float door_leaf_slide(const DoorProps& door, float open_fraction) {
    return open_fraction * door.open_offset;
}

Vec3 door_leaf_centre(const DoorProps& door, int side, float open_fraction) {
    const float sign = side == 0 ? -1.0f : 1.0f;
    return {sign * (door.width * 0.25f + door_leaf_slide(door, open_fraction)), door.height * 0.5f, 0};
}

Vec3 door_leaf_half(const DoorProps& door) {
    return {door.width * 0.25f, door.height * 0.5f, kDoorLeafHalfThickness};
}

Vec3 door_sensor_centre(const DoorProps& door) {
    return {0, door.height * 0.5f, 0};
}

Vec3 door_sensor_half(const DoorProps& door) {
    return {door.width * 0.5f, door.height * 0.5f, kDoorSensorHalfDepth};
}

Vec3 pickup_centre(const Vec3& position) {
    return position + Vec3(0, kPickupCentreHeight, 0);
}

Vec3 gas_cylinder_centre(const Vec3& position, const GasCylinderProps& cylinder) {
    return position + Vec3(0, cylinder.height * 0.5f, 0);
}

PlacedShape bounding_shape(const Entity& e) {
    if (auto solid = static_solid_shape(e)) {
        if (solid->kind == ShapeKind::Wedge) solid->kind = ShapeKind::Box;
        return *solid;
    }
    switch (e.type()) {
    case EntityType::Door: { // the doorway with its closed leaves
        const auto& d = e.as<DoorProps>();
        return placed(ShapeKind::Box, entity_frame(e), door_sensor_centre(d),
                      {d.width * 0.5f, d.height * 0.5f, kDoorLeafHalfThickness});
    }
    case EntityType::TopLight: { // hangs below its ceiling fixture
        const float hang = top_light_hang(e.as<TopLightProps>());
        return placed(ShapeKind::Box, entity_frame(e), Vec3(0, -hang * 0.5f, 0), {0.75f, hang * 0.5f, 0.75f});
    }
    case EntityType::Robot:
        return placed(ShapeKind::Box, entity_frame(e), Vec3(0, kRobotHeight * 0.5f, 0),
                      {kRobotRadius, kRobotHeight * 0.5f, kRobotRadius});
    case EntityType::Pickup:
        return unturned(ShapeKind::Box, e.position, Vec3(0, kPickupCentreHeight, 0), Vec3(kPickupHalfSize));
    case EntityType::Sound: // omnidirectional: its rotation turns nothing
        return unturned(ShapeKind::Box, e.position, Vec3(0.0f), Vec3(kSoundMarkerHalfSize));
    case EntityType::Trigger:
        return trigger_box(e);
    case EntityType::Spawner: // where its robots appear: one robot's body
        return placed(ShapeKind::Box, upright_frame(e), Vec3(0, kRobotHeight * 0.5f, 0),
                      {kRobotRadius, kRobotHeight * 0.5f, kRobotRadius});
    case EntityType::Message:
        return unturned(ShapeKind::Box, e.position, Vec3(0, kLogicMarkerHalfSize, 0),
                        Vec3(kLogicMarkerHalfSize));
    case EntityType::Brush: { // the box around its faces in its own frame: turns with it, as its faces do
        const brush::Brush& b = e.as<BrushProps>().brush;
        return placed(ShapeKind::Box, entity_frame(e), Vec3((b.bounds_min() + b.bounds_max()) * 0.5),
                      Vec3((b.bounds_max() - b.bounds_min()) * 0.5));
    }
    case EntityType::Model:
        return model_bounding_shape(e);
    default:
        break;
    }
    return placed(ShapeKind::Box, entity_frame(e), Vec3(0.0f), Vec3(0.5f));
}

PlacedShape trigger_box(const Entity& trigger) {
    const Vec3 size = trigger.as<TriggerProps>().size;
    return placed(ShapeKind::Box, upright_frame(trigger), Vec3(0, size.y * 0.5f, 0), size * 0.5f);
}

Mat4 robot_model_matrix(const Vec3& feet, float level_yaw) {
    return glm::rotate(glm::translate(Mat4(1.0f), feet), robot_model_yaw(level_yaw), Vec3(0, 1, 0));
}

Mat4 gas_cylinder_model_matrix(const Vec3& centre, float yaw, const GasCylinderProps& cylinder) {
    const Vec3 bottom = centre - Vec3(0, cylinder.height * 0.5f, 0);
    const Vec3 scale(cylinder.radius / kCylinderModelRadius, cylinder.height / kCylinderModelHeight,
                     cylinder.radius / kCylinderModelRadius);
    return glm::scale(glm::rotate(glm::translate(Mat4(1.0f), bottom), yaw, Vec3(0, 1, 0)), scale);
}

Mat4 pickup_model_matrix(const Vec3& centre, const Quat& turn) {
    const Vec3 origin = centre - Vec3(0, kPickupCentreHeight - kPickupModelLift, 0);
    return glm::translate(Mat4(1.0f), origin) * glm::mat4_cast(turn);
}

Mat4 door_model_matrix(const Entity& door) {
    const auto& d = door.as<DoorProps>();
    return entity_frame(door).matrix() *
           glm::scale(Mat4(1.0f), Vec3(d.width / kDoorModelSize, d.height / kDoorModelSize, 1.0f));
}

float door_model_leaf_shift(const DoorProps& door, float open_fraction) {
    const float model_scale_x = std::max(door.width / kDoorModelSize, 1e-3f);
    const float moved = door_leaf_centre(door, 1, open_fraction).x - door_leaf_centre(door, 1, 0.0f).x;
    return moved / model_scale_x;
}

Mat4 floor_light_model_matrix(const Entity& light) {
    const float s = light.as<FloorLightProps>().height / kFloorLightModelHeight;
    return entity_frame(light).matrix() * glm::scale(Mat4(1.0f), Vec3(s));
}

Mat4 top_light_model_matrix(const Entity& light) {
    const float s = top_light_hang(light.as<TopLightProps>()) / kTopLightModelHang;
    return entity_frame(light).matrix() * glm::scale(Mat4(1.0f), Vec3(s));
}

Mat4 control_panel_model_matrix(const Entity& panel) {
    const Vec3 s = panel.as<ControlPanelProps>().size / kControlPanelModelSize;
    return entity_frame(panel).matrix() * glm::scale(Mat4(1.0f), s);
}

} // namespace ks::level
