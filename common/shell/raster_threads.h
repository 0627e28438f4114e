#pragma once
// Thread count for Mesa's llvmpipe, set before the GL context exists (the driver reads LP_NUM_THREADS once,
// when its screen is created). llvmpipe defaults to one rasteriser thread per core; on a 2-core machine the
// frame's tiles then wait on whichever of the two threads the scheduler delays, and the slowest frames
// suffer. Twice as many threads as cores, measured on 2 cores (docs/performance.md, "Rasteriser threads"):
// the same median, p99 18.7-19.9 -> 15.1-16.5 ms on the main level. GPU drivers ignore the variable.
#include <string>

namespace ks::shell {

// The LP_NUM_THREADS value to use for `hardware_threads` cores: 2x on 2..4 cores (the measured case and
// its neighbours); 0 = leave the driver's default (unknown count, 1 core, or more than 4).
int software_raster_threads_for(unsigned hardware_threads);

// Sets LP_NUM_THREADS from std::thread::hardware_concurrency() unless it is already set (a user's or a
// benchmark's choice wins). Returns the value in effect afterwards ("" when left to the driver).
std::string configure_software_raster_threads();

} // namespace ks::shell
