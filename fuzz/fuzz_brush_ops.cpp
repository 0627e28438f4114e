// libFuzzer target: convex brushes and CSG on pairs of them, and their placement in the world; the
// properties checked are in brush_fuzz_properties.h (replayed by the GCC tests too).
#include "brush_fuzz_properties.h"
#include "fuzz_oracle.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string broken = ks::fuzz::brush_properties::check(data, size);
    if (!broken.empty()) ks::fuzz::fail(broken.c_str());
    return 0;
}
