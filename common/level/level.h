#pragma once
// Level format v4: the one data model that the loader reads, the editor edits, and the game spawns from.
// Each entity type's properties are defined once, as a struct with a visit() that lists every field with
// its default, range, unit and tooltip; loading, saving, validation and the editor's inspector all walk
// that list, so there are no parallel copies to keep in step. See docs/level-format.md.
#include "brush/brush.h"
#include "core/math.h"
#include "level/editor_data.h"

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace ks::level {

inline constexpr std::string_view kFormatName = "killswitch-level";
inline constexpr int kFormatVersion = 4;

// Metadata a visitor receives with each field. Ranges are inclusive; a field outside its range is an error.
struct FieldInfo {
    const char* name;
    const char* tooltip;
    double min = -1e6;
    double max = 1e6;
    const char* unit = "";
    // Fields added after version 1 shipped are written only when they differ from their default, so files
    // saved before the field existed re-save byte for byte. Such a default is part of the format for good.
    bool omitted_at_default = false;
    // The editor's inspector shows the number as a slider over [min, max] instead of a drag field.
    bool slider = false;
};

// A colour as designers write it ("#ffcc80"), held as sRGB components in 0..1.
struct Color {
    float r = 1, g = 1, b = 1;
    bool operator==(const Color&) const = default;
};

// An enumerated string field (pickup kind, texture names are free strings instead).
struct Choice {
    std::string value;
    std::vector<std::string> options;
    bool operator==(const Choice& o) const { return value == o.value; }
};

// A sound, named as its file in assets/sounds without ".wav" ("machine_hum"): lower-case letters, digits
// and underscores (level/sound_name.h has the rule). For a SoundName field, FieldInfo's min and max bound
// the name's length: min 0 lets the name be empty, meaning no sound. Whether the file exists is the
// editor's validation (a designer drops files into the folder); the format only checks the spelling.
struct SoundName {
    std::string value;
    bool operator==(const SoundName&) const = default;
};
inline constexpr int kMaxSoundNameLength = 64;

// A robot's patrol: the points it walks in order while idle, instead of wandering. No points means no
// patrol. `mode` "loop" goes from the last point back to the first, "ping_pong" turns round at either end;
// the robot stands `wait` seconds at every point it reaches.
struct Patrol {
    std::vector<Vec3> points;
    Choice mode{"loop", {"loop", "ping_pong"}};
    float wait = 0.0f;
    bool active() const { return !points.empty(); }
    bool ping_pong() const { return mode.value == "ping_pong"; }
    bool operator==(const Patrol&) const = default;
};
inline constexpr int kMaxPatrolPoints = 256;  // a route, not a polyline export: more is a mistake
inline constexpr double kMaxPatrolWait = 600; // seconds, the same bound as angry_duration
inline constexpr double kPatrolReach = 50;    // how far outside the level's extent a point may lie, units

// ---- per-type properties -------------------------------------------------------------------------------
// Positions: walls, stairs, doors, lights, robots, pickups, cylinders and the panel stand on `position`
// (it is their bottom centre); floors have their walking surface at position.y (ceilings their underside);
// a sound emitter's position is the point its sound comes from.

struct WallProps {
    Vec3 size{10.0f, 16.0f, 0.5f}; // width (local x), height (y), thickness (z)
    std::string texture = "concrete";
    float texture_scale = 4.0f; // world units per texture repeat
    template <class V>
    void visit(V& v) {
        v.field(size, {"size", "Width, height and thickness of the wall slab", 0.01, 1e4, "units"});
        v.field(texture,
                {"texture", "Surface material from assets/textures (the texture browser shows them)"});
        v.field(texture_scale,
                {"texture_scale", "World units covered by one repeat of the texture", 0.01, 1e4, "units"});
    }
    bool operator==(const WallProps&) const = default;
};

struct FloorProps {
    Vec2 size{20.0f, 20.0f}; // extent along local x and z
    float thickness = 0.5f;
    bool ceiling = false; // a ceiling: the slab lies above position.y and faces down
    std::string texture = "tiles";
    float texture_scale = 2.0f;
    template <class V>
    void visit(V& v) {
        v.field(size, {"size", "Extent along local x and z", 0.01, 1e4, "units"});
        v.field(thickness, {"thickness", "Slab thickness (below the surface, or above it for a ceiling)",
                            0.01, 100, "units"});
        v.field(ceiling, {"ceiling", "Acts as a ceiling: the slab is above position.y and faces down"});
        v.field(texture,
                {"texture", "Surface material from assets/textures (the texture browser shows them)"});
        v.field(texture_scale,
                {"texture_scale", "World units covered by one repeat of the texture", 0.01, 1e4, "units"});
    }
    bool operator==(const FloorProps&) const = default;
};

struct StairProps {
    Vec3 size{12.0f, 6.0f, 12.0f}; // width (x), total rise (y), run (z); rises toward local -z
    int steps = 10;
    std::string texture = "tiles";
    template <class V>
    void visit(V& v) {
        v.field(size, {"size", "Width, total rise and total run; the stair rises toward its local -z", 0.01,
                       1e4, "units"});
        v.field(steps, {"steps", "Number of steps", 1, 200});
        v.field(texture,
                {"texture", "Surface material from assets/textures (the texture browser shows them)"});
    }
    bool operator==(const StairProps&) const = default;
};

struct DoorProps {
    float width = 5.0f;
    float height = 5.0f;
    bool open = false;        // initial state
    float open_offset = 2.0f; // how far each leaf slides sideways
    float open_time = 0.5f;   // seconds to open or close
    bool locked = false;      // the player's E does nothing (links still open and close it)
    template <class V>
    void visit(V& v) {
        v.field(width, {"width", "Width of the doorway (two sliding leaves)", 0.5, 100, "units"});
        v.field(height, {"height", "Height of the doorway", 0.5, 100, "units"});
        v.field(open, {"open", "Open when the level starts"});
        v.field(open_offset, {"open_offset", "How far each leaf slides when opening", 0, 100, "units"});
        v.field(open_time, {"open_time", "Seconds to open or close", 0.01, 60, "s"});
        v.field(locked, {.name = "locked",
                         .tooltip = "Locked when the level starts: the player cannot open or close it (links "
                                    "still can; an unlock link frees it)",
                         .omitted_at_default = true});
    }
    bool operator==(const DoorProps&) const = default;
};

struct LightProps { // shared by floor_light (spot on a stand) and top_light (hanging point light)
    Color color{1, 1, 1};
    float intensity = 1.0f;
    float range = 24.0f;
    bool on = true;
    template <class V>
    void visit(V& v) {
        v.field(color, {"color", "Light colour (sRGB hex)"});
        v.field(intensity, {"intensity", "Brightness multiplier", 0, 100});
        v.field(range, {"range", "Distance at which the light fades to nothing", 0.1, 1000, "units"});
        v.field(on, {"on", "Lit when the level starts (E toggles floor lights)"});
    }
    bool operator==(const LightProps&) const = default;
};

struct FloorLightProps {
    LightProps light{{1, 1, 1}, 0.8f, 20.0f, true};
    float cone_angle = 35.0f; // half-angle of the spot, degrees
    float height = 4.0f;      // lamp stand height
    template <class V>
    void visit(V& v) {
        light.visit(v);
        v.field(cone_angle, {"cone_angle", "Half-angle of the spot light cone", 1, 89, "deg"});
        v.field(height, {"height", "Height of the lamp stand", 0.5, 20, "units"});
    }
    bool operator==(const FloorLightProps&) const = default;
};

struct TopLightProps {
    LightProps light{{1, 1, 1}, 1.0f, 24.0f, true};
    float hang = 2.0f; // the bulb hangs this far below position.y (the fixture is at the ceiling)
    template <class V>
    void visit(V& v) {
        light.visit(v);
        v.field(hang, {"hang", "How far below the fixture the bulb hangs", 0, 20, "units"});
    }
    bool operator==(const TopLightProps&) const = default;
};

struct RobotProps {
    float health = 100.0f;
    float velocity = 8.0f;           // chase speed
    float rotation_velocity = 8.0f;  // turn rate
    float shooting_distance = 11.0f; // stops and shoots at or inside this distance
    float eye_radius_min = 19.0f;    // notices the player inside this distance (with line of sight)
    float eye_radius_max = 25.0f;    // keeps following inside this distance
    float cooldown = 1.0f;           // seconds between shots
    float hit_probability = 0.7f;    // chance that a shot is fired at all
    float angry_duration = 10.0f;    // after being shot, follows regardless of distance
    float damage = 10.0f;            // damage per hit on the player
    bool dummy = false;              // the dojo's test robot: no AI, no collision, keys 1-5 play animations
    float search_time = 8.0f;        // after losing the player: keeps hunting, then searches, then idles
    float hearing_radius = 30.0f;    // shots and explosions inside this path distance alert the robot
    Patrol patrol;                   // walked while idle; none: random wander
    bool dormant = false;            // stands still, seeing and hearing nothing, until activated or shot
    template <class V>
    void visit(V& v) {
        v.field(health, {"health", "Hit points", 1, 1e5});
        v.field(velocity, {"velocity", "Chase speed", 0, 200, "units/s"});
        v.field(rotation_velocity, {"rotation_velocity", "Turn rate", 0, 100, "rad/s"});
        v.field(shooting_distance,
                {"shooting_distance", "Stops and shoots at or inside this distance", 0, 1000, "units"});
        v.field(eye_radius_min,
                {"eye_radius_min", "Notices the player inside this distance, with line of sight", 0, 1000,
                 "units"});
        v.field(eye_radius_max,
                {"eye_radius_max", "Keeps following the player inside this distance", 0, 1000, "units"});
        v.field(cooldown, {"cooldown", "Seconds between shots", 0, 60, "s"});
        v.field(hit_probability, {"hit_probability", "Chance that a shot is fired at all", 0, 1});
        v.field(angry_duration,
                {"angry_duration", "After being shot, follows regardless of distance for this long", 0, 600,
                 "s"});
        v.field(damage, {"damage", "Damage dealt to the player per hit", 0, 1000});
        v.field(dummy, {"dummy", "Animation dummy (the dojo's test robot): no AI, cannot be shot or collided "
                                 "with; keys 1-5 play its animations"});
        v.field(
            search_time,
            {"search_time",
             "After losing the player, hunts and then searches this long before returning to idle or patrol",
             0, 600, "s", true});
        v.field(hearing_radius,
                {"hearing_radius",
                 "Shots and explosions within this distance along the navigation mesh alert the robot", 0,
                 1000, "units", true});
        v.field(patrol, {"patrol", "Points walked in order while idle, instead of wandering", -1e5, 1e5,
                         "units", true});
        v.field(dormant, {.name = "dormant",
                          .tooltip = "Stands still, seeing and hearing nothing, until a link activates or "
                                     "alerts it or it is shot",
                          .omitted_at_default = true});
    }
    bool operator==(const RobotProps&) const = default;
};

struct PickupProps {
    Choice kind{"health", {"health", "ammo", "shield"}};
    float amount = 10.0f;
    template <class V>
    void visit(V& v) {
        v.field(kind, {"kind", "What the pickup restores"});
        v.field(amount, {"amount", "How much it adds (capped at the player's maximum)", 0, 10000});
    }
    bool operator==(const PickupProps&) const = default;
};

struct GasCylinderProps {
    float radius = 0.5f;
    float height = 2.0f;
    float damage = 30.0f; // at the centre of the blast; falls off with distance
    float blast_radius = 7.0f;
    float explosion_power = 25.0f; // knock-back speed
    template <class V>
    void visit(V& v) {
        v.field(radius, {"radius", "Cylinder radius", 0.05, 10, "units"});
        v.field(height, {"height", "Cylinder height", 0.1, 20, "units"});
        v.field(damage, {"damage", "Damage at the centre of the blast", 0, 1000});
        v.field(blast_radius, {"blast_radius", "Radius of the blast", 0, 100, "units"});
        v.field(explosion_power,
                {"explosion_power", "Knock-back speed given to bodies in the blast", 0, 500, "units/s"});
    }
    bool operator==(const GasCylinderProps&) const = default;
};

struct ControlPanelProps {
    Vec3 size{2.94f, 4.0f, 5.34f};
    template <class V>
    void visit(V& v) {
        v.field(size, {"size", "Collision box of the console", 0.1, 100, "units"});
    }
    bool operator==(const ControlPanelProps&) const = default;
};

// An ambient sound emitter. Unlike the other entities, its position is the point the sound comes from (the
// centre of the editor's marker), not a bottom centre. The game's rules ignore it: no body, no state; the
// runtime plays it.
struct SoundProps {
    SoundName sound{"machine_hum"};
    float volume = 1.0f;
    float radius = 40.0f; // heard within this distance, fading to silence at it
    bool loop = true;     // off: played once when the level starts
    template <class V>
    void visit(V& v) {
        v.field(sound,
                {"sound", "Sound file in assets/sounds, named without .wav (machine_hum, vent_loop, ...)", 1,
                 kMaxSoundNameLength});
        v.field(volume, {.name = "volume",
                         .tooltip = "Loudness at the emitter: 0 silent, 1 as recorded",
                         .min = 0,
                         .max = 1,
                         .slider = true});
        v.field(radius, {.name = "radius",
                         .tooltip = "Heard within this distance, fading to silence at it",
                         .min = 0.5,
                         .max = 500,
                         .unit = "units",
                         .slider = true});
        v.field(loop,
                {"loop", "Repeats for as long as the level runs; off: plays once when the level starts"});
    }
    bool operator==(const SoundProps&) const = default;
};

// ---- level logic (docs/level-format.md, "Level logic") ---------------------------------------------------
// The logic entities are invisible in the game: a trigger is a box that notices who walks in, a spawner makes
// robots during play, a message is a line of HUD text. Like every entity they stand on `position`.

// A box (bottom centre on position, turned by the yaw) that emits on_enter when someone of `who` enters it
// while it was empty and on_exit when the last one leaves.
struct TriggerProps {
    Vec3 size{4.0f, 4.0f, 4.0f};
    Choice who{"player", {"player", "robots", "both"}};
    bool enabled = true;
    template <class V>
    void visit(V& v) {
        v.field(size, {"size", "Width, height and depth of the box", 0.1, 1e4, "units"});
        v.field(who, {"who", "Who sets it off: the player, robots, or both"});
        v.field(enabled,
                {"enabled", "Notices anyone when the level starts (enable and disable links switch it)"});
    }
    bool operator==(const TriggerProps&) const = default;
};

// Makes robots (with `robot`'s properties) when a spawn link fires: `count` of them, one every `interval`
// seconds, never more than `max_alive` of its robots alive at once, each on the robots' navigation mesh.
struct SpawnerProps {
    int count = 3;
    float interval = 2.0f;
    int max_alive = 3;
    RobotProps robot;
    template <class V>
    void visit(V& v) {
        v.field(count, {"count", "Robots made by each spawn link", 1, 100});
        v.field(interval, {"interval", "Seconds between two robots", 0, 600, "s"});
        v.field(max_alive, {"max_alive", "At most this many of its robots alive at once (it waits)", 1, 100});
        robot.visit(v);
    }
    bool operator==(const SpawnerProps&) const = default;
};

inline constexpr int kMaxMessageLength = 500; // characters: one or two lines of HUD text

// A line of HUD text that a show link puts on screen for `duration` seconds.
struct MessageProps {
    std::string text = "Message";
    float duration = 4.0f;
    template <class V>
    void visit(V& v) {
        v.field(text, {"text", "What the HUD shows", 1, kMaxMessageLength});
        v.field(duration, {"duration", "Seconds on screen", 0.5, 600, "s"});
    }
    bool operator==(const MessageProps&) const = default;
};

// ---- shaped geometry (docs/level-format.md, "Brushes")
// ----------------------------------------------------- A convex brush: its face planes in the entity's own
// frame (world = R * local + position, like every entity), so moving, turning, duplicating and grouping work
// on brushes unchanged, and a brush near its position keeps small, exact plane distances. The brush is always
// valid (brush::Brush refuses invalid planes), so every user gets its derived vertices and faces; the world
// brush is level::world_brush.
inline constexpr std::string_view kDefaultBrushMaterial = "concrete";
inline constexpr double kDefaultBrushHalfSize = 2.0; // the default brush: a 4 x 4 x 4 box on its position

// A 4 x 4 x 4 box standing on the origin (bottom centre, like walls), every face kDefaultBrushMaterial.
const brush::Brush& default_brush();

struct BrushProps {
    brush::Brush brush = default_brush();
    bool ceiling = false; // casts no sun shadow; hidden in the editor's views while ceilings are hidden
    template <class V>
    void visit(V& v) {
        v.field(ceiling, {"ceiling", "Acts as a ceiling: casts no sun shadow (the sun stands for the "
                                     "simulator's overhead light) and is hidden with the editor's ceilings"});
        v.field(brush, {"faces", "The brush's face planes in the entity's frame, each with its material and "
                                 "texture mapping"});
    }
    bool operator==(const BrushProps&) const = default;
};

// ---- designers' models (docs/models.md) --------------------------------------------------------------
// A model file (glTF, OBJ, FBX) placed like a brush (world = R * scale * model + position, the model's origin
// on the entity's position), named relative to the shipped assets/models or the designer's models folder in
// the user data folder (modelio/model_files.h). Its collision is chosen: none, the box around it, one
// convex hull of its vertices, several hulls (a convex decomposition, at most `hulls` of them), or its own
// triangles (static, level/model_entity.h).
inline constexpr int kMaxModelFileLength = 200; // characters
inline constexpr int kDefaultModelHulls = 8;
inline constexpr int kMaxModelHulls = 32;

inline constexpr std::string_view kDefaultModelFile =
    "control_panel.gltf"; // a shipped model, so a new one shows

struct ModelProps {
    std::string file{kDefaultModelFile};
    float scale = 1.0f;
    Choice collision{"hull", {"none", "box", "hull", "hulls", "mesh"}};
    int hulls = kDefaultModelHulls;
    template <class V>
    void visit(V& v) {
        v.field(file, {"file",
                       "The model file (.glb, .gltf, .obj, .fbx) in assets/models or your models folder, "
                       "as a relative path with '/'",
                       1, kMaxModelFileLength});
        v.field(scale,
                {"scale", "Multiplies the model's size (one metre in the file is one unit)", 0.001, 1000});
        v.field(collision, {"collision", "What the player, robots and shots collide with: nothing, the box "
                                         "around the model, one convex hull of it, several convex hulls "
                                         "(a decomposition: for chairs, arches, shelves), or its triangles"});
        v.field(hulls,
                {.name = "hulls",
                 .tooltip = "The most convex hulls \"hulls\" collision cuts the model into: more follow "
                            "its shape closer and cost more in every contact test",
                 .min = 1,
                 .max = kMaxModelHulls,
                 .omitted_at_default = true,
                 .slider = true});
    }
    bool operator==(const ModelProps&) const = default;
};

// The variant's order is the EntityType order.
using Props = std::variant<WallProps, FloorProps, StairProps, DoorProps, FloorLightProps, TopLightProps,
                           RobotProps, PickupProps, GasCylinderProps, ControlPanelProps, SoundProps,
                           TriggerProps, SpawnerProps, MessageProps, BrushProps, ModelProps>;

enum class EntityType : std::uint8_t {
    Wall,
    Floor,
    Stair,
    Door,
    FloorLight,
    TopLight,
    Robot,
    Pickup,
    GasCylinder,
    ControlPanel,
    Sound,
    Trigger,
    Spawner,
    Message,
    Brush,
    Model,
    Count
};

// "wall", "floor", "stair", "door", "floor_light", "top_light", "robot", "pickup", "gas_cylinder",
// "control_panel", "sound", "trigger", "spawner", "message", "brush", "model"
std::string_view type_name(EntityType type);
bool type_from_name(std::string_view name, EntityType& out);
const std::array<EntityType, static_cast<size_t>(EntityType::Count)>& all_types();
Props default_props(EntityType type);

// "When `event` happens here, do `action` to `target`", `delay` seconds later; a `once` link fires only the
// first time. The target is named: an entity by its `name` (which must then be unique in the level), an
// objective by its `id`, or the level itself as "level" (win, lose). Which events a source emits and which
// actions a target takes are in level/logic_names.h; the names stay strings here so that a draft with a typo
// still loads into the editor, and the checks name the typo.
struct Link {
    std::string event;
    std::string target;
    std::string action;
    float delay = 0.0f; // seconds
    bool once = false;
    template <class V>
    void visit(V& v) {
        v.field(event, {"event", "What sets the link off (on_enter, on_death, on_use, ...)"});
        v.field(target, {"target", "The entity name, objective id or \"level\" it acts on"});
        v.field(action, {"action", "What it does to the target (open, show, spawn, complete, win, ...)"});
        v.field(delay, {"delay", "Seconds between the event and the action", 0, 3600, "s"});
        v.field(once, {"once", "Fires only the first time the event happens"});
    }
    bool operator==(const Link&) const = default;
};
inline constexpr int kMaxLinks = 64;          // per entity, objective or level: a fan-out, not a script
inline constexpr double kMaxLinkDelay = 3600; // seconds
inline constexpr std::string_view kLevelTarget = "level";

// One thing the player must do. It completes when a `complete` link names it, or when everything in `kill`
// (robots, and spawners: all their robots made and dead) is dead; completing it fires its on_complete links.
// The level is won when every objective is complete.
struct Objective {
    std::string id;   // unique among the objectives; links name it
    std::string text; // what the HUD shows
    std::vector<std::string> kill;
    std::vector<Link> links;
    template <class V>
    void visit(V& v) {
        v.field(id, {"id", "Names the objective in links (unique)"});
        v.field(text, {"text", "What the HUD shows", 1, kMaxMessageLength});
        v.field(kill, {"kill", "Names of robots and spawners that must all be dead to complete it"});
        v.field(links, {"links", "on_complete links"});
    }
    bool operator==(const Objective&) const = default;
};
inline constexpr int kMaxObjectives = 32;
inline constexpr int kMaxKillNames = 256;

struct Entity {
    int id = 0;       // stable, unique within the level, never reused
    std::string name; // free text shown in the editor's outliner
    Vec3 position{0.0f};
    Vec3 rotation{0.0f}; // yaw (about +y), pitch (about +x), roll (about +z), degrees
    Props props;
    std::vector<Link> links; // what this entity's events set off (file key "links", after "props")

    EntityType type() const { return static_cast<EntityType>(props.index()); }
    template <class T>
    T& as() {
        return std::get<T>(props);
    }
    template <class T>
    const T& as() const {
        return std::get<T>(props);
    }
    template <class T>
    T* try_as() {
        return std::get_if<T>(&props);
    }
    template <class T>
    const T* try_as() const {
        return std::get_if<T>(&props);
    }
    Quat orientation() const {
        return quat_from_ypr(radians(rotation.x), radians(rotation.y), radians(rotation.z));
    }
    bool operator==(const Entity&) const = default;
};

struct Settings {
    // Default colours sit on the file's 8-bit grid ("#8c99b3"...), so a new level survives save/load exactly.
    Color ambient_color{140 / 255.0f, 153 / 255.0f, 179 / 255.0f};
    float ambient_intensity = 0.2f;
    Color fog_color{13 / 255.0f, 15 / 255.0f, 20 / 255.0f};
    float fog_density = 0.004f; // exponential fog; 0 disables
    Vec3 sun_direction{
        -0.28221625f, -0.94072086f,
        -0.18814416f}; // the direction sunlight travels: (-0.3, -1, -0.2) normalised, as loading keeps it
    Color sun_color{1.0f, 245 / 255.0f, 230 / 255.0f};
    float sun_intensity = 0.1f;
    float gravity = -25.0f;                      // units/s^2 along y
    SoundName ambient_sound{"ambient_facility"}; // the level's ambient loop; "" = none
    template <class V>
    void visit(V& v) {
        v.field(ambient_color, {"ambient_color", "Colour of the ambient light"});
        v.field(ambient_intensity, {"ambient_intensity", "Ambient light strength", 0, 10});
        v.field(fog_color, {"fog_color", "Colour of the fog"});
        v.field(fog_density, {"fog_density", "Exponential fog density (0 = no fog)", 0, 1});
        v.field(sun_direction, {"sun_direction", "Direction the sunlight travels", -1, 1});
        v.field(sun_color, {"sun_color", "Colour of the sun"});
        v.field(sun_intensity, {"sun_intensity", "Sun strength", 0, 100});
        v.field(gravity, {"gravity", "Vertical acceleration (negative is down)", -1000, 0, "units/s^2"});
        v.field(ambient_sound,
                {"ambient_sound",
                 "The level's ambient loop from assets/sounds, named without .wav (\"\" = none)", 0,
                 kMaxSoundNameLength, "", true});
    }
    bool operator==(const Settings&) const = default;
};

struct PlayerStart {
    Vec3 position{0.0f}; // feet
    float yaw = 0.0f;    // degrees; 0 faces -z
    bool operator==(const PlayerStart&) const = default;
};

struct Level {
    std::string name = "Untitled";
    Settings settings;
    PlayerStart player_start;
    int next_id = 1;
    std::vector<Objective> objectives; // all complete: the level is won (none: it is never won by them)
    std::vector<Link> links;           // the level's own: on_start
    std::vector<Entity> entities;
    EditorData editor; // the editor's layers, groups, prefab instances, hidden and locked entities

    Entity* find(int id);
    const Entity* find(int id) const;
    // Adds an entity with a fresh id (next_id, then increments it) and returns it.
    Entity& add(EntityType type, Vec3 position = Vec3(0.0f), std::string name = {});
    bool operator==(const Level&) const = default;
};

} // namespace ks::level
