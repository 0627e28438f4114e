#include "render/level_scene.h"

#include "core/log.h"
#include "level/entity_shapes.h"
#include "level/model_entity.h"
#include "modelio/model_lod.h"
#include "render/brush_mesh.h"
#include "render/light_bake_cache.h"
#include "render/scene_renderer.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace ks::render {

using level::EntityType;

Vec3 to_linear(const level::Color& c) {
    auto f = [](float v) { return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f); };
    return Vec3(f(c.r), f(c.g), f(c.b));
}

Environment environment_from_settings(const level::Settings& s) {
    Environment env;
    env.sky_color = to_linear(s.ambient_color) * s.ambient_intensity;
    env.ground_color = env.sky_color * 0.6f;
    Vec3 dir = s.sun_direction;
    env.sun_direction = glm::length(dir) > 1e-6f && is_finite(dir) ? glm::normalize(dir) : Vec3(0, -1, 0);
    env.sun_color = to_linear(s.sun_color) * s.sun_intensity;
    env.fog_color = to_linear(s.fog_color);
    env.fog_density = s.fog_density;
    return env;
}

Environment preview_environment(float fog_density) {
    Environment env;
    env.sky_color = Vec3(0.35f, 0.38f, 0.45f);
    env.ground_color = Vec3(0.12f, 0.11f, 0.1f);
    env.sun_direction = Vec3(-0.4f, -1.0f, -0.5f);
    env.sun_color = Vec3(0.55f, 0.52f, 0.48f);
    env.fog_color = Vec3(0.02f, 0.025f, 0.035f);
    env.fog_density = fog_density;
    return env;
}

geometry::Camera player_start_camera(const level::Level& level, float aspect) {
    geometry::Camera cam;
    cam.position = level.player_start.position + Vec3(0.0f, 3.0f, 0.0f);
    cam.yaw = radians(level.player_start.yaw);
    cam.fov_y = radians(45.0f); // the reference's field of view
    cam.aspect = aspect;
    return cam;
}

namespace {
Mat4 entity_matrix(const level::Entity& e) {
    return level::entity_frame(e).matrix();
}

// The colour, brightness and reach both light entities share; position and aim are the caller's.
Light light_from(const level::LightProps& props, Light::Type type) {
    Light light;
    light.type = type;
    light.color = to_linear(props.color);
    light.intensity = props.intensity;
    light.range = props.range;
    return light;
}
} // namespace

namespace {
// Level geometry before its light map is baked: a mesh of polygons and solids (a wall's box, a stair's
// steps, a brush) and the surfaces drawn from it, one per material (polygon ranges of the mesh).
struct SolidGeometry {
    struct Part {
        const Material* material = nullptr;
        std::uint32_t first_polygon = 0, polygon_count = 0;
    };
    MeshData mesh;
    bool casts_shadow = true;
    std::vector<Part> parts;
};

// One solid of six quads, every vertex a corner of its bounds: an axis-aligned box, whose bounds are solid
// (occlusion culling). A stair's steps or a ramp's bounds hold air; a box drawn in two materials is drawn as
// two meshes, neither of them the whole box.
bool is_axis_aligned_box(const MeshData& data) {
    if (data.solid_sizes.size() != 1 || data.polygon_sizes.size() != 6) return false;
    for (std::uint32_t n : data.polygon_sizes)
        if (n != 4) return false;
    const geometry::Aabb bounds = data.bounds();
    const float eps = 1e-3f * (1.0f + glm::length(bounds.max - bounds.min));
    for (const auto& v : data.vertices)
        for (int a = 0; a < 3; ++a)
            if (std::abs(v.position[a] - bounds.min[a]) >= eps &&
                std::abs(v.position[a] - bounds.max[a]) >= eps)
                return false;
    return true;
}

// A wall's, floor's or stair's geometry: one material, ceilings cast no sun shadow (the sun stands for the
// simulator's overhead light, as in the reference).
std::optional<SolidGeometry> surface_geometry(const level::Entity& e, AssetLibrary& assets) {
    MeshData data = build_surface_mesh(e);
    if (data.vertices.empty()) return std::nullopt;
    const std::string& texture = e.try_as<level::WallProps>()    ? e.as<level::WallProps>().texture
                                 : e.try_as<level::FloorProps>() ? e.as<level::FloorProps>().texture
                                                                 : e.as<level::StairProps>().texture;
    SolidGeometry g;
    g.casts_shadow = !level::is_ceiling(e);
    g.parts.push_back({&assets.surface(texture), 0, static_cast<std::uint32_t>(data.polygon_sizes.size())});
    g.mesh = std::move(data);
    return g;
}
// A brush entity's geometry: its brush placed in the world (level::world_brush), each material's faces one
// surface; it occludes like a wall and casts the sun's shadow unless it is a ceiling (as floors).
std::optional<SolidGeometry> brush_geometry(const level::Entity& e, AssetLibrary& assets) {
    auto world = level::world_brush(e);
    if (!world.ok()) {
        log::warn("brush entity ", e.id, " not drawn: ", world.error().str());
        return std::nullopt;
    }
    BrushMesh built = build_brush_mesh(*world);
    SolidGeometry g;
    g.casts_shadow = !level::is_ceiling(e);
    for (const auto& range : built.materials)
        g.parts.push_back({&assets.surface(range.material), range.first_polygon, range.polygon_count});
    g.mesh = std::move(built.mesh);
    return g;
}
} // namespace

MeshData build_surface_mesh(const level::Entity& e) {
    MeshData mesh;
    const auto solid = level::static_solid_shape(e);
    if (!solid) return mesh;
    // Walls and floors are one box, stairs `steps` boxes (step i, from the low end at local +z, a block from
    // the floor up to its tread), all drawn as brushes: one geometry path for every level surface.
    std::vector<std::pair<Vec3, Vec3>> boxes; // centre and half size in the solid's frame
    float world_per_repeat = 4.0f;            // stairs: 4 units per repeat
    if (const auto* wall = e.try_as<level::WallProps>()) {
        boxes.emplace_back(solid->local_centre, solid->half);
        world_per_repeat = wall->texture_scale;
    } else if (const auto* floor = e.try_as<level::FloorProps>()) {
        boxes.emplace_back(solid->local_centre, solid->half);
        world_per_repeat = floor->texture_scale;
    } else if (const auto* stair = e.try_as<level::StairProps>()) {
        const Vec3 size = solid->half * 2.0f;
        const int steps = std::max(stair->steps, 1);
        const float rise = size.y / static_cast<float>(steps), run = size.z / static_cast<float>(steps);
        for (int i = 0; i < steps; ++i) {
            const float top = rise * static_cast<float>(i + 1),
                        z_front = size.z * 0.5f - run * static_cast<float>(i);
            boxes.emplace_back(Vec3(0.0f, top * 0.5f, z_front - run * 0.5f), Vec3(size.x, top, run) * 0.5f);
        }
    }
    for (const auto& [centre, half] : boxes) {
        auto box = placed_box_brush(centre, half, solid->frame, world_per_repeat);
        if (!box.ok()) {
            log::warn("entity ", e.id, ": not drawn: ", box.error().message);
            continue;
        }
        append_mesh(mesh, build_brush_mesh(*box).mesh);
    }
    return mesh;
}

namespace {
// Each polygon's albedo for the bake's bounce: its material's base colour times its colour map's mean.
std::vector<std::vector<Vec3>> surface_albedo(const std::vector<SolidGeometry>& geometry) {
    std::vector<std::pair<const Material*, Vec3>> known;
    std::vector<std::vector<Vec3>> out;
    for (const SolidGeometry& g : geometry) {
        std::vector<Vec3>& albedo = out.emplace_back(g.mesh.polygon_sizes.size(), Vec3(0.5f));
        for (const auto& part : g.parts) {
            if (!part.material) continue;
            auto it = std::find_if(known.begin(), known.end(),
                                   [&](const auto& k) { return k.first == part.material; });
            if (it == known.end()) {
                const Material& m = *part.material;
                known.emplace_back(&m, Vec3(m.base_factor) * texture_mean_color(m.base_map, Vec3(1.0f)));
                it = known.end() - 1;
            }
            for (std::uint32_t p = part.first_polygon;
                 p < part.first_polygon + part.polygon_count && p < albedo.size(); ++p)
                albedo[p] = it->second;
        }
    }
    return out;
}
} // namespace

LevelScene::Prop LevelScene::make_prop(const level::Entity& e, const ModelLevels& levels, const Mat4& root) {
    Prop p;
    p.entity_id = e.id;
    p.type = e.type();
    p.model = &levels.full();
    p.levels = &levels;
    p.root = root;
    p.ground = e.position.y;
    return p;
}

LevelSceneOptions level_scene_options(const RendererSettings& resolved) {
    return {resolved.quality == RenderQuality::Fast, resolved.lightmap_float};
}

std::unique_ptr<LevelScene> LevelScene::build(const level::Level& level, AssetLibrary& assets,
                                              const LevelSceneOptions& options) {
    auto scene = std::unique_ptr<LevelScene>(new LevelScene(options));
    scene->environment_ = environment_from_settings(level.settings);
    std::vector<SolidGeometry> geometry; // uploaded once their light-map coordinates are baked
    for (const auto& e : level.entities) {
        const Mat4 m = entity_matrix(e);
        switch (e.type()) {
        case EntityType::Wall:
        case EntityType::Floor:
        case EntityType::Stair:
            if (auto g = surface_geometry(e, assets)) geometry.push_back(std::move(*g));
            break;
        case EntityType::Brush:
            if (auto g = brush_geometry(e, assets)) geometry.push_back(std::move(*g));
            break;
        case EntityType::Door: {
            const auto& d = e.as<level::DoorProps>();
            Prop p = make_prop(e, assets.model_levels("door"), level::door_model_matrix(e));
            p.door_open = d.open ? 1.0f : 0.0f;
            p.door = d;
            scene->props_.push_back(p);
            break;
        }
        case EntityType::FloorLight: {
            const auto& f = e.as<level::FloorLightProps>();
            Prop p = make_prop(e, assets.model_levels("floor_light"), level::floor_light_model_matrix(e));
            p.light_on = f.light.on;
            p.light = light_from(f.light, Light::Type::Spot);
            p.light.cos_outer = std::cos(radians(f.cone_angle));
            p.light.cos_inner = std::cos(radians(f.cone_angle * 0.7f));
            std::vector<Mat4> world;
            p.model->node_transforms(p.root, p.model->rest_pose(), world);
            int origin = p.model->find_node("light_origin"), head = p.model->find_node("lamp_head");
            p.light.position =
                origin >= 0 ? Vec3(world[size_t(origin)][3]) : Vec3(m * Vec4(0, f.height * 0.95f, 0, 1));
            Mat4 aim = head >= 0 ? world[size_t(head)] : (origin >= 0 ? world[size_t(origin)] : m);
            p.light.direction = glm::normalize(-Vec3(aim[2]));
            scene->props_.push_back(p);
            break;
        }
        case EntityType::TopLight: {
            const auto& t = e.as<level::TopLightProps>();
            Prop p = make_prop(e, assets.model_levels("top_light"), level::top_light_model_matrix(e));
            p.light_on = t.light.on;
            p.light = light_from(t.light, Light::Type::Point);
            p.light.position = e.position - Vec3(0.0f, t.hang, 0.0f);
            scene->props_.push_back(p);
            break;
        }
        case EntityType::Robot:
            // The same placement as the game view's robots (tests/runtime/test_play_views.cpp).
            scene->props_.push_back(make_prop(e, assets.model_levels("robot"),
                                              level::robot_model_matrix(e.position, radians(e.rotation.x))));
            break;
        case EntityType::Pickup: {
            const auto& k = e.as<level::PickupProps>();
            const Mat4 root = level::pickup_model_matrix(level::pickup_centre(e.position), e.orientation());
            scene->props_.push_back(make_prop(e, assets.model_levels("pickup_" + k.kind.value), root));
            break;
        }
        case EntityType::GasCylinder: {
            const auto& g = e.as<level::GasCylinderProps>();
            const Mat4 root = level::gas_cylinder_model_matrix(level::gas_cylinder_centre(e.position, g),
                                                               radians(e.rotation.x), g);
            scene->props_.push_back(make_prop(e, assets.model_levels("gas_cylinder"), root));
            break;
        }
        case EntityType::ControlPanel: {
            scene->props_.push_back(
                make_prop(e, assets.model_levels("control_panel"), level::control_panel_model_matrix(e)));
            break;
        }
        case EntityType::Model: { // a designer's model; the marker cube when its file cannot be read
            scene->props_.push_back(
                make_prop(e, assets.level_model(e.as<level::ModelProps>().file), level::model_matrix(e)));
            break;
        }
        case EntityType::Sound:   // heard, not seen: the editor draws its own marker
        case EntityType::Trigger: // the logic entities are invisible in the game
        case EntityType::Spawner:
        case EntityType::Message:
        case EntityType::Count:
            break;
        }
    }
    for (const auto& g : geometry) scene->bounds_ = geometry::merge(scene->bounds_, g.mesh.bounds());
    for (const auto& p : scene->props_)
        scene->bounds_ = geometry::merge(scene->bounds_, geometry::transform_aabb(p.model->bounds, p.root));

    // Bake the level geometry's light (every light, then switch off those that start off).
    std::vector<Light>& bake_lights = scene->bake_lights_;
    for (auto& p : scene->props_)
        if (p.type == EntityType::FloorLight || p.type == EntityType::TopLight) {
            p.bake_light = static_cast<int>(bake_lights.size());
            bake_lights.push_back(p.light);
        }
    // Only the fast path reads the light map: GPUs (Full) skip the bake's CPU time.
    if (options.bake_light_map) {
        std::vector<std::vector<Vec3>> albedo = surface_albedo(geometry);
        std::vector<BakeSurface> bake_surfaces;
        for (size_t i = 0; i < geometry.size(); ++i)
            bake_surfaces.push_back({&geometry[i].mesh, geometry[i].casts_shadow, &albedo[i]});
        if (options.defer_bake)
            scene->bake_stats_ = scene->bake_.layout(bake_surfaces, options.bake);
        else if (options.cache_bake && options.background_bake)
            scene->restore_or_start_bake(bake_surfaces, options.bake);
        else if (options.cache_bake)
            scene->bake_stats_ =
                bake_cached(scene->bake_, bake_surfaces, scene->environment_, bake_lights, options.bake);
        else
            scene->bake_stats_ =
                scene->bake_.bake(bake_surfaces, scene->environment_, bake_lights, options.bake);
    }
    for (const auto& p : scene->props_)
        if (p.bake_light >= 0) scene->bake_.set_light_on(p.bake_light, p.light_on);
    for (const auto& g : geometry) {
        const bool occluder = g.parts.size() == 1 && is_axis_aligned_box(g.mesh);
        for (const auto& part : g.parts) {
            const bool whole = part.polygon_count == g.mesh.polygon_sizes.size();
            auto mesh = whole ? std::make_unique<GpuMesh>(g.mesh)
                              : std::make_unique<GpuMesh>(
                                    polygon_range(g.mesh, part.first_polygon, part.polygon_count));
            scene->surfaces_.push_back({std::move(mesh), part.material, g.casts_shadow, occluder});
        }
    }
    if (!scene->bounds_.valid()) scene->bounds_ = {Vec3(-1.0f), Vec3(1.0f)};
    return scene;
}

void LevelScene::restore_or_start_bake(const std::vector<BakeSurface>& surfaces,
                                       const BakeSettings& settings) {
    auto slot = restore_or_layout(bake_, surfaces, environment_, bake_lights_, settings,
                                  disk_cache::Store::user(), bake_stats_);
    if (!slot) return;
    // The direct light now (the full bake computes it again, with the bounce and the occlusion, on a worker).
    bake_stats_ = bake_.compute(environment_, bake_lights_, BakeSettings::direct_only());
    pending_bake_ = settings;
    pending_slot_ = std::make_shared<const LightBakeSlot>(std::move(*slot));
}

std::function<void(const LightBake&, const BakeStats&)> LevelScene::pending_bake_store() const {
    return [slot = pending_slot_](const LightBake& bake, const BakeStats& stats) {
        if (slot) (void)store_bake(bake, stats, *slot, disk_cache::Store::user());
    };
}

void LevelScene::adopt_light_bake(LightBake bake, const BakeStats& stats) {
    bake_ = std::move(bake);
    bake_stats_ = stats;
    pending_bake_.reset();
    for (const auto& p : props_)
        if (p.bake_light >= 0) bake_.set_light_on(p.bake_light, p.light_on);
    lightmap_stale_ = true;
}

void LevelScene::set_light_on(int id, bool on) {
    for (auto& p : props_)
        if (p.entity_id == id) {
            p.light_on = on;
            if (p.bake_light >= 0) bake_.set_light_on(p.bake_light, on);
        }
}

void LevelScene::set_door_open(int id, float fraction) {
    for (auto& p : props_)
        if (p.entity_id == id) p.door_open = std::clamp(is_finite(fraction) ? fraction : 0.0f, 0.0f, 1.0f);
}

void LevelScene::set_pose(int id, const ModelPose* pose) {
    for (auto& p : props_)
        if (p.entity_id == id) p.pose = pose;
}

namespace {
// A door's leaves are solid bevelled slabs (assets/generator/model_door.cpp: rounded_box with a 0.02 bevel,
// one segment): inset by more than the bevel across the height and thickness, and kept whole across the
// width so the two closed leaves meet, they are occluders. Their emit order is Model::emit's: nodes in
// order, each node's meshes in order. Only while the door's axes stay axis-aligned (yaw in 90-degree steps).
void mark_door_leaves(const Model& model, int left, int right, size_t first, std::vector<MeshInstance>& out) {
    constexpr float kBevelMargin = 0.03f;
    size_t k = first;
    for (size_t i = 0; i < model.nodes.size(); ++i)
        for (int m : model.nodes[i].meshes) {
            MeshInstance& inst = out[k++];
            const bool leaf = static_cast<int>(i) == left || static_cast<int>(i) == right;
            if (!leaf ||
                model.materials[static_cast<size_t>(model.meshes[static_cast<size_t>(m)].material)].name !=
                    "door_leaf")
                continue;
            bool axis_aligned = true; // every column of the rotation/scale part along one axis
            for (int c = 0; c < 3; ++c) {
                int nonzero = 0;
                for (int r = 0; r < 3; ++r) nonzero += std::abs(inst.world[c][r]) > 1e-4f ? 1 : 0;
                axis_aligned = axis_aligned && nonzero == 1;
            }
            const Vec3 size = inst.mesh->bounds().max - inst.mesh->bounds().min;
            if (!axis_aligned || size.y <= 4.0f * kBevelMargin || size.z <= 4.0f * kBevelMargin) continue;
            inst.occluder = true;
            inst.occluder_inset = Vec3(0.0f, kBevelMargin, kBevelMargin);
        }
}
} // namespace

void LevelScene::set_view(const geometry::Camera& camera, int viewport_height) {
    view_ = camera;
    view_height_ = viewport_height;
}

int LevelScene::model_lod(int entity_id) const {
    for (const Prop& p : props_)
        if (p.entity_id == entity_id) return p.lod;
    return -1;
}

int LevelScene::coarse_model_count() const {
    int n = 0;
    for (const Prop& p : props_) n += p.lod > 0 ? 1 : 0;
    return n;
}

void LevelScene::pick_model_lod(Prop& p) const {
    p.lod = model_lods_ && view_ ? pick_model_level(*p.levels, p.root, *view_, view_height_, p.lod) : 0;
}

void LevelScene::emit(std::vector<MeshInstance>& instances, std::vector<Light>& lights,
                      std::vector<ShadowCaster>* casters) {
    instances.clear();
    lights.clear();
    if (casters) casters->clear();
    // A light switched since the last frame: re-combine the light map (milliseconds) and upload it.
    if (bake_.update() || lightmap_stale_ || (lightmap_.id() == 0 && !bake_.texels().empty()))
        lightmap_.upload(bake_);
    lightmap_stale_ = false;
    for (const auto& s : surfaces_) {
        MeshInstance inst;
        inst.mesh = s.mesh.get();
        inst.material = s.material;
        inst.casts_shadow = s.casts_shadow;
        inst.lightmap = lightmap_.id();
        inst.occluder = s.occluder;
        instances.push_back(inst);
    }
    for (auto& p : props_) {
        const bool is_light = p.type == EntityType::FloorLight || p.type == EntityType::TopLight;
        const std::size_t first = instances.size();
        pick_model_lod(p);
        const Model& model = p.levels->level(p.lod); // every level has the full model's nodes
        if (p.type == EntityType::Door) {
            // Slide the leaves: door_l toward +x, door_r toward -x (the asset convention).
            if (pose_.local.size() != model.nodes.size()) pose_ = model.rest_pose();
            for (size_t i = 0; i < model.nodes.size(); ++i) pose_.local[i] = model.nodes[i].local;
            int l = model.find_node("door_l"), r = model.find_node("door_r");
            const float shift = level::door_model_leaf_shift(p.door, p.door_open);
            if (l >= 0)
                pose_.local[size_t(l)] =
                    glm::translate(Mat4(1.0f), Vec3(shift, 0, 0)) * pose_.local[size_t(l)];
            if (r >= 0)
                pose_.local[size_t(r)] =
                    glm::translate(Mat4(1.0f), Vec3(-shift, 0, 0)) * pose_.local[size_t(r)];
            model.emit(p.root, pose_, scratch_, instances);
            if (doors_occlude_) mark_door_leaves(model, l, r, first, instances);
        } else if (p.pose) {
            model.emit(p.root, *p.pose, scratch_, instances);
        } else {
            // Light fixtures glow with their light; they cast no sun shadow (thin stands, lamp heads).
            model.emit(p.root, scratch_, instances, is_light ? (p.light_on ? 1.5f : 0.0f) : 1.0f, !is_light);
        }
        if (is_light && p.light_on) lights.push_back(p.light);
        // What the game moves (robots, pickups, gas cylinders) casts contact shadows, as the game's view
        // does.
        const bool mover =
            p.type == EntityType::Robot || p.type == EntityType::Pickup || p.type == EntityType::GasCylinder;
        if (casters && mover) casters->push_back(shadow_caster_of(instances, first, p.ground));
    }
}

} // namespace ks::render
