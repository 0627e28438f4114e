// An ASCII FBX file's connection cycles refused before assimp reads it (modelio/fbx_connections.h): assimp's
// FBX converter follows them by recursion until the stack overflows (a fuzz finding).
#include "modelio/fbx_connections.h"
#include "modelio/model_import.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <string>

using namespace ks;

namespace {

std::string with_connections(const std::string& links) {
    return "; FBX 7.4.0 project file\nObjects:  {\n\tModel: 2, \"Model::cube\", \"Mesh\" {\n\t}\n}\n"
           "Connections:  {\n" +
           links + "}\n";
}

} // namespace

TEST_CASE("fbx connections: a loop of links is refused with the file and the line, anything else passes") {
    const std::filesystem::path file = "props/crate.fbx";
    CHECK(modelio::check_fbx_connections(with_connections("\tC: \"OO\",2,0\n\tC: \"OO\",3,2\n"), file).ok());
    // Two children of one parent, a property link, a diamond: no loop.
    CHECK(modelio::check_fbx_connections(
              with_connections("\tC: \"OO\",2,0\n\tC: \"OO\",3,0\n\tC: \"OP\",4,2, \"DiffuseColor\"\n"
                               "\tC: \"OO\",5,3\n\tC: \"OO\",5,2\n"),
              file)
              .ok());
    for (const std::string& loop : {std::string("\tC: \"OO\",2,2\n"),
                                    std::string("\tC: \"OO\",2,3\n\tC: \"OO\",3,4\n\tC: \"OO\",4,2\n"),
                                    std::string("\tC: \"OP\",7,8, \"X\"\n\tC:\"OO\",8,7\n")}) {
        CAPTURE(loop);
        auto r = modelio::check_fbx_connections(with_connections(loop), file);
        REQUIRE_FALSE(r.ok());
        const std::string message = r.error().str();
        CHECK(message.find("props/crate.fbx") != std::string::npos);
        CHECK(message.find("closes a loop") != std::string::npos);
        CHECK(message.find("line ") != std::string::npos);
    }
    // Huge ids, and a chain of 200 000 links (no recursion here either).
    CHECK(modelio::check_fbx_connections(
              with_connections("\tC: \"OO\",9223372036854775807,-9223372036854775807\n"), file)
              .ok());
    std::string chain;
    for (int i = 1; i <= 200000; ++i)
        chain += "\tC: \"OO\"," + std::to_string(i) + "," + std::to_string(i - 1) + "\n";
    CHECK(modelio::check_fbx_connections(with_connections(chain), file).ok());
    chain += "\tC: \"OO\",0,200000\n";
    CHECK_FALSE(modelio::check_fbx_connections(with_connections(chain), file).ok());
    // A binary file is not read here; malformed link lines are not links.
    CHECK(modelio::check_fbx_connections(std::string("Kaydara FBX Binary  \0\x1a\0", 23) + "C: \"OO\",2,2",
                                         file)
              .ok());
    CHECK(modelio::check_fbx_connections(with_connections("\tC: \"OO\",x,2\n\tC: \"OO\"\n\tC: \"QQ\",2,2\n"),
                                         file)
              .ok());
}

TEST_CASE("fbx connections: the import refuses a self-linked model instead of crashing") {
    test::ScratchDir dir;
    const auto file =
        test::write_file(dir / "loop.fbx", with_connections("\tC: \"OO\",2,2\n\tC: \"OO\",2,0\n"));
    auto model = modelio::import_model(file, modelio::ImportLimits{});
    REQUIRE_FALSE(model.ok());
    CHECK(model.error().str().find("closes a loop") != std::string::npos);
}
