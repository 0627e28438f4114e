// The binary glTF container checked before assimp reads it (modelio/glb_container.h), and every model input
// the fuzzer kept (tests/data/fuzz/fuzz_model_import/: hand-made seeds and what scripts/fuzz.sh found)
// replayed through the import: it imports or fails with an error naming the file, never a crash.
#include "hardening/fault_support.h"
#include "model_writers.h"
#include "modelio/glb_container.h"
#include "modelio/model_import.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <cstdint>
#include <string>

using namespace ks;

namespace glb_test {

std::string with_u32(std::string bytes, std::size_t at, std::uint32_t value) {
    for (int i = 0; i < 4; ++i) bytes[at + static_cast<std::size_t>(i)] = static_cast<char>(value >> (8 * i));
    return bytes;
}

std::uint32_t u32_at(const std::string& bytes, std::size_t at) {
    std::uint32_t v = 0;
    for (int i = 3; i >= 0; --i)
        v = v << 8 | static_cast<unsigned char>(bytes[at + static_cast<std::size_t>(i)]);
    return v;
}

} // namespace glb_test

TEST_CASE("glb container: a good file passes; damaged headers and chunk lengths are refused before assimp") {
    using glb_test::u32_at;
    using glb_test::with_u32;
    test::ScratchDir dir;
    const auto good_path = test::write_glb_cube(dir.path(), "cube", {});
    REQUIRE(modelio::check_glb_container(good_path).ok());
    REQUIRE(modelio::import_model(good_path, modelio::ImportLimits{}).ok());
    const std::string good = test::read_file(good_path);
    const std::uint32_t json_length = u32_at(good, 12);

    struct Case {
        const char* what;
        std::string bytes;
        const char* message;
    };
    const Case cases[] = {
        {"cut short", good.substr(0, good.size() - 10), "the GLB header says"},
        {"shorter than a header", good.substr(0, 7), "shorter than a GLB header"},
        {"wrong signature", "gltF" + good.substr(4), "GLB signature"},
        {"version 1", with_u32(good, 4, 1), "GLB version 1"},
        {"total length past the end", with_u32(good, 8, static_cast<std::uint32_t>(good.size() + 1)),
         "the GLB header says"},
        // The fuzz finding: the JSON chunk's length with its top bit set (assimp cleared 2 GB for it).
        {"JSON chunk length's top bit", with_u32(good, 12, json_length | 0x80000000u),
         "chunk 0 says it holds"},
        {"BIN chunk longer than the file", with_u32(good, 20 + json_length, 0x00ffffffu),
         "chunk 1 says it holds"},
        {"first chunk not JSON", with_u32(good, 16, 0x004E4942u), "not the JSON chunk"},
        {"no chunks", with_u32(good.substr(0, 12), 8, 12), "no JSON chunk"},
    };
    for (const Case& c : cases) {
        CAPTURE(c.what);
        const auto path =
            test::write_file(dir / (std::string("bad-") + std::to_string(&c - cases) + ".glb"), c.bytes);
        auto checked = modelio::check_glb_container(path);
        REQUIRE_FALSE(checked.ok());
        CHECK(checked.error().message.find(c.message) != std::string::npos);
        CHECK(checked.error().where.file == path.string());
        auto imported = modelio::import_model(path, modelio::ImportLimits{});
        REQUIRE_FALSE(imported.ok()); // the import refuses it the same way
        CHECK(imported.error().message == checked.error().message);
    }
}

TEST_CASE("fuzz regressions: every kept model input imports or fails with an error naming the file") {
    const auto inputs = hardening::fuzz_inputs("fuzz_model_import");
    REQUIRE_MESSAGE(!inputs.empty(), "tests/data/fuzz/fuzz_model_import/ holds the seeds and the findings");
    test::ScratchDir dir;
    static const char* kExtensions[] = {".glb", ".gltf", ".obj", ".fbx"}; // the fuzz target's first byte
    for (const auto& input : inputs) {
        CAPTURE(input.filename().string());
        const std::string bytes = test::read_file(input);
        if (bytes.empty()) continue;
        const auto format = static_cast<unsigned char>(bytes[0]);
        const auto file =
            test::write_file(dir / (input.filename().string() + kExtensions[format % 4]), bytes.substr(1));
        // The target's OBJ with its top bit set: the same bytes are its material library (the reader's
        // fallback name, the OBJ's with .mtl).
        std::error_code absent;
        std::filesystem::remove(dir / (input.filename().string() + ".mtl"), absent);
        if (format % 4 == 2 && (format & 0x80) != 0)
            test::write_file(dir / (input.filename().string() + ".mtl"), bytes.substr(1));
        auto model = modelio::import_model(file, modelio::ImportLimits{});
        if (!model.ok()) {
            CHECK_FALSE(model.error().message.empty());
            // The file itself, or the material library an OBJ reads (whose error names the OBJ too).
            std::filesystem::path library = file;
            library.replace_extension(".mtl");
            CHECK(
                (model.error().where.file == file.string() || model.error().where.file == library.string()));
            CHECK(model.error().str().find(file.filename().string()) != std::string::npos);
        }
    }
}
