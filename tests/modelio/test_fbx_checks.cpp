// An FBX file's connection cycles refused before assimp reads it (modelio/fbx_checks.h), ASCII and
// binary: assimp's FBX converter follows them by recursion until the stack overflows (a fuzz finding).
#include "modelio/fbx_checks.h"
#include "modelio/fbx_records.h"
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
    CHECK(modelio::check_fbx_file(with_connections("\tC: \"OO\",2,0\n\tC: \"OO\",3,2\n"), file).ok());
    // Two children of one parent, a property link, a diamond: no loop.
    CHECK(modelio::check_fbx_file(
              with_connections("\tC: \"OO\",2,0\n\tC: \"OO\",3,0\n\tC: \"OP\",4,2, \"DiffuseColor\"\n"
                               "\tC: \"OO\",5,3\n\tC: \"OO\",5,2\n"),
              file)
              .ok());
    for (const std::string& loop : {std::string("\tC: \"OO\",2,2\n"),
                                    std::string("\tC: \"OO\",2,3\n\tC: \"OO\",3,4\n\tC: \"OO\",4,2\n"),
                                    std::string("\tC: \"OP\",7,8, \"X\"\n\tC:\"OO\",8,7\n")}) {
        CAPTURE(loop);
        auto r = modelio::check_fbx_file(with_connections(loop), file);
        REQUIRE_FALSE(r.ok());
        const std::string message = r.error().str();
        CHECK(message.find("props/crate.fbx") != std::string::npos);
        CHECK(message.find("closes a loop") != std::string::npos);
        CHECK(message.find("line ") != std::string::npos);
    }
    // Huge ids, and a chain of 200 000 links (no recursion here either).
    CHECK(modelio::check_fbx_file(with_connections("\tC: \"OO\",9223372036854775807,-9223372036854775807\n"),
                                  file)
              .ok());
    std::string chain;
    for (int i = 1; i <= 200000; ++i)
        chain += "\tC: \"OO\"," + std::to_string(i) + "," + std::to_string(i - 1) + "\n";
    CHECK(modelio::check_fbx_file(with_connections(chain), file).ok());
    chain += "\tC: \"OO\",0,200000\n";
    CHECK_FALSE(modelio::check_fbx_file(with_connections(chain), file).ok());
    // Text after a binary file's magic is not read as ASCII (it is a damaged binary file); malformed link
    // lines are not links.
    auto text_as_binary =
        modelio::check_fbx_file(std::string("Kaydara FBX Binary  \0\x1a\0", 23) + "C: \"OO\",2,2", file);
    REQUIRE_FALSE(text_as_binary.ok());
    CHECK(text_as_binary.error().str().find("closes a loop") == std::string::npos);
    CHECK(text_as_binary.error().str().find("damaged") != std::string::npos);
    CHECK(modelio::check_fbx_file(with_connections("\tC: \"OO\",x,2\n\tC: \"OO\"\n\tC: \"QQ\",2,2\n"), file)
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

void put_at(std::string& out, size_t at, std::uint64_t value, size_t bytes) {
    for (size_t i = 0; i < bytes; ++i) out[at + i] = static_cast<char>((value >> (8 * i)) & 0xff);
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
        CHECK(modelio::check_fbx_file(scene, file).ok());

        for (const std::vector<Node>& loop :
             {std::vector<Node>{link("OO", 2, 0), link("OO", 5, 5)},
              std::vector<Node>{link("OO", 2, 3), link("OO", 3, 4), link("OO", 4, 2)},
              std::vector<Node>{link("OO", -1, std::numeric_limits<std::int64_t>::min()),
                                link("OP", std::numeric_limits<std::int64_t>::min(), -1)}}) {
            const std::string looped = binary_scene(loop, version);
            auto r = modelio::check_fbx_file(looped, file);
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
                (void)modelio::check_fbx_file(broken, "broken.fbx");
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

TEST_CASE("fbx checks: assimp's own binary export is refused where assimp's reader refuses it") {
    // assimp 5.2.5 cannot read back the binary FBX its exporter writes: a record's end offset leaves its
    // parent's children. The walk finds the same record; the links before it are read.
    test::ScratchDir dir;
    const auto gltf = test::write_gltf_cube(dir.path(), "cube");
    const auto fbx = dir / "cube.fbx";
    REQUIRE(test::convert_with_assimp(gltf, fbx, "fbx"));
    const std::string file = read_all(fbx);
    REQUIRE(modelio::read_fbx_links(file).binary);
    auto checked = modelio::check_fbx_file(file, fbx);
    REQUIRE_FALSE(checked.ok());
    MESSAGE(checked.error().str());
    auto imported = modelio::import_model(fbx, modelio::ImportLimits{});
    REQUIRE_FALSE(imported.ok());
    CHECK(imported.error().str() == checked.error().str());
}

TEST_CASE("fbx checks: damaged binary records are refused with their byte, before assimp can abort on them") {
    test::ScratchDir dir;
    const std::string good = binary_triangle(false);
    REQUIRE(modelio::check_fbx_file(good, "good.fbx").ok());
    // The records of the triangle: the header extension's first child is "FBXHeaderVersion".
    const size_t header_version =
        good.find("FBXHeaderVersion") - 25; // 7.5: three 8-byte words, a length byte
    const auto refused_with = [&](std::string bytes, const std::string& what) {
        CAPTURE(what);
        auto r = modelio::check_fbx_file(bytes, "damaged.fbx");
        REQUIRE_FALSE(r.ok());
        CHECK(r.error().str().find(what) != std::string::npos);
        CHECK(r.error().str().find("damaged.fbx") != std::string::npos);
        // And the import refuses it without crashing (assimp never sees it).
        const auto file = test::write_file(dir / "damaged.fbx", bytes);
        CHECK_FALSE(modelio::import_model(file, modelio::ImportLimits{}).ok());
    };
    // The fuzz finding: a property length near 2^64, which wrapped assimp's pointer (an assertion aborted).
    std::string wrapped = good;
    put_at(wrapped, header_version + 16, 0xfffffff700000005ull, 8);
    refused_with(wrapped,
                 "byte " + std::to_string(header_version) +
                     ": the record \"FBXHeaderVersion\" says its properties take 18446744035054845957 bytes");
    // A record that ends past its parent's children, or before it begins.
    std::string past = good;
    put_at(past, header_version, good.size() + 100, 8);
    refused_with(past, "past the children of \"FBXHeaderExtension\"");
    std::string before = good;
    put_at(before, header_version, 3, 8);
    refused_with(before, "before it begins");
    // An unknown property type, a name with a NUL, a null record that is not zeros.
    std::string type = good;
    type[good.find("FBXHeaderVersion") + 16] = 'Q';
    refused_with(type, "unknown property type code 81");
    std::string name = good;
    name[good.find("FBXHeaderVersion") + 3] = '\0';
    refused_with(name, "NUL");
    const size_t vertices = good.find("Vertices");
    std::string array_size = good;
    put_at(array_size, vertices + 9, 0x40000001u, 4); // 9 doubles claimed 2^30 + 1: 8 GiB, wraps in 32 bits
    refused_with(array_size, "larger than 4 GiB");
    std::string array_bytes = good;
    put_at(array_bytes, vertices + 9, 8u, 4); // 8 doubles in 72 bytes
    refused_with(array_bytes, "an array of 8 elements says it takes 72 bytes");
    std::string sentinel = good;
    sentinel[good.find("Connections") - 26] = '\x01'; // the last byte of the Objects record's null record
    refused_with(sentinel, "not all zeros");
    std::string cut = good.substr(0, good.size() / 2);
    refused_with(cut, "past the end of the file");
}

TEST_CASE("fbx checks: records and scopes nested deeper than assimp should recurse are refused") {
    for (std::uint32_t version : {7400u, 7500u}) {
        CAPTURE(version);
        const auto nested = [&](size_t depth) {
            Node inner{"P", int_property(1), 1, {}};
            for (size_t i = 1; i < depth; ++i) {
                Node outer{"N", "", 0, {}};
                outer.children.push_back(std::move(inner));
                inner = std::move(outer);
            }
            return binary_fbx({inner}, version);
        };
        CHECK(modelio::check_fbx_file(nested(modelio::kMaxFbxNesting), "deep.fbx").ok());
        auto r = modelio::check_fbx_file(nested(modelio::kMaxFbxNesting + 1), "deep.fbx");
        REQUIRE_FALSE(r.ok());
        CHECK(r.error().str().find("nested more than 64 deep") != std::string::npos);
        CHECK_FALSE(modelio::check_fbx_file(nested(2000), "deep.fbx").ok());
    }
    const auto ascii = [](size_t depth) {
        std::string text = "; a comment { { {\nA: \"{{{\" ";
        for (size_t i = 0; i < depth; ++i) text += "N: {\n";
        for (size_t i = 0; i < depth; ++i) text += "}\n";
        return text;
    };
    CHECK(modelio::check_fbx_file(ascii(modelio::kMaxFbxNesting - 1), "deep.fbx").ok());
    auto r = modelio::check_fbx_file(ascii(200000), "deep.fbx");
    REQUIRE_FALSE(r.ok());
    CHECK(r.error().str().find("line 65: scopes are nested more than 64 deep") != std::string::npos);
}
