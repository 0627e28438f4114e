// One ray traversal of the 8-wide BVH. Included twice by bvh.h (deliberately no include guard): with
// KS_BVH_TRAVERSE_AVX2 = 0 it defines ray_query_leaves_portable (SSE2, or plain C++ without SSE), with
// KS_BVH_TRAVERSE_AVX2 = 1, inside a `#pragma GCC target("avx2")` region, ray_query_leaves_avx2. The caller's
// visitor is inlined into both. Every lane performs the same float operations in the same order in all
// three variants, so they accept the same children with the same entry distances.
namespace ks::physics {

template <class VisitLeaf>
#if KS_BVH_TRAVERSE_AVX2
void Bvh::ray_query_leaves_avx2(const geometry::Ray& ray, const Vec3& inv, float max_t, VisitLeaf& visit) const {
#else
void Bvh::ray_query_leaves_portable(const geometry::Ray& ray, const Vec3& inv, float max_t, VisitLeaf& visit) const {
#endif
    if (wide_.empty()) return;
    // The near and far slab planes of each axis are picked by the direction's sign once per ray: with
    // inv > 0, (min - o) * inv <= (max - o) * inv lane by lane (rounding is monotone), so these are exactly
    // the values min() and max() of the two planes would give, without computing both per node.
    const int nx = inv.x < 0.0f ? 3 : 0, ny = inv.y < 0.0f ? 4 : 1, nz = inv.z < 0.0f ? 5 : 2;
    const int fx = 3 - nx, fy = 5 - ny, fz = 7 - nz;
#if KS_BVH_TRAVERSE_AVX2
    const __m256 ox = _mm256_set1_ps(ray.origin.x), oy = _mm256_set1_ps(ray.origin.y),
                 oz = _mm256_set1_ps(ray.origin.z);
    const __m256 ix = _mm256_set1_ps(inv.x), iy = _mm256_set1_ps(inv.y), iz = _mm256_set1_ps(inv.z);
    const __m256 zero = _mm256_setzero_ps(), widen = _mm256_set1_ps(geometry::kExitWiden);
#elif defined(__SSE2__)
    const __m128 ox = _mm_set1_ps(ray.origin.x), oy = _mm_set1_ps(ray.origin.y),
                 oz = _mm_set1_ps(ray.origin.z);
    const __m128 ix = _mm_set1_ps(inv.x), iy = _mm_set1_ps(inv.y), iz = _mm_set1_ps(inv.z);
    const __m128 zero = _mm_setzero_ps(), widen = _mm_set1_ps(geometry::kExitWiden);
#endif
    bvh_detail::Pending stack[kMaxDepth * kWidth];
    int top = 0;
    alignas(32) float t_enter[kWidth];
    std::int32_t cur = 0; // the node or (< 0) leaf being visited
    for (;;) {
        if (cur >= 0) {
            const WideNode& n = wide_[cur];
#if KS_BVH_TRAVERSE_AVX2
            const __m256 tnx = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(n.bounds[nx]), ox), ix);
            const __m256 tfx = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(n.bounds[fx]), ox), ix);
            const __m256 tny = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(n.bounds[ny]), oy), iy);
            const __m256 tfy = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(n.bounds[fy]), oy), iy);
            const __m256 tnz = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(n.bounds[nz]), oz), iz);
            const __m256 tfz = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(n.bounds[fz]), oz), iz);
            const __m256 tmin = _mm256_max_ps(_mm256_max_ps(tnx, tny), _mm256_max_ps(tnz, zero));
            const __m256 tmax =
                _mm256_min_ps(_mm256_min_ps(tfx, tfy), _mm256_min_ps(tfz, _mm256_set1_ps(max_t)));
            _mm256_store_ps(t_enter, tmin);
            int mask = _mm256_movemask_ps(_mm256_cmp_ps(tmin, _mm256_mul_ps(tmax, widen), _CMP_LE_OQ));
#elif defined(__SSE2__)
            int mask = 0;
            for (int h = 0; h < kWidth; h += 4) {
                const __m128 tnx = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(&n.bounds[nx][h]), ox), ix);
                const __m128 tfx = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(&n.bounds[fx][h]), ox), ix);
                const __m128 tny = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(&n.bounds[ny][h]), oy), iy);
                const __m128 tfy = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(&n.bounds[fy][h]), oy), iy);
                const __m128 tnz = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(&n.bounds[nz][h]), oz), iz);
                const __m128 tfz = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(&n.bounds[fz][h]), oz), iz);
                const __m128 tmin = _mm_max_ps(_mm_max_ps(tnx, tny), _mm_max_ps(tnz, zero));
                const __m128 tmax = _mm_min_ps(_mm_min_ps(tfx, tfy), _mm_min_ps(tfz, _mm_set1_ps(max_t)));
                _mm_store_ps(t_enter + h, tmin);
                mask |= _mm_movemask_ps(_mm_cmple_ps(tmin, _mm_mul_ps(tmax, widen))) << h;
            }
#else
        int mask = 0;
        for (int k = 0; k < kWidth; ++k) {
            const float tnx = (n.bounds[nx][k] - ray.origin.x) * inv.x;
            const float tfx = (n.bounds[fx][k] - ray.origin.x) * inv.x;
            const float tny = (n.bounds[ny][k] - ray.origin.y) * inv.y;
            const float tfy = (n.bounds[fy][k] - ray.origin.y) * inv.y;
            const float tnz = (n.bounds[nz][k] - ray.origin.z) * inv.z;
            const float tfz = (n.bounds[fz][k] - ray.origin.z) * inv.z;
            const float tmin = std::max(std::max(tnx, tny), std::max(tnz, 0.0f));
            const float tmax = std::min(std::min(tfx, tfy), std::min(tfz, max_t));
            t_enter[k] = tmin;
            if (tmin <= tmax * geometry::kExitWiden) mask |= 1 << k;
        }
#endif
            mask &= n.lanes;
            if (mask) {
                if ((mask & (mask - 1)) == 0) // one child hit (the common case deep in the tree): no stack
                    cur = n.child[std::countr_zero(static_cast<unsigned>(mask))];
                else
                    cur = bvh_detail::order_children(mask, t_enter, n.child, stack, top);
                continue;
            }
        } else if (!visit(static_cast<std::uint32_t>(~cur), max_t)) {
            return;
        }
        // Next: the nearest pending child still within reach (a closer hit may have shrunk max_t).
        for (;;) {
            if (top == 0) return;
            const bvh_detail::Pending p = stack[--top];
            if (p.t <= max_t) {
                cur = p.child;
                break;
            }
        }
    }
}

} // namespace ks::physics
