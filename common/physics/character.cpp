#include "physics/character.h"

#include "physics/triangle_mesh.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace ks::physics {
namespace {

constexpr float kGapTolerance = 1e-5f;     // a gap within skin + this counts as resting contact
constexpr float kApproachFraction = 1e-4f; // slower approach than this (relative) counts as sliding along

struct Planes {
    Vec3 n[8];
    int count = 0;
    void add(const Vec3& p) {
        for (int i = 0; i < count; ++i)
            if (glm::dot(n[i], p) > 0.9999f) return;
        if (count < 8) n[count++] = p;
    }
};

// Removes the parts of `v` that go into any plane: one plane projects, two slide along their crease,
// three or more (or an acute corner) stop.
Vec3 clip_to_planes(const Vec3& v, const Planes& planes) {
    auto into = [](const Vec3& x, const Vec3& n) { return std::min(glm::dot(x, n), 0.0f); };
    auto ok = [&](const Vec3& x, int skip_a, int skip_b) {
        for (int k = 0; k < planes.count; ++k)
            if (k != skip_a && k != skip_b && glm::dot(x, planes.n[k]) < -1e-6f) return false;
        return true;
    };
    if (ok(v, -1, -1)) return v;
    for (int i = 0; i < planes.count; ++i) {
        const Vec3 p = v - planes.n[i] * into(v, planes.n[i]);
        if (ok(p, i, -1)) return p;
    }
    for (int i = 0; i < planes.count; ++i)
        for (int j = i + 1; j < planes.count; ++j) {
            Vec3 crease = glm::cross(planes.n[i], planes.n[j]);
            const float len = glm::length(crease);
            if (len < 1e-6f) continue;
            crease /= len;
            const Vec3 p = crease * glm::dot(crease, v);
            if (ok(p, i, j)) return p;
        }
    return Vec3(0.0f);
}

geometry::Aabb swept_region(const Segment& s, float radius, const Vec3& motion, float skin);
float sweep_capsule_in(const Segment& s, float radius, const Vec3& motion, float len,
                       const geometry::Aabb& region, const Obstacle& o, float skin, Vec3& normal,
                       Vec3* surface, std::optional<Contact>* at_start = nullptr);

struct Mover {
    const std::vector<Obstacle>& obstacles;
    float radius, half;
    const CharacterSettings& cs;
    float cos_slope;
    std::vector<int>& touched; // obstacle indices contacted

    Segment segment_at(const Vec3& p) const {
        return {p - Vec3(0.0f, half, 0.0f), p + Vec3(0.0f, half, 0.0f)};
    }

    // Earliest hit along `motion` from p: t in [0, 1], -1 index when free. `at_start` (optional) gets the
    // hit's contact when it is at t = 0 (the capsule where it is), else stays unset.
    float sweep(const Vec3& p, const Vec3& motion, Vec3& normal, int& which, Vec3* surface = nullptr,
                std::optional<Contact>* at_start = nullptr) const {
        which = -1;
        if (at_start) at_start->reset();
        float best = 1.0f;
        const Segment s = segment_at(p);
        const float len = glm::length(motion);
        const geometry::Aabb region = swept_region(s, radius, motion, cs.skin);
        for (std::size_t i = 0; i < obstacles.size(); ++i) {
            if (!region.overlaps(obstacles[i].bounds))
                continue; // (sweep_capsule_in would return 1: no change)
            Vec3 n(0.0f, 1.0f, 0.0f), sn(0.0f, 1.0f, 0.0f);
            std::optional<Contact> start; // set only by a hit at t = 0
            const float t = sweep_capsule_in(s, radius, motion, len, region, obstacles[i], cs.skin, n,
                                             surface ? &sn : nullptr, at_start ? &start : nullptr);
            const float sy = surface ? sn.y : n.y;
            if (t < best || (t == best && which >= 0 && t < 1.0f && sy > (surface ? surface->y : normal.y))) {
                best = t, normal = n, which = static_cast<int>(i);
                if (surface) *surface = sn;
                if (at_start) *at_start = start;
            }
            // Nothing hits before t = 0, and a tie there only replaces the hit with a more upward normal:
            // after an upward-facing one (standing on a floor) no later obstacle can change the answer.
            if (best == 0.0f && which >= 0 && (surface ? surface->y : normal.y) >= 1.0f) break;
        }
        if (which < 0) best = 1.0f;
        return best;
    }

    void touch(int i) {
        if (std::find(touched.begin(), touched.end(), i) == touched.end()) touched.push_back(i);
    }

    // Collide-and-slide. Returns whether a steep (non-walkable) surface blocked the motion.
    // `velocity_planes` get walkable contacts as flat ground: sliding up a ramp must not turn into upward
    // velocity (which would read as a jump next step).
    bool slide(Vec3& p, Vec3 motion, bool grounded, Planes& planes, Planes& velocity_planes) {
        const Vec3 original = motion;
        bool steep = false;
        for (int iter = 0; iter < cs.max_slide_planes; ++iter) {
            if (glm::dot(motion, motion) < 1e-14f) break;
            Vec3 n(0.0f, 1.0f, 0.0f);
            int which;
            const float t = sweep(p, motion, n, which);
            p += motion * t;
            if (which < 0) break;
            touch(which);
            Vec3 plane = n;
            if (n.y < cos_slope) {
                steep = true;
                // On the ground a steep face acts as a vertical wall: it must not lift the character.
                if (grounded && n.y > 0.0f) {
                    plane.y = 0.0f;
                    const float len = glm::length(plane);
                    plane = len > 1e-3f ? plane / len : n;
                }
            }
            planes.add(plane);
            velocity_planes.add(n.y >= cos_slope ? Vec3(0.0f, 1.0f, 0.0f) : plane);
            motion = clip_to_planes(motion * (1.0f - t), planes);
            // Never turn back against the intended direction: that is what makes corners jitter.
            if (glm::dot(motion, original) <= 0.0f) break;
        }
        return steep;
    }
};

} // namespace

Vec3 surface_normal(const Shape& shape, const geometry::Transform& xf, const Vec3& point,
                    const Vec3& contact_normal) {
    // Unrotated (most level geometry): the frame change is a translation (rotating by the identity
    // quaternion returns its input exactly, so this only skips work).
    const bool unrotated = xf.rotation == Quat(1.0f, 0.0f, 0.0f, 0.0f);
    const Vec3 p = unrotated ? point - xf.position : xf.to_local(point);
    const float tol = 1e-3f;
    Vec3 best = contact_normal;
    float best_y = -2.0f;
    auto consider = [&](const Vec3& local_normal) {
        const Vec3 n = unrotated ? local_normal : xf.dir_to_world(local_normal);
        if (n.y > best_y) best_y = n.y, best = n;
    };
    switch (shape.kind) {
    case ShapeKind::Box:
        // A floor's top face (the usual answer): nothing is more upward, so the other faces need no look.
        if (unrotated && std::abs(p.y - shape.half_extents.y) <= tol + 1e-6f * shape.half_extents.y)
            return Vec3(0.0f, 1.0f, 0.0f);
        for (int i = 0; i < 3; ++i)
            for (float side : {-1.0f, 1.0f})
                if (std::abs(p[i] - side * shape.half_extents[i]) <= tol + 1e-6f * shape.half_extents[i]) {
                    Vec3 n(0.0f);
                    n[i] = side;
                    consider(n);
                }
        break;
    case ShapeKind::Wedge:
    case ShapeKind::Hull:
        for (const auto& f : shape.polyhedron->faces)
            if (std::abs(glm::dot(f.normal, p) - f.offset) <= tol) consider(f.normal);
        break;
    case ShapeKind::Cylinder:
        if (std::abs(p.y - shape.half_height) <= tol) return Vec3(0.0f, 1.0f, 0.0f);
        break;
    case ShapeKind::Capsule:
    case ShapeKind::Mesh: // the controller asks per triangle (triangle_normal)
        break;
    }
    return best_y > -2.0f ? best : contact_normal;
}

namespace {
// The box a capsule sweeps over `motion`, widened by the skin and a millimetre: obstacles whose bounds miss
// it cannot stop the sweep. Computed once per sweep, not once per obstacle.
geometry::Aabb swept_region(const Segment& s, float radius, const Vec3& motion, float skin) {
    geometry::Aabb swept{glm::min(s.p0, s.p1) - Vec3(radius), glm::max(s.p0, s.p1) + Vec3(radius)};
    swept.grow(geometry::Aabb{swept.min + motion, swept.max + motion});
    return swept.expanded(skin + 1e-3f);
}

// sweep_capsule with the motion's length and swept region precomputed.
float sweep_capsule_in(const Segment& s, float radius, const Vec3& motion, float len,
                       const geometry::Aabb& region, const Obstacle& o, float skin, Vec3& normal,
                       Vec3* surface, std::optional<Contact>* at_start) {
    if (!(len > 0.0f)) return 1.0f;
    if (!region.overlaps(o.bounds)) return 1.0f;
    float t = 0.0f;
    // Conservative advancement with Newton steps: the distance between convex sets along a translation is
    // a convex function of t, so its tangent never overshoots the first touch: t only grows toward it.
    for (int iter = 0; iter < 32; ++iter) {
        const Segment st{s.p0 + motion * t, s.p1 + motion * t};
        const auto c = collide_capsule_obstacle(st, radius, o, len * (1.0f - t) + skin + 1e-3f);
        if (!c) return 1.0f;
        const float gap = -c->penetration;
        const float rate = -glm::dot(c->normal, motion);
        if (gap <= skin + kGapTolerance) {
            if (rate <= kApproachFraction * len) return 1.0f; // resting or leaving: not blocking
            normal = c->normal;
            if (at_start && iter == 0) *at_start = c; // the capsule where it is: t = 0
            if (surface)
                *surface = o.triangle != Obstacle::kWholeShape
                               ? triangle_normal(*o.shape->mesh, o.triangle, o.transform, c->normal)
                               : surface_normal(*o.shape, o.transform, c->point - c->normal * (gap * 0.5f),
                                                c->normal);
            return t;
        }
        if (rate <= kApproachFraction * len) return 1.0f;
        t += (gap - skin) / rate;
        if (t >= 1.0f) return 1.0f;
        normal = c->normal;
    }
    if (surface) *surface = normal;
    return t;
}
} // namespace

std::optional<Contact> collide_capsule_obstacle(const Segment& s, float r, const Obstacle& o,
                                                float contact_margin) {
    if (o.triangle != Obstacle::kWholeShape)
        return collide_capsule_triangle(s, r, *o.shape->mesh, o.triangle, o.transform, contact_margin);
    // Most obstacles are walls and floors: straight to the box contact collide_capsule_shape would pick
    // (the world keeps yaw_only in step with the body's rotation).
    if (o.shape->kind == ShapeKind::Box && o.yaw_only)
        return collide_capsule_box(s, r, o.shape->half_extents, o.transform, contact_margin);
    return collide_capsule_shape(s, r, *o.shape, o.transform, contact_margin);
}

float sweep_capsule(const Segment& s, float radius, const Vec3& motion, const Obstacle& o, float skin,
                    Vec3& normal, Vec3* surface) {
    return sweep_capsule_in(s, radius, motion, glm::length(motion), swept_region(s, radius, motion, skin), o,
                            skin, normal, surface);
}

void move_character(const ObstacleSource& world, float radius, float half_segment,
                    const CharacterSettings& cs, CharacterState& state, Vec3& position, float dt,
                    CharacterScratch& scratch) {
    scratch.contacts.clear();
    if (!(dt > 0.0f) || !is_finite(position)) return;
    sanitize(state.movement);
    MovementState& m = state.movement;
    // cos of the slope limit, remembered for the last limit seen (every character of a game shares one, and
    // a cosf call per character per step is measurable).
    static thread_local float memo_degrees = -1.0f, memo_cos = 1.0f;
    const float degrees = std::clamp(cs.max_slope_degrees, 0.0f, 89.0f);
    if (!(degrees == memo_degrees)) memo_degrees = degrees, memo_cos = std::cos(radians(degrees));
    const float cos_slope = memo_cos;
    if (state.grounded && m.velocity.y > 1e-4f) { // the game launched it (jump, explosion): leave the ground
        state.grounded = false;
        state.jumping = true;
    }
    const bool was_grounded = state.grounded && !state.jumping;

    Vec3 disp;
    if (was_grounded) {
        // On the ground: no gravity into the floor; walk along the ground plane at the same horizontal speed.
        MovementState flat = m;
        flat.gravity = 0.0f;
        flat.velocity.y = 0.0f;
        flat.acceleration.y = std::max(flat.acceleration.y, 0.0f);
        disp = integrate(flat, dt);
        m.velocity = flat.velocity;
        const Vec3& n = state.ground_normal;
        if (n.y >= cos_slope && disp.y <= 0.0f) disp.y = -(disp.x * n.x + disp.z * n.z) / n.y;
    } else {
        disp = integrate(m, dt);
    }

    const float reach = std::max(cs.step_height, cs.ground_snap) + 2.0f * cs.skin + 0.05f;
    geometry::Aabb region{position - Vec3(radius, half_segment + radius, radius),
                          position + Vec3(radius, half_segment + radius, radius)};
    region.grow(geometry::Aabb{region.min + disp, region.max + disp});
    scratch.obstacles.clear();
    world.gather(region.expanded(reach), scratch.obstacles);

    static thread_local std::vector<int> touched;
    touched.clear();
    Mover mover{scratch.obstacles, radius, half_segment, cs, cos_slope, touched};

    // Resolve overlaps first (a door leaf closed on us, a spawn inside a crate): push out along the
    // exact contact normal to the skin distance.
    for (int iter = 0; iter < 4; ++iter) {
        bool any = false;
        const geometry::Aabb own{position - Vec3(radius, half_segment + radius, radius),
                                 position + Vec3(radius, half_segment + radius, radius)};
        for (std::size_t i = 0; i < scratch.obstacles.size(); ++i) {
            const Obstacle& o = scratch.obstacles[i];
            if (!own.overlaps(o.bounds)) continue;
            const auto c = collide_capsule_obstacle(mover.segment_at(position), radius, o);
            if (c && c->penetration > 0.0f) {
                position += c->normal * (c->penetration + cs.skin);
                mover.touch(static_cast<int>(i));
                any = true;
            }
        }
        if (!any) break;
    }

    const Vec3 start = position;
    Planes planes, velocity_planes;
    Vec3 moved = start;
    mover.slide(moved, disp, was_grounded, planes, velocity_planes);
    auto horizontal = [&](const Vec3& a) { return glm::length(Vec3(a.x - start.x, 0.0f, a.z - start.z)); };
    const float wanted = glm::length(Vec3(disp.x, 0.0f, disp.z));

    // Step up when walking was blocked (a step's edge, a low crate): the same horizontal motion lifted by
    // step_height, then down onto walkable ground; kept only if it got further.
    if (was_grounded && cs.step_height > 0.0f && wanted > 1e-6f && horizontal(moved) < 0.99f * wanted) {
        Vec3 n(0.0f, 1.0f, 0.0f);
        int which;
        Vec3 p = start;
        const Vec3 up(0.0f, cs.step_height, 0.0f);
        const float tu = mover.sweep(p, up, n, which);
        p += up * tu;
        Planes planes2, velocity_planes2;
        mover.slide(p, Vec3(disp.x, 0.0f, disp.z), true, planes2, velocity_planes2);
        const Vec3 down(0.0f, -(cs.step_height * tu + 2.0f * cs.skin + std::max(0.0f, -disp.y)), 0.0f);
        Vec3 ground(0.0f, 1.0f, 0.0f);
        const float td = mover.sweep(p, down, n, which, &ground);
        if (which >= 0 && std::max(n.y, ground.y) >= cos_slope &&
            horizontal(p + down * td) > horizontal(moved) + 1e-5f) {
            moved = p + down * td;
            velocity_planes = velocity_planes2;
        }
    }
    position = moved;
    m.velocity = clip_to_planes(m.velocity, velocity_planes);

    // Ground: probe (and snap while walking) unless rising from a jump.
    state.grounded = false;
    std::optional<Contact> ground_contact; // the probe's contact where the capsule now is (a hit at t = 0)
    int ground_index = -1;
    if (!(state.jumping && m.velocity.y > 0.0f)) {
        const float probe = was_grounded ? cs.ground_snap : 2.0f * cs.skin;
        Vec3 n(0.0f, 1.0f, 0.0f);
        int which;
        const Vec3 down(0.0f, -probe, 0.0f);
        Vec3 ground(0.0f, 1.0f, 0.0f);
        const float t = mover.sweep(position, down, n, which, &ground, &ground_contact);
        if (which >= 0 && std::max(n.y, ground.y) >= cos_slope) {
            position += down * t;
            ground_index = which;
            state.grounded = true;
            state.jumping = false;
            state.ground_normal = n.y >= ground.y ? n : ground;
            m.velocity.y = 0.0f;
            mover.touch(which);
        }
    }
    if (!state.grounded) state.ground_normal = Vec3(0.0f, 1.0f, 0.0f);

    // Report each touched obstacle once, with the exact contact at the final position.
    // The ground probe's contact at t = 0 is this very query (the same capsule, obstacle and function): only
    // the margin differs, and it returned within skin + kGapTolerance, which the report's 4 skin also keeps
    // for a box (whose contact is refused only beyond radius + margin) when 3 skin exceeds that tolerance and
    // the rounding of radius + margin.
    const bool reuse_ground = ground_contact && ground_index >= 0 &&
                              scratch.obstacles[ground_index].triangle == Obstacle::kWholeShape &&
                              scratch.obstacles[ground_index].shape->kind == ShapeKind::Box &&
                              3.0f * cs.skin > kGapTolerance + 4e-7f * (radius + 4.0f * cs.skin);
    for (int i : touched) {
        const Obstacle& o = scratch.obstacles[i];
        auto c = reuse_ground && i == ground_index
                     ? ground_contact
                     : collide_capsule_obstacle(mover.segment_at(position), radius, o, 4.0f * cs.skin);
        Contact contact;
        if (c)
            contact = *c;
        else { // touched on the way but left behind (slid past an edge)
            contact.normal = Vec3(0.0f, 1.0f, 0.0f);
            contact.point = position;
        }
        contact.penetration = std::max(0.0f, contact.penetration);
        scratch.contacts.push_back({o.id, contact});
    }
}

} // namespace ks::physics
