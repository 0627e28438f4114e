#pragma once
// The editor benchmarks' timer: the median wall time of an operation over repeated runs, after a warm-up.
#include <algorithm>
#include <chrono>
#include <functional>
#include <vector>

namespace ks::bench {

// Median wall time of `fn` in milliseconds over `reps` runs (after one warm-up run).
inline double median_ms(int reps, const std::function<void()>& fn) {
    fn();
    std::vector<double> t;
    t.reserve(static_cast<size_t>(reps));
    for (int i = 0; i < reps; ++i) {
        const auto t0 = std::chrono::steady_clock::now();
        fn();
        t.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
    std::nth_element(t.begin(), t.begin() + reps / 2, t.end());
    return t[static_cast<size_t>(reps / 2)];
}

} // namespace ks::bench
