#include "core/version.h"

#if !defined(KS_VERSION) || !defined(KS_LICENSE)
#error "KS_VERSION and KS_LICENSE come from the top-level CMakeLists.txt (set_source_files_properties)"
#endif

namespace ks::version {

std::string_view number() {
    return KS_VERSION;
}
std::string_view license() {
    return KS_LICENSE;
}
std::string line(std::string_view program) {
    return std::string(program) + " " + std::string(number());
}

} // namespace ks::version
