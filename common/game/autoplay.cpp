#include "game/autoplay.h"

#include "geometry/ground_plane.h"
#include "nav/nav_cache.h"
#include "physics/character.h"

#include <algorithm>
#include <cmath>

namespace ks::game {
namespace {

// A corner counts as reached this close (x, z): far enough that grazing a wall corner still reaches it.
constexpr float kCornerReached = 0.5f;

float wrap_angle(float a) {
    return std::remainder(a, 2.0f * kPi);
}

float yaw_toward(const Vec3& from, const Vec3& to) {
    return std::atan2(-(to.x - from.x), -(to.z - from.z));
}

} // namespace

Result<std::shared_ptr<nav::NavMesh>> build_autoplay_mesh(const level::Level& level,
                                                          float cylinder_keep_out) {
    level::Level widened = level;
    for (level::Entity& e : widened.entities)
        if (auto* cylinder = e.try_as<level::GasCylinderProps>()) cylinder->radius += cylinder_keep_out;
    const physics::CharacterSettings character;
    auto mesh = nav::build_cached(
        widened, nav::player_nav_settings(character.step_height, character.max_slope_degrees));
    if (!mesh) return mesh.error();
    for (const level::Entity& e : level.entities)
        if (e.type() == level::EntityType::Door) (*mesh)->set_door_open(e.id, true);
    return std::shared_ptr<nav::NavMesh>(std::move(*mesh));
}

Result<Autoplay> Autoplay::create(const level::Level& level, const Game& game, std::uint64_t seed,
                                  AutoplaySettings settings) {
    auto mesh = build_autoplay_mesh(level, settings.cylinder_keep_out);
    if (!mesh) return mesh.error();
    return Autoplay(game, std::move(*mesh), seed, settings);
}

Autoplay::Autoplay(const Game& game, std::shared_ptr<nav::NavMesh> mesh, std::uint64_t seed,
                   AutoplaySettings settings)
    : settings_(settings), rng_(seed, 0x626f74ull), mesh_(std::move(mesh)), planner_(game) {
    path_.reserve(64);
}

bool Autoplay::noticed(const Game& game, const Robot& r, const Vec3& to_robot) const {
    if (settings_.view_half_angle >= kPi) return true;
    if (since_shot_ < kTargetMemory && geometry::ground_distance(shot_from_, r.feet) < 3.0f) return true;
    const float off = std::abs(wrap_angle(yaw_toward(Vec3(0.0f), to_robot) - game.player().yaw));
    return off <= settings_.view_half_angle;
}

int Autoplay::pick_target(const Game& game) const {
    const PlayerState& p = game.player();
    const Vec3 eye = p.eye();
    int best = -1;
    float best_distance = settings_.engage_range;
    physics::RayFilter filter;
    filter.layers = physics::layer::kShootable;
    filter.ignore = p.body;
    const auto robots = game.robots();
    for (std::size_t i = 0; i < robots.size(); ++i) {
        const Robot& r = robots[i];
        if (!r.alive()) continue;
        const Vec3 centre = r.feet + Vec3(0, 1.5f, 0);
        const Vec3 d = centre - eye;
        const float dist = glm::length(d);
        if (dist >= best_distance || dist < 1e-3f || !noticed(game, r, d)) continue;
        physics::RayHit hit;
        if (!game.world().ray_closest({eye, d / dist, dist + 2.0f}, hit, filter) || !(hit.body == r.body))
            continue;
        best = static_cast<int>(i);
        best_distance = dist;
    }
    return best;
}

void Autoplay::aim_at(const Game& game, const Vec3& point, Input& in, float& yaw_error, float& pitch_error,
                      Vec2 offset) const {
    const PlayerState& p = game.player();
    const Vec3 eye = p.eye();
    const Vec3 d = point - eye;
    const float horizontal = std::sqrt(d.x * d.x + d.z * d.z);
    const float want_yaw = yaw_toward(eye, point) + offset.x;
    const float want_pitch = std::atan2(d.y, std::max(horizontal, 1e-4f)) + offset.y;
    const float max_turn = settings_.turn_rate * static_cast<float>(game.settings().step);
    yaw_error = wrap_angle(want_yaw - p.yaw);
    pitch_error = want_pitch - p.pitch;
    in.look_yaw = std::clamp(yaw_error, -max_turn, max_turn);
    in.look_pitch = std::clamp(pitch_error, -max_turn, max_turn);
}

void Autoplay::notice_events(const Game& game) {
    since_shot_ += static_cast<float>(game.settings().step);
    for (const Event& e : game.events()) {
        if (e.type == EventType::PlayerDamaged && e.position != e.end) { // from somewhere (not a fall)
            shot_from_ = e.position;
            since_shot_ = 0.0f;
        }
        switch (e.type) {
        case EventType::ObjectiveCompleted:
        case EventType::DoorToggled:
        case EventType::RobotSpawned:
        case EventType::PickupTaken:
        case EventType::Used:
        case EventType::LockedDoorUsed:
            goal_stale_ = true;
            break;
        default:
            break;
        }
    }
    if (goal_.kind == BotGoalKind::Hunt) { // it died (spawned robots are not in the level's records)
        for (const Robot& r : game.robots())
            if (r.entity_id == goal_.entity_id && !r.alive()) goal_stale_ = true;
    } else if (goal_.kind == BotGoalKind::Enter) { // the trigger noticed the bot
        for (const TriggerState& t : game.logic().triggers())
            if (t.entity_id == goal_.entity_id && t.occupied) goal_stale_ = true;
    }
}

void Autoplay::refresh_goal(const Game& game) {
    goal_stale_ = false;
    since_goal_ = 0.0f;
    const BotGoal next = planner_.choose(game, *mesh_);
    if (!next.same_target(goal_)) {
        since_plan_ = 1e9f; // a new goal: plan for it now
        if (settings_.look_around > 0.0f) {
            looking_left_ = settings_.look_around;
            look_direction_ = rng_.chance(0.5f) ? 1.0f : -1.0f;
        }
    }
    goal_ = next;
}

bool Autoplay::look_around(float dt, Input& in) {
    if (looking_left_ <= 0.0f) return false;
    // Half the time one way, half back: a glance round of turn_rate/4 each way.
    const float half = settings_.look_around * 0.5f;
    const float direction = looking_left_ > half ? look_direction_ : -look_direction_;
    looking_left_ -= dt;
    in.look_yaw = direction * settings_.turn_rate * 0.25f * dt;
    return true;
}

bool Autoplay::reacted(int target, float dt) {
    if (target != target_) {
        target_ = target;
        target_seen_ = 0.0f;
        draw_aim_offset();
    }
    target_lost_ = 0.0f;
    target_seen_ += dt;
    return target_seen_ >= settings_.reaction_time;
}

// Box-Muller from the bot's own Rng; nothing is drawn for a bot that aims true (the perfect profile's runs
// stay as they were).
void Autoplay::draw_aim_offset() {
    if (!(settings_.aim_error > 0.0f)) return;
    const float u1 = std::max(rng_.uniform(), 1e-7f), u2 = rng_.uniform();
    const float r = settings_.aim_error * std::sqrt(-2.0f * std::log(u1));
    aim_offset_ = Vec2(r * std::cos(2.0f * kPi * u2), r * std::sin(2.0f * kPi * u2));
}

void Autoplay::fight(const Game& game, int target, Input& in) {
    const PlayerState& p = game.player();
    const Robot& r = game.robots()[static_cast<std::size_t>(target)];
    const Vec3 centre = r.feet + Vec3(0, 1.5f, 0);
    float yaw_error = 0.0f, pitch_error = 0.0f;
    aim_at(game, centre, in, yaw_error, pitch_error, aim_offset_);
    const float distance = glm::length(centre - p.eye());
    const float tolerance = settings_.aim_tolerance * game.settings().robot_radius / std::max(distance, 1.0f);
    const float residual_yaw = yaw_error - in.look_yaw, residual_pitch = pitch_error - in.look_pitch;
    if (std::abs(residual_yaw) < tolerance && std::abs(residual_pitch) < tolerance && fire_wait_ <= 0.0f &&
        p.ammo > 0) {
        in.fire = true;
        fire_wait_ = settings_.fire_interval;
        draw_aim_offset(); // the next shot is a new aimed movement
    }
    stuck_time_ = 0.0f;
    stuck_anchor_ = p.feet;
}

bool Autoplay::use_goal(const Game& game, Input& in) {
    if (goal_.kind != BotGoalKind::Use || game.interact_target() != goal_.entity_id) return false;
    Vec3 aim = goal_.point;
    for (const Panel& k : game.panels())
        if (k.entity_id == goal_.entity_id) aim = k.centre;
    for (const Light& l : game.lights())
        if (l.entity_id == goal_.entity_id) aim = l.position + Vec3(0.0f, 2.0f, 0.0f); // the lamp
    float yaw_error = 0.0f, pitch_error = 0.0f;
    aim_at(game, aim, in, yaw_error, pitch_error);
    if (interact_wait_ <= 0.0f) {
        in.interact = true;
        interact_wait_ = 0.3f;
    }
    return true;
}

void Autoplay::follow_path(const Game& game) {
    const Vec3& feet = game.player().feet;
    if (since_plan_ >= settings_.replan_interval) {
        since_plan_ = 0.0f;
        close_blocking_doors(game, *mesh_); // the mesh may be shared: set its doors for this game
        // Found or Partial alike: walk as far as the mesh goes toward the goal.
        if (goal_.kind == BotGoalKind::None ||
            mesh_->find_path(feet, goal_.point, path_) == nav::PathStatus::StartOffMesh || path_.size() < 2)
            path_.clear();
        waypoint_ = 1; // path_[0] is where the bot stands, snapped to the mesh
    }
    while (waypoint_ + 1 < path_.size() && geometry::ground_distance(path_[waypoint_], feet) < kCornerReached)
        ++waypoint_;
}

bool Autoplay::path_passes_near(const Vec3& from, const Vec3& point, float radius, float length) const {
    Vec3 a = from;
    for (std::size_t k = waypoint_; k < path_.size() && length > 0.0f; ++k) {
        if (geometry::ground_distance_to_segment(point, a, path_[k]) < radius) return true;
        length -= geometry::ground_distance(a, path_[k]);
        a = path_[k];
    }
    return false;
}

// A closed door on the way: stop in its sensor, face it, press E, wait for it to open.
bool Autoplay::open_door_on_path(const Game& game, Input& in) {
    const PlayerState& p = game.player();
    for (const Door& d : game.doors()) {
        // A locked, shut door: E does nothing; the goal says what opens it (a link opening it still
        // lets the bot wait here for it).
        if (!d.player_inside || d.progress >= 0.95f || door_blocks(d)) continue;
        if (!path_passes_near(p.feet, d.frame.position, 3.0f, 16.0f)) continue;
        float yaw_error = 0.0f, pitch_error = 0.0f;
        aim_at(game, d.frame.position + Vec3(0, 2.5f, 0), in, yaw_error, pitch_error);
        if (!d.opening && game.interact_target() == d.entity_id && interact_wait_ <= 0.0f) {
            in.interact = true;
            interact_wait_ = 0.3f;
        }
        // E would act on something nearer (a floor lamp beside the door): step up to the door.
        if (game.interact_target() >= 0 && game.interact_target() != d.entity_id && !d.opening)
            in.move_forward = std::abs(yaw_error) < 0.5f ? 1.0f : 0.0f;
        return true;
    }
    return false;
}

// No progress for 2 s: strafe a random way for half a second and replan.
void Autoplay::unstick(const Game& game, Input& in) {
    const float dt = static_cast<float>(game.settings().step);
    const Vec3& feet = game.player().feet;
    stuck_time_ += dt;
    if (glm::length(feet - stuck_anchor_) > 1.5f) {
        stuck_time_ = 0.0f;
        stuck_anchor_ = feet;
    }
    if (stuck_time_ > 2.0f) {
        stuck_time_ = 0.0f;
        unstick_time_ = 0.5f;
        unstick_side_ = rng_.chance(0.5f) ? 1.0f : -1.0f;
        since_plan_ = 1e9f;
    }
    if (unstick_time_ > 0.0f) {
        unstick_time_ -= dt;
        in.move_right = unstick_side_;
        in.move_forward = -0.5f;
    }
}

Input Autoplay::decide(const Game& game) {
    Input in;
    if (game.phase() != Phase::Playing || game.paused()) return in;
    const float dt = static_cast<float>(game.settings().step);
    const PlayerState& p = game.player();
    fire_wait_ = std::max(0.0f, fire_wait_ - dt);
    interact_wait_ = std::max(0.0f, interact_wait_ - dt);
    since_plan_ += dt;
    since_goal_ += dt;
    notice_events(game);
    float yaw_error = 0.0f, pitch_error = 0.0f;

    // Fight: the nearest robot in sight, once the bot has reacted to it — with ammo. Without, fighting is
    // standing still (the soak found the bot aiming at robots for an hour with an empty rifle): it ignores
    // robots and heads for the panel.
    if (const int target = p.ammo > 0 ? pick_target(game) : -1; target >= 0) {
        if (reacted(target, dt)) {
            looking_left_ = 0.0f; // a fight ends any look round
            fight(game, target, in);
            return in;
        }
    } else if ((target_lost_ += dt) >= kTargetMemory) {
        target_ = -1;
    }

    if (goal_stale_ || since_goal_ >= settings_.replan_interval) refresh_goal(game);
    if (use_goal(game, in)) return in;
    if (look_around(dt, in)) return in;

    follow_path(game);
    if (open_door_on_path(game, in)) return in;
    // Waiting (for a delayed link, a door, a spawner's next robot): stand where the goal says.
    if (goal_.kind == BotGoalKind::Wait && geometry::ground_distance(p.feet, goal_.point) < 1.0f) {
        stuck_time_ = 0.0f;
        stuck_anchor_ = p.feet;
        return in;
    }
    if (!path_.empty()) {
        const Vec3& corner = path_[waypoint_];
        aim_at(game, corner + Vec3(0, p.eye().y - corner.y, 0), in, yaw_error, pitch_error);
        in.look_pitch = std::clamp(-p.pitch, -0.1f, 0.1f);
        in.move_forward = std::abs(yaw_error) < 0.5f ? 1.0f : 0.2f;
    }
    if (goal_.kind != BotGoalKind::None) unstick(game, in); // off the mesh too: a strafe may bring it back
    return in;
}

} // namespace ks::game
