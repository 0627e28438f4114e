// Ray and overlap queries: the static set's SIMD leaf packets, then movers and (when asked) triggers.
#include "physics/world.h"

#include <algorithm>
#include <bit>
#include <cmath>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace ks::physics {

namespace {
// Lanes of `bp` whose axis-aligned box ray_centred_aabb would accept within max_t: the same operations in
// the same order, four at once (plain SSE multiplies and subtractions: nothing to contract into an FMA).
// Also stores each lane's entry distance and its x and y slab entries (which face was entered).
template <class Packet>
std::uint32_t packet_slab(const Packet& bp, const Vec3& origin, const Vec3& inv, float max_t, float* tmin_out,
                          float* lox_out, float* loy_out) {
#if defined(__SSE2__)
    const __m128 ox = _mm_sub_ps(_mm_set1_ps(origin.x), _mm_load_ps(bp.cx));
    const __m128 oy = _mm_sub_ps(_mm_set1_ps(origin.y), _mm_load_ps(bp.cy));
    const __m128 oz = _mm_sub_ps(_mm_set1_ps(origin.z), _mm_load_ps(bp.cz));
    const __m128 hx = _mm_load_ps(bp.hx), hy = _mm_load_ps(bp.hy), hz = _mm_load_ps(bp.hz);
    const __m128 sign = _mm_set1_ps(-0.0f);
    const __m128 ix = _mm_set1_ps(inv.x), iy = _mm_set1_ps(inv.y), iz = _mm_set1_ps(inv.z);
    const __m128 tx0 = _mm_mul_ps(_mm_sub_ps(_mm_xor_ps(hx, sign), ox), ix);
    const __m128 tx1 = _mm_mul_ps(_mm_sub_ps(hx, ox), ix);
    const __m128 ty0 = _mm_mul_ps(_mm_sub_ps(_mm_xor_ps(hy, sign), oy), iy);
    const __m128 ty1 = _mm_mul_ps(_mm_sub_ps(hy, oy), iy);
    const __m128 tz0 = _mm_mul_ps(_mm_sub_ps(_mm_xor_ps(hz, sign), oz), iz);
    const __m128 tz1 = _mm_mul_ps(_mm_sub_ps(hz, oz), iz);
    const __m128 lox = _mm_min_ps(tx0, tx1), loy = _mm_min_ps(ty0, ty1);
    const __m128 tmin = _mm_max_ps(lox, _mm_max_ps(loy, _mm_min_ps(tz0, tz1)));
    const __m128 tmax =
        _mm_mul_ps(_mm_min_ps(_mm_max_ps(tx0, tx1), _mm_min_ps(_mm_max_ps(ty0, ty1), _mm_max_ps(tz0, tz1))),
                   _mm_set1_ps(geometry::kExitWiden));
    const __m128 ok = _mm_and_ps(_mm_and_ps(_mm_cmple_ps(tmin, tmax), _mm_cmpgt_ps(tmax, _mm_setzero_ps())),
                                 _mm_cmple_ps(tmin, _mm_set1_ps(max_t)));
    _mm_store_ps(tmin_out, tmin);
    _mm_store_ps(lox_out, lox);
    _mm_store_ps(loy_out, loy);
    return static_cast<std::uint32_t>(_mm_movemask_ps(ok));
#else
    std::uint32_t mask = 0;
    for (int k = 0; k < 4; ++k) {
        const Vec3 o = origin - Vec3(bp.cx[k], bp.cy[k], bp.cz[k]), half(bp.hx[k], bp.hy[k], bp.hz[k]);
        const Vec3 t0 = (-half - o) * inv, t1 = (half - o) * inv;
        const Vec3 lo = glm::min(t0, t1), hi = glm::max(t0, t1);
        const float tmin = std::max(lo.x, std::max(lo.y, lo.z));
        const float tmax = std::min(hi.x, std::min(hi.y, hi.z)) * geometry::kExitWiden;
        tmin_out[k] = tmin, lox_out[k] = lo.x, loy_out[k] = lo.y;
        if (tmin <= tmax && tmax > 0.0f && tmin <= max_t) mask |= 1u << k;
    }
    return mask;
#endif
}
} // namespace

template <class BoxHit, class OtherHit>
bool World::ray_leaf(std::uint32_t leaf, const geometry::Ray& ray, const Vec3& inv, const float& max_t,
                     const RayFilter& filter, BoxHit&& box, OtherHit&& other) const {
    const BoxPacket& bp = static_packets_[leaf];
    alignas(16) float tmin[4], lox[4], loy[4];
    std::uint32_t lanes = packet_slab(bp, ray.origin, inv, max_t, tmin, lox, loy) & (bp.boxes | bp.others);
    while (lanes) {
        const int k = std::countr_zero(lanes);
        lanes &= lanes - 1;
        if (!(bp.layers[k] & filter.layers) || !passes(filter, bp.body[k])) continue;
        if (!(bp.boxes >> k & 1u)) {
            if (!other(bp.first_slot + k)) return false;
            continue;
        }
        // What ray_centred_aabb returns, read from the lanes (max_t may have shrunk since the slab test).
        if (tmin[k] > max_t) continue;
        ShapeHit h;
        if (tmin[k] <= 0.0f) { // starts inside (or on the surface, heading in)
            h.distance = 0.0f;
            h.normal = -ray.direction;
        } else {
            const int axis = tmin[k] == lox[k] ? 0 : (tmin[k] == loy[k] ? 1 : 2);
            h.distance = tmin[k];
            h.normal = Vec3(0.0f);
            h.normal[axis] = ray.direction[axis] > 0.0f ? -1.0f : 1.0f;
        }
        if (!box(k, h)) return false;
    }
    return true;
}

bool World::ray_static(const geometry::Ray& ray, const Vec3& inv, const StaticPrim& p, ShapeHit& hit) const {
    if (p.kind == ShapeKind::Box) {
        if (p.axis_aligned) return ray_centred_aabb(ray, inv, p.position, p.half, hit);
        return ray_box(ray, p.half, {p.position, p.rotation}, hit);
    }
    const Body& b = bodies_[p.body];
    return ray_shape(ray, b.shape, b.transform, hit);
}

bool World::ray_body(const geometry::Ray& ray, std::uint32_t index, ShapeHit& hit) const {
    const Body& b = bodies_[index];
    return ray_shape(ray, b.shape, b.transform, hit);
}

namespace {
bool finite_ray(const geometry::Ray& r) {
    return is_finite(r.origin) && is_finite(r.direction) && !std::isnan(r.max_distance) &&
           glm::dot(r.direction, r.direction) > 0.5f;
}
} // namespace

bool World::ray_closest(const geometry::Ray& ray, RayHit& out, const RayFilter& filter) const {
    if (!finite_ray(ray)) return false;
    build_static();
    float best = ray.max_distance;
    std::uint32_t best_body = kNone;
    Vec3 best_normal(0.0f);
    // Equal distances go to the lower body index (best_body starts as kNone, above every index), so the
    // answer does not depend on the order the BVH and the lists are visited in.
    auto closer = [&](float distance, std::uint32_t body) {
        return distance < best || (distance == best && body < best_body);
    };
    const Vec3 inv = geometry::safe_inverse(ray.direction);
    static_bvh_.ray_query_leaves(ray, inv, ray.max_distance, [&](std::uint32_t leaf, float& max_t) {
        const BoxPacket& bp = static_packets_[leaf];
        auto take = [&](std::uint32_t body, const ShapeHit& h) {
            if (closer(h.distance, body)) {
                best = h.distance, best_body = body, best_normal = h.normal;
                max_t = h.distance;
            }
            return true;
        };
        return ray_leaf(
            leaf, ray, inv, max_t, filter, [&](int k, const ShapeHit& h) { return take(bp.body[k], h); },
            [&](std::uint32_t slot) {
                const StaticPrim& p = static_prims_[slot];
                ShapeHit h;
                geometry::Ray r = ray;
                r.max_distance = max_t;
                if (ray_static(r, inv, p, h)) take(p.body, h);
                return true;
            });
    });
    for (std::uint32_t index : movers_) {
        const Body& b = bodies_[index];
        if (!b.enabled || !(b.layers & filter.layers) || !passes(filter, index)) continue;
        geometry::Ray r = ray;
        r.max_distance = best;
        ShapeHit h;
        if (ray_body(r, index, h) && closer(h.distance, index))
            best = h.distance, best_body = index, best_normal = h.normal;
    }
    if (filter.layers & layer::kTrigger)
        for (std::uint32_t index : static_triggers_) {
            const Body& b = bodies_[index];
            if (!b.enabled || !passes(filter, index)) continue;
            geometry::Ray r = ray;
            r.max_distance = best;
            ShapeHit h;
            if (ray_body(r, index, h) && closer(h.distance, index))
                best = h.distance, best_body = index, best_normal = h.normal;
        }
    if (best_body == kNone) return false;
    out.body = id_of(best_body);
    out.distance = best;
    out.normal = best_normal;
    out.point = ray.origin + ray.direction * best;
    return true;
}

bool World::ray_any(const geometry::Ray& ray, const RayFilter& filter) const {
    if (!finite_ray(ray)) return false;
    build_static();
    bool found = false;
    const Vec3 inv = geometry::safe_inverse(ray.direction);
    static_bvh_.ray_query_leaves(ray, inv, ray.max_distance, [&](std::uint32_t leaf, float& max_t) {
        return ray_leaf(
            leaf, ray, inv, max_t, filter, [&](int, const ShapeHit&) { return !(found = true); },
            [&](std::uint32_t slot) {
                ShapeHit h;
                found = ray_static(ray, inv, static_prims_[slot], h);
                return !found;
            });
    });
    if (found) return true;
    for (std::uint32_t index : movers_) {
        const Body& b = bodies_[index];
        ShapeHit h;
        if (b.enabled && (b.layers & filter.layers) && passes(filter, index) && ray_body(ray, index, h))
            return true;
    }
    if (filter.layers & layer::kTrigger)
        for (std::uint32_t index : static_triggers_) {
            ShapeHit h;
            if (bodies_[index].enabled && passes(filter, index) && ray_body(ray, index, h)) return true;
        }
    return false;
}

int World::ray_all(const geometry::Ray& ray, std::vector<RayHit>& hits, HitOrder order,
                   const RayFilter& filter) const {
    if (!finite_ray(ray)) return 0;
    build_static();
    const std::size_t start = hits.size();
    auto add = [&](std::uint32_t index, const ShapeHit& h) {
        hits.push_back({id_of(index), ray.origin + ray.direction * h.distance, h.normal, h.distance});
    };
    static_bvh_.ray_query(ray, ray.max_distance, [&](std::uint32_t slot, const Vec3& inv, float&) {
        const StaticPrim& p = static_prims_[slot];
        if (!p.enabled || !(p.layers & filter.layers) || !passes(filter, p.body)) return true;
        ShapeHit h;
        if (ray_static(ray, inv, p, h)) add(p.body, h);
        return true;
    });
    auto scan = [&](const std::vector<std::uint32_t>& list, bool triggers) {
        for (std::uint32_t index : list) {
            const Body& b = bodies_[index];
            if (!b.enabled || !passes(filter, index)) continue;
            if (!triggers && !(b.layers & filter.layers)) continue;
            ShapeHit h;
            if (ray_body(ray, index, h)) add(index, h);
        }
    };
    scan(movers_, false);
    if (filter.layers & layer::kTrigger) scan(static_triggers_, true);
    auto first = hits.begin() + static_cast<std::ptrdiff_t>(start);
    // Ties broken by body index so the order is deterministic.
    if (order == HitOrder::Ascending)
        std::sort(first, hits.end(), [](const RayHit& a, const RayHit& b) {
            return a.distance < b.distance || (a.distance == b.distance && a.body.index < b.body.index);
        });
    else
        std::sort(first, hits.end(), [](const RayHit& a, const RayHit& b) {
            return a.distance > b.distance || (a.distance == b.distance && a.body.index < b.body.index);
        });
    return static_cast<int>(hits.size() - start);
}

int World::overlap_capsule(const Segment& s, float radius, std::vector<BodyId>& out,
                           std::uint32_t layers) const {
    build_static();
    geometry::Aabb region{glm::min(s.p0, s.p1) - Vec3(radius), glm::max(s.p0, s.p1) + Vec3(radius)};
    const std::size_t start = out.size();
    auto test = [&](std::uint32_t index) {
        const Body& b = bodies_[index];
        if (!b.enabled || !(b.layers & layers) || !b.bounds.overlaps(region)) return;
        if (auto c = collide_capsule_shape(s, radius, b.shape, b.transform); c && c->penetration > 0.0f)
            out.push_back(id_of(index));
    };
    static_bvh_.aabb_query(region, [&](std::uint32_t slot) {
        test(static_prims_[slot].body);
        return true;
    });
    for (std::uint32_t index : movers_) test(index);
    for (std::uint32_t index : static_triggers_) test(index);
    return static_cast<int>(out.size() - start);
}

} // namespace ks::physics
