#include "world_view.h"

#include "app/event_particles.h"
#include "app/muzzle_lights.h"
#include "level/entity_shapes.h"
#include "render/gpu_mesh.h"
#include "render/view_model.h"

#include <algorithm>
#include <cmath>

namespace ks::runtime {

level::Level static_part(const level::Level& level) {
    level::Level out = level;
    std::erase_if(out.entities, [](const level::Entity& e) {
        const auto t = e.type();
        return t == level::EntityType::Robot || t == level::EntityType::Pickup ||
               t == level::EntityType::GasCylinder;
    });
    return out;
}

std::unique_ptr<WorldView> WorldView::build(const level::Level& level, const game::Game& game,
                                            render::AssetLibrary& assets,
                                            const render::LevelSceneOptions& scene_options,
                                            std::function<void()> bake_ready) {
    auto view = std::unique_ptr<WorldView>(new WorldView());
    view->scene_ = render::LevelScene::build(static_part(level), assets, scene_options);
    if (scene_options.defer_bake) { // a live scenery edit: the preview first, then the full bake
        view->final_bake_ = scene_options.bake;
        view->bake_build_ = 1;
        view->bake_.start(*view->scene_, view->bake_build_, render::BakeSettings::preview());
    } else if (const auto& pending =
                   view->scene_->pending_bake()) { // a cold start: the full bake on a worker
        view->bake_build_ = 2;
        view->bake_.start(*view->scene_, view->bake_build_, *pending, view->scene_->pending_bake_store(),
                          std::move(bake_ready));
    }
    view->robot_model_ = &assets.model_levels("robot");
    view->cylinder_model_ = &assets.model_levels("gas_cylinder");
    view->rifle_ = &assets.model("rifle");
    view->pickup_models_[0] = &assets.model_levels("pickup_health");
    view->pickup_models_[1] = &assets.model_levels("pickup_ammo");
    view->pickup_models_[2] = &assets.model_levels("pickup_shield");
    view->robot_binding_ = anim::RigBinding(game.animations().rig, view->robot_model_->full().node_names());
    view->robot_pose_ = view->robot_model_->full().rest_pose();
    view->emitters_.reserve(64);
    view->lights_.reserve(64 + feedback::Feedback::kMaxLights);
    view->emitter_list_.reserve(64);
    view->capture(game, view->current_);
    view->previous_ = view->current_;
    return view;
}

void WorldView::follow_game(const game::Game& game) {
    // The new game's robots may be other ones, in another order: no interpolation from the old game's.
    robot_binding_ = anim::RigBinding(game.animations().rig, robot_model_->full().node_names());
    robot_lods_.clear();
    pickup_lods_.clear();
    cylinder_lods_.clear();
    capture(game, current_);
    previous_ = current_;
}

void WorldView::capture(const game::Game& game, Snapshot& s) const {
    const auto& p = game.player();
    const auto death = game.death_camera();
    s.eye = p.eye() - Vec3(0.0f, death.eye_drop, 0.0f);
    s.yaw = p.yaw;
    s.pitch = std::clamp(p.pitch + death.pitch, -kPi * 0.5f, kPi * 0.5f);
    s.roll = death.roll; // the game's roll is geometry::Camera's (positive leans the head right)
    const auto robots = game.robots();
    s.robot_feet.resize(robots.size());
    s.robot_yaw.resize(robots.size());
    for (std::size_t i = 0; i < robots.size(); ++i) {
        s.robot_feet[i] = robots[i].feet;
        s.robot_yaw[i] = robots[i].yaw;
    }
}

void WorldView::before_step(const game::Game& game) {
    (void)game;
    std::swap(previous_, current_);
}

void WorldView::after_step(const game::Game& game, float dt) {
    capture(game, current_);
    time_ += dt;
    if (dt > 0.0f) step_dt_ = dt;
    feedback_.update(dt); // this step's effects start at age 0
    for (const auto& e : game.events()) on_event(game, e);
    for (auto& e : emitters_) e->update(dt);
    std::erase_if(emitters_, [](const auto& e) { return e->finished(); });
}

void WorldView::spawn(const render::ParticleParams& params) {
    if (emitters_.size() >= 64) return; // a cap so a chain reaction cannot grow without bound
    emitters_.push_back(std::make_unique<render::ParticleEmitter>(params, next_seed_++));
}

void WorldView::on_event(const game::Game& game, const game::Event& e) {
    EventEmitters emitters;
    const HitTarget target = e.type == game::EventType::Hit ? hit_target(game, e) : HitTarget::Scenery;
    const int n = event_particles(e, target, emitters);
    for (int i = 0; i < n; ++i) spawn(emitters[static_cast<std::size_t>(i)]);
    feedback_.on_event(e, game.player().eye());
}

void WorldView::fill(const game::Game& game, float alpha, float fov_degrees, const DojoDummy* dummy,
                     render::SceneFrame& frame) {
    const float a = std::clamp(is_finite(alpha) ? alpha : 1.0f, 0.0f, 1.0f);
    // A light map computed on the worker, once done: a live edit's preview (then its full bake starts), or
    // the full bake that replaces a cold start's direct light.
    if (bake_.finish(*scene_, bake_build_) && bake_build_ == 1) {
        bake_build_ = 2;
        bake_.start(*scene_, bake_build_, final_bake_);
    }
    // Doors and lights follow the game.
    for (const auto& d : game.doors()) scene_->set_door_open(d.entity_id, d.progress);
    for (const auto& l : game.lights()) scene_->set_light_on(l.entity_id, l.on);
    // Designers' models pick their level of detail by the view (last frame's: set further down).
    scene_->set_view(camera_, frame.height);
    scene_->emit(instances_, lights_, &casters_);
    add_muzzle_lights(feedback_, lights_, a * step_dt_); // muzzle flashes light their surroundings

    // Robots: interpolated placement, posed from their animation player.
    const auto robots = game.robots();
    for (std::size_t i = 0; i < robots.size(); ++i) {
        if (robots[i].mode == game::RobotMode::Dead) continue;
        const bool have = i < previous_.robot_feet.size() && i < current_.robot_feet.size();
        const Vec3 feet =
            have ? glm::mix(previous_.robot_feet[i], current_.robot_feet[i], a) : robots[i].feet;
        const float yaw = have ? current_.robot_yaw[i] : robots[i].yaw;
        const Mat4 root = level::robot_model_matrix(feet, yaw);
        robot_binding_.write_locals(game.robot_pose(i), robot_pose_.local);
        // A robot just hit flashes red all over, fading over its hit flash.
        const std::size_t first = instances_.size();
        level_for(*robot_model_, root, robot_lods_, i, frame.height)
            .emit(root, robot_pose_, scratch_, instances_);
        const Vec3 tint = feedback::hit_tint(robots[i].hit_flash);
        for (std::size_t k = first; k < instances_.size(); ++k) instances_[k].tint = tint;
        casters_.push_back(render::shadow_caster_of(instances_, first, feet.y));
    }
    if (dummy && dummy->pose) {
        const Mat4 root = level::robot_model_matrix(dummy->feet, dummy->yaw);
        robot_binding_.write_locals(*dummy->pose, robot_pose_.local);
        const std::size_t first = instances_.size();
        dummy_lod_ = render::pick_model_level(*robot_model_, root, camera_, frame.height, dummy_lod_);
        robot_model_->level(dummy_lod_).emit(root, robot_pose_, scratch_, instances_);
        casters_.push_back(render::shadow_caster_of(instances_, first, dummy->feet.y));
    }
    // Pickups float and spin around the game's trigger centre.
    const Quat spin = glm::angleAxis(game.pickup_spin(), Vec3(0, 1, 0));
    const auto pickups = game.pickups();
    for (std::size_t i = 0; i < pickups.size(); ++i) {
        const auto& p = pickups[i];
        if (p.taken) continue;
        const float bob = 0.2f * std::sin(static_cast<float>(time_) * 2.5f + static_cast<float>(p.entity_id));
        const Mat4 root = level::pickup_model_matrix(p.centre + Vec3(0.0f, bob, 0.0f), spin);
        const std::size_t first = instances_.size();
        level_for(*pickup_models_[static_cast<int>(p.kind)], root, pickup_lods_, i, frame.height)
            .emit(root, scratch_, instances_);
        casters_.push_back(
            render::shadow_caster_of(instances_, first, p.centre.y - level::kPickupCentreHeight));
    }
    const auto cylinders = game.cylinders();
    for (std::size_t i = 0; i < cylinders.size(); ++i) {
        const auto& c = cylinders[i];
        if (c.exploded) continue;
        const Mat4 root = level::gas_cylinder_model_matrix(c.centre, c.yaw, c.props);
        // A lit fuse makes the cylinder glow before it goes.
        const std::size_t first = instances_.size();
        level_for(*cylinder_model_, root, cylinder_lods_, i, frame.height)
            .emit(root, scratch_, instances_, c.fuse >= 0.0f ? 3.0f : 1.0f);
        render::ShadowCaster caster = render::shadow_caster_of(instances_, first, 0.0f);
        caster.ground = caster.bounds.min.y; // it stands on its floor
        casters_.push_back(caster);
    }

    // Camera from the interpolated eye; the death camera's drop and tilt are in the snapshot. Explosions
    // shake the view only: the game's aim is the player's yaw and pitch.
    const feedback::ShakeAngles shake = feedback_.shake(a * step_dt_);
    camera_.position = glm::mix(previous_.eye, current_.eye, a);
    camera_.yaw = current_.yaw + shake.yaw;
    camera_.pitch = std::clamp(current_.pitch + shake.pitch, -kPi * 0.5f, kPi * 0.5f);
    camera_.roll = glm::mix(previous_.roll, current_.roll, a) + shake.roll;
    camera_.fov_y = radians(std::clamp(fov_degrees, 30.0f, 120.0f));
    camera_.aspect = static_cast<float>(frame.width) / static_cast<float>(std::max(1, frame.height));

    // The rifle kicks on each shot: recoil 1 at the shot, back to rest over 0.2 s (ease-out).
    view_model_.instances.clear();
    if (game.phase() == game::Phase::Playing) {
        const float since = game.player().recoil;
        const float k = std::clamp(1.0f - since / 0.2f, 0.0f, 1.0f);
        rifle_->emit(render::rifle_view_transform(k * k), scratch_, view_model_.instances);
        add_rifle_caster(game.player().grounded);
    }
    emitter_list_.clear();
    for (const auto& e : emitters_) emitter_list_.push_back(e.get());

    frame.camera = camera_;
    frame.environment = scene_->environment();
    frame.instances = &instances_;
    frame.lights = &lights_;
    frame.particles = &emitter_list_;
    frame.view_model = &view_model_;
    frame.shadow_casters = &casters_;
}

const render::Model& WorldView::level_for(const render::ModelLevels& levels, const Mat4& root,
                                          std::vector<int>& lods, std::size_t index, int height) {
    if (lods.size() <= index) lods.resize(index + 1, 0); // grows once per new mover, not per frame
    lods[index] = render::pick_model_level(levels, root, camera_, height, lods[index]);
    return levels.level(lods[index]);
}

void WorldView::add_rifle_caster(bool grounded) {
    // The rifle's shadow falls on the floor under the player (feet = eye - 3), only while standing on it.
    if (!grounded) return;
    const Mat4 camera_to_world = glm::inverse(camera_.view());
    render::ShadowCaster rifle;
    rifle.bounds = geometry::Aabb::empty();
    rifle.ground = camera_.position.y - 3.0f;
    for (const auto& inst : view_model_.instances)
        if (inst.mesh)
            rifle.bounds = geometry::merge(
                rifle.bounds, geometry::transform_aabb(inst.mesh->bounds(), camera_to_world * inst.world));
    casters_.push_back(rifle);
}

} // namespace ks::runtime
