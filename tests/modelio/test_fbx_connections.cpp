// An FBX file's connection cycles refused before assimp reads it (modelio/fbx_connections.h), ASCII and
// binary: assimp's FBX converter follows them by recursion until the stack overflows (a fuzz finding).
#include "modelio/fbx_connections.h"
#include "modelio/model_import.h"
#include "modelio/model_writers.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

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
    // Text after a binary file's magic is not read as ASCII; malformed link lines are not links.
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

namespace {

// A binary FBX node record as FBX 7.4 (32-bit offsets) or 7.5 (64-bit) writes it: end offset, property count,
// property bytes, name, properties, children and the null record after them.
struct Node {
    std::string name;
    std::string properties; // encoded property records
    std::uint64_t property_count = 0;
    std::vector<Node> children;
};

void put(std::string& out, std::uint64_t value, size_t bytes) {
    for (size_t i = 0; i < bytes; ++i) out += static_cast<char>((value >> (8 * i)) & 0xff);
}

std::string string_property(const std::string& s) {
    std::string out = "S";
    put(out, s.size(), 4);
    return out + s;
}

std::string long_property(std::int64_t v) {
    std::string out = "L";
    put(out, static_cast<std::uint64_t>(v), 8);
    return out;
}

std::string int_property(std::int32_t v) {
    std::string out = "I";
    put(out, static_cast<std::uint32_t>(v), 4);
    return out;
}

// An uncompressed array property: type code, count, encoding 0, byte length, the values.
template <typename T>
std::string array_property(char type, const std::vector<T>& values) {
    std::string out(1, type);
    put(out, values.size(), 4);
    put(out, 0, 4);
    put(out, values.size() * sizeof(T), 4);
    for (T v : values) {
        std::uint64_t bits = 0;
        std::memcpy(&bits, &v, sizeof(T));
        put(out, bits, sizeof(T));
    }
    return out;
}

void encode(const Node& node, size_t word, std::string& out) {
    const size_t at = out.size();
    put(out, 0, word); // the end offset, written below
    put(out, node.property_count, word);
    put(out, node.properties.size(), word);
    out += static_cast<char>(node.name.size());
    out += node.name + node.properties;
    for (const Node& child : node.children) encode(child, word, out);
    if (!node.children.empty()) out.append(3 * word + 1, '\0');
    std::string end;
    put(end, out.size(), word);
    out.replace(at, word, end);
}

std::string binary_fbx(const std::vector<Node>& records, std::uint32_t version) {
    const size_t word = version >= 7500 ? 8 : 4;
    std::string out("Kaydara FBX Binary  \0\x1a\0", 23);
    put(out, version, 4);
    for (const Node& record : records) encode(record, word, out);
    out.append(3 * word + 1, '\0');
    return out;
}

Node link(const std::string& kind, std::int64_t child, std::int64_t parent) {
    return {"C", string_property(kind) + long_property(child) + long_property(parent), 3, {}};
}

// An Objects record with a model that has an array and a nested record, then the given links.
std::string binary_scene(std::vector<Node> links, std::uint32_t version) {
    Node model{"Model",
               long_property(2) + string_property("Model::cube") +
                   array_property<double>('d', {1.0, 2.0, 3.0}),
               3,
               {}};
    model.children.push_back({"Properties70", "", 0, {{"P", string_property("Lcl Scaling"), 1, {}}}});
    Node objects{"Objects", "", 0, {model}};
    // Links FBX 6 wrote by name, and another record inside Connections: not links.
    links.push_back(
        {"C", string_property("OO") + string_property("Model::a") + string_property("Model::b"), 3, {}});
    links.push_back({"Comment", string_property("x"), 1, {}});
    return binary_fbx({{"FBXHeaderExtension", "", 0, {{"FBXVersion", int_property(7400), 1, {}}}},
                       objects,
                       {"Connections", "", 0, links}},
                      version);
}

// A one-triangle model in binary FBX 7.5 (the records tests/data/fuzz/fuzz_model_import/seed-fbx-triangle
// holds as text), its model linked to the root and, with `self_link`, also to itself.
std::string binary_triangle(bool self_link) {
    Node header{"FBXHeaderExtension",
                "",
                0,
                {{"FBXHeaderVersion", int_property(1003), 1, {}}, {"FBXVersion", int_property(7500), 1, {}}}};
    Node geometry{"Geometry",
                  long_property(1) + string_property(std::string("cube\0\1Geometry", 14)) +
                      string_property("Mesh"),
                  3,
                  {{"Vertices", array_property<double>('d', {0, 0, 0, 1, 0, 0, 0, 1, 0}), 1, {}},
                   {"PolygonVertexIndex", array_property<std::int32_t>('i', {0, 1, -3}), 1, {}}}};
    Node model{"Model",
               long_property(2) + string_property(std::string("cube\0\1Model", 11)) + string_property("Mesh"),
               3,
               {{"Version", int_property(232), 1, {}}}};
    std::vector<Node> links{link("OO", 1, 2), link("OO", 2, 0)};
    if (self_link) links.push_back(link("OO", 2, 2));
    return binary_fbx({header, {"Objects", "", 0, {geometry, model}}, {"Connections", "", 0, links}}, 7500);
}

std::string read_all(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

} // namespace

TEST_CASE("fbx connections: a binary file's links are read through its records, 32- and 64-bit offsets") {
    const std::filesystem::path file = "props/crate.fbx";
    for (std::uint32_t version : {7400u, 7500u}) {
        CAPTURE(version);
        const size_t word = version >= 7500 ? 8 : 4;
        const std::string scene = binary_scene(
            {link("OO", 2, 0),
             {"C",
              string_property("OP") + long_property(3) + long_property(2) + string_property("DiffuseColor"),
              4,
              {}}},
            version);
        const modelio::FbxLinks read = modelio::read_fbx_links(scene);
        CHECK(read.binary);
        REQUIRE(read.links.size() == 2);
        CHECK(read.links[0].child == 2);
        CHECK(read.links[0].parent == 0);
        CHECK(read.links[1].child == 3);
        CHECK(read.links[1].parent == 2);
        for (const modelio::FbxLink& l : read.links) CHECK(scene.substr(l.place + 3 * word, 2) == "\1C");
        CHECK(modelio::check_fbx_connections(scene, file).ok());

        for (const std::vector<Node>& loop :
             {std::vector<Node>{link("OO", 2, 0), link("OO", 5, 5)},
              std::vector<Node>{link("OO", 2, 3), link("OO", 3, 4), link("OO", 4, 2)},
              std::vector<Node>{link("OO", -1, std::numeric_limits<std::int64_t>::min()),
                                link("OP", std::numeric_limits<std::int64_t>::min(), -1)}}) {
            const std::string looped = binary_scene(loop, version);
            auto r = modelio::check_fbx_connections(looped, file);
            REQUIRE_FALSE(r.ok());
            const std::string message = r.error().str();
            CHECK(message.find("props/crate.fbx") != std::string::npos);
            CHECK(message.find("closes a loop") != std::string::npos);
            // The byte named is one of the loop's records.
            bool named = false;
            for (const modelio::FbxLink& l : modelio::read_fbx_links(looped).links)
                named = named || message.find("byte " + std::to_string(l.place) + ":") != std::string::npos;
            CHECK(named);
        }
    }
}

TEST_CASE(
    "fbx connections: a broken binary file is read within its bounds (every prefix, every byte changed)") {
    for (std::uint32_t version : {7400u, 7500u}) {
        CAPTURE(version);
        const std::string scene = binary_scene({link("OO", 2, 0), link("OO", 5, 5)}, version);
        REQUIRE(modelio::read_fbx_links(scene).links.size() == 2);
        // A prefix that cuts the Connections record reads none of its links (its end offset leaves the file).
        size_t complete_from = scene.size();
        for (size_t n = 0; n <= scene.size(); ++n) {
            const size_t links = modelio::read_fbx_links(std::string_view(scene).substr(0, n)).links.size();
            if (links == 2 && complete_from == scene.size()) complete_from = n;
            CHECK((links == 0 || links == 2));
        }
        CHECK(complete_from < scene.size()); // only the final null record may be missing
        for (size_t i = 0; i < scene.size(); ++i)
            for (char c : {'\0', '\x7f', '\xff'}) {
                std::string broken = scene;
                broken[i] = c;
                const auto read = modelio::read_fbx_links(broken);
                CHECK(read.links.size() <= 3); // a string id made a long one may read as a link
                (void)modelio::check_fbx_connections(broken, "broken.fbx");
            }
    }
}

TEST_CASE("fbx connections: a binary model with a self-linked object is refused instead of crashing") {
    test::ScratchDir dir;
    const auto good = test::write_file(dir / "triangle.fbx", binary_triangle(false));
    auto model = modelio::import_model(good, modelio::ImportLimits{});
    REQUIRE_MESSAGE(model.ok(), model.error().str());
    CHECK(model->triangle_count == 1);

    // Without the check assimp recurses from the root into the model and then into itself until the stack
    // overflows.
    const std::string looped = binary_triangle(true);
    const auto bad = test::write_file(dir / "loop.fbx", looped);
    model = modelio::import_model(bad, modelio::ImportLimits{});
    REQUIRE_FALSE(model.ok());
    const modelio::FbxLinks read = modelio::read_fbx_links(looped);
    REQUIRE(read.links.size() == 3);
    const std::string message = model.error().str();
    CHECK(message.find("loop.fbx") != std::string::npos);
    CHECK(message.find("byte " + std::to_string(read.links[2].place) + ": the connection of object 2 to 2") !=
          std::string::npos);
}

TEST_CASE("fbx connections: assimp's own binary export is read whole") {
    // assimp 5.2.5 cannot read back the binary FBX its exporter writes (its tokenizer refuses a record's end
    // offset), so only the links are checked here: the reader walks a real exporter's records.
    test::ScratchDir dir;
    const auto gltf = test::write_gltf_cube(dir.path(), "cube");
    const auto fbx = dir / "cube.fbx";
    REQUIRE(test::convert_with_assimp(gltf, fbx, "fbx"));
    const std::string file = read_all(fbx);
    const modelio::FbxLinks read = modelio::read_fbx_links(file);
    REQUIRE(read.binary);
    REQUIRE(read.links.size() >= 3); // the geometry and the material to the model, the model to the root
    bool root = false;
    for (const modelio::FbxLink& l : read.links) root = root || l.parent == 0;
    CHECK(root);
    CHECK(modelio::check_fbx_connections(file, fbx).ok());
}
