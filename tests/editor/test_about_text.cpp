// Help > About's text (editor/view/about_text.h): name and version first, the licence named.
#include "core/version.h"
#include "view/about_text.h"

#include <doctest/doctest.h>

#include <string>

TEST_CASE("about text: the editor's version first, then what it is and the licence") {
    const auto lines = ks::editor::about_lines();
    REQUIRE(lines.size() >= 3);
    CHECK(lines[0] == "Killswitch Editor " + std::string(ks::version::number()));
    bool licence = false;
    for (const std::string& line : lines)
        licence = licence || line.rfind("Licence: " + std::string(ks::version::license()), 0) == 0;
    CHECK(licence);
}
