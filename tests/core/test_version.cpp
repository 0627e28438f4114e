// The one project version (project(Killswitch VERSION ...) -> core/version.cpp) and the installed data
// folder the executables look for (<prefix>/bin/../share/killswitch).
#include "core/paths.h"
#include "core/version.h"

#include <doctest/doctest.h>

#include <regex>
#include <string>

using namespace ks;

TEST_CASE("version: x.y.z from CMake, the --version line, the licence") {
    const std::string v(version::number());
    CHECK(std::regex_match(v, std::regex("[0-9]+\\.[0-9]+\\.[0-9]+")));
    CHECK(version::line("killswitch") == "killswitch " + v);
    CHECK_FALSE(version::license().empty());
}

TEST_CASE("installed data folder: <prefix>/share/killswitch beside <prefix>/bin") {
    CHECK(paths::installed_data_dir("/usr/bin") == "/usr/share/killswitch");
    CHECK(paths::installed_data_dir("/opt/ks/bin/") == "/opt/ks/share/killswitch");
    CHECK(paths::installed_data_dir("/tmp/prefix/bin") == "/tmp/prefix/share/killswitch");
}
