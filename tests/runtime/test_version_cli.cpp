// `--version` on both executables: one line "killswitch 0.9.0" (the project version from CMake), exit 0,
// without a display and before any other option is looked at.
#include "core/version.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <string>

using namespace ks;

TEST_CASE("--version prints the program and the project version, exit 0, no display needed") {
    for (const char* program : {"killswitch", "killswitch-editor"}) {
        CAPTURE(program);
        const auto run =
            test::run_command("env -u DISPLAY " + (test::bin_dir() / program).string() + " --version");
        CHECK(run.exit_code == 0);
        CHECK(run.output == version::line(program) + "\n");
        CHECK(run.output.find(std::string(version::number())) != std::string::npos);
    }
}

TEST_CASE("--help of both executables mentions --version") {
    for (const char* program : {"killswitch", "killswitch-editor"}) {
        CAPTURE(program);
        const auto run =
            test::run_command("env -u DISPLAY " + (test::bin_dir() / program).string() + " --help");
        CHECK(run.exit_code == 0);
        CHECK(run.output.find("--version") != std::string::npos);
    }
}
