#include "shell/raster_threads.h"

#include <cstdlib>
#include <thread>

namespace ks::shell {

int software_raster_threads_for(unsigned hardware_threads) {
    if (hardware_threads < 2 || hardware_threads > 4) return 0;
    return static_cast<int>(hardware_threads) * 2;
}

std::string configure_software_raster_threads() {
    if (const char* set = std::getenv("LP_NUM_THREADS"); set && *set) return set;
    const int threads = software_raster_threads_for(std::thread::hardware_concurrency());
    if (threads == 0) return {};
    const std::string value = std::to_string(threads);
    setenv("LP_NUM_THREADS", value.c_str(), 0);
    return value;
}

} // namespace ks::shell
